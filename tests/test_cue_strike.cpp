// Tests of the level-cue strike relations (src/cue_strike.cpp) against the
// impulse-momentum equations solved directly.
#include "cueball/cue_strike.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cueball {
namespace {

// Solve the strike directly: unknowns J (impulse) and V' (cue after), with
//   ball:  m v0 = J,  I w0 = J b
//   cue:   M (V' - V) = -J
//   restitution along the cue line: (v0 + w0 b) - V' = e V
struct Strike {
  double v0, w0;
};
Strike strike(double cue_speed, double b, const BallParameters& ball, const CueParameters& cue) {
  const double inertia = moment_of_inertia(ball);
  // (J/m + J b^2 / I) - (V - J/M) = e V  =>  J (1/m + b^2/I + 1/M) = (1 + e) V
  const double j = (1 + cue.tip_restitution) * cue_speed / (1 / ball.mass + b * b / inertia + 1 / cue.mass);
  return {j / ball.mass, j * b / inertia};
}

TEST(CueStrike, TipHeightReproducesTheRequestedSpinRatio) {
  const BallParameters ball = pool_parameters().ball;
  const CueParameters cue;
  for (double b_fraction : {-0.5, -0.3, 0.0, 0.2, 0.4, 0.5}) {
    const double b = b_fraction * ball.radius;
    const Strike s = strike(3.0, b, ball, cue);
    EXPECT_NEAR(level_cue_tip_height(s.v0, s.w0, ball), b, 1e-15);
    EXPECT_NEAR(level_cue_speed(s.v0, b, ball, cue), 3.0, 1e-12);
  }
}

TEST(CueStrike, NaturalRollIsAtSevenTenthsOfTheBallHeight) {
  const BallParameters ball = snooker_parameters().ball;
  const double v0 = 1.7;
  const double b = level_cue_tip_height(v0, v0 / ball.radius, ball);
  EXPECT_NEAR(b, 0.4 * ball.radius, 1e-15);
  EXPECT_NEAR(ball.radius + b, 0.7 * 2 * ball.radius, 1e-15);
  EXPECT_EQ(level_cue_tip_height(v0, 0.0, ball), 0.0);
}

TEST(CueStrike, MiscueLimitIsHalfTheRadius) {
  const BallParameters ball = pool_parameters().ball;
  EXPECT_TRUE(cue_tip_offset_ok(0.5 * ball.radius, ball));
  EXPECT_TRUE(cue_tip_offset_ok(-0.49 * ball.radius, ball));
  EXPECT_FALSE(cue_tip_offset_ok(0.51 * ball.radius, ball));
  EXPECT_FALSE(cue_tip_offset_ok(-0.6 * ball.radius, ball));
}

TEST(CueStrike, StrikeNeverCreatesEnergy) {
  const BallParameters ball = pool_parameters().ball;
  const CueParameters cue;  // e < 1
  for (double b_fraction : {-0.5, 0.0, 0.5}) {
    const double b = b_fraction * ball.radius;
    const double speed = 4.0;
    const Strike s = strike(speed, b, ball, cue);
    const double cue_after = speed - ball.mass * s.v0 / cue.mass;
    const double before = 0.5 * cue.mass * speed * speed;
    const double after = 0.5 * cue.mass * cue_after * cue_after + 0.5 * ball.mass * s.v0 * s.v0 +
                         0.5 * moment_of_inertia(ball) * s.w0 * s.w0;
    EXPECT_LT(after, before);
  }
}

}  // namespace
}  // namespace cueball
