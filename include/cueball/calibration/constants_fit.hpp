// The table's constants fitted across many tracked shots, every shot's
// strike refitted with them.
//
// Fitted: the cloth's mu_s, mu_r, mu_sp and the chosen cushion model's
// restitution and friction (the model is chosen by name, not fitted).
//
// Method: an outer Nelder-Mead (1965) over the constants -- logarithms of
// the three cloth frictions, the cushion's two constants as they are --
// whose objective is the total cost of all the training shots, each shot's
// strike refitted by a few Levenberg-Marquardt iterations WARM-STARTED from
// the strikes of the best constants so far (the incumbent). Why not a
// joint least-squares fit of constants and every strike (6 N + 5
// parameters): it was tried on this data and did not converge (issue 28);
// the strikes of different shots do not interact, so eliminating them shot
// by shot (a variable-projection view: the outer cost is a minimum over the
// strikes) leaves a 5-parameter problem, and the simplex needs no
// derivatives of a cost that jumps when a contact appears or vanishes.
// Why not plain alternation (strikes fixed, constants fitted, repeat):
// speed and mu_r, side spin and cushion friction are strongly coupled, so
// alternating blocks zig-zag; refitting the strikes inside each evaluation
// follows the valley. The warm start from the incumbent (not from the last
// trial) makes the objective a function of the constants and the incumbent
// only, so a trial's value does not depend on the simplex's path.
#pragma once

#include <functional>
#include <vector>

#include "cueball/calibration/strike_fit.hpp"

namespace cueball {

struct ConstantsFitOptions {
  int max_evaluations = 60;   ///< outer objective evaluations, [1, 10000]
  int refine_iterations = 3;  ///< LM iterations of each strike refit per evaluation, [1, 100]
  int threads = 1;            ///< shots refitted in parallel, [1, 256]
};

struct ConstantsFit {
  FitModel model;                  ///< the start's model with the fitted constants
  std::vector<StrikeFit> strikes;  ///< every training shot's strike under them
  double cost = 0.0;               ///< total over the training shots, m^2
  int evaluations = 0;
};

/// Fits from `start` (its constants are the simplex's first vertex) and the
/// shots' strikes under it (`strikes`, one per shot). Throws InvalidArgument
/// for bad options ("max_evaluations", "refine_iterations", "threads") or
/// when strikes.size() != shots.size().
ConstantsFit fit_constants(const std::vector<PreparedShot>& shots, const FitModel& start,
                           const std::vector<StrikeFit>& strikes, const ConstantsFitOptions& options = {});

/// Runs `job(i)` for i in [0, n) on `threads` threads (the calling thread
/// among them); the first exception is rethrown.
void for_each_shot(int n, int threads, const std::function<void(int)>& job);

}  // namespace cueball
