// cueball cushion, cueball cushion-sweep: the ball-cushion impact of
// Mathavan, Jackson & Parkin (2010), one impact or the paper's figure families.
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <ostream>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "common.hpp"
#include "cueball/io/cushion_fit_data.hpp"
#include "cueball/io/cushion_json.hpp"
#include "cueball/models/cushion/fit.hpp"
#include "cueball/models/cushion/impact.hpp"
#include "cueball/models/cushion/model.hpp"
#include "cueball/core/errors.hpp"

namespace cueball::cli {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Solver and constants flags shared by both commands.
struct CushionFlags {
  std::string solver = "exact";
  std::string constants = "paper-fit";
  int steps = 5000;
  std::optional<double> restitution, friction, height;
};

void add_cushion_flags(CLI::App& app, CushionFlags& f) {
  app.add_option("--solver", f.solver,
                 "exact: event-driven, no discretisation error (default); paper: the authors' Euler in P_I")
      ->check(CLI::IsMember({"exact", "paper"}))
      ->capture_default_str();
  app.add_option("--steps", f.steps, "N for the paper solver: dP_I = (1 + e_e) M V0 sin(alpha) / N")
      ->capture_default_str();
  app.add_option("--constants", f.constants,
                 "paper-fit: e_e 0.98, mu_w 0.14 (the authors' fit, made with the paper solver; the default,\n"
                 "the exact solver agrees with it to 1e-3 m/s); translator-fit: e_e 0.986, mu_w 0.2093 (the\n"
                 "translator's afterword, for an exact solver)")
      ->check(CLI::IsMember({"paper-fit", "translator-fit"}))
      ->capture_default_str();
  app.add_option("--e", f.restitution, "Cushion restitution e_e, (0, 1]; overrides --constants");
  app.add_option("--mu-w", f.friction, "Ball-cushion friction mu_w >= 0; overrides --constants");
  app.add_option("--height", f.height, "Contact height h of the cushion above the bed, m, in (R, 2R); default 7R/5");
}

// A --solver value (checked by CLI11 to be "exact" or "paper").
CushionSolver solver_named(const std::string& name) { return name == "paper" ? CushionSolver::paper : CushionSolver::exact; }

CushionParameters cushion_of(const CushionFlags& f, const Parameters& p) {
  CushionParameters c = f.constants == "translator-fit" ? cushion_translator_exact_fit(p.ball)
                                                         : cushion_mathavan2010_paper_fit(p.ball);
  if (f.restitution) {
    check_flag("--e", *f.restitution, 1e-9, 1.0, "cushion restitution e_e, (0, 1]");
    c.restitution = *f.restitution;
  }
  if (f.height) {
    check_flag("--height", *f.height, p.ball.radius * (1 + 1e-9), 2 * p.ball.radius * (1 - 1e-9),
               "cushion contact height h, m, between R and 2R");
    c.contact_height = *f.height;
  }
  // After --height: the bound on mu_w is the contact angle's.
  if (f.friction) {
    check_flag("--mu-w", *f.friction, 0.0, std::tan(std::asin(cushion_sin_theta(c, p.ball))),
               "ball-cushion friction mu_w, at most tan(theta) or the ball would lift off the bed");
    c.friction = *f.friction;
  }
  check_flag("--steps", f.steps, 1, 1e8, "paper solver steps N");
  return c;
}

// --steps with the exact solver would be ignored: refused (issue 24's rule for
// another solver's keys). A --steps equal to the default cannot be told from
// none and passes.
void check_steps_for_solver(int steps, const std::string& solver) {
  if (solver_named(solver) == CushionSolver::exact && steps != CushionImpactOptions{}.paper_steps)
    throw UsageError("--steps = " + std::to_string(steps) +
                     " applies to --solver paper only; the exact solver takes no steps (its error is set by the "
                     "scenario's cushion.exact_tolerance)");
}

CushionImpactOptions options_of(const CushionFlags& f, bool history) {
  check_steps_for_solver(f.steps, f.solver);
  CushionImpactOptions o;
  o.solver = solver_named(f.solver);
  o.paper_steps = f.steps;
  o.record_history = history;
  return o;
}

// ------------------------------------------------------------------ cushion

struct ImpactFlags {
  std::string model = "mathavan_2010";
  std::optional<double> frequency_ratio;
  double v0 = 0.0;
  double alpha = 0.0;
  std::optional<double> topspin, topspin_k, sidespin, sidespin_k;
  bool history = false;
  CushionFlags cushion;
  ParameterFlags parameters;
};

double spin_from(const std::optional<double>& w, const std::optional<double>& k, double default_k, double v0,
                 double radius, const char* flag, const char* k_flag) {
  if (w && k) throw UsageError(std::string("give either ") + flag + " or " + k_flag + ", not both");
  if (w) {
    check_flag(flag, *w, -kMaxAngularSpeed, kMaxAngularSpeed, "spin, rad/s");
    return *w;
  }
  const double kk = k ? *k : default_k;
  check_flag(k_flag, kk, -20.0, 20.0, "spin as a multiple of V0/R");
  return kk * v0 / radius;
}

void print_history_csv(std::ostream& out, const std::vector<CushionImpactSample>& history) {
  out << "P,s,phi_deg,s_prime,phi_prime_deg,vx,vy,wx,wy,wz,work\n";
  char line[512];
  for (const CushionImpactSample& s : history) {
    std::snprintf(line, sizeof line, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", s.normal_impulse,
                  s.cushion_slip_speed, s.cushion_slip_angle / kDegree, s.bed_slip_speed, s.bed_slip_angle / kDegree,
                  s.velocity.x, s.velocity.y, s.angular_velocity.x, s.angular_velocity.y, s.angular_velocity.z, s.work);
    out << line;
  }
}

void add_incoming(Report& report, const ImpactFlags& f, const PaperIncidence& in) {
  report.begin_section("incoming", "incoming:");
  report.add("v0", f.v0, "m/s");
  report.add("alpha", f.alpha, "deg");
  report.add("topspin", in.topspin, "rad/s", "w_T (V0/R: rolling)");
  report.add("sidespin", in.sidespin, "rad/s", "w_S (> 0: right spin, Fig 2)");
  report.end_section();
}

// cueball cushion --model M for a model other than mathavan_2010: the
// rebound by the registry (cushion_model.hpp), with the model's own constants
// unless --e / --mu-w are given. Mathavan's solver flags do not apply.
void run_other_model(CushionModel model, const ImpactFlags& f, const PaperIncidence& in, const Parameters& p,
                     std::ostream& out, std::ostream& err) {
  const CushionFlags& c = f.cushion;
  if (f.history) throw UsageError("--history applies to --model mathavan_2010 only (its impulse-resolved solution)");
  if (c.solver != "exact" || c.steps != 5000 || c.constants != "paper-fit")
    throw UsageError("--solver, --steps and --constants apply to --model mathavan_2010 only");
  CushionSettings settings = default_cushion_settings(model);
  if (c.restitution) {
    check_flag("--e", *c.restitution, 0.0, 1.0, "the model's coefficient of restitution, [0, 1]");
    settings.restitution = *c.restitution;
  }
  if (c.friction) {
    check_flag("--mu-w", *c.friction, 0.0, 1.0, "the model's ball-cushion friction, [0, 1]");
    settings.friction = *c.friction;
  }
  if (f.frequency_ratio) {
    if (model != CushionModel::stronge_compliant) throw UsageError("--frequency-ratio applies to --model stronge_compliant only");
    check_flag("--frequency-ratio", *f.frequency_ratio, 1.0 + 1e-9, 1000.0,
               "Omega, tangential over normal natural frequency, (1, 1000]");
    settings.frequency_ratio = *f.frequency_ratio;
  }
  const double height = c.height.value_or(default_cushion_height(p.ball));
  if (c.height)
    check_flag("--height", height, p.ball.radius * (1 + 1e-9), 2 * p.ball.radius * (1 - 1e-9),
               "cushion contact height h, m, between R and 2R");
  const CushionRebound r = cushion_rebound(incoming_ball(in), cushion_contact(p, settings, height));
  const double speed = std::hypot(r.velocity.x, r.velocity.y);
  Report report(std::string("cushion impact, ") + to_string(model) + " (" + f.parameters.preset + " ball, SI units)");
  report.add("speed", speed, "m/s", "rebound speed");
  report.add("angle", std::atan2(-r.velocity.y, r.velocity.x) / kDegree, "deg",
             "rebound angle beta from the cushion (> 90: back on its own side)");
  report.add("v", {r.velocity.x, r.velocity.y}, "m/s", "outgoing velocity (X along the cushion, Y into it)");
  report.add("w", {r.angular_velocity.x, r.angular_velocity.y, r.angular_velocity.z}, "rad/s", "outgoing spin");
  add_incoming(report, f, in);
  report.begin_section("cushion", "cushion:");
  report.add_text("model", to_string(model));
  report.add("e", settings.restitution, "", "restitution");
  report.add("mu_w", settings.friction, "", "ball-cushion friction");
  if (model == CushionModel::stronge_compliant) {
    report.add("omega", settings.frequency_ratio, "", "tangential over normal natural frequency");
  } else {
    report.add("height", height, "m", "contact height h");
  }
  report.end_section();
  if (!(r.velocity.y < 0.0)) report.warn("the model leaves the ball pressing on the cushion (no rebound)");
  emit(report, f.parameters.json, out, err);
}

void run_cushion(const ImpactFlags& f, std::ostream& out, std::ostream& err) {
  const std::optional<CushionModel> model = cushion_model_from_string(f.model);
  if (!model) throw UsageError("--model = " + quote_input(f.model) + " is not known; allowed: " + cushion_model_names(""));
  check_flag("--v0", f.v0, 1e-6, kMaxSpeed, "incoming speed V0, m/s");
  check_flag("--alpha", f.alpha, 1e-9, 90.0, "angle between the velocity and the cushion, degrees, (0, 90]");
  const Parameters p = resolve_parameters(f.parameters);
  PaperIncidence in;
  in.speed = f.v0;
  in.angle = f.alpha * kDegree;
  in.topspin = spin_from(f.topspin, f.topspin_k, 1.0, f.v0, p.ball.radius, "--topspin", "--topspin-k");
  in.sidespin = spin_from(f.sidespin, f.sidespin_k, 0.0, f.v0, p.ball.radius, "--sidespin", "--sidespin-k");
  if (*model != CushionModel::mathavan_2010) return run_other_model(*model, f, in, p, out, err);
  const CushionParameters cushion = cushion_of(f.cushion, p);
  const CushionImpactResult r = cushion_impact(incoming_ball(in), p, cushion, options_of(f.cushion, f.history));

  Report report("cushion impact, mathavan_2010, " + f.cushion.solver + " solver (" + f.parameters.preset + " ball, SI units)");
  report.add("speed", r.rebound_speed, "m/s", "rebound speed");
  report.add("angle", r.rebound_angle / kDegree, "deg", "rebound angle beta from the cushion (> 90: back on its own side)");
  report.add("v", {r.velocity.x, r.velocity.y}, "m/s", "outgoing velocity (X along the cushion, Y into it)");
  report.add("w", {r.angular_velocity.x, r.angular_velocity.y, r.angular_velocity.z}, "rad/s", "outgoing spin");
  report.add("impulse_compression", r.compression_impulse, "N s", "P_I at the end of compression");
  report.add("impulse_total", r.total_impulse, "N s", "P_I at the end of restitution");
  report.add("work_compression", r.compression_work, "J", "W_c, work of the normal force in compression");
  add_incoming(report, f, in);
  report.begin_section("cushion", "cushion:");
  report.add_text("model", to_string(*model));
  report.add_text("solver", f.cushion.solver);
  report.add_text("constants", f.cushion.restitution || f.cushion.friction ? "custom" : f.cushion.constants);
  report.add("e", cushion.restitution, "", "restitution e_e");
  report.add("mu_w", cushion.friction, "", "ball-cushion friction");
  report.add("height", cushion.contact_height, "m", "contact height h");
  if (solver_named(f.cushion.solver) == CushionSolver::paper) report.add_count("steps", f.cushion.steps, "Euler steps N");
  report.end_section();
  if (r.beyond_rigid_cushion_limit) {
    report.warn("the normal speed " + std::to_string(f.v0 * std::sin(in.angle)) +
                " m/s exceeds 2.5 m/s, the limit of the rigid-cushion model (Mathavan 2010, Fig 7)");
  }
  if (f.parameters.json) {
    out << cushion_report_to_json(report, f.history ? &r.history : nullptr) << '\n';
    for (const std::string& w : report.warnings()) err << "cueball: warning: " << w << '\n';
  } else {
    emit(report, false, out, err);
    if (f.history) {
      out << "\nhistory over the normal impulse P_I (CSV):\n";
      print_history_csv(out, r.history);
    }
  }
}

// ------------------------------------------------------------------ cushion-sweep

struct SweepFlags {
  std::string model = "mathavan_2010";
  std::string family = "grid";
  CushionFlags cushion;
  ParameterFlags parameters;
};

// One impact of a sweep: its rebound speed and angle, by the chosen model.
struct SweepImpact {
  double speed = 0.0, angle = 0.0;
  bool beyond_rigid_cushion_limit = false;
};

void sweep_row(std::ostream& out, const char* family, const PaperIncidence& in, const SweepImpact& r, double radius,
               const std::string& solver) {
  char line[256];
  std::snprintf(line, sizeof line, "%s,%s,%.6g,%.6g,%.6g,%.6g,%.12g,%.12g\n", family, solver.c_str(), in.speed,
                in.angle / kDegree, in.topspin * radius / in.speed, in.sidespin * radius / in.speed, r.speed,
                r.angle / kDegree);
  out << line;
}

void run_sweep(const SweepFlags& f, std::ostream& out, std::ostream& err) {
  const std::optional<CushionModel> model = cushion_model_from_string(f.model);
  if (!model) throw UsageError("--model = " + quote_input(f.model) + " is not known; allowed: " + cushion_model_names(""));
  const bool mathavan = *model == CushionModel::mathavan_2010;
  if (!mathavan && (f.cushion.solver != "exact" || f.cushion.steps != 5000 || f.cushion.constants != "paper-fit" ||
                    f.cushion.restitution || f.cushion.friction))
    throw UsageError("--solver, --steps, --constants, --e and --mu-w apply to --model mathavan_2010 only");
  if (!mathavan && f.family == "fig12")
    throw UsageError("--family fig12 (the impact over P_I) applies to --model mathavan_2010 only");
  const Parameters p = resolve_parameters(f.parameters);
  const CushionParameters cushion = cushion_of(f.cushion, p);
  const CushionImpactOptions options = options_of(f.cushion, false);
  const double radius = p.ball.radius;
  // Another model: its own constants at the cushion's contact height.
  const CushionContact other =
      mathavan ? CushionContact{} : cushion_contact(p, default_cushion_settings(*model), cushion.contact_height);
  const std::string label = mathavan ? f.cushion.solver : f.model;
  const auto impact = [&](double v0, double alpha_deg, double top_k, double side_k) {
    PaperIncidence in{v0, alpha_deg * kDegree, top_k * v0 / radius, side_k * v0 / radius};
    SweepImpact r;
    if (mathavan) {
      const CushionImpactResult m = cushion_impact(incoming_ball(in), p, cushion, options);
      r = {m.rebound_speed, m.rebound_angle, m.beyond_rigid_cushion_limit};
    } else {
      const CushionRebound b = cushion_rebound(incoming_ball(in), other);
      r = {std::hypot(b.velocity.x, b.velocity.y), std::atan2(-b.velocity.y, b.velocity.x), false};
    }
    return std::pair{in, r};
  };
  const std::vector<double> topspins{-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0};
  const std::vector<double> sidespins{-2.0, -1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0};

  // --json: one object, the family, model, solver and ball with the rows
  // (fig12: the history over P_I, as cushion --history --json gives it;
  // io/cushion_json.hpp).
  const CushionSweepInfo info{f.family, f.model, mathavan ? f.cushion.solver : std::string(), f.parameters.preset};
  if (f.family == "fig12") {
    // Slip speeds and angles over the impact: V0 = 2, alpha = 45, w_S = 2 V0/R, w_T = 1.5 V0/R.
    PaperIncidence in{2.0, 45.0 * kDegree, 1.5 * 2.0 / radius, 2.0 * 2.0 / radius};
    CushionImpactOptions o = options;
    o.record_history = true;
    const std::vector<CushionImpactSample> history = cushion_impact(incoming_ball(in), p, cushion, o).history;
    if (f.parameters.json) {
      out << cushion_sweep_history_to_json(info, history) << '\n';
    } else {
      print_history_csv(out, history);
    }
    return;
  }
  std::vector<CushionSweepRow> rows;
  if (!f.parameters.json) out << "family,solver,v0,alpha_deg,topspin_k,sidespin_k,speed,angle_deg\n";
  const char* family = f.family.c_str();
  const auto row = [&](const PaperIncidence& in, const SweepImpact& r) {
    if (f.parameters.json) rows.push_back({in, r.speed, r.angle});
    else sweep_row(out, family, in, r, radius, label);
  };
  bool beyond_limit = false;
  for (int a = 1; a <= 90; ++a) {
    if (f.family == "fig8") {
      for (double v0 : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) {
        const auto [in, r] = impact(v0, a, 1.0, 0.0);
        beyond_limit = beyond_limit || r.beyond_rigid_cushion_limit;
        row(in, r);
      }
    } else if (f.family == "fig9") {
      for (double k : topspins) {
        const auto [in, r] = impact(1.0, a, k, 0.0);
        row(in, r);
      }
    } else if (f.family == "fig10") {
      for (double k : sidespins) {
        const auto [in, r] = impact(1.0, a, 1.0, k);
        row(in, r);
      }
    } else {
      for (double top : topspins) {
        for (double side : sidespins) {
          const auto [in, r] = impact(1.0, a, top, side);
          row(in, r);
        }
      }
    }
  }
  if (f.parameters.json) out << cushion_sweep_to_json(info, rows, radius) << '\n';
  if (beyond_limit) err << "cueball: warning: some rows exceed the rigid-cushion limit of 2.5 m/s normal speed\n";
}


// ------------------------------------------------------------------ figures

struct FigureFlags {
  std::string out = "figures";
  std::string format = "png";
  CushionFlags cushion;
  ParameterFlags parameters;
};

// One curve family of Figs 8-10: label, V0, topspin K, sidespin K.
struct Series {
  std::string label;
  double v0, top_k, side_k;
};

// Writes the series as gnuplot data blocks (one "index" each): alpha, speed, angle.
void write_family(const std::filesystem::path& file, const std::vector<Series>& family, const Parameters& p,
                  const CushionParameters& c, const CushionImpactOptions& o, const std::string& out_flag_value) {
  std::ofstream data(file);
  if (!data) throw UsageError("--out = " + quote_input(out_flag_value, kMaxEchoedPathChars) + ": cannot write " + quote_input(file.filename().string(), kMaxEchoedPathChars) +
                              " in the directory");
  for (const Series& s : family) {
    data << "# " << s.label << "\nalpha_deg speed angle_deg\n";
    for (int a = 1; a <= 90; ++a) {
      const PaperIncidence in{s.v0, a * kDegree, s.top_k * s.v0 / p.ball.radius, s.side_k * s.v0 / p.ball.radius};
      const CushionImpactResult r = cushion_impact(incoming_ball(in), p, c, o);
      data << a << ' ' << r.rebound_speed << ' ' << r.rebound_angle / kDegree << '\n';
    }
    data << "\n\n";
  }
  if (!data.flush())
    throw UsageError("--out = " + quote_input(out_flag_value, kMaxEchoedPathChars) + ": cannot write " + quote_input(file.filename().string(), kMaxEchoedPathChars) +
                     " in the directory");
}

// Opens FILE in the --out directory for writing, or throws UsageError naming --out.
std::ofstream open_in_out_dir(const std::filesystem::path& file, const std::string& out_flag_value) {
  std::ofstream f(file);
  if (!f) throw UsageError("--out = " + quote_input(out_flag_value, kMaxEchoedPathChars) + ": cannot write " + quote_input(file.filename().string(), kMaxEchoedPathChars) +
                           " in the directory");
  return f;
}

// Runs `gnuplot SCRIPT` in DIR without a shell: posix_spawnp with an argument
// vector, the working directory set by the spawn itself, stdout and stderr
// into LOG (both relative to DIR), stdin from /dev/null. The scripts name
// their files relative to DIR, so the directory's name never reaches gnuplot
// or a shell. Returns gnuplot's exit status (127: not installed).
int run_gnuplot(const std::filesystem::path& dir, const std::string& script, const std::string& log) {
  posix_spawn_file_actions_t actions;
  if (posix_spawn_file_actions_init(&actions) != 0) throw std::runtime_error("posix_spawn_file_actions_init failed");
  struct Cleanup {
    posix_spawn_file_actions_t* a;
    ~Cleanup() { posix_spawn_file_actions_destroy(a); }
  } cleanup{&actions};
  const std::string dir_name = dir.string();
  if (posix_spawn_file_actions_addchdir_np(&actions, dir_name.c_str()) != 0 ||
      posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0) != 0 ||
      posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644) != 0 ||
      posix_spawn_file_actions_adddup2(&actions, 1, 2) != 0)
    throw std::runtime_error("posix_spawn_file_actions failed");
  std::string program = "gnuplot";
  std::string argument = script;
  char* argv[] = {program.data(), argument.data(), nullptr};
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  if (rc == ENOENT) return 127;
  if (rc != 0) throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(rc));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(std::string("waitpid failed: ") + std::strerror(errno));
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

