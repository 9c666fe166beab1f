// Degrees: the conversion and an aim's one range, shared by the planners.
#pragma once

#include <cmath>
#include <numbers>

namespace cueball {

/// One degree in radians.
inline constexpr double kDegree = std::numbers::pi / 180.0;

/// An aim in degrees brought into (-180, 180], the same direction.
inline double wrapped_deg(double aim) {
  const double w = std::remainder(aim, 360.0);
  return w == -180.0 ? 180.0 : w;
}

}  // namespace cueball
