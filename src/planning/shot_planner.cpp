// The shot planner: ghost-ball and mirror geometry, corrected on the exact
// simulation, scored under execution noise; see shot_planner.hpp.
//
// Sources: ghost-ball aiming and the mirror systems of banks and kicks (D. G.
// Alciatore, "The Illustrated Principles of Pool and Billiards", 2004); the secant
// method with a bisection fallback once the root is bracketed (the safeguard
// of Dekker's method: R. P. Brent, "Algorithms for Minimization without
// Derivatives", 1973, ch. 4); the tournament noise of Archibald et al. 2010.
#include "cueball/planning/shot_planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

#include "cueball/core/errors.hpp"
#include "core/enum_names.hpp"
#include "planning/shot_search.hpp"

namespace cueball {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Shots of the brief noisy screen of every feasible shot, and the most
// feasible shots kept.
constexpr int kBaseScreenShots = 16;
constexpr std::size_t kMaxScreened = 12;
// Spin and speed variants (step 4 of the header): of the kVariantCandidates
// best feasible shots by window probability, each tip height of
// ShotSearch::variant_heights (ball radii: draw, centre, follow) at each
// cue-speed factor of its variant_speeds on the shot's own speed, one more step along the speed
// where the best was at an end, and side kVariantSide either way at the best;
// a variant's search may take kVariantRuns runs or so. A shot whose window
// probability is kNothingToGain or more is not varied.
// (ShotSearch's defaults: shot_search.hpp).
constexpr std::size_t kVariantCandidates = 3;
constexpr double kVariantSide = 0.2;
constexpr double kNothingToGain = 0.999;
// Window probabilities in one step of this rank by the brief noisy screen.
constexpr double kWindowStep = 0.02;
// The aim scan (header, step 2b): kScanAims aims across the cue ball's
// straight hits on the target at each cue speed of kScanSpeeds (m/s),
// centre ball; of the potting runs of aims found, at most kScanCandidates.
constexpr int kScanAims = 40;
constexpr std::array<double, 2> kScanSpeeds{2.0, 4.0};
constexpr std::size_t kScanCandidates = 3;
// The finalists screened on common draws, and the most shots each.
constexpr std::size_t kFinalists = 3;
constexpr int kFinalistShots = 200;
constexpr int kVariantRuns = 60;
// Engine runs one candidate's noise-free search may take.
constexpr int kCandidateRuns = 120;
// The screen's noise stream starts at kScreenFirstShot (shot_search.hpp);
// the final estimate's at 0, so `cueball batch` of the written scenario
// with the same seed draws the final estimate's noise.
// Arrival speed of the object ball at the pocket that the first speed aims at, m/s.
constexpr double kArrivalSpeed = 1.0;
// The largest step of the aim window's search outwards, degrees: a hole in
// the window wider than this (a jaw that turns the ball out between two
// aims that pot) is not stepped over.
constexpr double kAimWindowMostStepDeg = 0.2;
// The target's miss of the pocket's centre the aim is solved to, m.
constexpr double kLateralTol = 0.5e-3;
// Where the target through the pocket's centre does not drop: the misses
// tried instead, in steps of kOffsetFraction of the pocket's radius, at most
// kOffsetSteps to either side.
constexpr double kOffsetFraction = 0.3;
constexpr int kOffsetSteps = 3;

double angle_deg(Vec2 v) { return std::atan2(v.y, v.x) / kDegree; }

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

// The chance that x + sigma z, z standard normal, lies in [lo, hi] (sigma 0:
// whether x does).
double inside_probability(double lo, double hi, double x, double sigma) {
  if (!(sigma > 0.0)) return lo <= x && x <= hi ? 1.0 : 0.0;
  return std::max(0.0, normal_cdf((hi - x) / sigma) - normal_cdf((lo - x) / sigma));
}

// The success probability the noise-free windows predict (header, step 4):
// the aim inside the aim window under the aim noise and the squirt of the
// side-offset noise (C8, linearised at the strike's offsets), times the cue
// speed inside the speed window under the speed noise. It leaves out what
// the windows do not see (a scratch or a kiss under the tip-height noise, a
// window that moves with the speed), which the noisy screen catches.
double window_probability(const PlannedShot& shot, const CueStrikeNoise& noise, const BallParameters& ball,
                          const CueParameters& cue) {
  const double a = shot.strike.side * ball.radius, b = shot.strike.height * ball.radius;
  constexpr double h = 1e-4;  // m
  const double squirt_rate = (squirt_angle(a + h, b, ball, cue) - squirt_angle(a - h, b, ball, cue)) / (2.0 * h);
  const double sigma_aim_deg = std::hypot(noise.aim, squirt_rate * noise.side_offset) / kDegree;
  return inside_probability(shot.aim_window_deg[0], shot.aim_window_deg[1], shot.strike.aim_deg, sigma_aim_deg) *
         inside_probability(shot.speed_window[0], shot.speed_window[1], shot.strike.speed, noise.speed);
}

std::size_t index_of(const std::vector<SimulationBall>& balls, int id) {
  for (std::size_t i = 0; i < balls.size(); ++i)
    if (balls[i].id == id) return i;
  return balls.size();
}

// One candidate as geometry describes it.
struct Candidate {
  ShotKind kind = ShotKind::direct;
  std::string what;         // "bank off <cushion>, then <cushion> into <pocket>", ...
  std::size_t pocket = 0;
  std::vector<std::size_t> cushions;  // bank: the object ball's, in order; kick: the cue ball's
  std::size_t first_ball = 0;         // index of the ball the cue ball must meet first
  std::optional<std::size_t> intermediate;  // combination: index of ball A
  Vec2 last_leg;            // unit direction of the object ball's last leg into the pocket
  double aim_deg = 0.0;
  double cut_deg = 0.0;     // the cue ball's cut on first_ball
  double combination_cut_deg = 0.0;  // A's cut on the target
  double cue_path = 0.0;    // m
  double middle_path = 0.0; // A's path to the target, m
  double object_path = 0.0; // m
  double ease = 0.0;        // order of the search: larger first
};

// A noise-free engine run and what the planner reads from it.
struct Trial {
  bool simulated = false;
  bool success = false;
  bool touched = false;     // the cue ball's first contact is the intended ball (the target, or A)
  bool short_of_pocket = false;
  double lateral = kNaN;    // signed miss of the pocket centre across the last leg, m
  SimulationResult result;
};

// Thrown by Planner::play when the noise-free search has used its share.
struct BudgetSpent {};

class Planner {
 public:
  Planner(const Scenario& s, std::size_t cue, std::size_t target, int most_runs)
      : s_(s), cue_(cue), target_(target), R_(s.settings.parameters.ball.radius), most_runs_(most_runs) {}

  int runs() const { return runs_; }
  // Counts n runs made elsewhere (the aim scan's batch).
  void count(int n) { runs_ += n; }
  // Sets the most runs play() may take (in all).
  void limit(int most_runs) { most_runs_ = most_runs; }

