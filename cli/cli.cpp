#include "cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <ostream>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/planning/shot_planner.hpp"

namespace cueball::cli {

namespace {

constexpr const char* kDescription =
    "cueball: physics of billiard balls.\n"
    "Units are SI (m, s, kg, rad). Table frame: x, y on the bed, z up; a straight shot travels\n"
    "along +x. Topspin w0 > 0 turns the ball the way it rolls (R w0 = v0 is natural roll),\n"
    "w0 < 0 is draw. Side spin w_z > 0 is anticlockwise seen from above.";

// Longest value a flag takes (PATH_MAX).
constexpr std::size_t kMaxValueBytes = 4096;

std::string format_value(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

}  // namespace

std::string fixed(double v, int decimals) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v == 0.0 ? 0.0 : v);
  return buf;
}

std::string flag_for_field(const std::string& field) {
  std::string flag = "--";
  for (char c : field) flag += (c == '_' ? '-' : c);
  return flag;
}

std::string read_text_file(const std::string& path, const std::string& what, std::size_t max_bytes) {
  // POSIX reads with a cap: a never-ending file (/dev/zero, a FIFO fed
  // forever) or a huge one is refused after max_bytes, not read until memory
  // runs out.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw UsageError(quote_input(path, kMaxEchoedPathChars) + ": cannot open " + what + " (" + std::strerror(errno) + ")");
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) throw UsageError(quote_input(path, kMaxEchoedPathChars) + ": is a directory, not " + what);
  std::string text;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw UsageError(quote_input(path, kMaxEchoedPathChars) + ": cannot read " + what + " (" + std::strerror(errno) + ")");
    }
    if (n == 0) break;
    if (text.size() + static_cast<std::size_t>(n) > max_bytes)
      throw UsageError(quote_input(path, kMaxEchoedPathChars) + ": " + what + " is larger than the " + std::to_string(max_bytes) +
                       " bytes allowed (" + std::to_string(max_bytes >> 20) + " MiB)");
    text.append(buf, static_cast<std::size_t>(n));
  }
  return text;
}

std::string flag_of_library_field(const std::string& field) {
  static const std::map<std::string, std::string> flags{
      {"mass", "--mass"},         {"radius", "--radius"},       {"mu_s", "--mu-s"},       {"mu_r", "--mu-r"},
      {"mu_sp", "--mu-sp"},       {"g", "--g"},                 {"e_e", "--e"},           {"mu_w", "--mu-w"},
      {"h", "--height"},          {"sin_theta", "--height"},    {"V0", "--v0"},           {"alpha", "--alpha"},
      {"w_T", "--topspin"},       {"w_S", "--sidespin"},        {"paper_steps", "--steps"}, {"grid_step", "--grid-step"},
      {"sample_rate", "--sample"}, {"v0", "--v0"},              {"w0", "--w0"},           {"x0", "--x0"},
      {"x1", "--x1"},             {"x2", "--x2"},               {"v2", "--v2"},           {"cue_mass", "--cue-mass"},
      {"cue_tip_e", "--cue-tip-e"}, {"side_spin", "--side"},    {"t", "--at"},            {"preset", "--preset"},
  };
  const auto it = flags.find(field);
  return it == flags.end() ? std::string() : it->second;
}

void write_text_file(const std::string& path, std::string_view text, const std::string& flag, const std::string& what) {
  std::ofstream file(path, std::ios::binary);
  if (!file || !file.write(text.data(), static_cast<std::streamsize>(text.size())) || !file.flush())
    throw UsageError(flag + " " + quote_input(path, kMaxEchoedPathChars) + ": cannot write " + what);
}

void check_flag(const char* flag, double value, double lo, double hi, const char* meaning) {
  if (std::isfinite(value) && value >= lo && value <= hi) return;
  throw UsageError(std::string(flag) + " = " + format_number_beside(value, {lo, hi}) +
                   (std::isfinite(value) ? " is outside the allowed range [" : " is not a finite number; allowed: [") +
                   format_value(lo) + ", " + format_value(hi) + "] (" + meaning + ")");
}

