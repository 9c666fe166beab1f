// Level-cue strike relations; sources in cue_strike.hpp (Alciatore TP A.30,
// Marlow 1995).
#include "cueball/cue_strike.hpp"

#include <cmath>

namespace cueball {

double level_cue_tip_height(double v0, double w0, const BallParameters& ball) {
  // b = I w0 / (m v0) = 2 R^2 w0 / (5 v0)
  return 2.0 * ball.radius * ball.radius * w0 / (5.0 * v0);
}

double level_cue_speed(double v0, double tip_height, const BallParameters& ball, const CueParameters& cue) {
  const double offset = tip_height / ball.radius;
  const double effective = 1.0 + ball.mass / cue.mass + 2.5 * offset * offset;
  return v0 * effective / (1.0 + cue.tip_restitution);
}

bool cue_tip_offset_ok(double tip_height, const BallParameters& ball) {
  return std::abs(tip_height) <= kMiscueOffsetFraction * ball.radius;
}

}  // namespace cueball
