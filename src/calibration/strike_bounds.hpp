// Internal: the box of a fitted strike (speed, aim, elevation, side, height,
// strike time) and its projection, shared by the strike fit and the joint
// constants fit.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "cueball/calibration/tracked_shot.hpp"
#include "cueball/physics/cue_strike.hpp"

namespace cueball::detail {

enum StrikeParam { kSpeed, kAim, kElevation, kSide, kHeight, kStrike, kStrikeParams };

inline constexpr double kMaxTipOffset = 0.45;  // ball radii; the miscue limit is 0.5
inline constexpr double kMaxElevationDeg = 60.0;
/// Forward-difference steps: m/s, deg, deg, radii, radii, s.
inline constexpr std::array<double, kStrikeParams> kStrikeSteps{1e-3, 1e-3, 0.02, 1e-3, 1e-3, 1e-4};

struct StrikeBounds {
  std::vector<double> lower, upper;
};

/// Aim within 30 deg of the cue ball's first movement, elevation [0, 60]
/// deg, tip offsets within 0.45 radii, strike time between the cue ball's
/// last rest sample (at most 50 ms back) and its first moving one.
inline StrikeBounds strike_bounds(const PreparedShot& shot) {
  const double aim = shot.aim_estimate_deg;
  return {{0.05, aim - 30, 0.0, -kMaxTipOffset, -kMaxTipOffset, shot.strike_min},
          {kMaxCueSpeed, aim + 30, kMaxElevationDeg, kMaxTipOffset, kMaxTipOffset, shot.strike_max}};
}

/// The tip offsets brought within the circle of radius kMaxTipOffset.
inline void project_tip(std::vector<double>& q) {
  const double r = std::hypot(q[kSide], q[kHeight]);
  if (r > kMaxTipOffset) q[kSide] *= kMaxTipOffset / r, q[kHeight] *= kMaxTipOffset / r;
}

/// Into the box, then the tip circle.
inline void project_strike(const StrikeBounds& b, std::vector<double>& q) {
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = std::clamp(q[i], b.lower[i], b.upper[i]);
  project_tip(q);
}

}  // namespace cueball::detail
