// Step 3 of the shot planner (shot_planner.hpp), its numerical kernels: a
// noise-free trial of a strike and the target's miss of the pocket read from
// its exact trajectory, the aim solved to send the target through the
// pocket's centre, and a window's edge found by steps and bisection.
//
// Sources: the secant method with a bisection fallback once the root is
// bracketed (the safeguard of Dekker's method: R. P. Brent, "Algorithms for
// Minimization without Derivatives", 1973, ch. 4); golden-section search
// (ibid., ch. 5).
#include <algorithm>
#include <cmath>
#include <limits>

#include "planning/search_state.hpp"

namespace cueball::planning {

namespace {

// The closest approach of ball `b` to p over its exact trajectory (ending at
// end_time unless pocketed): each segment sampled, the best sample refined
// by golden section (the distance is smooth within a segment). A segment
// that cannot come nearer than the best so far is passed over: on the bed
// a ball's acceleration is at most a_max (sliding mu_s g, rolling
// 5/7 mu_r g, cloth_motion.hpp), so within a segment of duration T it stays
// within |v0| T + a_max T^2 / 2 of where it starts (the same answer, fewer
// evaluations: the target's path is mostly far from the pocket).
Vec2 closest_approach(const BallTrajectory& b, double end_time, Vec2 p, const Parameters& par) {
  constexpr double kRoundingSlack = 1e-9;  // m: the distances' rounding, far below it
  const double a_max = std::max(sliding_deceleration(par), rolling_deceleration(par));
  double best = std::numeric_limits<double>::infinity();
  Vec2 q{};
  for (std::size_t k = 0; k < b.segments.size(); ++k) {
    const double t0 = b.segments[k].start_time;
    const double t1 = k + 1 < b.segments.size() ? b.segments[k + 1].start_time
                      : b.pocketed              ? b.pocket_time
                                                : end_time;
    const double span = std::max(0.0, t1 - t0);
    const BallState& start = b.segments[k].state;
    const double reach = norm(start.velocity) * span + 0.5 * a_max * span * span;
    if (norm(start.position - p) - reach > best + kRoundingSlack) continue;
    // evolve(start, dt), its phase and next transition worked out once for
    // the segment (what evolve() does first on every call).
    const MotionPhase phase = motion_phase(start, par);
    const NextTransition next = next_transition(start, par);
    const auto at = [&](double dt) {
      if (dt < next.time || next.kind == Transition::none) return evolve_in_phase(start, phase, dt, par).position;
      return evolve(start, dt, par).position;
    };
    constexpr int kSamples = 24;
    int best_i = -1;
    double seg_best = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= kSamples; ++i) {
      const double d = norm(at(span * i / kSamples) - p);
      if (d < seg_best) seg_best = d, best_i = i;
    }
    double lo = span * std::max(0, best_i - 1) / kSamples, hi = span * std::min(kSamples, best_i + 1) / kSamples;
    // Golden section, each step reusing the inner point it keeps.
    const double g = (std::sqrt(5.0) - 1.0) / 2.0;
    double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    double d1 = norm(at(m1) - p), d2 = norm(at(m2) - p);
    for (int it = 0; it < 30 && hi - lo > 1e-7; ++it) {
      if (d1 < d2) {
        hi = m2, m2 = m1, d2 = d1;
        m1 = hi - g * (hi - lo), d1 = norm(at(m1) - p);
      } else {
        lo = m1, m1 = m2, d1 = d2;
        m2 = lo + g * (hi - lo), d2 = norm(at(m2) - p);
      }
    }
    Vec2 x = at(0.5 * (lo + hi));
    if (norm(x - p) > seg_best) x = at(span * best_i / kSamples);
    if (norm(x - p) < best) best = norm(x - p), q = x;
  }
  return q;
}

}  // namespace

Trial ExactTrials::play(const ShotAction& a, const Candidate& c) {
  const std::size_t pocket = c.pocket, target = c.target;
  const Vec2 last_leg = c.last_leg;
  Trial t;
  // Never a non-finite strike into the engine (it would throw
  // InvalidArgument): an unsimulated trial, which does not pot.
  if (!std::isfinite(a.speed) || !std::isfinite(a.aim_deg) || !std::isfinite(a.elevation_deg) ||
      !std::isfinite(a.side) || !std::isfinite(a.height))
    return t;
  if (runs_ >= most_runs_) throw BudgetSpent{};
  ++runs_;
  std::vector<SimulationBall> balls = s_.balls;
  balls[cue_].state =
      strike_ball(to_strike(a, R_), balls[cue_].state.position, s_.settings.parameters.ball, s_.cue_parameters);
  try {
    t.result = simulate_unchecked(s_.table, balls, s_.settings);
  } catch (const SimulationError&) {
    return t;
  }
  t.simulated = true;
  ShotOutcome o;
  outcome_from_result(t.result, s_.balls[cue_].id, o);
  const int first_ball = s_.balls[c.first_ball].id;
  t.touched = o.first_contact == first_ball;
  t.success = pots_target(o.first_contact, first_ball, o.pocket[target], static_cast<int>(pocket), o.pocketed[cue_]);
  if (!t.touched) return t;
  // A combination's A that missed the target: no miss to measure.
  const BallTrajectory& b = t.result.balls[target];
  if (!b.pocketed && b.final_state.position.x == s_.balls[target].state.position.x &&
      b.final_state.position.y == s_.balls[target].state.position.y)
    return t;
  const Vec2 p = s_.table.pockets[pocket].centre;
  const Vec2 q = closest_approach(b, t.result.end_time, p, s_.settings.parameters);
  t.lateral = cross(last_leg, q - p);
  const Vec2 end = b.final_state.position;
  t.short_of_pocket = !b.pocketed && norm(end - q) < 1e-3 && dot(last_leg, q - p) < -s_.table.pockets[pocket].radius;
  return t;
}

