// The robot's 2D question on a real table: which strike pots this ball in
// that pocket, and how sure is it? (issue 13: direct shots, banks off one or
// two cushions, kicks and combinations.)
//
// Method, per candidate (a pocket, a kind and its cushions or intermediate
// ball):
//   1. Geometry gives the first aim (the ghost-ball and mirror systems of D.
//      G. Alciatore, "The Illustrated Principles of Pool and Billiards",
//      2004). A cushion's "line" below is the line the centre of a ball
//      touching it follows: the nose line moved in by the contact distance
//      sqrt(h (2R - h)) (table.hpp); a point is mirrored in that line.
//      direct: the ghost ball G = O - 2R u, u the unit vector from the
//        object ball O to the pocket's capture centre P; the cue ball is
//        aimed at G (ghost-ball aiming).
//      bank off one cushion: P is mirrored in the cushion's line and the
//        object ball sent at the mirror point P' (the mirror system of bank
//        shots); the bank point X is where O -> P' crosses the line.
//      bank off two cushions: P is mirrored in the second cushion's line
//        (P1), P1 in the first's (P2); the object ball is sent at P2, meets
//        the first line at X1 (on O -> P2), the second at X2 (on X1 -> P1),
//        and goes on to P (mirror images twice, ibid.).
//      kick: the target is potted directly, but the cue ball reaches its
//        ghost ball G off one cushion: G is mirrored in that cushion's line
//        (G') and the cue ball aimed at G'; it meets the line at Y (on
//        C -> G') and goes on to G (the mirror system of kicks, ibid.).
//      combination: the cue ball sends another ball A into the target,
//        which goes in: A must reach the target's ghost ball G_T = O - 2R u,
//        so along v = (G_T - A) / |G_T - A|, and the cue ball is aimed at A's
//        ghost ball G_A = A - 2R v (the ghost ball applied twice, ibid.).
//        Any other ball on the table may be A; for each pocket only the
//        kMaxCombinationBalls with the smallest combined cut (the cue ball's
//        on A plus A's on the target) are kept.
//      The real rebound (Mathavan 2010) is not a mirror, nor is a real
//      collision a ghost ball (throw); step 3 fixes both.
//   2. Candidates whose straight paths are blocked are skipped: another
//      ball's centre within 2R of a leg (the swept-circle test) of the cue
//      ball (C -> G, C -> Y -> G for a kick, C -> G_A for a combination), of
//      A (A -> G_T) or of the object ball (O -> P, O -> X -> P, O -> X1 ->
//      X2 -> P); for a kick, the target within 2R of the cue ball's first leg
//      (it would be hit before the cushion); for a combination, the target
//      within 2R of the cue ball's path (it would be hit before A). So is a
//      candidate whose cut (either cut of a combination) exceeds
//      kMaxCutDeg, whose bank point is not on its cushion or meets it more
//      than 75 deg from its normal, or whose cue is obstructed at every
//      elevation up to kMaxPlanElevationDeg (cue_obstructed()).
//   2b. The aim scan (direct and bank shots): 40 aims spread evenly
//      over every straight line on which the cue ball meets the target, at
//      2 and 4 m/s, centre ball, in one simulate_many batch. Each run of
//      neighbouring aims that pots (the same pocket and cushion count) and
//      is wider than the aim window of any feasible shot of its kind into
//      its pocket becomes a candidate, its kind read from its middle aim
//      played out (a bank when the target meets a rail, not a pocket's
//      facing, before it drops). It finds what geometry misses: a ball on
//      the rail sent along it, a side pocket that wants the near jaw, a path
//      between two kisses.
//   3. The aim is corrected on the exact simulation (noise-free): the
//      target's signed lateral miss of P (its closest approach to P, measured
//      across the intended last leg) is driven to zero by the secant method,
//      so cut- and spin-induced throw, the cloth's curve and the cushions'
//      rebounds are in the answer; where the target passes the centre
//      without dropping (a jaw turns it out), misses of 0.3, 0.6 and 0.9
//      pocket radii either side are tried. The lowest cue speed that still
//      pots (the rest held) is found by bisection from there, to
//      kSpeedWindowTol, and the speed chosen: the first guess (the object
//      ball reaching the pocket at about 1 m/s), but at least max(0.3 m/s, a
//      quarter of the slowest pot) + 3 sigma above the slowest pot and at
//      most the speed window's middle; the aim is solved again at that speed.
//      The aim window (aims that pot, the rest held) is then found by steps
//      outwards of at most 0.2 deg and bisection, each edge to
//      kAimWindowTolDeg, and the aim played is its middle, the aim that takes
//      the most aim noise either way; the speed window is found at that aim.
//   4. Spin, speed and the shot are chosen under noise. Each feasible shot
//      has its window probability (PlannedShot::window_probability): the
//      chance that the aim, under the aim noise and the squirt of the
//      side-offset noise (C8 of cue_strike.hpp, linearised), stays inside the
//      aim window, times the chance that the cue speed stays inside the speed
//      window; over the planner benchmark's chosen shots it correlates 0.98
//      with the success rate of 2,000 noisy repeats, and it costs no noisy
//      shot. Every feasible shot (at most 12) is also screened briefly on
//      common noise draws (16 shots, fewer on a small budget). Unless the request gives
//      the tip height, the 3 best by window probability are
//      varied: draw (-0.3), centre and follow (+0.3) at 0.7, 1 and 1.8 times
//      their cue speed (kept 3 sigma of speed noise inside their speed
//      window), one more speed step where the best was at an end, and side
//      0.2 either way at the best (unless the request gives a
//      side), each variant's aim solved and windows found as in step 3 (its
//      speed held). The 3 best of all by window probability (in
//      steps of 0.02, then by the brief screen), with the best by the brief
//      screen among them, are screened on the same draws (common random
//      numbers: the comparison is paired) with a fifteenth of the budget each (at most 200); the
//      best is then measured with the rest of the budget (at least a fifth)
//      on fresh draws (the noise stream simulate_batch draws for the
//      request's seed, so its estimate carries no selection bias), standard
//      error sqrt(p (1 - p) / N).
// A noise-free strike pots only when the target drops in the intended
// pocket, the cue ball's first contact is the target (for a combination: ball
// A) and the cue ball is not pocketed (a scratch). A noisy shot succeeds on
// the same terms, except that a request without a pocket and not a call
// shot (any pocket, as in 9-ball) counts the target dropping in any pocket
// (PlanRequest::call_shot: only in the shot's own pocket); with several legal
// targets (PlanRequest::targets) each shot is planned on one of them, its
// target, and succeeds on its own target's terms; a miscue or an
// event-limit failure is a failure. Kinds are tried only when asked for: the default is direct
// and bank (the kicks and combinations of a full table add about as many
// candidates again; see the README's "Planning a 2D shot").
//
// The first strike of a candidate is centre ball unless the request gives
// the tip height; a centre-ball strike that misses or scratches (a
// straight-in's cue ball following the object ball in) is tried again with
// draw, then follow; the spin, speed and side variants of step 4 follow. It is
// level unless the cue must be raised to clear a ball or the rail (at the
// first aim, and again at the corrected one where the correction turns the
// cue into a ball or the rail: the aim is then solved and the windows found
// anew at the elevation that clears it); the butt
// of a level cue is below the rail, so most strikes come out at 2 degrees.
// Deterministic: the same scenario, request and seed give the same plan bit
// for bit, and the engine runs never exceed `simulations`. In the library
// each step above is a function of its own over one search state
// (src/planning/search_state.hpp names them and their files).
//
// Cue obstruction: cue_obstructed() (table/cue_obstruction.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/table/cue_obstruction.hpp"