std::string titles_of(const std::vector<Series>& family) {
  std::string t;
  for (const Series& s : family) t += (t.empty() ? "" : " ") + s.label;
  return t;
}

std::string terminal_for(const std::string& format) {
  return format == "svg" ? "set terminal svg size 1200,500 dynamic background rgb 'white' font 'sans,12'"
                         : "set terminal pngcairo size 1200,500 font 'sans,11'";
}

void run_figures(const FigureFlags& f, std::ostream& out, std::ostream& err) {
  if (f.format != "png" && f.format != "svg") throw UsageError("--format = " + f.format + " is not one of png, svg");
  const Parameters p = resolve_parameters(f.parameters);
  // Both solvers with the same constants (the paper's fit unless overridden),
  // so any gap between the curves is the Euler scheme's discretisation.
  CushionFlags paper_flags = f.cushion;
  paper_flags.solver = "paper";
  const CushionParameters c = cushion_of(paper_flags, p);
  const CushionImpactOptions paper = options_of(paper_flags, false);
  CushionImpactOptions exact = paper;
  exact.solver = CushionSolver::exact;
  const std::filesystem::path dir = f.out;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw UsageError("--out = " + quote_input(f.out, kMaxEchoedPathChars) + ": cannot create the directory (" + ec.message() + ")");
  if (!std::filesystem::is_directory(dir, ec))
    throw UsageError("--out = " + quote_input(f.out, kMaxEchoedPathChars) + ": is not a directory");

  std::vector<Series> fig8, fig9, fig10;
  for (double v0 : {0.5, 1.0, 1.5, 2.0, 2.5}) fig8.push_back({"V0=" + std::to_string(v0).substr(0, 3), v0, 1.0, 0.0});
  for (double k : {-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0}) {
    char label[32];
    std::snprintf(label, sizeof label, "k=%g", k);
    fig9.push_back({label, 1.0, k, 0.0});
  }
  for (double k : {-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0}) {
    char label[32];
    std::snprintf(label, sizeof label, "k=%g", k);
    fig10.push_back({label, 1.0, 1.0, k});
  }
  const struct {
    const char* name;
    const char* caption;
    const std::vector<Series>* family;
  } figures[] = {
      {"fig8", "Fig 8: rolling, no sidespin (w_T = V0/R)", &fig8},
      {"fig9", "Fig 9: topspin w_T = k V0/R, V0 = 1 m/s", &fig9},
      {"fig10", "Fig 10: sidespin w_S = k V0/R, rolling, V0 = 1 m/s", &fig10},
  };
  char constants[128];
  std::snprintf(constants, sizeof constants, "e_e = %g, mu_w = %g; lines: paper (Euler, N = %d), points: exact",
                c.restitution, c.friction, f.cushion.steps);
  std::vector<std::filesystem::path> written;
  for (const auto& fig : figures) {
    write_family(dir / (std::string(fig.name) + "_paper.dat"), *fig.family, p, c, paper, f.out);
    write_family(dir / (std::string(fig.name) + "_exact.dat"), *fig.family, p, c, exact, f.out);
    const std::filesystem::path image = dir / (std::string(fig.name) + "." + f.format);
    std::ofstream gp = open_in_out_dir(dir / (std::string(fig.name) + ".gp"), f.out);
    // Every file name relative to the directory gnuplot runs in: no user text in the script.
    gp << terminal_for(f.format) << "\n"
       << "set output '" << fig.name << "." << f.format << "'\n"
       << "titles = '" << titles_of(*fig.family) << "'\n"
       << "n = words(titles)\n"
       << "set multiplot layout 1,2 title \"" << fig.caption << "\\n{/*0.8 " << constants << "}\" enhanced\n"
       << "set grid\nset key outside right top font ',9'\nset xlabel 'angle of incidence alpha (deg)'\n"
       << "set xrange [0:90]\nset ylabel 'rebound speed (m/s)'\n"
       << "plot for [i=0:n-1] '" << fig.name << "_paper.dat' index i using 1:2 with lines lw 2 lc i+1 title word(titles, i+1), "
       << "for [i=0:n-1] '" << fig.name << "_exact.dat' index i using 1:2 every 5 with points pt 6 ps 0.6 lc i+1 notitle\n"
       << "set ylabel 'rebound angle beta (deg)'\n"
       << "plot for [i=0:n-1] '" << fig.name << "_paper.dat' index i using 1:3 with lines lw 2 lc i+1 title word(titles, i+1), "
       << "for [i=0:n-1] '" << fig.name << "_exact.dat' index i using 1:3 every 5 with points pt 6 ps 0.6 lc i+1 notitle\n"
       << "unset multiplot\n";
    written.push_back(image);
  }
  // Fig 12: slip speeds and angles over the normal impulse.
  {
    const PaperIncidence in{2.0, 45.0 * kDegree, 1.5 * 2.0 / p.ball.radius, 2.0 * 2.0 / p.ball.radius};
    for (const auto& [name, options] : {std::pair{"paper", paper}, std::pair{"exact", exact}}) {
      CushionImpactOptions o = options;
      o.record_history = true;
      std::ofstream data = open_in_out_dir(dir / (std::string("fig12_") + name + ".csv"), f.out);
      print_history_csv(data, cushion_impact(incoming_ball(in), p, c, o).history);
      if (!data.flush()) throw UsageError("--out = " + quote_input(f.out, kMaxEchoedPathChars) + ": cannot write fig12_" + name + ".csv");
    }
    const std::filesystem::path image = dir / ("fig12." + f.format);
    std::ofstream gp = open_in_out_dir(dir / "fig12.gp", f.out);
    gp << terminal_for(f.format) << "\n"
       << "set output 'fig12." << f.format << "'\nset datafile separator ','\n"
       << "set multiplot layout 1,2 title \"Fig 12: slip over the impact, V0 = 2 m/s, alpha = 45 deg, "
       << "w_S = 2 V0/R, w_T = 1.5 V0/R\\n{/*0.8 " << constants << "}\" enhanced\n"
       << "set grid\nset xlabel 'normal impulse P_I (N s)'\nset ylabel 'slip speed (m/s)'\n"
       << "plot 'fig12_paper.csv' using 1:2 with lines lw 2 title 's (cushion, I)', "
       << "'fig12_paper.csv' using 1:4 with lines lw 2 title \"s' (cloth, C)\", "
       << "'fig12_exact.csv' using 1:2 with points pt 6 ps 0.5 lc 1 notitle, "
       << "'fig12_exact.csv' using 1:4 with points pt 6 ps 0.5 lc 2 notitle\n"
       << "set ylabel 'slip angle (deg)'\n"
       << "plot 'fig12_paper.csv' using 1:3 with lines lw 2 title 'Phi', "
       << "'fig12_paper.csv' using 1:5 with lines lw 2 title \"Phi'\", "
       << "'fig12_exact.csv' using 1:3 with points pt 6 ps 0.5 lc 1 notitle, "
       << "'fig12_exact.csv' using 1:5 with points pt 6 ps 0.5 lc 2 notitle\n"
       << "unset multiplot\n";
    written.push_back(image);
  }
  // The cushion models side by side (cushion_model.hpp), each with its own
  // constants: Fig 9's rolling ball and Fig 10's with running side K = 1.
  {
    std::ofstream data = open_in_out_dir(dir / "models.dat", f.out);
    std::string titles;
    int curves = 0;
    for (CushionModel model : kCushionModels) {
      const CushionContact contact = cushion_contact(p, default_cushion_settings(model), default_cushion_height(p.ball));
      for (double side : {0.0, 1.0}) {
        const std::string title = std::string(to_string(model)) + (side == 0.0 ? "" : "/side=1");
        titles += (titles.empty() ? "" : " ") + title;
        data << "# " << title << "\nalpha_deg speed angle_deg\n";
        for (int a = 1; a <= 90; ++a) {
          const PaperIncidence in{1.0, a * kDegree, 1.0 / p.ball.radius, side / p.ball.radius};
          const CushionRebound r = cushion_rebound(incoming_ball(in), contact);
          data << a << ' ' << std::hypot(r.velocity.x, r.velocity.y) << ' '
               << std::atan2(-r.velocity.y, r.velocity.x) / kDegree << '\n';
        }
        data << "\n\n";
        ++curves;
      }
    }
    if (!data.flush()) throw UsageError("--out = " + quote_input(f.out, kMaxEchoedPathChars) + ": cannot write models.dat");
    std::ofstream gp = open_in_out_dir(dir / "models.gp", f.out);
    gp << terminal_for(f.format) << "\n"
       << "set output 'models." << f.format << "'\n"
       << "titles = '" << titles << "'\n"
       << "set multiplot layout 1,2 title \"The cushion models, rolling at V0 = 1 m/s (solid) and with running side "
       << "w_S = V0/R (dashed)\\n{/*0.8 each model with its own constants}\" enhanced\n"
       << "set grid\nset key left bottom font ',9' noenhanced\nset xlabel 'angle of incidence alpha (deg)'\n"
       << "set xrange [0:90]\nset ylabel 'rebound speed (m/s)'\n"
       << "plot for [i=0:" << curves - 1 << "] 'models.dat' index i using 1:2 with lines lw 2 lc (i/2+1) dt i%2+1 "
       << "title word(titles, i+1)\n"
       << "set ylabel 'rebound angle beta (deg)'\nset key left top\n"
       << "plot for [i=0:" << curves - 1 << "] 'models.dat' index i using 1:3 with lines lw 2 lc (i/2+1) dt i%2+1 "
       << "title word(titles, i+1)\n"
       << "unset multiplot\n";
    written.push_back(dir / ("models." + f.format));
  }
  for (const char* name : {"fig8", "fig9", "fig10", "fig12", "models"}) {
    const int status = run_gnuplot(dir, std::string(name) + ".gp", std::string(name) + ".log");
    if (status == 127) throw std::runtime_error("gnuplot is not installed (apt-get install gnuplot-nox)");
    if (status != 0)
      throw std::runtime_error(std::string("gnuplot failed on ") + name + ".gp (status " + std::to_string(status) +
                               "); see " + quote_input((dir / name).string() + ".log", kMaxEchoedPathChars));
  }
  if (f.parameters.json) {
    std::vector<std::string> files;
    for (const auto& image : written) files.push_back(image.string());
    out << figures_to_json(f.out, f.format, files) << '\n';
  } else {
    for (const auto& image : written) out << image.string() << '\n';
  }
  (void)err;
}

