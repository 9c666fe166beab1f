#include "cueball/calibration/strike_fit.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include "calibration/levenberg_marquardt.hpp"
#include "calibration/strike_bounds.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball {

namespace {

using namespace detail;  // StrikeParam, bounds and steps (strike_bounds.hpp)

Scenario scenario_of(const PreparedShot& shot, const FitModel& model) {
  Scenario s;
  s.table = model.table;
  s.settings = model.settings;
  s.balls = shot.layout;
  s.cue_parameters = model.cue;
  s.cue = ShotStrike{};  // ball 0, the cue ball; the strike is given to each run
  return s;
}

std::vector<double> to_vector(const ShotAction& a, double strike) {
  return {a.speed, a.aim_deg, a.elevation_deg, a.side, a.height, strike};
}
ShotAction to_action(const std::vector<double>& q) { return {q[kSpeed], q[kAim], q[kElevation], q[kSide], q[kHeight]}; }

// The simulation of one strike, or nothing when the engine refuses it.
std::optional<SimulationResult> play(const Scenario& scenario, const ShotAction& action) {
  try {
    const std::vector<SimulationBall> balls = balls_after_strike(scenario, to_strike(action, scenario.table.ball.radius));
    return simulate_unchecked(scenario.table, balls, scenario.settings);
  } catch (const SimulationError&) {
    return std::nullopt;
  } catch (const InvalidArgument&) {
    return std::nullopt;
  }
}

void residuals_of(const PreparedShot& shot, const Scenario& scenario, const SimulationResult& r, double strike, double window,
                  std::vector<double>& out) {
  out.clear();
  const Parameters& p = scenario.settings.parameters;
  for (const FitSample& s : shot.samples) {
    if (window > 0 && s.t > window) continue;
    const Vec2 q = r.state_at(static_cast<std::size_t>(s.ball), std::max(s.t - strike, 0.0), p).position;
    out.push_back(q.x - s.x);
    out.push_back(q.y - s.y);
  }
}

// The ball went kMoveThreshold or more from where it was laid (at the start
// of a segment of its path, or at the end).
bool moved_from_layout(const SimulationResult& r, std::size_t ball, Vec2 layout) {
  const BallTrajectory& b = r.balls[ball];
  if (norm(b.final_state.position - layout) >= kMoveThreshold) return true;
  for (const TrajectorySegment& s : b.segments)
    if (norm(s.state.position - layout) >= kMoveThreshold) return true;
  return false;
}

// The other ball of the first ball-ball contact (the cue ball is the only
// one moving before it), -1 when there is none.
int first_ball_contact(const SimulationResult& r) {
  for (const Event& e : r.events)
    if (e.type == EventType::ball_ball) return e.ball == 0 ? e.other : e.ball;
  return -1;
}

// ------------------------------------------------------------- fit_strike's steps

struct FitContext {
  const PreparedShot& shot;
  const FitModel& model;
  const StrikeFitOptions& options;
  Scenario scenario;
  int simulations = 0;
  std::vector<std::vector<double>> starts;  // parameter vectors
  StrikeFit best;
};

detail::LeastSquaresProblem problem_of(FitContext& c, double window) {
  detail::LeastSquaresProblem p;
  const StrikeBounds b = strike_bounds(c.shot);
  p.lower = b.lower;
  p.upper = b.upper;
  p.step.assign(kStrikeSteps.begin(), kStrikeSteps.end());
  p.project = project_tip;
  p.residuals = [&c, window](const std::vector<double>& q, std::vector<double>& r) {
    ++c.simulations;
    const auto result = play(c.scenario, to_action(q));
    if (!result) return false;
    residuals_of(c.shot, c.scenario, *result, q[kStrike], window, r);
    return true;
  };
  return p;
}

// Cue speed that gives the cue ball the estimated speed with a centre hit.
double cue_speed_estimate(const FitContext& c) {
  const ShotAction unit{1.0, 0.0, 0.0, 0.0, 0.0};
  const auto balls = balls_after_strike(c.scenario, to_strike(unit, c.scenario.table.ball.radius));
  const double ratio = std::max(norm(balls[0].state.velocity), 1e-3);
  return std::clamp(c.shot.speed_estimate / ratio, 0.1, kMaxCueSpeed);
}

// Step 1: the grid of strikes, played by simulate_many, ranked by final positions.
void screen_starts(FitContext& c) {
  const double speed = cue_speed_estimate(c);
  const double aim = c.shot.aim_estimate_deg;
  std::vector<ShotAction> grid;
  for (double f : {0.8, 1.0, 1.25})
    for (double da : {-1.5, 0.0, 1.5})
      for (double side : {-0.35, 0.0, 0.35})
        for (double height : {-0.35, 0.0, 0.35})
          grid.push_back({std::min(speed * f, kMaxCueSpeed), aim + da, 3.0, side, height});
  const ManyResult many = simulate_many(c.scenario, grid, {}, ManyOptions{});
  c.simulations += many.shots;
  // Each ball's last sample (its rest position as far as the tracker saw).
  const std::size_t nb = c.shot.layout.size();
  std::vector<Vec2> last(nb);
  for (std::size_t j = 0; j < nb; ++j) last[j] = c.shot.layout[j].state.position;
  for (const FitSample& s : c.shot.samples) last[static_cast<std::size_t>(s.ball)] = {s.x, s.y};
  std::vector<std::pair<double, int>> ranked;
  for (int k = 0; k < many.shots; ++k) {
    double score = 0.0;
    for (std::size_t j = 0; j < nb; ++j) {
      const double* f = &many.final_position[(static_cast<std::size_t>(k) * nb + j) * 2];
      score += (f[0] - last[j].x) * (f[0] - last[j].x) + (f[1] - last[j].y) * (f[1] - last[j].y);
    }
    ranked.emplace_back(std::isfinite(score) ? score : std::numeric_limits<double>::infinity(), k);
  }
  std::sort(ranked.begin(), ranked.end());
  c.starts.push_back(to_vector({speed, aim, 3.0, 0.0, 0.0}, 0.0));
  for (int i = 0; i < std::min<int>(c.options.starts, static_cast<int>(ranked.size())); ++i)
    c.starts.push_back(to_vector(grid[static_cast<std::size_t>(ranked[static_cast<std::size_t>(i)].second)], 0.0));
}

// Steps 2 and 3: each start through the continuation; the best one kept.
void refine_starts(FitContext& c) {
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<double> best_q;
  for (std::vector<double> q : c.starts) {
    for (double w : c.options.windows) {
      if (w >= c.shot.duration) break;
      q = detail::levenberg_marquardt(problem_of(c, w), q, c.options.stage_iterations).q;
    }
    const auto r = detail::levenberg_marquardt(problem_of(c, 0.0), q, c.options.final_iterations);
    if (r.cost < best_cost) best_cost = r.cost, best_q = r.q;
  }
  if (best_q.empty()) best_q = c.starts.front();
  c.best = evaluate_strike(c.shot, c.model, to_action(best_q), best_q[kStrike]);
}

}  // namespace