namespace cueball {

/// No shot of the requested kinds can pot the ball (every pocket blocked,
/// the cue obstructed, no aim pots on the exact simulation, ...). what() is
/// one line saying why, for each candidate.
class NoFeasibleShot : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  /// `simulations`: the engine runs spent before the plan gave up.
  NoFeasibleShot(const std::string& what, int simulations) : std::runtime_error(what), simulations_(simulations) {}
  /// The engine runs spent before the plan gave up; -1 when not known.
  int simulations() const { return simulations_; }

 private:
  int simulations_ = -1;
};

/// direct: the cue ball pots the target; bank: the target goes in off one
/// or two cushions; kick: the cue ball reaches the target off a cushion;
/// combination: the cue ball sends another ball into the target.
enum class ShotKind { direct, bank, kick, combination };

/// Every kind, in the order of ShotKind.
inline constexpr std::array<ShotKind, 4> kShotKinds{ShotKind::direct, ShotKind::bank, ShotKind::kick,
                                                    ShotKind::combination};

/// "direct", "bank", "kick" or "combination".
const char* to_string(ShotKind kind);

/// The kind with that name (to_string()), or nullopt.
std::optional<ShotKind> shot_kind_from_string(std::string_view name);

/// The names of kShotKinds, each between `quote`s, joined by ", ":
/// "direct, bank, kick, combination".
std::string shot_kind_names(std::string_view quote = "");