// ------------------------------------------------------------------ fit-cushion

struct FitFlags {
  std::string data;
  std::string solver = "exact";
  int steps = 5000;
  double grid_step = 0.01;
  ParameterFlags parameters;
};

void run_fit(const FitFlags& f, std::ostream& out, std::ostream& err) {
  check_flag("--steps", f.steps, 1, 1e7, "paper solver steps N");
  check_steps_for_solver(f.steps, f.solver);
  check_flag("--grid-step", f.grid_step, 0.001, 0.5, "grid spacing over (0, 1]^2");
  const Parameters p = resolve_parameters(f.parameters);
  const CushionFitData data = cushion_fit_data_from_csv(read_text_file(f.data, "the data file", kMaxDataFileBytes),
                                                        quote_input(f.data, kMaxEchoedPathChars), p.ball.radius);
  CushionFitOptions options;
  options.solver = solver_named(f.solver);
  options.paper_steps = f.steps;
  options.grid_step = f.grid_step;
  const CushionFit fit = fit_cushion(data, p, options);
  Report r("cushion constants fitted to " + f.data + " (" + f.solver + " solver, " + f.parameters.preset + " ball)");
  r.add("e", fit.restitution, "", "restitution e_e");
  r.add("mu_w", fit.friction, "", "ball-cushion friction");
  r.add("e_sigma", fit.restitution_sigma, "", "standard error of e_e");
  r.add("mu_w_sigma", fit.friction_sigma, "", "standard error of mu_w");
  r.add("correlation", fit.correlation, "", "of the two estimates");
  r.add("residual", fit.residual, "m^2/s^2", "sum of squared errors at the fit");
  r.add("grid_e", fit.grid_restitution, "", "best point of the 0.01 grid (paper 3.5)");
  r.add("grid_mu_w", fit.grid_friction, "");
  r.add_count("head_on_points", static_cast<long long>(data.head_on.size()));
  r.add_count("oblique_points", static_cast<long long>(data.oblique.size()));
  if (fit.poorly_separated)
    r.warn("the data barely separate e_e from mu_w (correlation " + std::to_string(fit.correlation) + "): " +
           (data.oblique.empty() ? "head-on rolling impacts alone fix only one combination of them; add oblique impacts"
                                 : "add impacts at other angles and spins"));
  if (fit.beyond_rigid_cushion_limit > 0)
    r.warn(std::to_string(fit.beyond_rigid_cushion_limit) +
           " measurements have a normal speed above 2.5 m/s, beyond the rigid-cushion model");
  emit(r, f.parameters.json, out, err);
}

}  // namespace

