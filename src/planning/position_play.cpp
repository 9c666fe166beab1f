// Position play: a one-shot lookahead over plan_shot(); see position_play.hpp.
#include "cueball/planning/position_play.hpp"

#include <algorithm>
#include <chrono>
#include <initializer_list>
#include <string>
#include <utility>

#include "cueball/core/errors.hpp"
#include "planning/shot_search.hpp"

namespace cueball {

namespace {

bool has_ball(const Scenario& s, int id) {
  return std::any_of(s.balls.begin(), s.balls.end(), [&](const SimulationBall& b) { return b.id == id; });
}

// The lowest id on the table other than those of `except` (9-ball's next
// ball); -1 when none.
int lowest_ball(const Scenario& s, std::initializer_list<int> except) {
  int next = -1;
  for (const SimulationBall& b : s.balls)
    if (std::find(except.begin(), except.end(), b.id) == except.end() && (next < 0 || b.id < next)) next = b.id;
  return next;
}

// A candidate shot, the table it leaves and its leave's scores.
struct Candidate {
  PlannedShot shot;
  Leave leave;
  Scenario left;
  int next_id = -1;          // the ball planned next on the table it leaves; -1: none left
  double next_window = 0.0;  // the best next shot's window probability (1: no ball left)
};

}  // namespace

Scenario table_left_by(const Scenario& table_state, const PlannedShot& shot) {
  Scenario left = table_state;
  left.cue.reset();
  left.balls.clear();
  for (const SimulationBall& b : table_state.balls) {
    const auto it = std::find_if(shot.predicted.begin(), shot.predicted.end(),
                                 [&](const PredictedBall& p) { return p.id == b.id; });
    if (it == shot.predicted.end() || it->pocketed) continue;
    SimulationBall at_rest = b;
    at_rest.state = BallState{};
    at_rest.state.position = it->position;
    left.balls.push_back(std::move(at_rest));
  }
  return left;
}

PositionPlanResult plan_shot_for_position(const Scenario& table_state, const PositionRequest& q) {
  const auto start = std::chrono::steady_clock::now();
  const Scenario& s = table_state;
  if (q.next_simulations < kMinPlanSimulations || q.next_simulations > kMaxPlanSimulations)
    throw InvalidArgument("next_simulations", static_cast<double>(q.next_simulations),
                          "[" + std::to_string(kMinPlanSimulations) + ", " + std::to_string(kMaxPlanSimulations) + "]",
                          "engine runs of each next-shot plan");
  PositionPlanResult result;
  // The cue ball as plan_shot() takes it (which checks it, the target and the rest).
  const int cue_id = q.shot.cue_ball ? *q.shot.cue_ball : s.cue ? s.cue->ball : 0;
  if (q.next_target) {
    const int next = *q.next_target;
    if (!has_ball(s, next))
      throw InvalidArgument("next", "next = " + std::to_string(next) + " is not the id of a ball on the table");
    if (next == cue_id || next == q.shot.target)
      throw InvalidArgument("next", "next = " + std::to_string(next) + " is the " +
                                        (next == cue_id ? "cue ball" : "target") + "; choose another ball");
    result.next_target = next;
  } else {
    result.next_target = lowest_ball(s, {cue_id, q.shot.target});
  }

  PlanRequest next = q.shot;
  next.cue_ball = cue_id;
  next.target = result.next_target;
  next.pocket.reset();
  next.simulations = q.next_simulations;

  // 1. The shot planned with the wide variant search: every feasible shot
  // and variant is a candidate leave.
  ShotSearch wide;
  wide.variant_heights = {kPositionHeights.begin(), kPositionHeights.end()};
  wide.variant_speeds = {kPositionSpeedFactors.begin(), kPositionSpeedFactors.end()};
  wide.vary_easy = true;
  wide.keep_every = true;
  wide.variant_runs = kPositionVariantBudgets * q.shot.simulations;
  if (result.next_target < 0) wide = ShotSearch{};  // no lookahead: plan_shot()'s own plan
  SearchedShots found = search_shots(s, q.shot, wide);
  int simulations = found.plan.simulations;
  if (result.next_target < 0) {
    result.plan = std::move(found.plan);
    const auto cue_end = std::find_if(result.plan.shot.predicted.begin(), result.plan.shot.predicted.end(),
                                      [&](const PredictedBall& p) { return p.id == cue_id; });
    result.leave.cue_ball = cue_end->position;
    result.leave.screened_probability = result.plan.shot.success_probability;
    result.leave.score = result.plan.shot.success_probability;
    result.plan.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }
  result.plan.rejected = std::move(found.plan.rejected);
  result.plan.cue_ball = cue_id;

  // 2. The leaves scored by window probabilities alone (no noisy shot): this
  // shot's, times the best next shot's on the table it leaves.
  std::vector<Candidate> candidates;
  double best_window = 0.0;
  for (const PlannedShot& shot : found.every) best_window = std::max(best_window, shot.window_probability);
  for (PlannedShot& shot : found.every) {
    const bool known = std::any_of(candidates.begin(), candidates.end(),
                                   [&](const Candidate& c) { return c.shot.strike == shot.strike; });
    if (!known && shot.window_probability >= kPositionKeepFraction * best_window)
      candidates.push_back({std::move(shot), {}, {}, -1, 0.0});
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.shot.window_probability > b.shot.window_probability;
  });
  if (candidates.size() > kPositionLeaves) candidates.resize(kPositionLeaves);
  ShotSearch windows_only;
  windows_only.noisy = false;
  for (Candidate& c : candidates) {
    const auto cue_end = std::find_if(c.shot.predicted.begin(), c.shot.predicted.end(),
                                      [&](const PredictedBall& p) { return p.id == cue_id; });
    c.leave.cue_ball = cue_end->position;
    c.left = table_left_by(s, c.shot);
    // The next target, or when the shot pots it too, the lowest ball left
    // (9-ball's rule); none left: nothing to score.
    PlanRequest n = next;
    n.target = has_ball(c.left, result.next_target) ? result.next_target : lowest_ball(c.left, {cue_id});
    c.next_id = n.target;
    c.next_window = 1.0;
    if (n.target < 0) continue;
    c.next_window = 0.0;
    try {
      const SearchedShots w = search_shots(c.left, n, windows_only);
      simulations += w.plan.simulations;
      c.next_window = w.plan.shot.window_probability;
    } catch (const NoFeasibleShot&) {
      simulations += q.next_simulations;  // counted at its budget (the error does not say what it spent)
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.shot.window_probability * a.next_window > b.shot.window_probability * b.next_window;
  });
  if (candidates.size() > kMaxPositionCandidates) candidates.resize(kMaxPositionCandidates);