/// The computational-pool tournaments' execution noise (Archibald, Altman,
/// Greenspan & Shoham, "Computational Pool: A New Challenge for Game Theory
/// Pragmatics", AI Magazine 31(4), 2010; issue 13): sigma 0.5 mm on both tip
/// offsets, 0.1 deg elevation, 0.125 deg aim, 0.075 m/s speed.
CueStrikeNoise tournament_noise();

/// Largest cut angle a candidate may need, degrees (thinner cuts are skipped).
inline constexpr double kMaxCutDeg = 80.0;
/// Most intermediate balls tried per pocket for a combination (those with the
/// smallest combined cut).
inline constexpr std::size_t kMaxCombinationBalls = 3;
/// Highest elevation the planner raises the cue to, to clear an obstruction, degrees.
inline constexpr double kMaxPlanElevationDeg = 30.0;
/// Precision of the aim window's edges, degrees, and of the speed window's, m/s.
inline constexpr double kAimWindowTolDeg = 0.01;
inline constexpr double kSpeedWindowTol = 0.03;
/// Accepted `simulations` budgets.
inline constexpr int kMinPlanSimulations = 500;
inline constexpr int kMaxPlanSimulations = 1'000'000;

/// True when the cue, aligned for `strike` (radians, metres) on the ball
/// with id `cue_ball`, passes through another of `balls` or below the rail
/// (header comment). Throws InvalidArgument("cue_ball") when no ball has
/// that id.
bool cue_obstructed(const Table& table, const std::vector<SimulationBall>& balls, int cue_ball, const CueStrike& strike,
                    const BallParameters& ball);


/// What the plan is asked to pot. A rule drives it through `targets` (the
/// legal balls: 9-ball's lowest, an 8-ball group, snooker's reds) and
/// `pocket` (a called pocket); a called ball is a single target. Existing
/// callers give `target` alone: `targets` empty means {target}.
struct PlanRequest {
  std::optional<int> cue_ball;           ///< id; default: the scenario's cue ball, else 0
  int target = 1;                        ///< id of the ball to pot, when `targets` is empty
  /// Ids of the legal targets: the plan pots any one of them (each target's
  /// candidates searched as a lone target's are, in one order of ease and
  /// one budget; the best shot of all chosen, PlannedShot::target naming its
  /// ball). Empty: {target}. No id twice, none the cue ball.
  std::vector<int> targets;
  std::optional<int> pocket;             ///< index into table.pockets (a called pocket); none: any pocket
  /// Call shot (WPA Rules of Play 1.6; 8-ball 3.x and 10-ball 9.x, not
  /// 9-ball): each shot counts a pot only in its own pocket (the one it aims
  /// at, PlannedShot::pocket, which the player calls), as the rules score
  /// it; false: a pot in any pocket counts. Its success estimates, and the
  /// leaves position play scores, change; the candidates do not.
  bool call_shot = false;
  /// The ball the cue ball must meet first (the rotation games' lowest
  /// numbered ball on the table: WPA Rules of Play 6.2, with sections 2
  /// and 9 for 9-ball and 10-ball). Given: a target other than it is played only by a
  /// combination through it (the cue ball sends it into the target; kinds
  /// must include combination), and a shot at it only by the other kinds (a
  /// combination through another ball would meet that ball first, a foul,
  /// WPA 6.2); none: every kind as asked, a combination through any ball.
  std::optional<int> ball_on;
  std::vector<ShotKind> kinds{ShotKind::direct, ShotKind::bank};
  CueStrikeNoise noise = tournament_noise();  ///< m/s, rad, rad, m, m
  std::uint64_t seed = 0;
  int simulations = 4000;                ///< engine runs at most, [kMinPlanSimulations, kMaxPlanSimulations]
  double side = 0.0;                     ///< tip offset to the right, ball radii (as the scenario's "cue")
  /// Tip offset above the centre, ball radii. None: centre ball, and where
  /// that misses or scratches, draw (-0.3), then follow (+0.3); then draw,
  /// centre and follow at three speeds screened under noise (header, step 4).
  /// Given: that height only, no variants.
  std::optional<double> height;
};