Command add_fit_cushion_command(CLI::App& app) {
  auto flags = std::make_shared<FitFlags>();
  CLI::App* sub = app.add_subcommand(
      "fit-cushion",
      "Fits the cushion constants e_e and mu_w to measured impacts (paper 000 section 3.5): the paper's\n"
      "0.01 grid over (0, 1]^2, then a local refinement. DATA.csv has one impact per line: 'v0,v_out'\n"
      "(head-on, rolling, no side spin, as in the paper's experiment) or\n"
      "'v0,alpha_deg,topspin_k,sidespin_k,v_out,beta_deg' (oblique; spins as K V0/R). Speeds m/s.\n"
      "Reports the fit, its residual and how well each constant is determined.");
  sub->add_option("data", flags->data, "CSV file of measured impacts")->required();
  sub->add_option("--solver", flags->solver, "Solver the constants are fitted for: exact or paper")
      ->check(CLI::IsMember({"exact", "paper"}))
      ->capture_default_str();
  sub->add_option("--steps", flags->steps, "N for the paper solver")->capture_default_str();
  sub->add_option("--grid-step", flags->grid_step, "Grid spacing (the paper's 0.01)")->capture_default_str();
  add_parameter_flags(*sub, flags->parameters);
  return [flags](std::ostream& out, std::ostream& err) { run_fit(*flags, out, err); };
}

