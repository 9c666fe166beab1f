// Ball in hand (issue 13, the run-outs' "cue ball in hand placed by the
// planner"): where to place the cue ball so that it pots the target and
// leaves the next ball well, as after a foul in 9-ball or at the start of a
// drill.
//
//   1. Spots. For each target (PlanRequest::targets, or its target) and
//      each pocket whose straight path from the target O is clear
//      (no other ball's centre within 2R of the segment from O to the
//      pocket's capture centre P), the ghost ball G = O - 2R u, u the unit
//      vector from O to P (ghost-ball aiming: D. G. Alciatore, "The
//      Illustrated Principles of Pool and Billiards", 2004). The spots lie
//      behind G, at each distance of kInHandDistances from G, along -u
//      turned by each cut angle of kInHandCutsDeg; with a region, also where
//      that line first enters the region and the middle of its stretch
//      inside (up to kInHandFarthest behind G). A spot must be a place for
//      the cue ball (ball_on_table(), at least 2R + kInHandGap from every
//      other ball), inside the request's region when it gives one, with the
//      cue ball's straight path to G clear (no other ball within 2R). When
//      no pocket gives a spot (every straight path of the target blocked),
//      the spots are the centres of a kInHandGrid grid over the bed (or the
//      region) where the cue ball can be placed, for any shot the request
//      asks for (a bank, ...).
//   2. Each spot is scored without a noisy shot: the best window
//      probability (PlannedShot::window_probability) of a direct shot into
//      its pocket (a grid spot: of any shot asked for), plan_shot()'s
//      noise-free search with kMinPlanSimulations runs. The kInHandSpots
//      best are kept (window probabilities in steps of 0.02, then the shorter
//      cue ball and object ball paths first), at most two a target and pocket (grid
//      spots: no such limit). With PositionRequest::valuation ghost_ball
//      the spot's score is its ghost-ball chance instead (ghost_ball.hpp:
//      the straight pot into its pocket, a grid spot's into any pocket
//      allowed; no engine run). Where no spot scores above 0 on a score
//      that sees straight pots only (every ghost-ball chance, or every
//      spot's direct shot, is 0), the grid's places are scored by the
//      window search of every shot asked for instead, as a bank or a kick
//      may still pot the target from them.
//   3. On each kept spot the shot is played for position
//      (plan_shot_for_position(), the request's budgets, any pocket the
//      request allows); the spot whose leave scores best (P(this pot) x
//      P(next pot), Leave::score) is chosen.
#pragma once

#include <array>
#include <optional>

#include "cueball/planning/position_play.hpp"
#include "cueball/table/placement.hpp"

namespace cueball {

/// Distances of the spots behind the ghost ball, m.
inline constexpr std::array<double, 3> kInHandDistances{0.15, 0.3, 0.6};
/// Cut angles the spots give, degrees.
inline constexpr std::array<double, 3> kInHandCutsDeg{0.0, 15.0, -15.0};
/// The fallback grid of spots, along x and along y.
inline constexpr std::array<int, 2> kInHandGrid{8, 4};
/// Farthest spot behind the ghost ball that a region adds, m.
inline constexpr double kInHandFarthest = 3.0;
/// Most spots played for position.
inline constexpr std::size_t kInHandSpots = 4;
/// Least gap between the placed cue ball and any other ball, m.
inline constexpr double kInHandGap = 0.002;

/// A rectangle [x_min, x_max] x [y_min, y_max], m, as earlier releases took
/// the region; it converts to a PlacementRegion of kind rectangle. Kept for
/// one release: use PlacementRegion (table/placement.hpp).
struct InHandRegion {
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;
  operator PlacementRegion() const { return {PlacementRegion::Kind::rectangle, x_min, x_max, y_min, y_max}; }
};

struct BallInHandRequest {
  /// The shot and its lookahead (position_play.hpp); the cue ball's own
  /// place on the table, if any, is ignored.
  PositionRequest position;
  /// Where the cue ball may go (table/placement.hpp: anywhere, behind the
  /// head string, inside the D, a rectangle); none: anywhere on the bed.
  std::optional<PlacementRegion> region;
};

struct BallInHandResult {
  Vec2 cue_ball;                ///< the chosen spot, m
  PositionPlanResult plan;      ///< the shot from there, played for position
  int spots = 0;                ///< spots that passed step 1
  int spots_played = 0;         ///< spots played for position (step 3)
  /// The scenario with the cue ball at the chosen spot (its "cue" cleared):
  /// plan.plan.shot is planned on it.
  Scenario table;
};

/// Places the cue ball and plans the shot (header comment). Throws what
/// plan_shot_for_position() throws; InvalidArgument("region") for a region
/// with a non-finite bound or x_min >= x_max or y_min >= y_max, or wholly
/// off the playing surface [0, length] x [0, width];
/// NoFeasibleShot when no spot gives a feasible shot. plan.plan.simulations
/// counts every engine run, step 2's included; plan.plan.seconds the whole
/// placement.
BallInHandResult plan_ball_in_hand(const Scenario& table_state, const BallInHandRequest& request);

}  // namespace cueball
