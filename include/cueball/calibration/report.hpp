// What a calibration reports: per shot and per ball the RMSE, the summary
// over a set of shots (median, 90th percentile, mean), the shots whose fit
// made (or missed) a contact the real balls did not.
#pragma once

#include <string>
#include <vector>

#include "cueball/calibration/strike_fit.hpp"

namespace cueball {

/// One shot's fit as reported.
struct ShotReport {
  std::string id;
  bool held_out = false;             ///< not used to fit the constants
  std::vector<std::string> balls;    ///< names, layout order (the cue ball first)
  StrikeFit fit;
  std::vector<std::string> notes;    ///< from prepare_shot
};

/// Summary statistics of a set of shots (metres). Percentiles by linear
/// interpolation between order statistics (the p-quantile at (n - 1) p).
struct FitSummary {
  int shots = 0;
  double cue_rmse_median = 0.0, cue_rmse_p90 = 0.0, cue_rmse_mean = 0.0;
  double all_rmse_median = 0.0, all_rmse_p90 = 0.0, all_rmse_mean = 0.0;
  /// Object balls: per shot the root mean square of their RMSEs.
  double object_rmse_median = 0.0, object_rmse_p90 = 0.0;
  int contact_mismatches = 0;        ///< shots with StrikeFit::contact_mismatch
  double seconds_per_shot = 0.0;     ///< mean strike-fit time
};

/// The quantile q in [0, 1] of `values` (NaN for none).
double quantile(std::vector<double> values, double q);

/// The summary of the held-out shots (held_out true) or the training ones.
FitSummary summarize(const std::vector<ShotReport>& shots, bool held_out);

}  // namespace cueball