void add_sigma_flags(CLI::App& app, SigmaFlags& flags) {
  app.add_option("--sigma-speed", flags.speed, "Sigma of the cue speed, m/s, [0, 5]");
  app.add_option("--sigma-aim", flags.aim, "Sigma of the aim, degrees, [0, 30]");
  app.add_option("--sigma-elevation", flags.elevation, "Sigma of the cue elevation, degrees, [0, 30]");
  app.add_option("--sigma-side", flags.side, "Sigma of the side tip offset, ball radii, [0, 0.5]");
  app.add_option("--sigma-height", flags.height, "Sigma of the height tip offset, ball radii, [0, 0.5]");
}

CueStrikeNoise with_sigma_flags(const SigmaFlags& f, CueStrikeNoise noise, double radius) {
  const double degree = std::numbers::pi / 180.0;
  if (f.speed) check_flag("--sigma-speed", *f.speed, 0, 5, "sigma of the cue speed, m/s"), noise.speed = *f.speed;
  if (f.aim) check_flag("--sigma-aim", *f.aim, 0, 30, "sigma of the aim, degrees"), noise.aim = *f.aim * degree;
  if (f.elevation)
    check_flag("--sigma-elevation", *f.elevation, 0, 30, "sigma of the elevation, degrees"),
        noise.elevation = *f.elevation * degree;
  if (f.side)
    check_flag("--sigma-side", *f.side, 0, 0.5, "sigma of the side offset, ball radii"),
        noise.side_offset = *f.side * radius;
  if (f.height)
    check_flag("--sigma-height", *f.height, 0, 0.5, "sigma of the height offset, ball radii"),
        noise.height_offset = *f.height * radius;
  return noise;
}

void add_parameter_flags(CLI::App& app, ParameterFlags& flags) {
  app.add_option("--preset", flags.preset, "Named parameter set: pool (WPA ball), snooker (Mathavan 2010) or carom (heated cloth, fitted)")
      ->check(CLI::IsMember({"snooker", "pool"}))
      ->capture_default_str();
  const auto add = [&](const char* name, std::optional<double>& target, const ParameterRange& r) {
    std::string help = std::string("Override ") + r.meaning + (*r.unit ? std::string(", ") + r.unit : "") + "; allowed [" +
                       format_value(r.min) + ", " + format_value(r.max) + "]";
    app.add_option(name, target, help);
  };
  add("--mass", flags.mass, kMassRange);
  add("--radius", flags.radius, kRadiusRange);
  add("--mu-s", flags.mu_s, kSlidingFrictionRange);
  add("--mu-r", flags.mu_r, kRollingResistanceRange);
  add("--mu-sp", flags.mu_sp, kSpinFrictionRange);
  add("--g", flags.g, kGravityRange);
  app.add_flag("--json", flags.json, "Print one JSON object (SI units) instead of a table");
}

Parameters resolve_parameters(const ParameterFlags& flags) {
  Parameters p = preset_parameters(flags.preset);
  if (flags.mass) p.ball.mass = *flags.mass;
  if (flags.radius) p.ball.radius = *flags.radius;
  if (flags.mu_s) p.cloth.sliding_friction = *flags.mu_s;
  if (flags.mu_r) p.cloth.rolling_resistance = *flags.mu_r;
  if (flags.mu_sp) p.cloth.spin_friction = *flags.mu_sp;
  if (flags.g) p.cloth.gravity = *flags.g;
  try {
    validate(p);
  } catch (const InvalidArgument& e) {
    throw UsageError(flag_for_field(e.field()) + ": " + e.what());
  }
  return p;
}

void emit(const Report& report, bool json, std::ostream& out, std::ostream& err) {
  report.print(out, json);
  for (const std::string& w : report.warnings()) err << "cueball: warning: " << w << '\n';
}

