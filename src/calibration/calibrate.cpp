#include "cueball/calibration/calibrate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball {

namespace {

struct CalibrationContext {
  const TrackedShots& input;
  const CalibrationOptions& options;
  CalibrationReport report;
  std::vector<PreparedShot> prepared;
  std::vector<int> training;  // indices of the training shots
};

void prepare_shots(CalibrationContext& c) {
  for (std::size_t i = 0; i < c.input.shots.size(); ++i) {
    const std::string path = "shots[" + std::to_string(i) + "]";
    validate_tracked_shot(c.input.shots[i], c.input.table, path);
    c.prepared.push_back(prepare_shot(c.input.shots[i], c.input.table, path));
    ShotReport r;
    r.id = c.input.shots[i].id;
    r.balls = c.prepared.back().names;
    r.notes = c.prepared.back().notes;
    c.report.shots.push_back(r);
  }
}

void draw_held_out(CalibrationContext& c) {
  const int n = static_cast<int>(c.prepared.size());
  const std::vector<bool> held = held_out_shots(n, c.options.evaluate_only ? 0.0 : c.options.held_out, c.options.seed);
  for (int i = 0; i < n; ++i) {
    c.report.shots[static_cast<std::size_t>(i)].held_out = held[static_cast<std::size_t>(i)];
    if (!held[static_cast<std::size_t>(i)]) c.training.push_back(i);
  }
}

std::vector<StrikeFit> fit_strikes(CalibrationContext& c, const std::vector<int>& which, const FitModel& model) {
  std::vector<StrikeFit> fits(which.size());
  for_each_shot(static_cast<int>(which.size()), c.options.threads, [&](int k) {
    const auto i = static_cast<std::size_t>(which[static_cast<std::size_t>(k)]);
    fits[static_cast<std::size_t>(k)] = fit_strike(c.prepared[i], model, c.options.strike);
  });
  return fits;
}

void fit_training(CalibrationContext& c) {
  std::vector<StrikeFit> strikes = fit_strikes(c, c.training, c.report.start);
  if (c.options.evaluate_only) {
    for (std::size_t k = 0; k < c.training.size(); ++k) c.report.shots[static_cast<std::size_t>(c.training[k])].fit = strikes[k];
    return;
  }
  std::vector<PreparedShot> shots;
  for (int i : c.training) shots.push_back(c.prepared[static_cast<std::size_t>(i)]);
  ConstantsFitOptions o = c.options.constants;
  o.threads = c.options.threads;
  o.strike = c.options.strike;
  const ConstantsFit fit = fit_constants(shots, c.report.start, strikes, o);
  c.report.model = fit.model;
  c.report.constant_evaluations = fit.evaluations;
  c.report.constant_iterations = fit.iterations;
  c.report.constant_restarts = fit.restarts_taken;
  BootstrapOptions b = c.options.bootstrap;
  b.threads = c.options.threads;
  c.report.spread = bootstrap_constants(shots, fit, b);
  c.report.bootstrap_replicates = c.report.spread.empty() ? 0 : b.replicates;
  // The training shots refitted from scratch under the final constants
  // (a strike the warm starts kept in a wrong basin gets its chance again);
  // the better of that and the warm-started strike is kept.
  const std::vector<StrikeFit> fresh = fit_strikes(c, c.training, c.report.model);
  for (std::size_t k = 0; k < c.training.size(); ++k) {
    const StrikeFit& best = fresh[k].cost <= fit.strikes[k].cost ? fresh[k] : fit.strikes[k];
    c.report.shots[static_cast<std::size_t>(c.training[k])].fit = best;
  }
}

void fit_held_out(CalibrationContext& c) {
  std::vector<int> held;
  for (std::size_t i = 0; i < c.report.shots.size(); ++i)
    if (c.report.shots[i].held_out) held.push_back(static_cast<int>(i));
  const std::vector<StrikeFit> fits = fit_strikes(c, held, c.report.model);
  for (std::size_t k = 0; k < held.size(); ++k) c.report.shots[static_cast<std::size_t>(held[k])].fit = fits[k];
}

}  // namespace

// A seeded Fisher-Yates shuffle; the first round(F N) shots of it are held out.
std::vector<bool> held_out_shots(int n, double held_out, std::uint64_t seed) {
  std::vector<int> order(static_cast<std::size_t>(std::max(n, 0)));
  std::iota(order.begin(), order.end(), 0);
  RandomStream random(stream_seed(seed, 0x68656c64));
  for (int i = n - 1; i > 0; --i) std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(random.integer(0, i))]);
  int held = static_cast<int>(std::lround(held_out * n));
  held = std::min(held, n - 1);
  std::vector<bool> result(order.size(), false);
  for (int k = 0; k < held; ++k) result[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] = true;
  return result;
}

FitModel default_fit_model(const TrackedShots& shots) {
  FitModel m;
  m.table = shots.table;
  m.settings.parameters = default_parameters(shots.table);  // as a scenario on this table has them
  return m;
}

CalibrationReport calibrate(const TrackedShots& shots, const FitModel& start, const CalibrationOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!(options.held_out >= 0.0 && options.held_out <= 0.9))
    throw InvalidArgument("held_out", options.held_out, "[0, 0.9]", "fraction of the shots held out");
  if (options.threads < 1 || options.threads > 256) throw InvalidArgument("threads", options.threads, "[1, 256]", "threads");
  if (shots.shots.empty()) throw InvalidArgument("shots", "shots is empty (nothing to calibrate)");
  if (options.bootstrap.replicates < 0 || options.bootstrap.replicates > 1000)
    throw InvalidArgument("bootstrap", options.bootstrap.replicates, "[0, 1000]", "bootstrap replicates");
  CalibrationContext c{shots, options, {}, {}, {}};
  c.report.start = c.report.model = start;
  c.report.table_name = shots.table_name;
  prepare_shots(c);
  draw_held_out(c);
  fit_training(c);
  fit_held_out(c);
  c.report.training = summarize(c.report.shots, false);
  c.report.held_out = summarize(c.report.shots, true);
  c.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return c.report;
}

std::vector<ShotDrawing> shot_drawings(const TrackedShots& shots, const CalibrationReport& report) {
  if (shots.shots.size() != report.shots.size())
    throw InvalidArgument("shots", "the report has " + std::to_string(report.shots.size()) + " shots, the file " +
                                       std::to_string(shots.shots.size()) + "; allowed: the file the report was made from");
  std::vector<ShotDrawing> out;
  for (std::size_t i = 0; i < shots.shots.size(); ++i) {
    const TrackedShot& shot = shots.shots[i];
    const ShotReport& r = report.shots[i];
    const std::string path = "shots[" + std::to_string(i) + "]";
    if (shot.id != r.id)
      throw InvalidArgument(path, path + " is shot " + quote_input(shot.id) + " where the report has " + quote_input(r.id));
    const PreparedShot prepared = prepare_shot(shot, shots.table, path);
    ShotDrawing d;
    d.id = r.id;
    d.held_out = r.held_out;
    d.contact_mismatch = r.fit.contact_mismatch;
    d.cue_rmse = r.fit.cue_rmse;
    d.names = prepared.names;
    d.ball_rmse = r.fit.ball_rmse;
    for (const std::string& name : prepared.names) {
      std::vector<Vec2> samples;
      for (const TrackedBall& b : shot.balls)
        if (b.name == name)
          for (std::size_t k = 0; k < b.t.size(); ++k) samples.push_back({b.x[k], b.y[k]});
      d.measured.push_back(std::move(samples));
    }
    d.simulated = simulated_paths(prepared, report.model, r.fit.action, r.fit.strike_offset);
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace cueball
