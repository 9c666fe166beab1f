// Position play (issue 13, item 2): among the shots that pot the target,
// prefer the one that leaves the cue ball where the next target has the
// highest success probability. A one-shot lookahead over plan_shot():
//
//   1. The shot is planned with a wide variant search: plan_shot()'s step 4
//      (shot_planner.hpp) with the tip heights kPositionHeights at the cue
//      speeds kPositionSpeedFactors x the shot's own (kept inside its speed
//      window), side +-0.2 at the best, for the PositionRequest::varied_shots
//      best shots (three by default) even when they leave nothing to gain
//      in potting; kPositionVariantBudgets x the
//      request's budget more engine runs for these. Every shot and variant
//      found, with the noise-free end of every ball (PlannedShot::predicted),
//      is a candidate; those whose window probability is at least
//      kPositionKeepFraction of the best's are kept (valued by windows, at
//      most kPositionLeaves; by the ghost ball, every one),
//      best first.
//   2. Each candidate's leave is scored: its window probability times the
//      best window probability of the next target's shots on the table it
//      leaves (the balls not pocketed, at rest where the noise-free shot
//      leaves them; plan_shot()'s geometry, aim solve and windows,
//      `next_simulations` runs at most). With
//      PositionRequest::candidate_noisy_leaves, that next value is averaged
//      with the same on the tables left by the successes among that many
//      noisy repeats of the candidate (the finalists' draws, common to every
//      candidate), so that a leave good only where the noise-free shot stops
//      does not crowd a robust one out of the finalists. The window probability is
//      the planner's prediction of a shot's success (0.98 correlated with
//      measured success on the planner benchmark). The next target is the
//      request's (PositionRequest::next_targets, as a rule gives them), by
//      default 9-ball's: the lowest id; a shot that pots it too is scored on
//      the ball after it (the lowest id left), and with no ball left on its
//      window probability alone.
//   3. The PositionRequest::finalists best by that score are the finalists: each
//      is screened on the same noisy draws (a kPositionScreenFraction-th of
//      the request's budget: common random numbers, a paired comparison),
//      and the next target's shot planned in full with plan_shot() on the
//      table the noise-free shot leaves (the same kinds and noise,
//      `next_simulations` runs). A next shot with no feasible candidate
//      scores 0. The leaves of the first PositionRequest::noisy_leaves
//      successes of the screen (the balls where each noisy shot left them)
//      are scored too: the next shot's best window probability on each
//      (1 where the shot left no next ball), averaged. At depth 2
//      (PositionRequest::depth) each of these leaves is valued two shots
//      deep instead: the best, over the next shot's kPositionSecondShots
//      best shots, of its window probability times the best window of the
//      shot after it on the table it leaves. Under the tournament
//      noise a 0.075 m/s speed error moves the cue ball's stop by tens of
//      centimetres, so a leave that is good only where the noise-free shot
//      stops (a narrow window, a ball that blocks a few centimetres away)
//      scores less than one good over the spread: the expectation over the
//      shot's outcomes that the tournament programs' search takes (M. Smith,
//      "PickPocket: A computer billiards shark", Artificial Intelligence 171
//      (2007) 1069-1091, the expectimax's chance nodes; C. Archibald, A.
//      Altman, Y. Shoham, "Analysis of a winning computational billiards
//      player", IJCAI 2009, CueCard's sampled outcomes).
//   4. The finalist played maximises P(this pot) x P(next pot), the
//      probability of potting both under the noise: the screened
//      probability times the mean next window over the noisy leaves (times
//      the full next plan's probability from the noise-free leave when
//      noisy_leaves is 0 or no noisy shot succeeded). The product treats the
//      two as independent: a one-shot lookahead, as in the
//      computational-pool tournament programs' first level of search. Its
//      success probability is then measured on fresh draws (a
//      kPositionEstimateFraction-th of the budget), so it carries no
//      selection bias.
//
// With PositionRequest::valuation ghost_ball, steps 2 and 3 value each
// leave (noise-free and noisy) by the next shot's best ghost-ball chance
// instead (ghost_ball.hpp, no engine run) and plan no next shot in full:
// what a decision on a budget of a tenth of a second can afford. At depth 2
// step 3's leaves are valued two shots deep by the ghost ball: the best,
// over the next shot's kPositionSecondShots best ghost-ball pots, of its
// chance times the best ghost-ball chance of the shot after it, over the
// tables the pot's noise-free strokes kGhostBallStrokeSpeeds x
// kGhostBallStrokeHeights leave (ghost_ball_stroke(), one engine run each;
// a stroke that scratches scores 0): a sampled second ply where the
// windows' depth 2 plans one. At depth 3 the shot after the next is valued
// so in turn on each of those tables: the next three shots' chances, each
// later shot's stroke searched, by a branch and bound that searches a
// table only where its next chance exceeds the best value found (the value
// is a product of chances, so no more than that chance): 7-16 % more time
// a decision than depth 2 on the run-out suite, and no more run-outs within
// the noise (docs/planner-benchmark.md, "Three shots ahead by the ghost
// ball"), so the strongest agent stays at depth 2.
//
// By default (valuation windows) the leave's quality is measured on the
// exact simulation and the real planner, so it includes what the next shot
// needs (its cut, distance, blockers and the cue's clearance), not a
// distance heuristic. Paper 001's
// inverse problem (a ball stopping at a planned point) is not used: the cue
// ball's end after a collision is not a straight roll from the strike, so
// the leave is read from the simulation instead.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/planning/shot_planner.hpp"