  // 3. The finalists: each shot screened on the same noisy draws, the next
  // shot planned in full on the table it leaves.
  const int screen_shots = std::max(1, q.shot.simulations / kPositionScreenFraction);
  for (Candidate& c : candidates) {
    set_estimate(c.shot, noisy_successes(s, q.shot, cue_id, c.shot, screen_shots, kScreenFirstShot), screen_shots);
    c.shot.simulations += screen_shots;
    c.leave.screened_probability = c.shot.success_probability;
    simulations += screen_shots;
    if (c.next_id < 0) {
      c.leave.score = c.leave.screened_probability;
      continue;
    }
    try {
      PlanRequest after = next;
      after.target = c.next_id;
      const ShotPlanResult n = plan_shot(c.left, after);
      simulations += n.simulations;
      c.leave.next_feasible = true;
      c.leave.next_success_probability = n.shot.success_probability;
      c.leave.next_kind = to_string(n.shot.kind);
      c.leave.next_pocket = n.shot.pocket_name;
    } catch (const NoFeasibleShot&) {
      simulations += q.next_simulations;
    }
    c.leave.score = c.leave.screened_probability * c.leave.next_success_probability;
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.leave.score > b.leave.score; });

  // 4. The one played measured on fresh draws (those plan_shot()'s final
  // estimate takes), so its estimate carries no selection bias.
  PlannedShot& played = candidates.front().shot;
  const int final_shots = std::max(1, q.shot.simulations / kPositionEstimateFraction);
  set_estimate(played, noisy_successes(s, q.shot, cue_id, played, final_shots, 0), final_shots);
  played.simulations += final_shots;
  simulations += final_shots;

  result.plan.shot = std::move(played);
  result.leave = candidates.front().leave;
  for (std::size_t k = 1; k < candidates.size(); ++k) {
    result.plan.alternatives.push_back(std::move(candidates[k].shot));
    result.alternative_leaves.push_back(candidates[k].leave);
  }
  result.plan.simulations = simulations;
  result.plan.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace cueball