bool simulated_residuals(const PreparedShot& shot, const FitModel& model, const ShotAction& action, double strike_offset,
                         double window, std::vector<double>& residuals) {
  const Scenario s = scenario_of(shot, model);
  const auto r = play(s, action);
  if (!r) return false;
  residuals_of(shot, s, *r, strike_offset, window, residuals);
  return true;
}

StrikeFit evaluate_strike(const PreparedShot& shot, const FitModel& model, const ShotAction& action, double strike_offset) {
  StrikeFit f;
  f.action = action;
  f.strike_offset = strike_offset;
  f.strike_time = shot.origin + strike_offset;
  f.simulations = 1;
  const Scenario s = scenario_of(shot, model);
  const auto r = play(s, action);
  const std::size_t nb = shot.layout.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  f.ball_rmse.assign(nb, nan);
  f.moved_simulated.assign(nb, 0);
  if (!r) {
    f.cost = f.cue_rmse = f.all_rmse = std::numeric_limits<double>::infinity();
    return f;
  }
  std::vector<double> res;
  residuals_of(shot, s, *r, strike_offset, 0.0, res);
  std::vector<double> sum(nb, 0.0);
  double total = 0.0, cost = 0.0;
  std::size_t tracked = 0;
  for (std::size_t i = 0; i < shot.samples.size(); ++i) {
    const double d2 = res[2 * i] * res[2 * i] + res[2 * i + 1] * res[2 * i + 1];
    cost += d2;
    if (shot.samples[i].held) continue;  // in the fit, not in the RMSEs
    sum[static_cast<std::size_t>(shot.samples[i].ball)] += d2;
    total += d2;
    ++tracked;
  }
  f.cost = cost;
  for (std::size_t j = 0; j < nb; ++j) {
    if (shot.samples_per_ball[j] > 0) f.ball_rmse[j] = std::sqrt(sum[j] / shot.samples_per_ball[j]);
    f.moved_simulated[j] = moved_from_layout(*r, j, shot.layout[j].state.position) ? 1 : 0;
    if (j > 0 && f.moved_simulated[j] != shot.moved[j]) f.contact_mismatch = true;
  }
  f.first_contact = first_ball_contact(*r);
  if (shot.first_object_ball >= 0 && f.first_contact != shot.first_object_ball) f.contact_mismatch = true;
  f.cue_rmse = f.ball_rmse[0];
  f.all_rmse = tracked == 0 ? 0.0 : std::sqrt(total / static_cast<double>(tracked));
  return f;
}

