// Position play (issue 13, item 2): among the shots that pot the target,
// prefer the one that leaves the cue ball where the next target has the
// highest success probability. A one-shot lookahead over plan_shot():
//
//   1. The shot is planned freely (plan_shot()'s own spin, speed and side
//      variants) and at each tip height (centre ball, draw -0.3, follow +0.3
//      ball radii); only at the request's when it gives one: each plan_shot()
//      call returns its best shot and its ranked alternatives, every one with
//      the noise-free end of every ball (PlannedShot::predicted).
//   2. For each of those candidates (those whose success probability is at
//      least kPositionKeepFraction of the best's, at most kMaxPositionCandidates,
//      best first), the table it leaves is built: the balls not pocketed, at
//      rest where the noise-free shot leaves them, and the next target's
//      shot is planned on it with plan_shot() (the same kinds and noise,
//      `next_simulations` engine runs). A next shot with no feasible candidate
//      scores 0.
//   3. The candidate played maximises P(this pot) x P(next pot), the
//      probability of potting both under the noise (each estimated from
//      noisy simulations; the product treats them as independent and takes
//      the next shot from the noise-free leave: a one-shot lookahead, as in
//      the computational-pool tournament programs' first level of search:
//      M. Smith, "PickPocket: A computer billiards shark", Artificial
//      Intelligence 171 (2007) 1069-1091).
//
// The leave's quality is measured on the exact simulation and the real
// planner, so it includes what the next shot needs (its cut, distance,
// blockers and the cue's clearance), not a distance heuristic. Paper 001's
// inverse problem (a ball stopping at a planned point) is not used: the cue
// ball's end after a collision is not a straight roll from the strike, so
// the leave is read from the simulation instead.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cueball/shot_planner.hpp"

namespace cueball {

/// Candidates weaker than this fraction of the best success probability are not played for position.
inline constexpr double kPositionKeepFraction = 0.5;
/// Most candidates whose leave is evaluated.
inline constexpr std::size_t kMaxPositionCandidates = 8;

struct PositionRequest {
  PlanRequest shot;  ///< the shot that pots shot.target; its `simulations` is each plan's budget
  /// Id of the next target. None: the lowest id on the table other than the
  /// cue ball and the target (9-ball's rule); with no such ball there is no
  /// lookahead and the shot is plan_shot()'s.
  std::optional<int> next_target;
  /// Engine runs of each next-shot plan, [kMinPlanSimulations, kMaxPlanSimulations].
  int next_simulations = kMinPlanSimulations;
};

/// What a candidate leaves for the next shot.
struct Leave {
  Vec2 cue_ball;                           ///< where the noise-free shot leaves the cue ball, m
  bool next_feasible = false;              ///< the next shot has a feasible candidate
  double next_success_probability = 0.0;   ///< of the next shot's plan from there (0 when infeasible)
  std::string next_kind;                   ///< the next shot's kind ("direct", ...); empty when infeasible
  std::string next_pocket;                 ///< the next shot's pocket name; empty when infeasible
  double score = 0.0;                      ///< success_probability x next_success_probability
};

struct PositionPlanResult {
  ShotPlanResult plan;                 ///< shot: the one played; alternatives: the others evaluated, by score
  int next_target = -1;                ///< -1: no next ball, no lookahead
  Leave leave;                         ///< plan.shot's
  std::vector<Leave> alternative_leaves;  ///< plan.alternatives[k]'s
};

/// Plans the shot for position (header comment). Throws what plan_shot()
/// throws, and InvalidArgument("next") when next_target is not a ball on
/// the table or is the cue ball or the target, InvalidArgument
/// ("next_simulations") out of range. plan.simulations and plan.seconds
/// count every plan made (a next plan that finds no feasible shot counted at
/// its whole budget, so plan.simulations is an upper bound). A leave whose
/// noise-free shot pots the next target too scores as if there were no next
/// target (its success probability alone).
PositionPlanResult plan_shot_for_position(const Scenario& table_state, const PositionRequest& request);

/// The table a planned shot leaves: its balls not pocketed, at rest where
/// PlannedShot::predicted puts them, the scenario's "cue" cleared.
Scenario table_left_by(const Scenario& table_state, const PlannedShot& shot);

}  // namespace cueball
