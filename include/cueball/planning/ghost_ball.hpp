// Ghost-ball pots: the straight pots of a table read from its geometry alone,
// no engine run, and the chance of each under the aim noise. The ghost-ball
// agent aims by them (agents/agent.hpp), the safety search screens the
// opponent's chance by them, and position play and ball in hand can value a
// leave by them (PositionRequest::valuation, LeaveValuation::ghost_ball):
// microseconds a leave where the planner's window search takes milliseconds.
//
// Geometry (D. G. Alciatore, "The Illustrated Principles of Pool and
// Billiards", 2004, the ghost ball): the cue ball C aimed at the ghost ball
// G = O - 2R u of a ball O for a pocket P (u the unit vector from O to P's
// centre) sends O along u. The chance: an aim error d(theta) of the cue
// ball's line moves its contact |CG| d(theta) sideways, which turns the
// object ball by |CG| d(theta) / (2R cos(cut)), and that must stay within
// w / |OP| of the pocket's centre line (w = kPotTolerance): the aim tolerance
// is 2R w cos(cut) / (|CG| |OP|) = 2R w score, and under Gaussian aim noise
// sigma the pot succeeds with probability erf(tolerance / (sigma sqrt 2)).
// Throw, squirt, the jaws' shape, the speed and the cue's clearance are left
// out: a screen, not a plan.
#pragma once

#include <vector>

#include "cueball/simulation/scenario.hpp"

namespace cueball {

/// The pocket's half-width for a ball's centre, m (a 9-ft table's corner
/// mouth of 4.5 in less a ball, halved, rounded down).
inline constexpr double kPotTolerance = 0.025;

/// One ghost-ball pot: `target` into table.pockets[pocket].
struct GhostBallPot {
  int target = -1;
  int pocket = -1;     ///< index into table.pockets
  Vec2 ghost;          ///< G, where the cue ball's centre meets the target, m
  double score = 0.0;  ///< cos(cut) / (|CG| |OP|), 1/m^2: the small-angle aim tolerance, larger is easier
};

/// Every clear ghost-ball pot of `targets` from the cue ball where it lies:
/// pockets whose cut is at most kMaxCutDeg and whose straight paths C -> G
/// and O -> P are clear of every other ball's centre by two radii; best
/// score first (equal scores in the targets' order, then the pockets').
/// Empty when the cue ball is not on the table. The cue's clearance is not
/// checked.
std::vector<GhostBallPot> ghost_ball_pots(const Scenario& table, int cue_ball, const std::vector<int>& targets);

/// The chance of a ghost-ball pot of this score under Gaussian aim noise of
/// `aim_sigma` (rad, CueStrikeNoise::aim; 0: the chance is 1), for balls of
/// `radius` (m): see above.
double ghost_ball_pot_chance(double score, double radius, double aim_sigma);

/// The best chance over ghost_ball_pots() (0 when there is none).
double best_ghost_ball_chance(const Scenario& table, int cue_ball, const std::vector<int>& targets, double aim_sigma);

}  // namespace cueball
