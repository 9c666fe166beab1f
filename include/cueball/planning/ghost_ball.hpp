// Ghost-ball pots: the straight pots of a table read from its geometry alone,
// no engine run, and the chance of each under the aim noise. The ghost-ball
// agent aims by them (agents/agent.hpp), the safety search screens the
// opponent's chance by them, and position play and ball in hand can value a
// leave by them (PositionRequest::valuation, LeaveValuation::ghost_ball):
// microseconds a leave where the planner's window search takes milliseconds.
//
// Geometry (D. G. Alciatore, "The Illustrated Principles of Pool and
// Billiards", 2004, the ghost ball): the cue ball C aimed at the ghost ball
// G = O - 2R u of a ball O sends O along u, the unit vector from O to the
// point P it is sent to. P is the pocket's centre moved sideways onto the
// middle of the lines that drop a ball coming from O's direction (the
// pocket's window, pocket_windows.hpp): head on into a corner that is the
// centre; 20 deg off the corner's axis, 35 mm to its side, where a ball sent
// at the centre barely drops. The chance: an aim error d(theta) of the cue
// ball's line moves its contact |CG| d(theta) sideways, which turns the
// object ball by |CG| d(theta) / (2R cos(cut)), and that must stay within
// w / |OP| of the middle of the lines that drop it, where w is half the
// width of the pocket's window for the direction O comes from, measured on
// the engine for this table (pocket_windows.hpp: up to 35 mm head on into a
// 9-ft table's corner, none into a side pocket from beyond about 65 deg):
// the aim tolerance is 2R w cos(cut) / (|CG| |OP|) = 2R w score, and under
// Gaussian aim noise sigma the pot succeeds with probability
// erf(tolerance / (sigma sqrt 2)). Throw, squirt, the speed and the cue's
// clearance are left out: a screen, not a plan. (On 539 pots of one ball
// in 300 random layouts on the 9-ft table, this chance against the
// planner's measured success of the same pot, 2,000 runs each: Brier score
// 0.011, correlation 0.93; sent at the pocket's centre with that
// direction's window, 0.014 and 0.92. On 549 earlier pots, by a script's
// copy of the windows: 0.021 against 0.033 with a fixed w of 25 mm for
// every pocket and direction, as before 5 December 2026.)
#pragma once

#include <array>
#include <initializer_list>
#include <vector>

#include "cueball/simulation/scenario.hpp"

