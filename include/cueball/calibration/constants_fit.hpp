// The table's constants fitted across many tracked shots, every shot's
// strike refitted with them.
//
// Fitted: the cloth's mu_s, mu_r, mu_sp and the chosen cushion model's
// restitution and friction (the model is chosen by name, not fitted).
//
// Method, in two stages:
//  1. Nelder-Mead (1965) over the constants -- logarithms of the three cloth
//     frictions, the cushion's two constants as they are -- whose objective
//     is the total cost of the training shots, each shot's strike refitted
//     by 5 Levenberg-Marquardt iterations WARM-STARTED from the strikes of
//     the best constants so far (the incumbent: so a trial's value depends
//     on the constants and the incumbent, not on the simplex's path),
//     restarted with a fresh simplex while a restart gains; then a profile
//     over mu_sp (`spin_profile` values spanning a spin deceleration of 2
//     to 16 rad/s^2, the other constants held, every strike fitted afresh
//     at each) and, when another mu_sp wins, a simplex refining from it;
//     then `restarts` more simplexes from points along the valley where the
//     cushion's friction and restitution trade, each with its strikes
//     fitted afresh there, and the end points judged alike (each shot
//     under each point given the best of every run's strike for it). The simplex
//     needs no derivatives of a cost that jumps when a contact appears or
//     vanishes, and the strikes follow the constants nonlinearly.
//  2. A joint least-squares polish of the constants and every strike (6 a
//     shot) from there: Levenberg-Marquardt on the block-arrow normal
//     equations, each shot's 6 x 6 block eliminated (Schur complement) and a
//     5 x 5 system solved for the constants, as bundle adjustment does
//     (Triggs et al. 2000, sec. 6.1): 12 simulations a shot an iteration.
// Why two stages (each was tried alone on six synthetic shots, test_constants_fit):
// the joint LM from the strikes fitted under the start constants cannot move
// (its full step changes contacts, so it is damped to nothing; a
// continuation over growing windows of the record let mu_r run off, since
// early in a shot it trades against the cue speed); Nelder-Mead alone gets
// into the valley but crawls along it (the note that a cold joint
// fit did not converge is the same failure). Alternating blocks (strikes
// fixed, constants fitted) zig-zags: speed and mu_r, side spin and cushion
// friction are strongly coupled. Both stages accept only steps that lower
// the total cost.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cueball/calibration/strike_fit.hpp"

namespace cueball {

struct ConstantsFitOptions {
  int max_evaluations = 300;  ///< stage 1: evaluations of the simplex's objective, [1, 100000]
  int max_iterations = 20;    ///< stage 2: Levenberg-Marquardt iterations of the joint fit, [0, 10000]
  int threads = 1;            ///< shots refitted in parallel, [1, 256]
  /// Restarts of the simplex stage from other points (see fit_constants), [0, 16].
  int restarts = 2;
  /// Points of the profile over mu_sp after the first simplex (see
  /// fit_constants), [0, 16]; 0: none.
  int spin_profile = 7;
  /// Of the strikes fitted afresh (the restarts, the profile); calibrate
  /// passes its own.
  StrikeFitOptions strike;
};

/// The bootstrap over shots (Efron and Tibshirani 1993, ch. 6): each
/// replicate draws the training shots with replacement (seeded) and refits
/// the constants from the fitted ones -- a simplex of steps a third of the
/// first stage's, every strike warm-started from its fitted strike, a shot
/// drawn k times weighing k times -- so the spread of the replicates is how
/// far the constants move when the shots change, model error included
/// (the residuals of a shot are correlated in time, so a Gauss-Newton
/// covariance of the samples would be far too narrow).
struct BootstrapOptions {
  int replicates = 0;            ///< 0: no uncertainties; [0, 1000]
  std::uint64_t seed = 0;        ///< of the draws
  int max_evaluations = 60;      ///< of each replicate's simplex, [1, 100000]
  int threads = 1;               ///< [1, 256]
};

/// One fitted constant and its spread over the replicates.
struct ConstantSpread {
  std::string name;              ///< "mu_s", "mu_r", "mu_sp", "cushion_restitution", "cushion_friction"
  double value = 0.0;            ///< the fit on all training shots
  double std_dev = 0.0;          ///< of the replicates
  double p05 = 0.0, p95 = 0.0;   ///< their 5th and 95th percentiles
};

struct ConstantsFit {
  FitModel model;                  ///< the start's model with the fitted constants
  std::vector<StrikeFit> strikes;  ///< every training shot's strike under them
  double cost = 0.0;               ///< total over the training shots, m^2
  int evaluations = 0;             ///< stage 1's evaluations
  int iterations = 0;              ///< stage 2's iterations
  int restarts_taken = 0;          ///< 1 when the mu_sp profile's or a restart's point won over the first run's, else 0
};

/// Fits from `start` (its constants are the simplex's first vertex) and the
/// shots' strikes under it (`strikes`, one per shot). Throws InvalidArgument
/// for bad options ("max_evaluations", "max_iterations", "threads") or
/// when strikes.size() != shots.size().
ConstantsFit fit_constants(const std::vector<PreparedShot>& shots, const FitModel& start,
                           const std::vector<StrikeFit>& strikes, const ConstantsFitOptions& options = {});

/// The bootstrap's spread of the constants of `fit` (fitted on `shots`);
/// empty for 0 replicates. Throws InvalidArgument for bad options
/// ("bootstrap", "bootstrap_evaluations", "threads").
std::vector<ConstantSpread> bootstrap_constants(const std::vector<PreparedShot>& shots, const ConstantsFit& fit,
                                                const BootstrapOptions& options);

/// Runs `job(i)` for i in [0, n) on `threads` threads (the calling thread
/// among them); the first exception is rethrown.
void for_each_shot(int n, int threads, const std::function<void(int)>& job);

}  // namespace cueball
