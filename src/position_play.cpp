// Position play: a one-shot lookahead over plan_shot(); see position_play.hpp.
#include "cueball/position_play.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "cueball/errors.hpp"

namespace cueball {

namespace {

bool has_ball(const Scenario& s, int id) {
  return std::any_of(s.balls.begin(), s.balls.end(), [&](const SimulationBall& b) { return b.id == id; });
}

// The next target when none is given: the lowest id other than the cue ball and the target; -1 when none.
int default_next_target(const Scenario& s, int cue_ball, int target) {
  int next = -1;
  for (const SimulationBall& b : s.balls)
    if (b.id != cue_ball && b.id != target && (next < 0 || b.id < next)) next = b.id;
  return next;
}

// A candidate and the plan that produced it.
struct Candidate {
  PlannedShot shot;
  Leave leave;
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
    result.next_target = default_next_target(s, cue_id, q.shot.target);
  }

  // The free plan (its spin, speed and side variants) first, then centre
  // ball, draw and follow; the request's tip height alone when it gives one.
  const std::vector<std::optional<double>> heights =
      q.shot.height ? std::vector<std::optional<double>>{*q.shot.height}
                    : std::vector<std::optional<double>>{std::nullopt, 0.0, -0.3, 0.3};
  std::vector<Candidate> candidates;
  int simulations = 0;
  std::optional<NoFeasibleShot> infeasible;
  for (const std::optional<double>& height : heights) {
    PlanRequest at_height = q.shot;
    at_height.height = height;
    try {
      ShotPlanResult plan = plan_shot(s, at_height);
      simulations += plan.simulations;
      if (candidates.empty()) result.plan.rejected = plan.rejected;
      candidates.push_back({std::move(plan.shot), {}});
      for (PlannedShot& alt : plan.alternatives) candidates.push_back({std::move(alt), {}});
    } catch (const NoFeasibleShot& e) {
      if (!infeasible) infeasible.emplace(e);
    }
  }
  if (candidates.empty()) throw *infeasible;
  result.plan.cue_ball = cue_id;

  // Best first by this shot's own probability; the weak ones dropped.
  std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.shot.success_probability > b.shot.success_probability;
  });
  const double best_p = candidates.front().shot.success_probability;
  std::size_t kept = 1;
  while (kept < candidates.size() && kept < kMaxPositionCandidates &&
         candidates[kept].shot.success_probability >= kPositionKeepFraction * best_p)
    ++kept;
  candidates.resize(kept);

  for (Candidate& c : candidates) {
    const auto cue_end = std::find_if(c.shot.predicted.begin(), c.shot.predicted.end(),
                                      [&](const PredictedBall& p) { return p.id == cue_id; });
    c.leave.cue_ball = cue_end->position;
    if (result.next_target < 0) {
      c.leave.score = c.shot.success_probability;
      continue;
    }
    const Scenario left = table_left_by(s, c.shot);
    if (!has_ball(left, result.next_target)) {  // the next ball went down too: scored as if there were none
      c.leave.score = c.shot.success_probability;
      continue;
    }
    PlanRequest next = q.shot;
    next.cue_ball = cue_id;
    next.target = result.next_target;
    next.pocket.reset();
    next.simulations = q.next_simulations;
    try {
      const ShotPlanResult n = plan_shot(left, next);
      simulations += n.simulations;
      c.leave.next_feasible = true;
      c.leave.next_success_probability = n.shot.success_probability;
      c.leave.next_kind = to_string(n.shot.kind);
      c.leave.next_pocket = n.shot.pocket_name;
    } catch (const NoFeasibleShot&) {
      simulations += q.next_simulations;  // counted at its budget (the error does not say what it spent)
    }
    c.leave.score = c.shot.success_probability * c.leave.next_success_probability;
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.leave.score > b.leave.score; });

  result.plan.shot = std::move(candidates.front().shot);
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