namespace cueball {

/// One ghost-ball pot: `target` into table.pockets[pocket].
struct GhostBallPot {
  int target = -1;
  int pocket = -1;     ///< index into table.pockets
  Vec2 ghost;          ///< G, where the cue ball's centre meets the target, m
  double score = 0.0;  ///< cos(cut) / (|CG| |OP|), 1/m^2: the geometry's part of the aim tolerance
  double window = 0.0; ///< w, m: half the pocket's window for the target's direction to it (0: none)
  double aim_tolerance = 0.0;  ///< 2R w score, rad: the aim error that still pots, larger is easier
  Vec2 pocket_aim;      ///< P, where the target is sent: the pocket's centre moved to the middle of its window
  /// A combination's ball on: the ball the cue ball meets first, sent into
  /// the target (ghost_ball_combinations()); -1 for a straight pot. Then
  /// `ghost` is the cue ball's ghost ball on it and `score` is
  /// 2R cos(cut on it) cos(its cut on the target) / (|CG| |AT| |OP|).
  int ball_on = -1;
};

/// Where a ghost-ball pot sends its target.
enum class GhostBallAim {
  window_middle,  ///< the middle of the pocket's window for the target's direction (the default)
  pocket_centre,  ///< the pocket's centre, the textbook rule (the ghost-ball agent's, the benchmarks' baseline)
};

/// Whether a ball's centre moving straight from a to b passes every ball
/// but those whose ids are in `except` at `clearance` or more (2R: it meets
/// none of them): the clear path of a ghost-ball pot, a combination, a
/// placement behind a ball, a safe hit.
bool path_clear(const std::vector<SimulationBall>& balls, Vec2 a, Vec2 b, double clearance,
                std::initializer_list<int> except);

/// Every clear ghost-ball pot of `targets` from the cue ball where it lies:
/// pockets whose cut is at most kMaxCutDeg and whose straight paths C -> G
/// and O -> P are clear of every other ball's centre by two radii; the
/// largest aim tolerance first (equal ones in the targets' order, then the
/// pockets'). A pocket whose window is closed to the target's direction is
/// listed with an aim tolerance of 0. Empty when the cue ball is not on the
/// table. The cue's clearance is not checked. The pocket windows are
/// measured on the table's first use (pocket_windows()). `aim` chooses the
/// point P the target is sent to (see above); with pocket_centre the window
/// is still the one for the direction to the centre, though a ball sent
/// there may pass outside it (20 deg off a corner's axis it barely drops).
std::vector<GhostBallPot> ghost_ball_pots(const Scenario& table, int cue_ball, const std::vector<int>& targets,
                                          GhostBallAim aim = GhostBallAim::window_middle);

/// The chance of a ghost-ball pot of this aim tolerance (rad,
/// GhostBallPot::aim_tolerance) under Gaussian aim noise of `aim_sigma`
/// (rad, CueStrikeNoise::aim; 0: the chance is 1 for any open window): see above.
double ghost_ball_pot_chance(double aim_tolerance, double aim_sigma);

/// The best chance over ghost_ball_pots() (its first's; 0 when there is none).
double best_ghost_ball_chance(const Scenario& table, int cue_ball, const std::vector<int>& targets, double aim_sigma);

/// Every clear ghost-ball combination of `target` through `ball_on` from the
/// cue ball where it lies: the cue ball C sent at the ghost ball G of the
/// ball on A for the point T = O - 2R u at which A meets the target O and
/// sends it along u to the pocket's point P (each pocket's, as for
/// ghost_ball_pots()); both cuts at most kMaxCutDeg, the paths C -> G,
/// A -> T and O -> P clear of every other ball by two radii. An aim error
/// d(theta) turns A by |CG| d(theta) / (2R cos(cut at A)), which turns the
/// target by |AT| / (2R cos(cut at O)) times that: the aim tolerance is
/// (2R)^2 w cos cos / (|CG| |AT| |OP|) = 2R w score, where w is the window's
/// half width for the target's direction (Alciatore's ghost ball applied
/// twice; throw between the two object balls, which turns the target off
/// the line of centres, is left out as for a straight pot). Largest aim
/// tolerance first; empty when a ball is missing or two ids are the same.
std::vector<GhostBallPot> ghost_ball_combinations(const Scenario& table, int cue_ball, int ball_on, int target);

/// The strokes a ghost-ball pot is played with when position play looks two
/// shots ahead by the ghost ball (PositionRequest::depth 2): every cue speed
/// (m/s) with every tip height (ball radii; draw, stun, follow), no side.
inline constexpr std::array<double, 4> kGhostBallStrokeSpeeds{0.8, 1.5, 2.5, 4.0};
inline constexpr std::array<double, 3> kGhostBallStrokeHeights{-0.4, 0.0, 0.4};

/// What the noise-free stroke of a ghost-ball pot did.
struct GhostBallStroke {
  Scenario left;           ///< the table it leaves (table_after(): the pocketed removed)
  bool potted = false;     ///< the pot's target dropped (into any pocket)
  bool scratched = false;  ///< the cue ball dropped, or the engine refused the shot
};

/// Plays `pot` once without noise: the cue ball struck with a level cue along
/// C -> G (no throw or squirt allowed for) at cue speed `speed` (m/s) and tip
/// height `height` (ball radii), on the exact simulation (one engine run).
GhostBallStroke ghost_ball_stroke(const Scenario& table, int cue_ball, const GhostBallPot& pot, double speed,
                                  double height);

}  // namespace cueball