namespace cueball {

/// Tip heights of the wide variant search, ball radii.
inline constexpr std::array<double, 5> kPositionHeights{-0.4, -0.2, 0.0, 0.2, 0.4};
/// Cue-speed factors of the wide variant search, on each shot's own speed.
inline constexpr std::array<double, 6> kPositionSpeedFactors{0.6, 0.8, 1.0, 1.3, 1.8, 2.5};
/// Engine runs of the wide variant search, in budgets of the request's.
inline constexpr int kPositionVariantBudgets = 3;
/// The feasible shots the wide variant search varies, by default
/// (PositionRequest::varied_shots: plan_shot()'s three best by window
/// probability), and the most allowed.
inline constexpr int kPositionVariedShots = 3;
inline constexpr int kMaxPositionVariedShots = 16;
/// Candidates whose window probability is under this fraction of the best's are not played for position.
inline constexpr double kPositionKeepFraction = 0.5;
/// Most candidates whose leave is scored by window probabilities
/// (LeaveValuation::windows; by ghost-ball chances every candidate is).
inline constexpr std::size_t kPositionLeaves = 24;
/// Candidates whose leave is evaluated in full (the finalists), by default
/// (PositionRequest::finalists), and the most allowed.
inline constexpr int kPositionFinalists = 3;
inline constexpr int kMaxPositionFinalists = 16;
/// The finalists' noisy successes whose leaves are scored (step 3), at
/// most, by default (PositionRequest::noisy_leaves), and the most allowed.
inline constexpr int kPositionNoisyLeaves = 4;
inline constexpr int kMaxPositionNoisyLeaves = 64;
/// Lookahead depths (PositionRequest::depth): 1, the next shot; 2, the next
/// two; 3, the next three (valuation ghost_ball only). At depth 2 a leave's
/// next shot is valued by its kPositionSecondShots best shots (noise-free,
/// by window probability), each times the best window of the shot after it
/// on the table it leaves; at depth 3 by the ghost ball, the shot after it
/// valued so in turn.
inline constexpr int kMaxPositionDepth = 3;
/// The deepest lookahead with valuation windows (a full window search per
/// shot of every ply: deeper costs kPositionSecondShots + 1 times as much
/// again).
inline constexpr int kMaxWindowsDepth = 2;
inline constexpr std::size_t kPositionSecondShots = 3;
/// The finalists' common screen takes the request's budget over this; the
/// final estimate of the one played, the budget over kPositionEstimateFraction.
inline constexpr int kPositionScreenFraction = 5;
inline constexpr int kPositionEstimateFraction = 4;

/// How position play values a leave for the next shot (PositionRequest::valuation).
enum class LeaveValuation : unsigned char {
  /// The planner's window search: the best window probability of the next
  /// shot's candidates (the request's kinds), found on the exact simulation
  /// with `next_simulations` runs at most; each finalist's next shot also
  /// planned in full (step 3). Milliseconds a leave.
  windows,
  /// The best ghost-ball pot's chance under the request's aim noise
  /// (best_ghost_ball_chance(), ghost_ball.hpp): no engine run,
  /// microseconds a leave; straight pots only, without throw, squirt, the
  /// speed or the cue's clearance. For decisions on a budget of a tenth of a
  /// second. `next_simulations` is not used; at depth 2 the next shot's
  /// strokes are played once each instead of planned (header comment).
  ghost_ball,
};

/// The deepest lookahead a valuation allows: kMaxWindowsDepth with windows,
/// kMaxPositionDepth with ghost_ball.
inline constexpr int max_position_depth(LeaveValuation valuation) {
  return valuation == LeaveValuation::windows ? kMaxWindowsDepth : kMaxPositionDepth;
}
/// "windows", "ghost_ball".
const char* to_string(LeaveValuation valuation);
std::optional<LeaveValuation> leave_valuation_from_string(std::string_view name);
std::string leave_valuation_names();

struct PositionRequest {
  /// The shot that pots shot.target; its `simulations` is the budget of its
  /// plan, and kPositionVariantBudgets times it more go to the wide variant search.
  PlanRequest shot;
  /// Id of the next target. None: the lowest id on the table other than the
  /// cue ball and the target (9-ball's rule); with no such ball there is no
  /// lookahead and the shot is plan_shot()'s. Where the shot pots it too,
  /// the lowest id left is next. (A rule gives next_targets instead.)
  std::optional<int> next_target;
  /// The next shots' legal targets, in turn, as a rule gives them: the next
  /// shot may pot any ball of next_targets[0] that the shot leaves on the
  /// table (PlanRequest::targets of the next plan); where it leaves none of
  /// them, next_targets[1], and so on; where it leaves none of any, there is
  /// no next shot and the leave scores this pot alone. 9-ball:
  /// {{2}, {3}, ..., {9}} (the lowest ball, and where the shot pots it too,
  /// the next lowest); 8-ball on the stripes: {{9, 10, ..., 15}, {8}}.
  /// Empty: 9-ball's rule, from next_target when given (as above). Not both.
  std::vector<std::vector<int>> next_targets;
  /// Engine runs of each next-shot plan, [kMinPlanSimulations, kMaxPlanSimulations].
  int next_simulations = kMinPlanSimulations;
  /// The noisy successes of each finalist whose leaves are scored (step 3),
  /// [0, kMaxPositionNoisyLeaves]; 0: the noise-free leave alone, the next
  /// shot's full plan from it (the one-shot lookahead before issue 27).
  int noisy_leaves = kPositionNoisyLeaves;
  /// Shots looked ahead, [1, kMaxPositionDepth]: 1, the next shot's best
  /// window on each leave (step 3); 2, the best over the next shot's
  /// kPositionSecondShots best shots of its window times the best window of
  /// the shot after it, on the table that next shot leaves (its noise-free
  /// end): a leave that gives an easy next shot from which the one after is
  /// hard scores less than one that gives two good shots. The same budget
  /// (`next_simulations` runs a plan) for every plan; depth 2 makes about
  /// kPositionSecondShots + 1 times as many next plans. With valuation
  /// ghost_ball the same by ghost-ball chances, the next shot's strokes
  /// played once each (12 engine runs a next pot, header comment); 3
  /// (ghost_ball only, [1, kMaxWindowsDepth] with windows): the shot after
  /// the next valued two shots deep in turn on each table its strokes
  /// leave, by an exact branch and bound (a table whose next chance is no
  /// more than the best value so far is not searched).
  int depth = 1;
  /// How a leave's next shot is valued in steps 2 and 3 (LeaveValuation).
  LeaveValuation valuation = LeaveValuation::windows;
  /// A ball whose legal pot ends the run at once, whichever ball the cue
  /// ball meets first (9-ball's 9: WPA Rules of Play, section 2; 10-ball's
  /// called 10: section 9). With valuation ghost_ball, where the next
  /// target is one ball other than it, a leave (and each table the
  /// lookahead's strokes leave) is valued by the larger of the run's
  /// ghost-ball chances and the best ghost-ball combination of the game
  /// ball through that target (ghost_ball_combinations()), the run then
  /// won. None (the default): pots one by one alone. A ball on the table
  /// other than the cue ball, with valuation ghost_ball only.
  std::optional<int> game_ball;
  /// The chance of each shot of a run beyond the lookahead, (0, 1]: a
  /// game ball's combination wins the rack, while the run's value covers
  /// only the `depth` shots looked ahead, so the combination's chance is
  /// divided by later_shot_chance to the power of the run's balls beyond
  /// them (at most 1 in all) before the two are compared. 1 (the default):
  /// compared as they are. The strongest agent sets kRunOutShotChance.
  double later_shot_chance = 1.0;
  /// Noisy repeats of every candidate whose successes' leaves are valued in
  /// step 2 beside the noise-free leave, [0, kMaxPositionNoisyLeaves]; 0
  /// (the default): the noise-free leave alone, the lookahead before
  /// 5 December 2026. As many engine runs more a candidate (and next-shot
  /// valuations: free by the ghost ball, a window search each by windows).
  int candidate_noisy_leaves = 0;
  /// The finalists of step 3, [1, kMaxPositionFinalists]: each screened
  /// under the noise (a kPositionScreenFraction-th of the budget more
  /// engine runs each) and its noisy leaves valued.
  int finalists = kPositionFinalists;
  /// The feasible shots of step 1 whose spin and speed variants are
  /// searched, the best by window probability, [1, kMaxPositionVariedShots]:
  /// each shot more (another pocket, a bank) adds its tip heights x speeds
  /// as candidate leaves, up to kPositionVariantBudgets x the budget in
  /// engine runs. The default, 3, is plan_shot()'s own.
  int varied_shots = kPositionVariedShots;
};

/// What a candidate leaves for the next shot.
struct Leave {
  Vec2 cue_ball;                           ///< where the noise-free shot leaves the cue ball, m
  bool next_feasible = false;              ///< the next shot has a feasible candidate
  double next_success_probability = 0.0;   ///< of the next shot's plan from there (0 when infeasible)
  /// This shot's success probability on the finalists' common noisy draws.
  double screened_probability = 0.0;
  std::string next_kind;                   ///< the next shot's kind ("direct", ...); empty when infeasible
  std::string next_pocket;                 ///< the next shot's pocket name; empty when infeasible
  int next_ball = -1;                      ///< the ball the next shot's plan pots; -1 when none or infeasible
  /// screened_probability x noisy_next_window (x next_success_probability
  /// when noisy_leaves is 0 at depth 1 by windows; by the ghost ball,
  /// noisy_next_window is then the noise-free leave's value). With a
  /// PositionRequest::game_ball and the ghost ball, next_* may be that
  /// ball's combination through the next ball (next_kind "combination",
  /// next_ball the game ball). When the noise-free shot pots the next target
  /// too, next_* are of the ball after it (the lowest id left); with no ball
  /// left, score = screened_probability.
  double score = 0.0;
  /// The noisy successes of the finalists' screen whose leaves were scored
  /// (at most PositionRequest::noisy_leaves; 0: the noise-free leave
  /// scores), and the mean over them of the best next shot's window
  /// probability (at depth 2: of the next two shots' best product, above).
  int noisy_leaves = 0;
  double noisy_next_window = 0.0;
  /// Step 2's value of the leave: the next shot's value on the noise-free
  /// leave averaged with it on the leaves of the successes among the
  /// candidate's PositionRequest::candidate_noisy_leaves noisy repeats
  /// (candidate_noisy_leaves of them; 0: the noise-free leave alone).
  int candidate_noisy_leaves = 0;
  double candidate_next_window = 0.0;
};

struct PositionPlanResult {
  ShotPlanResult plan;                 ///< shot: the one played; alternatives: the others evaluated, by score
  /// The next target on the table planned from (the first ball of the first
  /// set of next_targets on it, other than the cue ball and the shot's
  /// targets); -1: no next ball, no lookahead.
  int next_target = -1;
  Leave leave;                         ///< plan.shot's
  std::vector<Leave> alternative_leaves;  ///< plan.alternatives[k]'s
};

/// Plans the shot for position (header comment). Throws what plan_shot()
/// throws, and InvalidArgument("next") when next_target is not a ball on
/// the table or is the cue ball or a target, InvalidArgument("next_targets")
/// when one of its ids is not a ball on the table or is the cue ball, a set
/// is empty or next_target is given too, InvalidArgument
/// ("next_simulations") out of range. plan.simulations and plan.seconds
/// count every plan made (a next plan that finds no feasible shot counted at
/// its whole budget, so plan.simulations is an upper bound).
PositionPlanResult plan_shot_for_position(const Scenario& table_state, const PositionRequest& request);

/// The table a planned shot leaves: its balls not pocketed, at rest where
/// PlannedShot::predicted puts them, the scenario's "cue" cleared.
Scenario table_left_by(const Scenario& table_state, const PlannedShot& shot);

}  // namespace cueball