  Trial play(const ShotAction& a, const Candidate& c) {
    const std::size_t pocket = c.pocket;
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
    balls[cue_].state = strike_ball(to_strike(a, R_), balls[cue_].state.position, s_.settings.parameters.ball,
                                    s_.cue_parameters);
    try {
      t.result = simulate_unchecked(s_.table, balls, s_.settings);
    } catch (const SimulationError&) {
      return t;
    }
    t.simulated = true;
    ShotOutcome o;
    outcome_from_result(t.result, s_.balls[cue_].id, o);
    t.touched = o.first_contact == s_.balls[c.first_ball].id;
    t.success = t.touched && o.pocket[target_] == static_cast<int>(pocket) && !o.pocketed[cue_];
    if (!t.touched) return t;
    // A combination's A that missed the target: no miss to measure.
    const BallTrajectory& moved = t.result.balls[target_];
    if (!moved.pocketed && moved.final_state.position.x == s_.balls[target_].state.position.x &&
        moved.final_state.position.y == s_.balls[target_].state.position.y)
      return t;
    // The target's closest approach to the pocket's centre, over its exact
    // trajectory: each segment sampled, the best sample refined by golden
    // section (the distance is smooth within a segment).
    const Vec2 p = s_.table.pockets[pocket].centre;
    const BallTrajectory& b = t.result.balls[target_];
    const Parameters& par = s_.settings.parameters;
    double best = std::numeric_limits<double>::infinity();
    Vec2 q{};
    for (std::size_t k = 0; k < b.segments.size(); ++k) {
      const double t0 = b.segments[k].start_time;
      const double t1 = k + 1 < b.segments.size() ? b.segments[k + 1].start_time
                        : b.pocketed              ? b.pocket_time
                                                  : t.result.end_time;
      const double span = std::max(0.0, t1 - t0);
      const auto at = [&](double dt) { return evolve(b.segments[k].state, dt, par).position; };
      constexpr int kSamples = 24;
      int best_i = -1;
      double seg_best = std::numeric_limits<double>::infinity();
      for (int i = 0; i <= kSamples; ++i) {
        const double d = norm(at(span * i / kSamples) - p);
        if (d < seg_best) seg_best = d, best_i = i;
      }
      double lo = span * std::max(0, best_i - 1) / kSamples, hi = span * std::min(kSamples, best_i + 1) / kSamples;
      const double g = (std::sqrt(5.0) - 1.0) / 2.0;
      for (int it = 0; it < 30 && hi - lo > 1e-7; ++it) {
        const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
        if (norm(at(m1) - p) < norm(at(m2) - p)) hi = m2;
        else lo = m1;
      }
      Vec2 x = at(0.5 * (lo + hi));
      if (norm(x - p) > seg_best) x = at(span * best_i / kSamples);
      if (norm(x - p) < best) best = norm(x - p), q = x;
    }
    t.lateral = cross(last_leg, q - p);
    const Vec2 end = b.final_state.position;
    t.short_of_pocket = !b.pocketed && norm(end - q) < 1e-3 && dot(last_leg, q - p) < -s_.table.pockets[pocket].radius;
    return t;
  }

