// Step 2b of the shot planner (shot_planner.hpp): the aim scan, the pots
// that geometry misses or whose aim the secant cannot solve (a ball on the
// rail sent along it, a side pocket that wants the near jaw, a narrow path
// between two kisses).
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "planning/search_state.hpp"

namespace cueball::planning {

namespace {

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

// The scan's aims, each at its clearing elevation; an obstructed aim kept
// unplayed (a NaN speed), so that the runs stay in order.
std::vector<ShotAction> scan_actions(const Scenario& s, std::size_t cue, double centre, double half) {
  std::vector<ShotAction> actions;
  for (double speed : kScanSpeeds)
    for (int i = 0; i < kScanAims; ++i) {
      const double aim = centre - half + (i + 0.5) * 2.0 * half / kScanAims;
      const std::optional<double> elevation = clearing_elevation(s, cue, aim, 0.0, 0.0);
      actions.push_back({elevation ? speed : kNaN, aim, elevation.value_or(0.0), 0.0, 0.0});
    }
  return actions;
}

// The runs of neighbouring potting aims in the batch `m` of the played
// (finite-speed) `actions`, in scan order.
std::vector<AimRun> potting_runs(const Scenario& s, std::size_t cue, std::size_t target,
                                 const std::vector<ShotAction>& actions, const ManyResult& m) {
  std::vector<AimRun> runs;
  const auto n = static_cast<std::size_t>(m.balls);
  std::size_t k = 0;
  bool extends = false;
  for (const ShotAction& a : actions) {
    if (!std::isfinite(a.speed)) {
      extends = false;
      continue;
    }
    const std::size_t row = k++;
    const bool pots = !m.failure[row] && pots_target(m.first_contact[row], s.balls[target].id,
                                                     m.pocket[row * n + target], std::nullopt, m.pocketed[row * n + cue]);
    if (!pots) {
      extends = false;
      continue;
    }
    const auto pocket = static_cast<std::size_t>(m.pocket[row * n + target]);
    const int cushions = m.cushions[row * n + target];
    if (extends && runs.back().pocket == pocket && runs.back().cushions == cushions && runs.back().speed == a.speed) {
      runs.back().last_aim = a.aim_deg;
      ++runs.back().aims;
    } else {
      runs.push_back({pocket, cushions, a.speed, a.aim_deg, a.aim_deg, 1});
    }
    extends = true;
  }
  return runs;
}

// The scan's batch and its runs; `played`: its engine runs.
AimScan scan_aims(const Scenario& s, std::size_t cue, std::size_t target, int& played) {
  const double R = s.settings.parameters.ball.radius;
  const Vec2 C = s.balls[cue].state.position, O = s.balls[target].state.position;
  const double half = std::asin(std::min(1.0, 2.0 * R / norm(O - C))) / kDegree;
  const std::vector<ShotAction> actions = scan_actions(s, cue, angle_deg(O - C), half);
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
  out.runs = potting_runs(s, cue, target, actions, m);
  std::stable_sort(out.runs.begin(), out.runs.end(), [](const AimRun& a, const AimRun& b) { return a.aims > b.aims; });
  return out;
}

// A run's candidate: its middle aim played once in full (one engine run, at
// `elevation`), the target a bank when it meets a rail (a cushion long enough
// to bank off, not a pocket's facing) before it drops; nullopt when that
// play fails or does not pot. has_legs: its first and last legs have a
// direction (the last leg and the cut are then set). `ball` begins its
// description ("ball <id>: " with several targets).
struct ScannedCandidate {
  Candidate candidate;
  bool has_legs = false;
};

std::optional<ScannedCandidate> scanned_candidate(const Scenario& s, std::size_t cue, std::size_t target, const AimRun& r,
                                                  double elevation, const std::string& ball) {
  const double R = s.settings.parameters.ball.radius;
  ScannedCandidate out;
  Candidate& c = out.candidate;
  c.target = target;
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
  c.what = ball + to_string(c.kind) + " into " + s.table.pockets[r.pocket].name;
  for (std::size_t i = 0; i < c.cushions.size(); ++i)
    c.what += (i == 0 ? " off " : ", then ") + cushion_name(s.table, c.cushions[i]);
  c.what += " (found by the aim scan)";
  return out;
}

// Whether a feasible shot of the run's kind into its pocket, with as many
// cushions, already has an aim window at least as wide as the run.
bool known_from_geometry(const SearchState& st, const Candidate& c, const AimRun& r, double step_deg) {
  return std::any_of(st.feasible.begin(), st.feasible.end(), [&](const PlannedShot& f) {
    return f.target == st.s.balls[c.target].id && f.kind == c.kind && f.pocket == static_cast<int>(r.pocket) &&
           f.cushions.size() == c.cushions.size() && f.aim_window_deg[1] - f.aim_window_deg[0] >= r.aims * step_deg;
  });
}

// The scanned candidate searched at the run's speed from its middle aim.
void search_scanned(SearchState& st, const Candidate& c, const AimRun& r) {
  st.candidates.push_back(c);
  const int runs_before = st.trials.runs();
  std::string why;
  std::optional<PlannedShot> shot;
  try {
    shot = search_candidate(st, st.candidates.back(), st.q.side, st.q.height.value_or(0.0), why,
                            std::pair<double, double>{r.speed, c.aim_deg});
  } catch (const BudgetSpent&) {
    why = "not finished (the simulation budget is spent)";
  }
  if (!shot) {
    st.result.rejected.push_back(c.what + ": " + why);
    return;
  }
  shot->simulations = st.trials.runs() - runs_before;
  st.feasible.push_back(std::move(*shot));
  st.feasible_of.push_back(st.candidates.size() - 1);
}

// One target's scan: runs into the pocket asked for, of a kind asked for,
// wider than the aim window of any feasible shot of that kind into that
// pocket; the widest first.
void scan_target(SearchState& st, std::size_t target) {
  const Scenario& s = st.s;
  const PlanRequest& q = st.q;
  int played = 0;
  const AimScan scan = scan_aims(s, st.cue, target, played);
  st.trials.count(played);
  std::size_t found = 0;
  for (const AimRun& r : scan.runs) {
    if (found == kScanCandidates) break;
    if (q.pocket && static_cast<std::size_t>(*q.pocket) != r.pocket) continue;
    const std::optional<double> elevation = clearing_elevation(s, st.cue, 0.5 * (r.first_aim + r.last_aim), 0.0, 0.0);
    if (!elevation) continue;
    if (st.trials.runs() >= q.simulations * 3 / 5) break;
    st.trials.count(1);
    const std::optional<ScannedCandidate> sc = scanned_candidate(
        s, st.cue, target, r, *elevation, st.targets.size() > 1 ? "ball " + std::to_string(s.balls[target].id) + ": " : "");
    if (!sc) continue;
    const Candidate& c = sc->candidate;
    if (std::find(q.kinds.begin(), q.kinds.end(), c.kind) == q.kinds.end() || c.cushions.size() > 2) continue;
    if (known_from_geometry(st, c, r, scan.step_deg)) continue;
    ++found;
    if (!sc->has_legs) continue;
    search_scanned(st, c, r);
  }
}

}  // namespace

void scan_for_candidates(SearchState& st) {
  const PlanRequest& q = st.q;
  const bool scan_kinds = std::find(q.kinds.begin(), q.kinds.end(), ShotKind::direct) != q.kinds.end() ||
                          std::find(q.kinds.begin(), q.kinds.end(), ShotKind::bank) != q.kinds.end();
  if (!scan_kinds) return;
  const int scan_runs = kScanAims * static_cast<int>(kScanSpeeds.size());
  for (std::size_t target : st.targets)
    if (kind_allowed(st.s, q, target, ShotKind::direct) &&
        st.trials.runs() + scan_runs + static_cast<int>(kScanCandidates) * kCandidateRuns <= q.simulations * 3 / 5)
      scan_target(st, target);
}

}  // namespace cueball::planning