Command add_game_command(CLI::App& app);  // cli/command_game.cpp

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{kDescription, "cueball"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every subcommand");
  std::vector<std::pair<CLI::App*, Command>> commands;
  const auto chosen = [&]() -> Command* {
    for (auto& [sub, command] : commands)
      if (sub->parsed()) return &command;
    return nullptr;
  };
  const auto add = [&](const char* name, Command command) { commands.emplace_back(app.get_subcommand(name), command); };
  add("roll", add_roll_command(app));
  add("plan", add_plan_command(app));
  add("cushion", add_cushion_command(app));
  add("cushion-sweep", add_cushion_sweep_command(app));
  add("figures", add_figures_command(app));
  add("fit-cushion", add_fit_cushion_command(app));
  add("simulate", add_simulate_command(app));
  add("batch", add_batch_command(app));
  add("many", add_many_command(app));
  add("plan-shot", add_plan_shot_command(app));
  add("view", add_view_command(app));
  add("calibrate", add_calibrate_command(app));
  add("game", add_game_command(app));

  // Every option that takes a value: an empty value (--v0 "") is an error,
  // not 0, and so are control characters and values longer than a path.
  for (CLI::App* sub : app.get_subcommands({})) {
    for (CLI::Option* opt : sub->get_options()) {
      if (opt->get_type_size_max() <= 0) continue;  // a flag
      const std::string description = opt->get_description().substr(0, opt->get_description().find('\n'));
      const std::string type = opt->get_type_name();
      opt->check(CLI::Validator(
          [description, type](std::string& value) -> std::string {
            if (value.empty()) return "the value is empty (expected: " + description + ")";
            bool control = false;
            for (char c : value) control = control || static_cast<unsigned char>(c) < 0x20 || c == 0x7F;
            if (control) return "the value " + quote_input(value) + " contains control characters";
            if (value.size() > kMaxValueBytes)
              return "the value " + quote_input(value) + " is longer than " + std::to_string(kMaxValueBytes) + " bytes";
            // Numbers: the whole value must be one (CLI11 would say only "Could not convert").
            char* end = nullptr;
            if (type == "FLOAT") (void)std::strtod(value.c_str(), &end);
            if (type == "INT") (void)std::strtoll(value.c_str(), &end, 10);
            if (end != nullptr && (end == value.c_str() || *end != '\0'))
              return quote_input(value) + " is not " + (type == "INT" ? "an integer" : "a number") + " (expected: " +
                     description + ")";
            return {};
          },
          "", "value"));
    }
  }

  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const auto& entry : commands) {
      names += (names.empty() ? "" : ", ") + entry.first->get_name();
      known = known || entry.first->get_name() == argv[1];
    }
    if (!known) {
      err << "cueball: error: unknown subcommand " << quote_input(argv[1]) << "; choose one of: " << names << '\n';
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    err << "cueball: error: " << one_line(e.what()) << '\n';
    return 2;
  }
  try {
    Command* command = chosen();
    if (command == nullptr) throw UsageError("no subcommand given; see cueball --help");
    (*command)(out, err);
    return 0;
  } catch (const UsageError& e) {
    err << "cueball: error: " << one_line(e.what()) << '\n';
    return 2;
  } catch (const CheckFailed& e) {
    err << "cueball: " << one_line(e.what()) << '\n';
    return 1;
  } catch (const InvalidArgument& e) {
    // A JSON path (scenario.balls[1].position) is named in the message
    // itself; a library field (mu_s) is shown as the flag that sets it
    // (--mu-s); a field no flag sets is left to the message.
    const std::string flag = flag_of_library_field(e.field());
    err << "cueball: error: " << one_line((flag.empty() ? "" : flag + ": ") + e.what()) << '\n';
    return 2;
  } catch (const InfeasibleShot& e) {
    err << "cueball: error: " << one_line(e.what()) << '\n';
    return 2;
  } catch (const NoFeasibleShot& e) {
    // A well-formed request with no answer (plan-shot): status 3.
    err << "cueball: " << one_line(e.what()) << '\n';
    return 3;
  } catch (const std::exception& e) {
    err << "cueball: internal error: " << one_line(e.what()) << '\n';
    return 1;
  }
}

}  // namespace cueball::cli