/// A ball where the noise-free shot leaves it.
/// A ball's end of the planned shot, noise-free (simulation/scenario.hpp).
using PredictedBall = BallAfterShot;

/// The robot's form of the strike (paper 001 relations, cue_strike.hpp): the
/// level cue's tip height and cue speed that give the cue ball the same
/// speed and topspin just after the strike as the planned strike does.
struct RobotForm {
  double tip_height = 0.0;  ///< b, m (level_cue_tip_height)
  double cue_speed = 0.0;   ///< V, m/s (level_cue_speed)
};

struct PlannedShot {
  int target = -1;                  ///< id of the ball it pots
  ShotKind kind = ShotKind::direct;
  int pocket = -1;                  ///< index into table.pockets
  std::string pocket_name;
  std::string cushion;              ///< bank, kick: the (first) cushion's name; direct, combination: empty
  /// The cushions in the order they are met: bank, the object ball's (one
  /// or two); kick, the cue ball's (one); direct, combination: none.
  std::vector<std::string> cushions;
  int intermediate_ball = -1;       ///< combination: id of the ball the cue ball sends into the target; else -1
  ShotAction strike;                ///< in the scenario's "cue" units: cue speed m/s, aim_deg, elevation_deg, side, height
  double geometric_aim_deg = 0.0;   ///< the first guess from geometry (ghost ball, mirror point)
  double cut_deg = 0.0;             ///< cut angle of the cue ball on the first ball it meets (geometry), degrees
  double combination_cut_deg = 0.0; ///< combination: cut angle of ball A on the target (geometry), degrees; else 0
  double ball_speed = 0.0;          ///< cue ball speed just after the strike, m/s
  RobotForm robot;
  double success_probability = 0.0; ///< under the request's noise
  double success_standard_error = 0.0;
  int noisy_shots = 0;              ///< N of the estimate
  /// The success probability the noise-free windows predict: the aim inside
  /// aim_window_deg under the aim noise and the side noise's squirt, times
  /// the cue speed inside speed_window under the speed noise (the planner's
  /// ranking before its noisy screen; header, step 4).
  double window_probability = 0.0;
  std::array<double, 2> aim_window_deg{};  ///< aims that pot, the rest held, noise-free
  std::array<double, 2> speed_window{};    ///< cue speeds that pot, the rest held, noise-free, m/s
  std::vector<PredictedBall> predicted;    ///< every ball's end, noise-free, in the scenario's order
  int simulations = 0;              ///< engine runs spent on this candidate
};

struct ShotPlanResult {
  PlannedShot shot;                       ///< the recommended one
  /// The other feasible shots, best first (by screened probability): of each
  /// (kind, pocket, cushions, intermediate ball) other than the chosen one's,
  /// its best variant only.
  std::vector<PlannedShot> alternatives;
  std::vector<std::string> rejected;      ///< each skipped candidate and why
  int cue_ball = 0;                       ///< id of the struck ball
  int simulations = 0;                    ///< engine runs in all (<= the request's budget)
  double seconds = 0.0;                   ///< wall-clock time of the plan
};

/// Plans the shot (header comment). The scenario's own "cue" strike is
/// ignored (its cue mass and tip restitution are used). Throws
/// InvalidArgument naming the field for bad input ("cue_ball", "target",
/// "targets", "pocket", "kinds", "simulations", "side", "height", "sigma ...", the
/// scenario as the simulator checks it) and NoFeasibleShot when no
/// candidate pots.
ShotPlanResult plan_shot(const Scenario& table_state, const PlanRequest& request);

/// The scenario with the planned strike as its "cue" (aim in degrees, offsets
/// in ball radii, as given) and the request's noise as its "noise":
/// run_scenario() of it plays the planned shot noise-free, bit for bit as
/// the planner simulated it.
Scenario scenario_with_shot(const Scenario& table_state, int cue_ball, const PlannedShot& shot,
                            const CueStrikeNoise& noise);

}  // namespace cueball