Command add_cushion_command(CLI::App& app) {
  auto flags = std::make_shared<ImpactFlags>();
  CLI::App* sub = app.add_subcommand(
      "cushion",
      "One ball-cushion impact, by default Mathavan, Jackson & Parkin (2010); --model chooses another.\n"
      "Cushion frame: X along the cushion,\n"
      "Y into it, Z up. --alpha is the angle between the velocity and the cushion in degrees (90: head-on).\n"
      "Topspin w_T > 0 turns the ball the way it rolls (V0/R: natural roll, the default); sidespin w_S > 0\n"
      "is the 'right' spin of the paper's Fig 2, about +Z. The --*-k forms give spin as K V0 / R. Output\n"
      "angle beta is measured from the cushion line; above 90 the ball comes back on its own side. SI units.");
  sub->add_option("--model", flags->model,
                  "The cushion model: " + cushion_model_names("") +
                      "; a model other than\nmathavan_2010 takes its own constants unless --e and --mu-w "
                      "are given, and no solver flags")
      ->capture_default_str();
  sub->add_option("--frequency-ratio", flags->frequency_ratio,
                  "stronge_compliant: Omega, tangential over normal natural frequency, (1, 1000]; default 1.8");
  sub->add_option("--v0", flags->v0, "Incoming speed V0, m/s")->required();
  sub->add_option("--alpha", flags->alpha, "Angle of incidence from the cushion, degrees, (0, 90]")->required();
  sub->add_option("--topspin", flags->topspin, "Topspin w_T, rad/s");
  sub->add_option("--topspin-k", flags->topspin_k, "Topspin as K: w_T = K V0 / R (default 1: rolling)");
  sub->add_option("--sidespin", flags->sidespin, "Sidespin w_S, rad/s");
  sub->add_option("--sidespin-k", flags->sidespin_k, "Sidespin as K: w_S = K V0 / R (default 0)");
  sub->add_flag("--history", flags->history, "Also print s, Phi, s', Phi', velocities, spins and W over P_I");
  add_cushion_flags(*sub, flags->cushion);
  add_parameter_flags(*sub, flags->parameters);
  return [flags](std::ostream& out, std::ostream& err) { run_cushion(*flags, out, err); };
}