StrikeFit fit_strike(const PreparedShot& shot, const FitModel& model, const StrikeFitOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  if (options.starts < 1 || options.starts > 64) throw InvalidArgument("starts", options.starts, "[1, 64]", "refined starts");
  FitContext c{shot, model, options, scenario_of(shot, model), 0, {}, {}};
  validate_simulation_input(c.scenario.table, c.scenario.balls, c.scenario.settings);
  screen_starts(c);
  refine_starts(c);
  c.best.simulations += c.simulations;
  c.best.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return c.best;
}

StrikeFit refine_strike(const PreparedShot& shot, const FitModel& model, const StrikeFit& start, int iterations) {
  const auto t0 = std::chrono::steady_clock::now();
  const StrikeFitOptions options;
  FitContext c{shot, model, options, scenario_of(shot, model), 0, {}, {}};
  const auto r = detail::levenberg_marquardt(problem_of(c, 0.0), to_vector(start.action, start.strike_offset), iterations);
  StrikeFit f = evaluate_strike(shot, model, to_action(r.q), r.q[kStrike]);
  f.simulations += c.simulations;
  f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return f;
}

std::vector<std::vector<Vec2>> simulated_paths(const PreparedShot& shot, const FitModel& model, const ShotAction& action,
                                               double strike_offset, double step) {
  if (!(step > 0.0) || !std::isfinite(step)) throw InvalidArgument("step", step, "(0, inf)", "time between path points (s)");
  const Scenario scenario = scenario_of(shot, model);
  const auto result = play(scenario, action);
  if (!result) return {};
  const Parameters& p = scenario.settings.parameters;
  const double end = std::max(result->end_time, shot.duration - strike_offset);
  constexpr double kMinSpacing = 0.002;
  std::vector<std::vector<Vec2>> paths(shot.layout.size());
  const auto steps = static_cast<std::size_t>(std::ceil(std::max(end, 0.0) / step));
  for (std::size_t j = 0; j < paths.size(); ++j) {
    for (std::size_t k = 0; k <= steps; ++k) {
      const double t = std::min(static_cast<double>(k) * step, std::max(end, 0.0));
      const Vec2 q = result->state_at(j, t, p).position;
      if (paths[j].empty() || norm(q - paths[j].back()) >= kMinSpacing || k == steps) paths[j].push_back(q);
    }
  }
  return paths;
}

}  // namespace cueball