  // The aim that sends the target through the pocket's centre at this
  // speed (|lateral miss| < kLateralTol), from a.aim_deg: the secant method,
  // bisection once the root is bracketed and the secant step leaves the
  // bracket. It must pot; when `limit` runs do not converge, the potting aim
  // with the smallest miss; nullopt when none potted.
  std::optional<double> solve_aim(ShotAction a, const Candidate& c, bool& short_of_pocket, int limit) {
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
      for (int k = 1; k <= kOffsetSteps; ++k)
        for (const double sign : {1.0, -1.0}) {
          double f = kNaN;
          run(root + sign * k * step / slope, f);
          if (best) return best;
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

  // The last value from `inside` (pots) towards `direction` that still pots:
  // steps doubling from `step` until one misses (or `limit` is passed, which
  // is then the edge), then bisection to `tol`. `set` writes the value into
  // the action.
  template <class Set>
  double window_edge(ShotAction a, const Candidate& c, double inside, double direction, double step, double tol,
                     double limit, Set set, double most_step = std::numeric_limits<double>::infinity()) {
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

 private:
  const Scenario& s_;
  std::size_t cue_, target_;
  double R_;
  int most_runs_;
  int runs_ = 0;
};

// The tip heights tried: the request's, or centre ball, then draw, then follow.
std::vector<double> tip_heights(const PlanRequest& q) {
  if (q.height) return {*q.height};
  return {0.0, -0.3, 0.3};
}

// The lowest elevation, in 2 degree steps from level up to
// kMaxPlanElevationDeg, at which the cue clears the balls and the rail.
std::optional<double> clearing_elevation(const Scenario& s, std::size_t cue, double aim_deg, double side,
                                         double height) {
  for (int k = 0; 2.0 * k <= kMaxPlanElevationDeg; ++k) {
    const ShotAction probe{1.0, aim_deg, 2.0 * k, side, height};
    if (!cue_obstructed(s.table, s.balls, s.balls[cue].id, to_strike(probe, s.settings.parameters.ball.radius),
                        s.settings.parameters.ball))
      return 2.0 * k;
  }
  return std::nullopt;
}

// The aim scan (header, step 2b): kScanAims aims spread evenly over the cue
// ball's straight hits on the target at each speed of kScanSpeeds, centre
// ball, each at its clearing elevation (an obstructed aim is not played), in
// one simulate_many batch; each run of neighbouring aims that pot (the
// target dropping, the cue ball touching it first and staying up) at one
// speed into one pocket with one cushion count.
struct AimRun {
  std::size_t pocket;
  int cushions;
  double speed, first_aim, last_aim;
  int aims;
};
struct AimScan {
  std::vector<AimRun> runs;  // the widest first
  double step_deg = 0.0;     // between neighbouring aims
};

// The scan's batch and its runs; `played`: its engine runs.
AimScan scan_aims(const Scenario& s, std::size_t cue, std::size_t target, int& played) {
  const double R = s.settings.parameters.ball.radius;
  const Vec2 C = s.balls[cue].state.position, O = s.balls[target].state.position;
  const double half = std::asin(std::min(1.0, 2.0 * R / norm(O - C))) / kDegree;
  const double centre = angle_deg(O - C);
  std::vector<ShotAction> actions;
  for (double speed : kScanSpeeds)
    for (int i = 0; i < kScanAims; ++i) {
      const double aim = centre - half + (i + 0.5) * 2.0 * half / kScanAims;
      const std::optional<double> elevation = clearing_elevation(s, cue, aim, 0.0, 0.0);
      // An obstructed aim is kept unplayed (a NaN speed): the runs stay in order.
      actions.push_back({elevation ? speed : kNaN, aim, elevation.value_or(0.0), 0.0, 0.0});
    }
  std::vector<ShotAction> to_play;
  for (const ShotAction& a : actions)
    if (std::isfinite(a.speed)) to_play.push_back(a);
  Scenario scan = s;
  scan.cue = ShotStrike{};
  scan.cue->ball = s.balls[cue].id;
  const ManyResult m = to_play.empty() ? ManyResult{} : simulate_many(scan, to_play, {}, ManyOptions{});
  played = m.shots;
  AimScan out;
  out.step_deg = 2.0 * half / kScanAims;
  const auto n = static_cast<std::size_t>(m.balls);
  std::size_t k = 0;
  bool extends = false;
  for (const ShotAction& a : actions) {
    if (!std::isfinite(a.speed)) {
      extends = false;
      continue;
    }
    const std::size_t row = k++;
    const bool pots = !m.failure[row] && m.first_contact[row] == s.balls[target].id && m.pocketed[row * n + target] &&
                      !m.pocketed[row * n + cue];
    if (!pots) {
      extends = false;
      continue;
    }
    const auto pocket = static_cast<std::size_t>(m.pocket[row * n + target]);
    const int cushions = m.cushions[row * n + target];
    std::vector<AimRun>& runs = out.runs;
    if (extends && runs.back().pocket == pocket && runs.back().cushions == cushions && runs.back().speed == a.speed) {
      runs.back().last_aim = a.aim_deg;
      ++runs.back().aims;
    } else {
      runs.push_back({pocket, cushions, a.speed, a.aim_deg, a.aim_deg, 1});
    }
    extends = true;
  }
  std::stable_sort(out.runs.begin(), out.runs.end(), [](const AimRun& a, const AimRun& b) { return a.aims > b.aims; });
  return out;
}

// A run's candidate: its middle aim played once in full (one engine run, at
// `elevation`), the target a bank when it meets a rail (a cushion long enough
// to bank off, not a pocket's facing) before it drops; nullopt when that
// play fails or does not pot. has_legs: its first and last legs have a
// direction (the last leg and the cut are then set).
struct ScannedCandidate {
  Candidate candidate;
  bool has_legs = false;
};

std::optional<ScannedCandidate> scanned_candidate(const Scenario& s, std::size_t cue, std::size_t target, const AimRun& r,
                                                  double elevation) {
  const double R = s.settings.parameters.ball.radius;
  ScannedCandidate out;
  Candidate& c = out.candidate;
  c.pocket = r.pocket;
  c.first_ball = target;
  c.aim_deg = 0.5 * (r.first_aim + r.last_aim);
  std::vector<SimulationBall> balls = s.balls;
  balls[cue].state = strike_ball(to_strike(ShotAction{r.speed, c.aim_deg, elevation, 0.0, 0.0}, R),
                                 balls[cue].state.position, s.settings.parameters.ball, s.cue_parameters);
  SimulationResult played_out;
  try {
    played_out = simulate_unchecked(s.table, balls, s.settings);
  } catch (const SimulationError&) {
    return std::nullopt;
  }
  const BallTrajectory& t = played_out.balls[target];
  if (!t.pocketed || t.segments.size() < 2) return std::nullopt;
  for (const Event& e : played_out.events) {
    if (e.type != EventType::ball_cushion || e.ball != s.balls[target].id) continue;
    const CushionSegment& seg = s.table.cushions[static_cast<std::size_t>(e.other)];
    if (norm(seg.end - seg.start) >= 6.0 * R) c.cushions.push_back(static_cast<std::size_t>(e.other));
  }
  c.kind = c.cushions.empty() ? ShotKind::direct : ShotKind::bank;
  const Vec2 last = t.segments.back().state.velocity, first = t.segments[1].state.velocity;
  out.has_legs = norm(last) > 0.0 && norm(first) > 0.0;
  if (!out.has_legs) return out;
  c.last_leg = last / norm(last);
  c.cut_deg =
      std::acos(std::clamp(dot(first / norm(first), Vec2{std::cos(c.aim_deg * kDegree), std::sin(c.aim_deg * kDegree)}),
                           -1.0, 1.0)) /
      kDegree;
  c.what = std::string(to_string(c.kind)) + " into " + s.table.pockets[r.pocket].name;
  for (std::size_t i = 0; i < c.cushions.size(); ++i)
    c.what += (i == 0 ? " off " : ", then ") + cushion_name(s.table, c.cushions[i]);
  c.what += " (found by the aim scan)";
  return out;
}


// A cushion's line: where the centre of a ball touching the cushion is (the
// nose line moved in by the contact distance, header comment).
struct CushionLine {
  Vec2 start, along;  // along: unit, start -> end
  double length = 0.0;
  Vec2 normal;        // into the table
  double contact = 0.0;
  CushionLine(const CushionSegment& seg, double R)
      : start(seg.start), along((seg.end - seg.start) / norm(seg.end - seg.start)), length(norm(seg.end - seg.start)),
        normal(inward_normal(seg)), contact(cushion_contact_distance(seg.contact_height, R)) {}
  // Positive on the table's side of the line.
  double signed_distance(Vec2 x) const { return dot(x - start, normal) - contact; }
  Vec2 mirror(Vec2 x) const { return x - 2.0 * signed_distance(x) * normal; }
  // Where a -> b crosses the line (a on the table's side, b beyond it).
  Vec2 crossing(Vec2 a, Vec2 b) const {
    const double sa = signed_distance(a), sb = signed_distance(b);
    return a + sa / (sa - sb) * (b - a);
  }
  // A point of the line that is on the cushion, 3R clear of its ends.
  bool on_cushion(Vec2 x, double R) const {
    const double foot = dot(x - start, along);
    return foot >= 3.0 * R && foot <= length - 3.0 * R;
  }
  // Degrees from the normal at which a ball coming from `from` meets the line at x.
  double incidence_deg(Vec2 from, Vec2 x) const {
    return std::acos(std::clamp(dot((from - x) / norm(from - x), normal), -1.0, 1.0)) / kDegree;
  }
};

// The largest angle from its normal at which a ball may be sent into a cushion, degrees.
constexpr double kMaxIncidenceDeg = 75.0;

// Candidates of one kind for one pocket, with the reasons others were dropped.
void geometric_candidates(const Scenario& s, const PlanRequest& q, std::size_t cue, std::size_t target,
                          std::size_t pocket, ShotKind kind, std::vector<Candidate>& out,
                          std::vector<std::string>& rejected) {
  const Table& table = s.table;
  const double R = s.settings.parameters.ball.radius;
  const Vec2 C = s.balls[cue].state.position;
  const Vec2 O = s.balls[target].state.position;
  const Vec2 P = table.pockets[pocket].centre;
  const std::string pocket_name = table.pockets[pocket].name;
  const auto unit = [](Vec2 v) { return v / norm(v); };
  const auto angle_between_deg = [](Vec2 a, Vec2 b) {
    return std::acos(std::clamp(dot(a, b), -1.0, 1.0)) / kDegree;
  };
  const auto cut_text = [](double deg) {
    return format_number(std::round(deg * 10) / 10) + " deg > " + format_number(kMaxCutDeg) + " deg";
  };
  // The first ball (other than the cue ball, the target and `also`) whose
  // centre is within 2R of the path a -> b, or "".
  const auto blocker = [&](Vec2 a, Vec2 b, std::optional<std::size_t> also) -> std::string {
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
      if (i == cue || i == target || (also && i == *also)) continue;
      if (distance_to_path(s.balls[i].state.position, a, b) < 2.0 * R) return "ball " + std::to_string(s.balls[i].id);
    }
    return {};
  };
  const auto length = [](const std::vector<Vec2>& legs) {
    double l = 0.0;
    for (std::size_t i = 0; i + 1 < legs.size(); ++i) l += norm(legs[i + 1] - legs[i]);
    return l;
  };
  // The legs of the cue ball (C -> ... -> its ghost ball of c.first_ball), of
  // A (combination: A -> the target's ghost ball) and of the target (O ->
  // ... -> P): checked, and pushed to `into` when clear.
  const auto consider = [&](Candidate c, const std::vector<Vec2>& cue_legs, const std::vector<Vec2>& middle_legs,
                            const std::vector<Vec2>& object_legs, std::vector<Candidate>& into) {
    const std::string& what = c.what;
    // A leg of no length has no direction (a ball frozen to the cushion it
    // would be banked off meets that cushion where it is: its bank point is
    // the ball itself, and the ghost ball O - 2R u of u = 0/0 is NaN).
    const auto degenerate = [](const std::vector<Vec2>& legs) {
      for (std::size_t i = 0; i < legs.size(); ++i) {
        if (!std::isfinite(legs[i].x) || !std::isfinite(legs[i].y)) return true;
        if (i + 1 < legs.size() && !(norm(legs[i + 1] - legs[i]) >= 1e-9)) return true;
      }
      return false;
    };
    if (degenerate(object_legs) || degenerate(middle_legs)) {
      rejected.push_back(what + ": the object ball's path has a leg of no length (it touches the cushion)");
      return;
    }
    for (std::size_t i = 0; i + 1 < cue_legs.size(); ++i)
      if (!(norm(cue_legs[i + 1] - cue_legs[i]) >= 1e-9)) {
        rejected.push_back(what + ": the cue ball is on the ghost ball");
        return;
      }
    const std::vector<Vec2>& first_ball_legs = middle_legs.empty() ? object_legs : middle_legs;
    const Vec2 first = unit(first_ball_legs[1] - first_ball_legs[0]);
    const Vec2 w = unit(cue_legs.back() - cue_legs[cue_legs.size() - 2]);
    c.cut_deg = angle_between_deg(w, first);
    if (c.cut_deg > kMaxCutDeg) {
      rejected.push_back(what + ": cut " + cut_text(c.cut_deg));
      return;
    }
    if (!middle_legs.empty()) {
      c.combination_cut_deg = angle_between_deg(unit(middle_legs.back() - middle_legs[middle_legs.size() - 2]),
                                                unit(object_legs[1] - object_legs[0]));
      if (c.combination_cut_deg > kMaxCutDeg) {
        rejected.push_back(what + ": cut of ball " + std::to_string(s.balls[*c.intermediate].id) + " on the target " +
                           cut_text(c.combination_cut_deg));
        return;
      }
    }
    for (std::size_t i = 0; i + 1 < cue_legs.size(); ++i) {
      if (const std::string b = blocker(cue_legs[i], cue_legs[i + 1], c.intermediate); !b.empty()) {
        rejected.push_back(what + ": the cue ball's path is blocked by " + b);
        return;
      }
      // The cue ball must not meet the target first (a combination's
      // target, a kick's target before the cushion).
      const bool last = i + 2 == cue_legs.size();
      if ((c.intermediate || !last) &&
          distance_to_path(O, cue_legs[i], cue_legs[i + 1]) < 2.0 * R) {
        rejected.push_back(what + ": the cue ball's path is blocked by the target");
        return;
      }
    }
    for (std::size_t i = 0; i + 1 < middle_legs.size(); ++i)
      if (const std::string b = blocker(middle_legs[i], middle_legs[i + 1], c.intermediate); !b.empty()) {
        rejected.push_back(what + ": ball " + std::to_string(s.balls[*c.intermediate].id) + "'s path is blocked by " + b);
        return;
      }
    for (std::size_t i = 0; i + 1 < object_legs.size(); ++i)
      if (const std::string b = blocker(object_legs[i], object_legs[i + 1], c.intermediate); !b.empty()) {
        rejected.push_back(what + ": the object ball's path is blocked by " + b);
        return;
      }
    c.aim_deg = angle_deg(cue_legs[1] - cue_legs[0]);
    c.cue_path = length(cue_legs);
    c.middle_path = length(middle_legs);
    c.object_path = length(object_legs);
    c.last_leg = unit(object_legs.back() - object_legs[object_legs.size() - 2]);
    // The cue must reach the ball (at some tip height tried).
    bool clear = false;
    for (double height : tip_heights(q))
      clear = clear || clearing_elevation(s, cue, c.aim_deg, q.side, height).has_value();
    if (!clear) {
      rejected.push_back(what + ": the cue is obstructed at every elevation up to " +
                         format_number(kMaxPlanElevationDeg) + " deg");
      return;
    }
    // Each cushion halves the ease, a combination's second collision more.
    double factor = 1.0;
    if (c.kind == ShotKind::bank || c.kind == ShotKind::kick) factor = std::pow(0.5, static_cast<double>(c.cushions.size()));
    if (c.kind == ShotKind::combination) factor = 0.35 * std::cos(c.combination_cut_deg * kDegree);
    c.ease = std::cos(c.cut_deg * kDegree) / (c.cue_path + c.middle_path + c.object_path) * factor;
    into.push_back(c);
  };
  // The cue ball's ghost ball for a ball at b sent towards `towards`.
  const auto ghost = [&](Vec2 b, Vec2 towards) { return b - 2.0 * R * unit(towards - b); };

  Candidate base;
  base.kind = kind;
  base.pocket = pocket;
  base.first_ball = target;
  // The cushions a ball may be banked or kicked off (not the pocket facings
  // and short pieces).
  std::vector<std::size_t> rails;
  for (std::size_t k = 0; k < table.cushions.size(); ++k)
    if (norm(table.cushions[k].end - table.cushions[k].start) >= 8.0 * R) rails.push_back(k);

  if (kind == ShotKind::direct) {
    base.what = "direct into " + pocket_name;
    consider(base, {C, ghost(O, P)}, {}, {O, P}, out);
    return;
  }
  // Rejects `c` (true) when `ball` meets a cushion more than
  // kMaxIncidenceDeg from its normal.
  const auto too_steep = [&](const Candidate& c, const char* ball, double incidence, const char* which) {
    if (incidence <= kMaxIncidenceDeg) return false;
    rejected.push_back(c.what + ": " + ball + " would meet the cushion at " + format_number(std::round(incidence)) +
                       " deg from its normal (> " + format_number(kMaxIncidenceDeg) + ")" + which);
    return true;
  };
  if (kind == ShotKind::kick) {
    const Vec2 G = ghost(O, P);
    for (std::size_t k : rails) {
      const CushionLine line(table.cushions[k], R);
      if (line.signed_distance(C) <= 0.0 || line.signed_distance(G) <= 0.0) continue;
      Candidate c = base;
      c.cushions = {k};
      c.what = "kick off " + cushion_name(table, k) + " into " + pocket_name;
      const Vec2 Y = line.crossing(C, line.mirror(G));
      if (!line.on_cushion(Y, R)) {
        rejected.push_back(c.what + ": the cue ball's bank point is not on the cushion");
        continue;
      }
      if (too_steep(c, "the cue ball", line.incidence_deg(C, Y), "")) continue;
      consider(c, {C, Y, G}, {}, {O, P}, out);
    }
    return;
  }
  if (kind == ShotKind::combination) {
    const Vec2 GT = ghost(O, P);
    std::vector<Candidate> combinations;
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
      if (i == cue || i == target) continue;
      const Vec2 A = s.balls[i].state.position;
      if (norm(GT - A) < 1e-9) continue;
      Candidate c = base;
      c.first_ball = i;
      c.intermediate = i;
      c.what = "combination via ball " + std::to_string(s.balls[i].id) + " into " + pocket_name;
      consider(c, {C, ghost(A, GT)}, {A, GT}, {O, P}, combinations);
    }
    // The few with the smallest combined cut.
    std::stable_sort(combinations.begin(), combinations.end(), [](const Candidate& a, const Candidate& b) {
      return a.cut_deg + a.combination_cut_deg < b.cut_deg + b.combination_cut_deg;
    });
    for (std::size_t i = 0; i < combinations.size(); ++i) {
      if (i < kMaxCombinationBalls) out.push_back(combinations[i]);
      else
        rejected.push_back(combinations[i].what + ": not among the " + std::to_string(kMaxCombinationBalls) +
                           " with the smallest combined cut");
    }
    return;
  }
  // Banks: off one cushion, then off two.
  for (std::size_t k : rails) {
    const CushionLine line(table.cushions[k], R);
    const double sp = line.signed_distance(P), so = line.signed_distance(O);
    if (sp < 4.0 * R || so <= 0.0) continue;  // the pocket is on this cushion's rail
    Candidate c = base;
    c.cushions = {k};
    c.what = "bank off " + cushion_name(table, k) + " into " + pocket_name;
    const Vec2 X = line.crossing(O, line.mirror(P));
    if (!line.on_cushion(X, R)) {
      rejected.push_back(c.what + ": the bank point is not on the cushion");
      continue;
    }
    if (too_steep(c, "the object ball", line.incidence_deg(O, X), "")) continue;
    consider(c, {C, ghost(O, X)}, {}, {O, X, P}, out);
  }
  for (std::size_t k1 : rails) {
    const CushionLine first(table.cushions[k1], R);
    for (std::size_t k2 : rails) {
      const CushionLine second(table.cushions[k2], R);
      // Two pieces of one rail (either side of a side pocket) are one line.
      if (k1 == k2 || dot(first.normal, second.normal) > 0.99) continue;
      // P1, P mirrored in the second line; P2, P1 in the first.
      if (second.signed_distance(P) < 4.0 * R) continue;  // the pocket is on the second cushion's rail
      const Vec2 P1 = second.mirror(P);
      if (first.signed_distance(O) <= 0.0 || first.signed_distance(P1) <= 0.0 || second.signed_distance(O) <= 0.0)
        continue;
      const Vec2 X1 = first.crossing(O, first.mirror(P1));
      if (second.signed_distance(X1) <= 0.0) continue;  // the second line would come first
      const Vec2 X2 = second.crossing(X1, P1);
      if (first.signed_distance(X2) <= 0.0) continue;
      Candidate c = base;
      c.cushions = {k1, k2};
      c.what = "bank off " + cushion_name(table, k1) + ", then " + cushion_name(table, k2) + " into " + pocket_name;
      if (!first.on_cushion(X1, R) || !second.on_cushion(X2, R)) {
        rejected.push_back(c.what + ": a bank point is not on its cushion");
        continue;
      }
      if (too_steep(c, "the object ball", std::max(first.incidence_deg(O, X1), second.incidence_deg(X1, X2)),
                    ", first or second bank"))
        continue;
      consider(c, {C, ghost(O, X1)}, {}, {O, X1, X2, P}, out);
    }
  }
}

}  // namespace

const char* to_string(ShotKind kind) {
  switch (kind) {
    case ShotKind::direct: return "direct";
    case ShotKind::bank: return "bank";
    case ShotKind::kick: return "kick";
    case ShotKind::combination: return "combination";
  }
  return "direct";
}

std::optional<ShotKind> shot_kind_from_string(std::string_view name) {
  return value_named(kShotKinds, name);
}

std::string shot_kind_names(std::string_view quote) {
  return names_of(kShotKinds, quote);
}

CueStrikeNoise tournament_noise() {
  CueStrikeNoise n;
  n.speed = 0.075;
  n.aim = 0.125 * kDegree;
  n.elevation = 0.1 * kDegree;
  n.side_offset = 0.0005;
  n.height_offset = 0.0005;
  return n;
}

bool cue_obstructed(const Table& table, const std::vector<SimulationBall>& balls, int cue_ball, const CueStrike& strike,
                    const BallParameters& ball) {
  const std::size_t cue = index_of(balls, cue_ball);
  if (cue == balls.size())
    throw InvalidArgument("cue_ball", "cue_ball = " + std::to_string(cue_ball) + " is not the id of a ball on the table");
  std::vector<Vec2> others;
  others.reserve(balls.size());
  for (std::size_t i = 0; i < balls.size(); ++i)
    if (i != cue) others.push_back(balls[i].state.position);
  return cue_obstructed(table, balls[cue].state.position, others, strike, ball.radius);
}

Scenario scenario_with_shot(const Scenario& table_state, int cue_ball, const PlannedShot& shot,
                            const CueStrikeNoise& noise) {
  Scenario s = table_state;
  ShotStrike cue;
  cue.ball = cue_ball;
  cue.strike = to_strike(shot.strike, s.settings.parameters.ball.radius);
  cue.given = CueStrikeInUnits{shot.strike.aim_deg, shot.strike.elevation_deg, shot.strike.side, shot.strike.height};
  s.cue = cue;
  s.noise = noise;
  return s;
}

int noisy_successes(const Scenario& table_state, const PlanRequest& q, int cue_ball, const PlannedShot& shot, int shots,
                    std::uint64_t first_shot) {
  Scenario noisy = table_state;
  noisy.cue = ShotStrike{};  // simulate_many strikes cue.ball with each action
  noisy.cue->ball = cue_ball;
  noisy.noise = q.noise;
  const std::size_t cue = index_of(noisy.balls, cue_ball), target = index_of(noisy.balls, q.target);
  const int first_contact = shot.intermediate_ball >= 0 ? shot.intermediate_ball : q.target;
  const std::vector<ShotAction> actions(static_cast<std::size_t>(shots), shot.strike);
  ManyOptions options;
  options.seed = q.seed;
  options.noise = true;
  options.first_shot = first_shot;
  const ManyResult m = simulate_many(noisy, actions, {}, options);
  const auto n = static_cast<std::size_t>(m.balls);
  int hits = 0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(m.shots); ++k)
    hits += !m.miscue[k] && !m.failure[k] && m.first_contact[k] == first_contact &&
                    (q.pocket ? m.pocket[k * n + target] == shot.pocket : m.pocketed[k * n + target] != 0) &&
                    !m.pocketed[k * n + cue]
                ? 1
                : 0;
  return hits;
}

