// cueball calibrate: fits strikes and the table's constants to tracked shots.
#include <memory>
#include <optional>
#include <ostream>

#include "common.hpp"
#include "cueball/calibration/calibrate.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/io/calibration_html.hpp"
#include "cueball/io/tracked_shots_csv.hpp"
#include "cueball/io/tracked_shots_json.hpp"
#include "cueball/models/ball_collision/model.hpp"
#include "cueball/models/cushion/model.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball::cli {

namespace {

struct CalibrateFlags {
  std::vector<std::string> shots;
  std::optional<std::string> table;
  std::optional<std::string> cue_ball;
  double held_out = 0.25;
  long long seed = 0;
  int threads = 1;
  int max_evaluations = ConstantsFitOptions{}.max_evaluations;
  int max_iterations = ConstantsFitOptions{}.max_iterations;
  int starts = StrikeFitOptions{}.starts;
  int restarts = ConstantsFitOptions{}.restarts;
  int spin_profile = ConstantsFitOptions{}.spin_profile;
  int bootstrap = 0;
  int bootstrap_evaluations = BootstrapOptions{}.max_evaluations;
  std::optional<std::string> html;
  std::optional<std::string> cushion_model;
  std::optional<std::string> ball_collision_model;
  std::optional<std::string> constants;
  std::optional<std::string> output;
  bool evaluate = false;
  bool json = false;
};

void add_summary(Report& report, const std::string& section, const std::string& heading, const FitSummary& s,
                 const std::string& mismatched) {
  report.begin_section(section, heading);
  report.add_count("shots", s.shots);
  report.add("cue_rmse_median", s.cue_rmse_median, "m", "cue ball RMSE, median over the shots");
  report.add("cue_rmse_p90", s.cue_rmse_p90, "m", "cue ball RMSE, 90th percentile");
  report.add("cue_rmse_mean", s.cue_rmse_mean, "m");
  report.add("all_rmse_median", s.all_rmse_median, "m", "every ball's samples pooled");
  report.add("all_rmse_p90", s.all_rmse_p90, "m");
  report.add("object_rmse_median", s.object_rmse_median, "m", "the object balls");
  report.add("object_rmse_p90", s.object_rmse_p90, "m");
  report.add_count("contact_mismatches", s.contact_mismatches, "shots whose fit made or missed a contact");
  if (!mismatched.empty()) report.add_text("mismatched_shots", mismatched, "their ids");
  report.add("seconds_per_shot", s.seconds_per_shot, "s", "strike fit time, mean");
  report.end_section();
}

// The ids of the shots whose fit made or missed a contact, comma-separated.
std::string mismatched_ids(const CalibrationReport& r, bool held_out) {
  std::string ids;
  for (const ShotReport& s : r.shots)
    if (s.held_out == held_out && s.fit.contact_mismatch) ids += (ids.empty() ? "" : ", ") + s.id;
  return ids;
}

bool ends_with_csv(const std::string& name) {
  return name.size() > 4 && (name.compare(name.size() - 4, 4, ".csv") == 0 || name.compare(name.size() - 4, 4, ".CSV") == 0);
}

// One tracked-shots JSON file, or CSV files (one a shot) on --table.
TrackedShots read_shots(const CalibrateFlags& f) {
  if (!ends_with_csv(f.shots.front())) {
    if (f.shots.size() > 1)
      throw UsageError("calibrate reads one tracked-shots JSON file or CSV files (one a shot), not " +
                       quote_input(f.shots[1], kMaxEchoedPathChars) + " after a JSON file");
    if (f.table || f.cue_ball) throw UsageError("--table and --cue-ball are for CSV shots; the JSON file names them");
    return tracked_shots_from_json(read_text_file(f.shots.front(), "the tracked-shots file", kMaxTrackedShotsBytes));
  }
  if (!f.table) throw UsageError("--table is needed with CSV shots (pool_9ft, snooker_12ft or carom_10ft)");
  std::vector<CsvShotFile> files;
  for (const std::string& name : f.shots) {
    if (!ends_with_csv(name))
      throw UsageError(quote_input(name, kMaxEchoedPathChars) + " is not a .csv file; allowed: all CSV files or one JSON file");
    files.push_back({name, read_text_file(name, "a tracked-shot CSV file", kMaxTrackedShotCsvBytes)});
  }
  return tracked_shots_from_csv(files, *f.table, f.cue_ball.value_or(""));
}

void run_calibrate(const CalibrateFlags& f, std::ostream& out, std::ostream& err) {
  check_flag("--held-out", f.held_out, 0.0, 0.9, "fraction of the shots held out");
  check_flag("--threads", f.threads, 1, 256, "worker threads");
  check_flag("--max-evaluations", f.max_evaluations, 1, 100000, "evaluations of the constants fit's simplex");
  check_flag("--max-iterations", f.max_iterations, 0, 10000, "iterations of the joint fit of constants and strikes");
  check_flag("--starts", f.starts, 1, 64, "refined starts per strike fit");
  check_flag("--restarts", f.restarts, 0, 16, "restarts of the constants fit's simplex");
  check_flag("--spin-profile", f.spin_profile, 0, 16, "points of the constants fit's profile over mu_sp");
  check_flag("--bootstrap", f.bootstrap, 0, 1000, "bootstrap replicates for the constants' uncertainties");
  check_flag("--bootstrap-evaluations", f.bootstrap_evaluations, 1, 100000, "simplex evaluations of a bootstrap replicate");
  if (f.seed < 0) check_flag("--seed", static_cast<double>(f.seed), 0, 9.007199254740992e15, "random seed");
  if (f.evaluate && !f.constants) throw UsageError("--evaluate needs --constants FILE (the constants to evaluate)");
  const TrackedShots shots = read_shots(f);
  FitModel start = default_fit_model(shots);
  if (f.constants) start = fit_model_from_json(read_text_file(*f.constants, "the constants file", kMaxScenarioBytes), shots);
  if (f.cushion_model) {
    const auto model = cushion_model_from_string(*f.cushion_model);
    if (!model)
      throw UsageError("--cushion-model = " + quote_input(*f.cushion_model) + " is not known; allowed: " + cushion_model_names(""));
    if (*model != start.settings.cushion.model) start.settings.cushion = default_cushion_settings(*model);
  }
  if (f.ball_collision_model) {
    const auto model = ball_collision_model_from_string(*f.ball_collision_model);
    if (!model)
      throw UsageError("--ball-collision-model = " + quote_input(*f.ball_collision_model) +
                       " is not known; allowed: " + ball_collision_model_names(""));
    if (*model != start.settings.ball_collision_model)
      start.settings.ball_collision_model = *model, start.settings.ball_collision = default_ball_collision(*model);
  }
  CalibrationOptions options;
  options.held_out = f.evaluate ? 0.0 : f.held_out;
  options.seed = static_cast<std::uint64_t>(f.seed);
  options.evaluate_only = f.evaluate;
  options.threads = f.threads;
  options.strike.starts = f.starts;
  options.constants.max_evaluations = f.max_evaluations;
  options.constants.max_iterations = f.max_iterations;
  options.constants.restarts = f.restarts;
  options.constants.spin_profile = f.spin_profile;
  options.bootstrap.replicates = f.bootstrap;
  options.bootstrap.seed = options.seed;
  options.bootstrap.max_evaluations = f.bootstrap_evaluations;
  const CalibrationReport r = calibrate(shots, start, options);
  if (f.output) write_text_file(*f.output, constants_to_json(r.model, r.table_name) + "\n", "-o", "the constants");
  if (f.html)
    write_text_file(*f.html, calibration_report_html(r, shots.table, shot_drawings(shots, r)), "--html", "the HTML report");
  if (f.json) {
    out << calibration_report_to_json(r, 1) << '\n';
    return;
  }
  Report report(std::string(f.evaluate ? "evaluation" : "calibration") + " on " + std::to_string(shots.shots.size()) +
                " tracked shots (" + r.table_name + ")");
  report.begin_section("constants", "constants");
  const Parameters& p = r.model.settings.parameters;
  const auto add_constant = [&](const std::string& name, double value, const std::string& what) {
    std::string note = what;
    for (const ConstantSpread& s : r.spread)
      if (s.name == name)
        note += (note.empty() ? "" : "; ") + std::string("+- ") + format_number(s.std_dev) + " (5-95 %: " + format_number(s.p05) +
                " to " + format_number(s.p95) + ")";
    report.add(name, value, "", note);
  };
  add_constant("mu_s", p.cloth.sliding_friction, "sliding friction");
  add_constant("mu_r", p.cloth.rolling_resistance, "rolling resistance");
  add_constant("mu_sp", p.cloth.spin_friction, "spin friction");
  report.add_text("cushion_model", to_string(r.model.settings.cushion.model));
  add_constant("cushion_restitution", r.model.settings.cushion.restitution, "");
  add_constant("cushion_friction", r.model.settings.cushion.friction, "");
  report.add_text("ball_collision_model", to_string(r.model.settings.ball_collision_model), "not fitted");
  report.add_count("evaluations", r.constant_evaluations, "of the simplex (stage 1, restarts included)");
  report.add_count("restart_won", r.constant_restarts, "1: the mu_sp profile or a restart found the better point");
  report.add_count("iterations", r.constant_iterations, "of the joint fit (stage 2)");
  if (r.bootstrap_replicates > 0) report.add_count("bootstrap", r.bootstrap_replicates, "replicates behind the +- (std. dev.)");
  report.end_section();
  add_summary(report, "training", f.evaluate ? "shots" : "training shots", r.training, mismatched_ids(r, false));
  if (r.held_out.shots > 0) add_summary(report, "held_out", "held-out shots", r.held_out, mismatched_ids(r, true));
  report.add("seconds", r.seconds, "s", "wall-clock time");
  emit(report, false, out, err);
}

}  // namespace