std::optional<double> ExactTrials::solve_aim(ShotAction a, const Candidate& c, bool& short_of_pocket, int limit) {
  short_of_pocket = false;
  std::optional<double> best;
  double best_miss = std::numeric_limits<double>::infinity();
  const auto run = [&](double x, double& f) {
    a.aim_deg = x;
    const Trial t = play(a, c);
    short_of_pocket = t.short_of_pocket;
    f = t.lateral;
    if (t.success && std::abs(f) < best_miss) best = x, best_miss = std::abs(f);
    return t.success && std::abs(f) < kLateralTol;
  };
  // The target through the pocket's centre without dropping (a side
  // pocket met at an angle, a jaw that turns it out): aims that send it
  // kOffsetSteps steps of a fraction of the pocket's radius to either side
  // of the centre, nearest first, from the local slope of the miss.
  const auto off_centre = [&](double root, double slope) -> std::optional<double> {
    if (!std::isfinite(slope) || slope == 0.0) return best;
    const double step = kOffsetFraction * s_.table.pockets[c.pocket].radius;
    for (int k = 1; k <= kOffsetSteps; ++k) {
      const double offset = k * step / std::abs(slope);
      if (offset > kOffsetMostDeg) break;
      for (const double sign : {1.0, -1.0}) {
        double f = kNaN;
        run(root + std::copysign(offset, sign * slope), f);
        if (best) return best;
      }
    }
    return best;
  };
  double x0 = a.aim_deg, f0 = kNaN;
  if (run(x0, f0)) return x0;
  if (short_of_pocket || !std::isfinite(f0)) return best;
  double x1 = x0 + 0.05, f1 = kNaN;
  bool bracketed = false;
  double lo = 0.0, flo = 0.0, hi = 0.0;  // f(lo) and f(hi) of opposite signs
  for (int i = 0; i < limit; ++i) {
    if (run(x1, f1)) return x1;
    if (short_of_pocket) return best;
    if (!std::isfinite(f1)) {  // missed the target: back towards the last good aim
      x1 = 0.5 * (x0 + x1);
      continue;
    }
    if (std::abs(f1) < kLateralTol) return best ? best : off_centre(x1, (f1 - f0) / (x1 - x0));
    if (!bracketed && std::signbit(f0) != std::signbit(f1)) {
      bracketed = true;
      lo = x0, flo = f0, hi = x1;
    } else if (bracketed) {
      if (std::signbit(f1) == std::signbit(flo)) lo = x1, flo = f1;
      else hi = x1;
    }
    double next = f1 != f0 ? x1 - f1 * (x1 - x0) / (f1 - f0) : x1 + 0.05;
    next = std::clamp(next, x1 - 3.0, x1 + 3.0);
    if (bracketed && !(next > std::min(lo, hi) && next < std::max(lo, hi))) next = 0.5 * (lo + hi);
    x0 = x1, f0 = f1, x1 = next;
  }
  return best;
}

double ExactTrials::window_edge(ShotAction a, const Candidate& c, WindowAxis axis, double inside, double direction,
                                double step, double tol, double limit, double most_step) {
  const auto set = [axis](ShotAction& x, double v) {
    if (axis == WindowAxis::speed) x.speed = v;
    else x.aim_deg = v;
  };
  double in = inside, out = kNaN;
  for (int i = 0; i < 8; ++i) {
    double x = in + direction * step;
    if ((x - limit) * direction >= 0.0) x = limit;
    set(a, x);
    if (!play(a, c).success) {
      out = x;
      break;
    }
    in = x;
    if (x == limit) return limit;
    step = std::min(2.0 * step, most_step);
  }
  if (!std::isfinite(out)) return in;
  while (std::abs(out - in) > tol) {
    const double mid = 0.5 * (in + out);
    set(a, mid);
    if (play(a, c).success) in = mid;
    else out = mid;
  }
  return in;
}

}  // namespace cueball::planning
