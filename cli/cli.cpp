#include "cli.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <ostream>
#include <vector>

#include "common.hpp"
#include "cueball/errors.hpp"

namespace cueball::cli {

namespace {

constexpr const char* kDescription =
    "cueball: physics of billiard balls.\n"
    "Units are SI (m, s, kg, rad). Table frame: x, y on the bed, z up; a straight shot travels\n"
    "along +x. Topspin w0 > 0 turns the ball the way it rolls (R w0 = v0 is natural roll),\n"
    "w0 < 0 is draw. Side spin w_z > 0 is anticlockwise seen from above.";

std::string format_value(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

}  // namespace

std::string flag_for_field(const std::string& field) {
  std::string flag = "--";
  for (char c : field) flag += (c == '_' ? '-' : c);
  return flag;
}

std::string read_text_file(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(path + ": cannot open " + what);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text_file(const std::string& path, std::string_view text, const std::string& flag, const std::string& what) {
  std::ofstream file(path, std::ios::binary);
  if (!file || !file.write(text.data(), static_cast<std::streamsize>(text.size())) || !file.flush())
    throw UsageError(flag + " " + path + ": cannot write " + what);
}

void check_flag(const char* flag, double value, double lo, double hi, const char* meaning) {
  if (std::isfinite(value) && value >= lo && value <= hi) return;
  throw UsageError(std::string(flag) + " = " + format_value(value) +
                   (std::isfinite(value) ? " is outside the allowed range [" : " is not a finite number; allowed: [") +
                   format_value(lo) + ", " + format_value(hi) + "] (" + meaning + ")");
}

void add_parameter_flags(CLI::App& app, ParameterFlags& flags) {
  app.add_option("--preset", flags.preset, "Named parameter set: snooker (Mathavan 2010) or pool (WPA ball)")
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
  add("view", add_view_command(app));

  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const auto& entry : commands) {
      names += (names.empty() ? "" : ", ") + entry.first->get_name();
      known = known || entry.first->get_name() == argv[1];
    }
    if (!known) {
      err << "cueball: error: unknown subcommand '" << argv[1] << "'; choose one of: " << names << '\n';
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
    err << "cueball: error: " << e.what() << '\n';
    return 2;
  }
  try {
    Command* command = chosen();
    if (command == nullptr) throw UsageError("no subcommand given; see cueball --help");
    (*command)(out, err);
    return 0;
  } catch (const UsageError& e) {
    err << "cueball: error: " << e.what() << '\n';
    return 2;
  } catch (const InvalidArgument& e) {
    // A JSON path (scenario.balls[1].position) is named in the message itself;
    // a library field (mu_s) is shown as the flag that sets it (--mu-s).
    const std::string& field = e.field();
    const bool json_path = field.find_first_of(".[") != std::string::npos || field == "scenario" || field == "table";
    err << "cueball: error: " << (json_path ? "" : flag_for_field(e.field()) + ": ") << e.what() << '\n';
    return 2;
  } catch (const InfeasibleShot& e) {
    err << "cueball: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    err << "cueball: internal error: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace cueball::cli