Command add_calibrate_command(CLI::App& app) {
  auto flags = std::make_shared<CalibrateFlags>();
  CLI::App* sub = app.add_subcommand(
      "calibrate",
      "Fits the engine to tracked shots (README, 'Tracked shots'): each shot's strike (speed, aim,\n"
      "elevation, tip offsets, strike time) by multi-start least squares on every ball's samples, and\n"
      "the table's constants (cloth mu_s, mu_r, mu_sp; the cushion model's restitution and friction)\n"
      "across the training shots. A seeded fraction of the shots is held out and only evaluated.\n"
      "-o writes the constants as a scenario fragment; --constants FILE --evaluate fits only the\n"
      "strikes under given constants. RMSEs in metres.");
  sub->add_option("shots", flags->shots, "Tracked-shots JSON file, or CSV files (one a shot: ball,t,x,y)")->required();
  sub->add_option("--table", flags->table, "The table of CSV shots: pool_9ft, snooker_12ft, carom_10ft");
  sub->add_option("--cue-ball", flags->cue_ball, "The struck ball of CSV shots (default: the ball that moves first)");
  sub->add_option("--held-out", flags->held_out, "Fraction of the shots held out, [0, 0.9]")->capture_default_str();
  sub->add_option("--seed", flags->seed, "Random seed of the held-out draw")->capture_default_str();
  sub->add_option("--threads", flags->threads, "Worker threads, [1, 256]")->capture_default_str();
  sub->add_option("--max-evaluations", flags->max_evaluations, "Evaluations of the constants fit's simplex (stage 1), [1, 100000]")
      ->capture_default_str();
  sub->add_option("--max-iterations", flags->max_iterations, "Iterations of the joint fit of constants and strikes (stage 2), [0, 10000]")
      ->capture_default_str();
  sub->add_option("--starts", flags->starts, "Refined starts per strike fit, [1, 64]")->capture_default_str();
  sub->add_option("--restarts", flags->restarts, "Restarts of the constants fit's simplex from other points, [0, 16]")
      ->capture_default_str();
  sub->add_option("--spin-profile", flags->spin_profile,
                  "Points of the profile over mu_sp after the first simplex (0: none), [0, 16]")
      ->capture_default_str();
  sub->add_option("--bootstrap", flags->bootstrap,
                  "Bootstrap replicates over the training shots for the constants' uncertainties (0: none), [0, 1000]")
      ->capture_default_str();
  sub->add_option("--bootstrap-evaluations", flags->bootstrap_evaluations,
                  "Simplex evaluations of each bootstrap replicate, [1, 100000]")
      ->capture_default_str();
  sub->add_option("--html", flags->html, "Write the report as a self-contained HTML page: the error distribution and every shot drawn");
  sub->add_option("--cushion-model", flags->cushion_model, "Cushion model to fit (default: the constants' or the table's)");
  sub->add_option("--ball-collision-model", flags->ball_collision_model,
                  "Ball-ball model the fit plays (not fitted; default: the constants' or coulomb_impulse): "
                  "coulomb_impulse, mathavan_2014");
  sub->add_option("--constants", flags->constants, "Start from (or, with --evaluate, use) these constants: a scenario JSON");
  sub->add_option("-o,--output", flags->output, "Write the fitted constants to this file (a scenario fragment)");
  sub->add_flag("--evaluate", flags->evaluate, "Fit the strikes only, under --constants, and report");
  sub->add_flag("--json", flags->json, "Print the whole report as one JSON object");
  return [flags](std::ostream& out, std::ostream& err) { run_calibrate(*flags, out, err); };
}

}  // namespace cueball::cli