void set_estimate(PlannedShot& shot, int hits, int shots) {
  shot.noisy_shots = shots;
  shot.success_probability = static_cast<double>(hits) / shots;
  const double p = shot.success_probability;
  shot.success_standard_error = std::sqrt(p * (1.0 - p) / shots);
}

ShotPlanResult plan_shot(const Scenario& table_state, const PlanRequest& q) {
  return search_shots(table_state, q, ShotSearch{}).plan;
}

SearchedShots search_shots(const Scenario& table_state, const PlanRequest& q, const ShotSearch& o) {
  const auto start = std::chrono::steady_clock::now();
  const Scenario& s = table_state;
  validate_simulation_input(s.table, s.balls, s.settings);
  std::string ids;
  for (const SimulationBall& b : s.balls) ids += (ids.empty() ? "" : ", ") + std::to_string(b.id);
  const int cue_id = q.cue_ball ? *q.cue_ball : s.cue ? s.cue->ball : 0;
  const std::size_t cue = index_of(s.balls, cue_id);
  if (cue == s.balls.size()) {  // the request's cue_ball, else the scenario's cue.ball (0 without a cue)
    const std::string f = q.cue_ball ? "cue_ball" : "scenario.cue.ball";
    throw InvalidArgument(f, f + " = " + std::to_string(cue_id) + (q.cue_ball || s.cue ? "" : " (the default: no cue given)") +
                                 " is not the id of a ball on the table; allowed: " + ids);
  }
  const std::size_t target = index_of(s.balls, q.target);
  if (target == s.balls.size())
    throw InvalidArgument("target", "target = " + std::to_string(q.target) +
                                        " is not the id of a ball on the table; allowed: " + ids);
  if (target == cue)
    throw InvalidArgument("target", "target = " + std::to_string(q.target) + " is the cue ball; choose another ball");
  if (s.table.pockets.empty()) throw InvalidArgument("pocket", "the table has no pockets");
  if (q.pocket && (*q.pocket < 0 || static_cast<std::size_t>(*q.pocket) >= s.table.pockets.size()))
    throw InvalidArgument("pocket", static_cast<double>(*q.pocket),
                          "[0, " + std::to_string(s.table.pockets.size() - 1) + "]", "index into the table's pockets");
  if (q.kinds.empty()) throw InvalidArgument("kinds", "kinds is empty; give one or more of " + shot_kind_names());
  if (q.simulations < kMinPlanSimulations || q.simulations > kMaxPlanSimulations)
    throw InvalidArgument("simulations", static_cast<double>(q.simulations),
                          "[" + std::to_string(kMinPlanSimulations) + ", " + std::to_string(kMaxPlanSimulations) + "]",
                          "engine runs the plan may use");
  require_in_range("side", q.side, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset to the right, ball radii");
  const double given_height = q.height.value_or(0.0);
  require_in_range("height", given_height, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset above the centre, ball radii");
  // Draw and follow (+-0.3) are tried with a centre-ball side of at most 0.4.
  const double most_height = q.height ? std::abs(given_height) : 0.3;
  if (std::hypot(q.side, most_height) > kMiscueOffsetFraction * (1.0 + 1e-12))
    throw InvalidArgument("side", q.side, "a tip offset sqrt(side^2 + height^2) <= 0.5 (height " + format_number(most_height) + ")",
                          "tip offset to the right, ball radii");
  validate(q.noise);

  ShotPlanResult result;
  result.cue_ball = cue_id;
  const double R = s.settings.parameters.ball.radius;
  const BallParameters& ball = s.settings.parameters.ball;

  // 1-2. Geometry: candidates in order of ease.
  std::vector<Candidate> candidates;
  for (std::size_t k = 0; k < s.table.pockets.size(); ++k) {
    if (q.pocket && static_cast<std::size_t>(*q.pocket) != k) continue;
    for (ShotKind kind : kShotKinds)
      if (std::find(q.kinds.begin(), q.kinds.end(), kind) != q.kinds.end())
        geometric_candidates(s, q, cue, target, k, kind, candidates, result.rejected);
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.ease > b.ease; });

  // 3. The exact simulation: aim corrected, windows, speed chosen.
  // At most half the budget on the search (a candidate started before then
  // may go on to three quarters), the rest for the noise.
  const int search_budget = q.simulations * 2 / 5;
  Planner planner(s, cue, target, q.simulations * 3 / 4);
  const Parameters& par = s.settings.parameters;
  const double roll = par.cloth.rolling_resistance * par.cloth.gravity;
  std::vector<PlannedShot> feasible;
  // One candidate at one tip height: the aim solved, the windows found, the
  // speed chosen; nullopt and `why` when it does not pot.
  // `fixed`: a variant's cue speed and the aim its solve starts from (the
  // speed is then kept, not chosen).
  const auto search = [&](const Candidate& c, double side, double height, std::string& why,
                          std::optional<std::pair<double, double>> fixed = std::nullopt) -> std::optional<PlannedShot> {
    // First speed: the object ball arriving at about kArrivalSpeed, rolling
    // (5/7 of its speed kept after sliding), 95 % of the striking ball's
    // speed along the line of centres passed on, each cushion losing a
    // quarter (the object ball's of a bank, the cue ball's of a kick); a
    // combination's ball A is the target's striking ball.
    const double object_cushions = c.kind == ShotKind::bank ? static_cast<double>(c.cushions.size()) : 0.0;
    double v_object = 1.4 * std::sqrt(kArrivalSpeed * kArrivalSpeed + 2.0 * roll * c.object_path) /
                      std::pow(0.75, object_cushions);
    if (c.kind == ShotKind::combination) {
      const double v_middle = v_object / (0.95 * std::cos(c.combination_cut_deg * kDegree));
      v_object = 1.4 * std::sqrt(v_middle * v_middle + 2.0 * roll * c.middle_path);
    }
    const double v_cue = v_object / (0.95 * std::cos(c.cut_deg * kDegree));
    const double v0 = 1.2 * std::sqrt(v_cue * v_cue + 2.0 * roll * c.cue_path) / (c.kind == ShotKind::kick ? 0.75 : 1.0);
    const double cue_speed_of = level_cue_speed(v0, height * R, ball, s.cue_parameters);
    const std::optional<double> elevation = clearing_elevation(s, cue, c.aim_deg, side, height);
    if (!elevation) {
      why = "the cue is obstructed at every elevation up to " + format_number(kMaxPlanElevationDeg) + " deg";
      return std::nullopt;
    }
    if (!std::isfinite(cue_speed_of) || !std::isfinite(c.aim_deg)) {
      why = "no finite first speed or aim from geometry";
      return std::nullopt;
    }
    ShotAction a{std::clamp(cue_speed_of / std::cos(*elevation * kDegree), 0.3, 10.0), c.aim_deg, *elevation, side,
                 height};
    std::optional<double> aim;
    const auto set_speed = [](ShotAction& x, double v) { x.speed = v; };
    const auto set_aim = [](ShotAction& x, double v) { x.aim_deg = v; };
    if (fixed) {
      a.speed = std::clamp(fixed->first, 0.3, kMaxCueSpeed);
      a.aim_deg = fixed->second;
      bool short_of_pocket = false;
      aim = planner.solve_aim(a, c, short_of_pocket, 8);
      if (!aim) {
        why = "no aim pots it at this speed and spin";
        return std::nullopt;
      }
      a.aim_deg = *aim;
    }
    for (int tries = 0; tries < 4 && !aim; ++tries) {
      bool short_of_pocket = false;
      aim = planner.solve_aim(a, c, short_of_pocket, 12);
      if (!aim && !short_of_pocket) break;
      if (!aim) a.speed = std::min(kMaxCueSpeed, a.speed * 1.6);
    }
    if (!aim) {
      why = "no aim pots it on the exact simulation";
      return std::nullopt;
    }
    a.aim_deg = *aim;
    const double slowest = fixed ? 0.0 : planner.window_edge(a, c, a.speed, -1.0, 0.25, kSpeedWindowTol, 0.05, set_speed);
    const double fastest = fixed ? 0.0 : planner.window_edge(a, c, a.speed, +1.0, 0.5, kSpeedWindowTol, kMaxCueSpeed, set_speed);
    // Speed: a margin above the slowest pot (speed noise and the roll-off
    // near the pocket), at most the window's middle.
    const double margin = std::max(0.3, 0.25 * slowest) + 3.0 * q.noise.speed;
    const double chosen = fixed ? a.speed : std::min(std::max(a.speed, slowest + margin), 0.5 * (slowest + fastest));
    if (chosen != a.speed) {
      a.speed = chosen;
      bool short_of_pocket = false;
      aim = planner.solve_aim(a, c, short_of_pocket, 8);
      if (!aim) {
        why = "no aim pots it at the chosen speed";
        return std::nullopt;
      }
      a.aim_deg = *aim;
    }
    PlannedShot shot;
    shot.kind = c.kind;
    shot.pocket = static_cast<int>(c.pocket);
    shot.pocket_name = s.table.pockets[c.pocket].name;
    for (std::size_t k : c.cushions) shot.cushions.push_back(cushion_name(s.table, k));
    if (!shot.cushions.empty()) shot.cushion = shot.cushions.front();
    if (c.intermediate) shot.intermediate_ball = s.balls[*c.intermediate].id;
    shot.geometric_aim_deg = c.aim_deg;
    shot.cut_deg = c.cut_deg;
    shot.combination_cut_deg = c.combination_cut_deg;
    shot.aim_window_deg = {
        planner.window_edge(a, c, a.aim_deg, -1.0, 0.1, kAimWindowTolDeg, a.aim_deg - 20.0, set_aim, kAimWindowMostStepDeg),
        planner.window_edge(a, c, a.aim_deg, +1.0, 0.1, kAimWindowTolDeg, a.aim_deg + 20.0, set_aim, kAimWindowMostStepDeg)};
    // The window's middle: the most aim noise it can take either way.
    a.aim_deg = 0.5 * (shot.aim_window_deg[0] + shot.aim_window_deg[1]);
    shot.speed_window = {planner.window_edge(a, c, a.speed, -1.0, 0.25, kSpeedWindowTol, 0.05, set_speed),
                         planner.window_edge(a, c, a.speed, +1.0, 0.5, kSpeedWindowTol, kMaxCueSpeed, set_speed)};
    const CueStrike strike = to_strike(a, R);
    if (cue_obstructed(s.table, s.balls, cue_id, strike, ball)) {
      why = "the cue is obstructed at the corrected aim";
      return std::nullopt;
    }
    const Trial final_trial = planner.play(a, c);
    if (!final_trial.success) {
      why = "the corrected strike does not pot it";
      return std::nullopt;
    }
    shot.strike = a;
    const BallState after = strike_ball(strike, s.balls[cue].state.position, ball, s.cue_parameters);
    shot.ball_speed = norm(after.velocity);
    const Vec2 aim_dir{std::cos(strike.aim), std::sin(strike.aim)};
    const double topspin = dot(Vec2{after.angular_velocity.x, after.angular_velocity.y}, perp(aim_dir));
    shot.robot.tip_height = level_cue_tip_height(shot.ball_speed, topspin, ball);
    shot.robot.cue_speed = level_cue_speed(shot.ball_speed, shot.robot.tip_height, ball, s.cue_parameters);
    for (const BallTrajectory& b : final_trial.result.balls)
      shot.predicted.push_back({b.id, b.final_state.position, b.pocketed, b.pocketed ? b.pocket : -1});
    shot.window_probability = window_probability(shot, q.noise, ball, s.cue_parameters);
    return shot;
  };
  // Centre ball first; a scratch or a miss there tries draw, then follow (the
  // spin and speed variants come after the screen, step 4).
  const std::vector<double> heights = tip_heights(q);
  std::vector<std::size_t> feasible_of;  // the candidate of each feasible shot
  for (std::size_t ci = 0; ci < candidates.size(); ++ci) {
    const Candidate& c = candidates[ci];
    const std::string& what = c.what;
    if (planner.runs() > 0 && planner.runs() + kCandidateRuns > search_budget) {
      result.rejected.push_back(what + ": not searched (the simulation budget is spent)");
      continue;
    }
    const int runs_before = planner.runs();
    std::string why;
    std::optional<PlannedShot> shot;
    for (double height : heights) {
      try {
        shot = search(c, q.side, height, why);
      } catch (const BudgetSpent&) {
        why = "not finished (the simulation budget is spent)";
        break;
      }
      if (shot || (planner.runs() > 0 && planner.runs() + kCandidateRuns > search_budget)) break;
    }
    if (!shot) {
      result.rejected.push_back(what + ": " + why);
      continue;
    }
    shot->simulations = planner.runs() - runs_before;
    feasible.push_back(std::move(*shot));
    feasible_of.push_back(ci);
  }
  // 2b. The aim scan: pots that geometry misses or whose aim the secant
  // cannot solve (a ball on the rail sent along it, a side pocket that wants
  // the near jaw, a narrow path between two kisses).
  const bool scan_kinds = std::find(q.kinds.begin(), q.kinds.end(), ShotKind::direct) != q.kinds.end() ||
                          std::find(q.kinds.begin(), q.kinds.end(), ShotKind::bank) != q.kinds.end();
  const int scan_runs = kScanAims * static_cast<int>(kScanSpeeds.size());
  if (scan_kinds && planner.runs() + scan_runs + static_cast<int>(kScanCandidates) * kCandidateRuns <= q.simulations * 3 / 5) {
    int played = 0;
    const AimScan scan = scan_aims(s, cue, target, played);
    planner.count(played);
    // Runs into the pocket asked for, of a kind asked for, wider than the
    // aim window of any feasible shot of that kind into that pocket; the
    // widest first.
    std::size_t found = 0;
    for (const AimRun& r : scan.runs) {
      if (found == kScanCandidates) break;
      if (q.pocket && static_cast<std::size_t>(*q.pocket) != r.pocket) continue;
      const std::optional<double> elevation = clearing_elevation(s, cue, 0.5 * (r.first_aim + r.last_aim), 0.0, 0.0);
      if (!elevation) continue;
      if (planner.runs() >= q.simulations * 3 / 5) break;
      planner.count(1);
      const std::optional<ScannedCandidate> sc = scanned_candidate(s, cue, target, r, *elevation);
      if (!sc) continue;
      const Candidate& c = sc->candidate;
      if (std::find(q.kinds.begin(), q.kinds.end(), c.kind) == q.kinds.end() || c.cushions.size() > 2) continue;
      const bool known = std::any_of(feasible.begin(), feasible.end(), [&](const PlannedShot& f) {
        return f.kind == c.kind && f.pocket == static_cast<int>(r.pocket) && f.cushions.size() == c.cushions.size() &&
               f.aim_window_deg[1] - f.aim_window_deg[0] >= r.aims * scan.step_deg;
      });
      if (known) continue;
      ++found;
      if (!sc->has_legs) continue;
      candidates.push_back(c);
      const int runs_before = planner.runs();
      std::string why;
      std::optional<PlannedShot> shot;
      try {
        shot = search(candidates.back(), q.side, q.height.value_or(0.0), why, std::pair<double, double>{r.speed, c.aim_deg});
      } catch (const BudgetSpent&) {
        why = "not finished (the simulation budget is spent)";
      }
      if (!shot) {
        result.rejected.push_back(c.what + ": " + why);
        continue;
      }
      shot->simulations = planner.runs() - runs_before;
      feasible.push_back(std::move(*shot));
      feasible_of.push_back(candidates.size() - 1);
    }
  }
  result.simulations = planner.runs();
  if (feasible.empty()) {
    // A summary by reason first (the message is cut in the middle when long), then each.
    std::string why, summary;
    for (const std::string& r : result.rejected) why += (why.empty() ? "" : "; ") + r;
    const auto count = [&](const char* reason, const char* said) {
      std::size_t n = 0;
      for (const std::string& r : result.rejected) n += r.find(reason) != std::string::npos ? 1u : 0u;
      if (n > 0) summary += (summary.empty() ? "" : ", ") + std::to_string(n) + " " + said;
    };
    count("blocked", "blocked by a ball");
    count("deg > ", "cut too thin");
    count("bank point", "bank point off the cushion");
    count("the cushion at", "bank too shallow");
    count("obstructed", "cue obstructed");
    count("exact simulation", "no potting aim on the exact simulation");
    if (why.empty()) why = "no candidate of the requested kinds";
    throw NoFeasibleShot("no feasible shot pots ball " + std::to_string(q.target) + " (" +
                         std::to_string(result.rejected.size()) + " candidates" +
                         (summary.empty() ? "" : ": " + summary) + "): " + why);
  }

  // 4. Noise: every feasible candidate screened (common noise draws), the
  // best measured again on fresh draws.
  const auto successes = [&](const PlannedShot& shot, int shots, std::uint64_t first_shot) {
    return noisy_successes(s, q, cue_id, shot, shots, first_shot);
  };
  if (feasible.size() > kMaxScreened) {
    for (std::size_t i = kMaxScreened; i < feasible.size(); ++i)
      result.rejected.push_back(std::string(to_string(feasible[i].kind)) + " into " + feasible[i].pocket_name +
                                ": not screened (more than " + std::to_string(kMaxScreened) + " feasible)");
    feasible.resize(kMaxScreened);
    feasible_of.resize(kMaxScreened);
  }
  // Spin and speed under noise (header, step 4). Every feasible shot is
  // screened briefly (its alternatives' estimate); unless the request fixes
  // the tip height, the kVariantCandidates best by their window probability
  // are tried again at other tip heights, speeds and sides; the
  // kFinalists best of all by window probability (and the best by the brief
  // screen) are screened on the same draws, the best of them measured on
  // fresh draws.
  SearchedShots out;
  if (!o.noisy) {  // ranked by window probability, no noisy shot
    std::vector<std::size_t> order(feasible.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return feasible[a].window_probability > feasible[b].window_probability;
    });
    result.shot = feasible[order.front()];
    for (std::size_t k = 1; k < order.size(); ++k) result.alternatives.push_back(feasible[order[k]]);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.plan = std::move(result);
    return out;
  }
  const int budget = q.simulations;
  const int finalist_shots = std::min(kFinalistShots, budget / 15);
  const int final_reserve = budget / 5;
  const int base_screen =
      feasible.size() > 1 ? std::min(kBaseScreenShots, budget / (10 * static_cast<int>(feasible.size()))) : 0;
  int screened_shots = 0;
  const auto screen = [&](PlannedShot& shot, int shots) {
    set_estimate(shot, successes(shot, shots, kScreenFirstShot), shots);
    shot.simulations += shots;
    screened_shots += shots;
  };
  if (base_screen > 0)
    for (PlannedShot& shot : feasible) screen(shot, base_screen);
  std::vector<std::size_t> family(feasible.size());  // the feasible candidate each shot varies
  for (std::size_t i = 0; i < family.size(); ++i) family[i] = i;
  // Better first: the window probability in steps of kWindowStep, then the
  // brief screen's estimate.
  const auto by_window = [&](std::size_t a, std::size_t b) {
    const double wa = std::floor(feasible[a].window_probability / kWindowStep);
    const double wb = std::floor(feasible[b].window_probability / kWindowStep);
    if (wa != wb) return wa > wb;
    return feasible[a].success_probability > feasible[b].success_probability;
  };
  if (!q.height) {
    std::vector<std::size_t> order(feasible.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), by_window);
    const std::size_t variant_candidates = std::min(kVariantCandidates, order.size());
    // What the variants may spend: the finalists' screen and the final
    // estimate's reserve stay free.
    const int variant_cap =
        budget + o.variant_runs - final_reserve - static_cast<int>(kFinalists) * finalist_shots - screened_shots;
    bool spent = false;
    // One variant of feasible[base]: nullopt when it does not pot (or spent).
    const auto vary = [&](std::size_t base, double side, double height, double speed) -> std::optional<std::size_t> {
      if (spent) return std::nullopt;
      if (planner.runs() + kVariantRuns > variant_cap) {
        spent = true;
        return std::nullopt;
      }
      planner.limit(variant_cap);
      const std::size_t ci = feasible_of[family[base]];
      const int runs_before = planner.runs();
      std::string why;
      std::optional<PlannedShot> v;
      try {
        v = search(candidates[ci], side, height, why, std::pair<double, double>{speed, feasible[base].strike.aim_deg});
      } catch (const BudgetSpent&) {
        spent = true;
      }
      if (!v) return std::nullopt;
      v->simulations = planner.runs() - runs_before;
      feasible.push_back(std::move(*v));
      family.push_back(family[base]);
      return feasible.size() - 1;
    };
    // The speed of a variant at `factor` times the base's, kept 3 sigma of
    // speed noise inside the base's speed window; nullopt when that leaves
    // it too close to the base's own speed.
    const auto variant_speed = [&](const PlannedShot& b, double factor) -> std::optional<double> {
      double speed = b.strike.speed * factor;
      if (factor > 1.0) {
        speed = std::min(speed, b.speed_window[1] - 3.0 * q.noise.speed);
        if (speed < b.strike.speed * 1.2) return std::nullopt;
      } else if (factor < 1.0) {
        speed = std::max(speed, b.speed_window[0] + 3.0 * q.noise.speed);
        if (speed > b.strike.speed * 0.9) return std::nullopt;
      }
      return speed;
    };
    for (std::size_t r = 0; r < variant_candidates && !spent; ++r) {
      const std::size_t base = order[r];
      if (!o.vary_easy && feasible[base].window_probability >= kNothingToGain) continue;
      // Tip heights x speeds about the base.
      std::size_t best = base;
      double best_factor = 1.0;
      for (double height : o.variant_heights)
        for (double factor : o.variant_speeds) {
          if (height == feasible[base].strike.height && factor == 1.0) continue;
          const std::optional<double> speed = variant_speed(feasible[base], factor);
          if (!speed) continue;
          if (const std::optional<std::size_t> v = vary(base, feasible[base].strike.side, height, *speed);
              v && feasible[*v].window_probability > feasible[best].window_probability)
            best = *v, best_factor = factor;
        }
      // Further along the speed of the best, when it was at an end.
      if (best_factor != 1.0) {
        const double factor = best_factor < 1.0 ? o.variant_speeds.front() : o.variant_speeds.back();
        if (const std::optional<double> speed = variant_speed(feasible[best], factor))
          if (const std::optional<std::size_t> v = vary(best, feasible[best].strike.side, feasible[best].strike.height, *speed);
              v && feasible[*v].window_probability > feasible[best].window_probability)
            best = *v;
      }
      // Side spin at the best, unless the request gives the side.
      if (q.side == 0.0)
        for (double side : {-kVariantSide, kVariantSide})
          if (std::hypot(side, feasible[best].strike.height) <= kMiscueOffsetFraction)
            vary(best, side, feasible[best].strike.height, feasible[best].strike.speed);
    }
  }
  // The finalists: the best by window probability, and the best by the brief screen.
  std::vector<std::size_t> finalists(feasible.size());
  for (std::size_t i = 0; i < finalists.size(); ++i) finalists[i] = i;
  std::stable_sort(finalists.begin(), finalists.end(), by_window);
  if (finalists.size() > kFinalists) {
    const auto screened_best =
        std::max_element(finalists.begin(), finalists.end(), [&](std::size_t a, std::size_t b) {
          return feasible[a].noisy_shots > 0 && feasible[b].noisy_shots > 0
                     ? feasible[a].success_probability < feasible[b].success_probability
                     : feasible[a].noisy_shots < feasible[b].noisy_shots;
        });
    if (screened_best - finalists.begin() >= static_cast<std::ptrdiff_t>(kFinalists))
      std::swap(finalists[kFinalists - 1], *screened_best);
    finalists.resize(kFinalists);
  }
  std::size_t chosen = finalists.front();
  if (finalists.size() > 1 && finalist_shots > 0) {
    for (std::size_t i : finalists) screen(feasible[i], finalist_shots);
    for (std::size_t i : finalists) {
      const PlannedShot& a = feasible[i];
      const PlannedShot& b = feasible[chosen];
      if (a.success_probability > b.success_probability ||
          (a.success_probability == b.success_probability && a.window_probability > b.window_probability))
        chosen = i;
    }
  }
  result.simulations = planner.runs() + screened_shots;
  const int final_shots = std::max(1, budget - result.simulations);
  if (o.keep_every) out.every = feasible;
  PlannedShot& best = feasible[chosen];
  set_estimate(best, successes(best, final_shots, 0), final_shots);
  best.simulations += final_shots;
  result.simulations += final_shots;
  result.shot = std::move(best);
  // Best first: the screened probability (of the most shots screened), then the window's.
  std::vector<std::size_t> rest;
  for (std::size_t i = 0; i < feasible.size(); ++i)
    if (i != chosen) rest.push_back(i);
  std::stable_sort(rest.begin(), rest.end(), [&](std::size_t a, std::size_t b) {
    if (feasible[a].success_probability != feasible[b].success_probability)
      return feasible[a].success_probability > feasible[b].success_probability;
    return feasible[a].window_probability > feasible[b].window_probability;
  });
  // The alternatives: the best variant (tip height, speed, side) of each
  // other shot, a shot being its kind, pocket, cushions and intermediate ball.
  const auto same_shot = [](const PlannedShot& a, const PlannedShot& b) {
    return a.kind == b.kind && a.pocket == b.pocket && a.cushions == b.cushions &&
           a.intermediate_ball == b.intermediate_ball;
  };
  for (std::size_t i : rest) {
    const bool shown = same_shot(feasible[i], result.shot) ||
                       std::any_of(result.alternatives.begin(), result.alternatives.end(),
                                   [&](const PlannedShot& a) { return same_shot(a, feasible[i]); });
    if (!shown) result.alternatives.push_back(std::move(feasible[i]));
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.plan = std::move(result);
  return out;
}

}  // namespace cueball
