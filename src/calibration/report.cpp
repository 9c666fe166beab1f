#include "cueball/calibration/report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cueball {

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double at = q * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (at - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

namespace {

double mean(const std::vector<double>& v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

}  // namespace

FitSummary summarize(const std::vector<ShotReport>& shots, bool held_out) {
  FitSummary s;
  std::vector<double> cue, all, object;
  double seconds = 0.0;
  for (const ShotReport& r : shots) {
    if (r.held_out != held_out) continue;
    ++s.shots;
    cue.push_back(r.fit.cue_rmse);
    all.push_back(r.fit.all_rmse);
    if (r.fit.ball_rmse.size() > 1) {
      double sum = 0.0;
      int n = 0;
      for (std::size_t j = 1; j < r.fit.ball_rmse.size(); ++j)
        if (std::isfinite(r.fit.ball_rmse[j])) sum += r.fit.ball_rmse[j] * r.fit.ball_rmse[j], ++n;
      if (n > 0) object.push_back(std::sqrt(sum / n));
    }
    s.contact_mismatches += r.fit.contact_mismatch ? 1 : 0;
    seconds += r.fit.seconds;
  }
  s.cue_rmse_median = quantile(cue, 0.5), s.cue_rmse_p90 = quantile(cue, 0.9), s.cue_rmse_mean = mean(cue);
  s.all_rmse_median = quantile(all, 0.5), s.all_rmse_p90 = quantile(all, 0.9), s.all_rmse_mean = mean(all);
  s.object_rmse_median = quantile(object, 0.5), s.object_rmse_p90 = quantile(object, 0.9);
  s.seconds_per_shot = s.shots > 0 ? seconds / s.shots : 0.0;
  return s;
}

}  // namespace cueball
