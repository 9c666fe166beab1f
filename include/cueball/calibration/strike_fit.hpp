// One tracked shot's strike fitted by least squares: cue speed, aim,
// elevation, the two tip offsets and the strike time, so that the simulated
// positions of ALL balls match the tracked samples.
//
// Method (fit_strike):
//   1. screen: a grid of strikes around the estimate from the cue ball's
//      first samples (aim +-1.5 deg, speed x {0.8, 1, 1.25}, side and height
//      in {-0.35, 0, 0.35} ball radii) is played by simulate_many (the batch
//      API) and ranked by the distance of every ball's final position to its
//      last sample;
//   2. the best StrikeFitOptions::starts of them (and the plain centre-ball
//      estimate) are refined by Levenberg-Marquardt with a continuation over
//      the record: the residuals of the samples up to 0.6 s, then 1.5 s,
//      3 s, then the whole record, each stage starting where the last ended
//      (the early samples fix speed and aim while the cost is still smooth
//      in them; later ones bring in spin, cushions and the object balls);
//   3. the start with the lowest cost over the whole record wins. (Taking
//      the cheapest start whose contacts agree with the record's instead,
//      when one does, was tried on the recorded match's 30 training shots
//      under fixed constants: each of the 4 wrong-contact fits had an
//      agreeing start, but at 1.1-17x the cost, and 3 of the 4 cue-ball
//      RMSEs got worse, one from 6.3 to 45 cm; the wrong contacts there are
//      late ones, the second object ball met or missed after several
//      cushions, which a better start does not mend.)
// The residual of a sample at time t (after the estimated strike) is the
// simulated position at t - t_strike minus the tracked one, both axes, every
// ball weighted alike, and RMSE = sqrt(mean of squared distances).
#pragma once

#include <string>
#include <vector>

#include "cueball/calibration/tracked_shot.hpp"
#include "cueball/physics/cue_strike.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/simulator.hpp"

namespace cueball {

/// What a strike is fitted under: the table, the simulator's settings
/// (cloth, cushion and ball-collision constants) and the cue.
struct FitModel {
  Table table;
  SimulationSettings settings;
  CueParameters cue;
};

struct StrikeFitOptions {
  int starts = 32;                                 ///< refined starts after the screen, [1, 64]
  std::vector<double> windows = {0.6, 1.5, 3.0};   ///< continuation stages (s), then the whole record
  int stage_iterations = 6;                        ///< LM iterations per continuation stage
  int final_iterations = 15;                       ///< LM iterations on the whole record
};

struct StrikeFit {
  ShotAction action;                 ///< speed m/s, aim and elevation deg, side and height ball radii
  double strike_offset = 0.0;        ///< strike time on the samples' clock (s after PreparedShot::origin)
  double strike_time = 0.0;          ///< the same on the record's clock
  double cost = 0.0;                 ///< sum of squared residuals, m^2
  std::vector<double> ball_rmse;     ///< per ball, layout order, m (NaN for a ball without samples after the strike)
  double cue_rmse = 0.0;             ///< the cue ball's RMSE, m
  double all_rmse = 0.0;             ///< over every sample of every ball, m
  /// The simulated ball moved kMoveThreshold or more from the layout (a
  /// graze that moves it less is not seen by a tracker either).
  std::vector<char> moved_simulated;
  int first_contact = -1;            ///< the object ball the simulated cue ball struck first (layout index), -1 none
  /// A ball moved in the simulation but not in the record, or the other way
  /// round, or the cue ball struck another ball first than the record's
  /// PreparedShot::first_object_ball: the fit found (or missed) a contact
  /// the real balls did not make.
  bool contact_mismatch = false;
  int simulations = 0;
  double seconds = 0.0;
};

/// The multi-start fit described above. Throws InvalidArgument when the
/// model or the layout fails the simulator's checks.
StrikeFit fit_strike(const PreparedShot& shot, const FitModel& model, const StrikeFitOptions& options = {});

/// Levenberg-Marquardt on the whole record from `start` only (a warm start:
/// the constants fit refits strikes so after each change of the constants).
StrikeFit refine_strike(const PreparedShot& shot, const FitModel& model, const StrikeFit& start, int iterations);

/// The fit's figures (cost, RMSEs, moved, contact_mismatch) of a strike.
StrikeFit evaluate_strike(const PreparedShot& shot, const FitModel& model, const ShotAction& action, double strike_offset);

/// The simulated positions at the samples' times, in the order of
/// shot.samples (x, y interleaved), for a strike; false when the simulation
/// fails. `window`: only the samples up to that time (<= 0: all).
bool simulated_residuals(const PreparedShot& shot, const FitModel& model, const ShotAction& action, double strike_offset,
                         double window, std::vector<double>& residuals);

/// The simulated paths of a strike, for drawing: per ball (layout order)
/// its centre every `step` seconds (> 0) from the strike until the last
/// ball stops or the record ends, whichever is later, points closer than
/// 2 mm to the last one kept left out (a resting ball is one point). Times
/// as FitSample::t; empty when the simulation fails.
std::vector<std::vector<Vec2>> simulated_paths(const PreparedShot& shot, const FitModel& model, const ShotAction& action,
                                               double strike_offset, double step = 0.02);

}  // namespace cueball