Command add_cushion_sweep_command(CLI::App& app) {
  auto flags = std::make_shared<SweepFlags>();
  CLI::App* sub = app.add_subcommand(
      "cushion-sweep",
      "The paper's families of cushion impacts as CSV (speed m/s, angles degrees):\n"
      "  fig8   rolling, no sidespin, V0 = 0.5 ... 3 m/s, alpha 1-90\n"
      "  fig9   V0 = 1 m/s, topspin K in {-1, -0.5, 0, 0.5, 1, 1.5, 2}, alpha 1-90\n"
      "  fig10  rolling, V0 = 1 m/s, sidespin K in {-2, -1.5, ..., 2}, alpha 1-90\n"
      "  fig12  slip speeds and angles over P_I at V0 = 2, alpha = 45, w_S = 2 V0/R, w_T = 1.5 V0/R\n"
      "  grid   alpha 1-90 x topspin K (7 values) x sidespin K (9 values) at V0 = 1 m/s\n"
      "Columns: family, solver (exact or paper; the model's name with --model), v0, alpha_deg,\n"
      "topspin_k, sidespin_k, speed, angle_deg. --json: one object with family, model, solver, preset\n"
      "and the rows as objects (fig12: the history, as cushion --history --json).");
  sub->add_option("--model", flags->model,
                  "The cushion model: " + cushion_model_names("") +
                      "; another model than mathavan_2010 with its own\nconstants (fig8, fig9, fig10, grid)")
      ->capture_default_str();
  sub->add_option("--family", flags->family, "fig8, fig9, fig10, fig12 or grid")
      ->check(CLI::IsMember({"fig8", "fig9", "fig10", "fig12", "grid"}))
      ->capture_default_str();
  add_cushion_flags(*sub, flags->cushion);
  flags->parameters.preset = "snooker";  // the paper's ball: its figures
  add_parameter_flags(*sub, flags->parameters);
  return [flags](std::ostream& out, std::ostream& err) { run_sweep(*flags, out, err); };
}

Command add_figures_command(CLI::App& app) {
  auto flags = std::make_shared<FigureFlags>();
  CLI::App* sub = app.add_subcommand(
      "figures",
      "Redraws the cushion paper's Figs 8, 9, 10 and 12 with gnuplot into --out: rebound speed and angle\n"
      "against the angle of incidence, and the slip speeds and angles over the impact. Lines are the\n"
      "paper's Euler solver, points the exact solver, with the same constants (the paper's fit unless\n"
      "--e / --mu-w are given), so a gap between them is the Euler scheme's error. Prints the files\n"
      "(--json: an object with out, format and the files).");
  sub->add_option("--out", flags->out, "Directory for the images, data and gnuplot scripts")->capture_default_str();
  sub->add_option("--format", flags->format, "png or svg")->check(CLI::IsMember({"png", "svg"}))->capture_default_str();
  add_cushion_flags(*sub, flags->cushion);
  flags->parameters.preset = "snooker";  // the paper's ball: its figures
  add_parameter_flags(*sub, flags->parameters);
  return [flags](std::ostream& out, std::ostream& err) { run_figures(*flags, out, err); };
}

}  // namespace cueball::cli
