// Step 3 of the shot planner (shot_planner.hpp), per candidate: the first
// speed from geometry, the aim solved on the exact simulation, the speed
// chosen, the aim and speed windows found, and the planned shot read from
// the corrected strike.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "cueball/core/errors.hpp"
#include "planning/search_state.hpp"

namespace cueball::planning {

namespace {

// First speed: the object ball arriving at about kArrivalSpeed, rolling
// (5/7 of its speed kept after sliding), 95 % of the striking ball's
// speed along the line of centres passed on, each cushion losing a
// quarter (the object ball's of a bank, the cue ball's of a kick); a
// combination's ball A is the target's striking ball. The cue ball's speed
// just after the strike, m/s.
double first_ball_speed(const Candidate& c, double roll) {
  const double object_cushions = c.kind == ShotKind::bank ? static_cast<double>(c.cushions.size()) : 0.0;
  double v_object = 1.4 * std::sqrt(kArrivalSpeed * kArrivalSpeed + 2.0 * roll * c.object_path) /
                    std::pow(0.75, object_cushions);
  if (c.kind == ShotKind::combination) {
    const double v_middle = v_object / (0.95 * std::cos(c.combination_cut_deg * kDegree));
    v_object = 1.4 * std::sqrt(v_middle * v_middle + 2.0 * roll * c.middle_path);
  }
  const double v_cue = v_object / (0.95 * std::cos(c.cut_deg * kDegree));
  return 1.2 * std::sqrt(v_cue * v_cue + 2.0 * roll * c.cue_path) / (c.kind == ShotKind::kick ? 0.75 : 1.0);
}

// Solve aim: from the geometric aim at the first speed (a too-short shot
// tried again 1.6 times faster, up to four times), or for a variant from
// its fixed speed and starting aim. False and `why` when no aim pots.
bool solve_first_aim(ExactTrials& trials, ShotAction& a, const Candidate& c,
                     const std::optional<std::pair<double, double>>& fixed, std::string& why) {
  std::optional<double> aim;
  if (fixed) {
    a.speed = std::clamp(fixed->first, 0.3, kMaxCueSpeed);
    a.aim_deg = fixed->second;
    bool short_of_pocket = false;
    aim = trials.solve_aim(a, c, short_of_pocket, 8);
    if (!aim) {
      why = "no aim pots it at this speed and spin";
      return false;
    }
    a.aim_deg = wrapped_deg(*aim);
  }
  for (int tries = 0; tries < 4 && !aim; ++tries) {
    bool short_of_pocket = false;
    aim = trials.solve_aim(a, c, short_of_pocket, 12);
    if (!aim && !short_of_pocket) break;
    if (!aim) a.speed = std::min(kMaxCueSpeed, a.speed * 1.6);
  }
  if (!aim) {
    why = "no aim pots it on the exact simulation";
    return false;
  }
  a.aim_deg = wrapped_deg(*aim);
  return true;
}

// Choose speed: a margin above the slowest pot (speed noise and the
// roll-off near the pocket), at most the speed window's middle; the aim
// solved again at that speed. A variant keeps its speed. False and `why`
// when no aim pots at the chosen speed.
bool choose_speed(SearchState& st, ShotAction& a, const Candidate& c, bool fixed, std::string& why) {
  ExactTrials& trials = st.trials;
  const double slowest =
      fixed ? 0.0 : trials.window_edge(a, c, WindowAxis::speed, a.speed, -1.0, 0.25, kSpeedWindowTol, 0.05);
  const double fastest =
      fixed ? 0.0 : trials.window_edge(a, c, WindowAxis::speed, a.speed, +1.0, 0.5, kSpeedWindowTol, kMaxCueSpeed);
  const double margin = std::max(0.3, 0.25 * slowest) + 3.0 * st.q.noise.speed;
  const double chosen = fixed ? a.speed : std::min(std::max(a.speed, slowest + margin), 0.5 * (slowest + fastest));
  if (chosen == a.speed) return true;
  a.speed = chosen;
  bool short_of_pocket = false;
  const std::optional<double> aim = trials.solve_aim(a, c, short_of_pocket, 8);
  if (!aim) {
    why = "no aim pots it at the chosen speed";
    return false;
  }
  a.aim_deg = wrapped_deg(*aim);
  return true;
}

// Windows: the aims that pot (the rest held), each edge to
// kAimWindowTolDeg; the aim played is the window's middle, the most aim
// noise it can take either way; the speed window is found at that aim.
void find_windows(ExactTrials& trials, ShotAction& a, const Candidate& c, PlannedShot& shot) {
  shot.aim_window_deg = {trials.window_edge(a, c, WindowAxis::aim, a.aim_deg, -1.0, 0.1, kAimWindowTolDeg,
                                            a.aim_deg - 20.0, kAimWindowMostStepDeg),
                         trials.window_edge(a, c, WindowAxis::aim, a.aim_deg, +1.0, 0.1, kAimWindowTolDeg,
                                            a.aim_deg + 20.0, kAimWindowMostStepDeg)};
  a.aim_deg = 0.5 * (shot.aim_window_deg[0] + shot.aim_window_deg[1]);
  shot.speed_window = {trials.window_edge(a, c, WindowAxis::speed, a.speed, -1.0, 0.25, kSpeedWindowTol, 0.05),
                       trials.window_edge(a, c, WindowAxis::speed, a.speed, +1.0, 0.5, kSpeedWindowTol, kMaxCueSpeed)};
}

// What geometry says of the shot: its kind, pocket, cushions, ball A and cuts.
PlannedShot shot_of(const Scenario& s, const Candidate& c) {
  PlannedShot shot;
  shot.kind = c.kind;
  shot.target = s.balls[c.target].id;
  shot.pocket = static_cast<int>(c.pocket);
  shot.pocket_name = s.table.pockets[c.pocket].name;
  for (std::size_t k : c.cushions) shot.cushions.push_back(cushion_name(s.table, k));
  if (!shot.cushions.empty()) shot.cushion = shot.cushions.front();
  if (c.intermediate) shot.intermediate_ball = s.balls[*c.intermediate].id;
  shot.geometric_aim_deg = c.aim_deg;
  shot.cut_deg = c.cut_deg;
  shot.combination_cut_deg = c.combination_cut_deg;
  return shot;
}

// The corrected strike (its cue clear: clear_the_cue()) played once more:
// the cue ball's speed, the robot's form, every ball's end and the window
// probability. False and `why` when the strike does not pot.
bool finish_shot(SearchState& st, const ShotAction& a, const Candidate& c, PlannedShot& shot, std::string& why) {
  const Scenario& s = st.s;
  const BallParameters& ball = s.settings.parameters.ball;
  const CueStrike strike = to_strike(a, ball.radius);
  const Trial final_trial = st.trials.play(a, c);
  if (!final_trial.success) {
    why = "the corrected strike does not pot it";
    return false;
  }
  shot.strike = a;
  const BallState after = strike_ball(strike, s.balls[st.cue].state.position, ball, s.cue_parameters);
  shot.ball_speed = norm(after.velocity);
  const Vec2 aim_dir{std::cos(strike.aim), std::sin(strike.aim)};
  const double topspin = dot(Vec2{after.angular_velocity.x, after.angular_velocity.y}, perp(aim_dir));
  shot.robot.tip_height = level_cue_tip_height(shot.ball_speed, topspin, ball);
  shot.robot.cue_speed = level_cue_speed(shot.ball_speed, shot.robot.tip_height, ball, s.cue_parameters);
  for (const BallTrajectory& b : final_trial.result.balls)
    shot.predicted.push_back({b.id, b.final_state.position, b.pocketed, b.pocketed ? b.pocket : -1});
  shot.window_probability = window_probability(shot, st.q.noise, ball, s.cue_parameters);
  return true;
}

// The cue clear at the corrected aim. Where the aim correction turned it
// into a ball or the rail (the elevation was chosen at the first aim): the
// lowest elevation that clears it there, the aim solved again and the
// windows found anew, and the cue checked once more at the aim that gives.
// False and `why` when it stays obstructed or no aim pots at that elevation.
bool clear_the_cue(SearchState& st, ShotAction& a, const Candidate& c, PlannedShot& shot, std::string& why) {
  const Scenario& s = st.s;
  const BallParameters& ball = s.settings.parameters.ball;
  const auto obstructed = [&] {
    return cue_obstructed(s.table, s.balls, s.balls[st.cue].id, to_strike(a, ball.radius), ball);
  };
  if (!obstructed()) return true;
  why = "the cue is obstructed at the corrected aim";
  const std::optional<double> elevation = clearing_elevation(s, st.cue, a.aim_deg, a.side, a.height);
  if (!elevation || *elevation <= a.elevation_deg) return false;
  a.elevation_deg = *elevation;
  bool short_of_pocket = false;
  const std::optional<double> aim = st.trials.solve_aim(a, c, short_of_pocket, 8);
  if (!aim) {
    why += ", and no aim pots at the elevation that clears it";
    return false;
  }
  a.aim_deg = wrapped_deg(*aim);
  find_windows(st.trials, a, c, shot);
  return !obstructed();
}

// Whether a new candidate's search would take the search past its budget.
bool search_budget_spent(const SearchState& st) {
  return st.trials.runs() > 0 && st.trials.runs() + kCandidateRuns > st.search_budget();
}

}  // namespace

std::optional<PlannedShot> search_candidate(SearchState& st, const Candidate& c, double side, double height,
                                            std::string& why, std::optional<std::pair<double, double>> fixed) {
  const Scenario& s = st.s;
  const Parameters& par = s.settings.parameters;
  const double roll = par.cloth.rolling_resistance * par.cloth.gravity;
  const double cue_speed_of = level_cue_speed(first_ball_speed(c, roll), height * par.ball.radius, par.ball,
                                              s.cue_parameters);
  const std::optional<double> elevation = clearing_elevation(s, st.cue, c.aim_deg, side, height);
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
  if (!solve_first_aim(st.trials, a, c, fixed, why)) return std::nullopt;
  if (!choose_speed(st, a, c, fixed.has_value(), why)) return std::nullopt;
  PlannedShot shot = shot_of(s, c);
  find_windows(st.trials, a, c, shot);
  if (!clear_the_cue(st, a, c, shot, why)) return std::nullopt;
  if (!finish_shot(st, a, c, shot, why)) return std::nullopt;
  return shot;
}

void search_candidates(SearchState& st) {
  // Centre ball first; a scratch or a miss there tries draw, then follow (the
  // spin and speed variants come after the screen, step 4).
  const std::vector<double> heights = tip_heights(st.q);
  for (std::size_t ci = 0; ci < st.candidates.size(); ++ci) {
    const Candidate& c = st.candidates[ci];
    if (search_budget_spent(st)) {
      st.result.rejected.push_back(c.what + ": not searched (the simulation budget is spent)");
      continue;
    }
    const int runs_before = st.trials.runs();
    std::string why;
    std::optional<PlannedShot> shot;
    for (double height : heights) {
      try {
        shot = search_candidate(st, c, st.q.side, height, why);
      } catch (const BudgetSpent&) {
        why = "not finished (the simulation budget is spent)";
        break;
      }
      if (shot || search_budget_spent(st)) break;
    }
    if (!shot) {
      st.result.rejected.push_back(c.what + ": " + why);
      continue;
    }
    shot->simulations = st.trials.runs() - runs_before;
    st.feasible.push_back(std::move(*shot));
    st.feasible_of.push_back(ci);
  }
}

}  // namespace cueball::planning
