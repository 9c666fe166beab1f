// Tests of the one-impulse cushion model of Han (2005),
// src/models/cushion/han_2005.cpp (equations H1-H5): the frictionless limit in
// closed form, a rolling head-on ball worked by hand, the stick and slip
// regimes of Coulomb's law, the angular impulse consistent with the linear
// one (R n x J / I), energy, mirror symmetry, the head-on plane, scale
// invariance, and validation.
#include "cueball/models/cushion/han_2005.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cueball/core/errors.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {
namespace {

constexpr double kPi = 3.14159265358979323846;

BallParameters pool_ball() { return pool_parameters().ball; }

Han2005Cushion han(double e = kHan2005Restitution, double mu = kHan2005Friction) {
  const BallParameters b = pool_ball();
  return han_2005_cushion(b, e, mu, 1.4 * b.radius);
}

double energy(const BallParameters& b, Vec3 v, Vec3 w) {
  return 0.5 * b.mass * (v.x * v.x + v.y * v.y + v.z * v.z) +
         0.5 * moment_of_inertia(b) * (w.x * w.x + w.y * w.y + w.z * w.z);
}

// A ball into the cushion: speed V, angle alpha from the cushion line, spins
// in units of V / R as in the paper (topspin along the motion, sidespin about Z).
IncomingBall incoming(double v, double alpha_deg, double k_top, double k_side) {
  return incoming_ball({v, alpha_deg * kPi / 180.0, k_top * v / pool_ball().radius, k_side * v / pool_ball().radius});
}

TEST(Han2005, FrictionlessReversesTheNormalComponentAlongTheContactNormalOnly) {
  const Han2005Cushion c = han(0.85, 0.0);
  const double cos2 = 1.0 - c.sin_theta * c.sin_theta;
  const IncomingBall in = incoming(1.3, 35.0, 0.7, -1.2);
  const CushionRebound out = han_2005_rebound(in, c);
  EXPECT_DOUBLE_EQ(out.velocity.x, in.velocity.x);
  EXPECT_NEAR(out.velocity.y, (1.0 - 1.85 * cos2) * in.velocity.y, 1e-15);
  EXPECT_EQ(out.velocity.z, 0.0);
  EXPECT_DOUBLE_EQ(out.angular_velocity.x, in.angular_velocity.x);
  EXPECT_DOUBLE_EQ(out.angular_velocity.y, in.angular_velocity.y);
  EXPECT_DOUBLE_EQ(out.angular_velocity.z, in.angular_velocity.z);
}

TEST(Han2005, RollingHeadOnBallWorkedByHand) {
  // v = (0, V, 0), w = (-V/R, 0, 0): slip at I along t is -V (1 + sin(theta)),
  // 1.4 V (2/7) M = 0.4 M V to stop it against mu P_n = 0.2 x 1.85 x cos(theta)
  // M V = 0.3391 M V: the contact slides, P_t = +mu P_n.
  const Han2005Cushion c = han();
  const double s = 0.4, cs = std::sqrt(0.84), V = 1.0, R = c.radius, M = c.mass;
  const CushionRebound out = han_2005_rebound({{0.0, V, 0.0}, {-V / R, 0.0, 0.0}}, c);
  const double pn = 1.85 * M * V * cs, pt = 0.2 * pn;
  EXPECT_NEAR(out.velocity.y, V + (-pn * cs - pt * s) / M, 1e-14);
  EXPECT_NEAR(out.velocity.y, -0.689644, 1e-6);
  EXPECT_NEAR(out.angular_velocity.x, -V / R + 2.5 * pt / (M * R), 1e-12);
  EXPECT_EQ(out.velocity.x, 0.0);
  EXPECT_EQ(out.angular_velocity.y, 0.0);
  EXPECT_EQ(out.angular_velocity.z, 0.0);
}

TEST(Han2005, StickingStopsTheSlipAlongTheCushion) {
  // A large mu: the impulse that stops the slip at I lies inside the cone, so
  // the surface's slip along X is zero after the impact (Z is not involved in it).
  const Han2005Cushion c = han(0.85, 1.0);
  const IncomingBall in = incoming(1.0, 40.0, 0.2, 0.3);
  const CushionRebound out = han_2005_rebound(in, c);
  const double cs = std::sqrt(1.0 - c.sin_theta * c.sin_theta);
  const double slip_x = out.velocity.x + c.radius * (out.angular_velocity.y * c.sin_theta - out.angular_velocity.z * cs);
  EXPECT_NEAR(slip_x, 0.0, 1e-14);
}

TEST(Han2005, SlidingFrictionIsMuTimesTheNormalImpulse) {
  const Han2005Cushion c = han();
  for (double alpha : {10.0, 30.0, 60.0}) {
    const IncomingBall in = incoming(2.0, alpha, 1.0, 1.5);
    const CushionRebound out = han_2005_rebound(in, c);
    const double cs = std::sqrt(1.0 - c.sin_theta * c.sin_theta);
    const double px = c.mass * (out.velocity.x - in.velocity.x);
    const double pt = (out.angular_velocity.x - in.angular_velocity.x) * c.mass * c.radius / 2.5;
    const double pn = 1.85 * c.mass * in.velocity.y * cs;
    EXPECT_NEAR(std::hypot(px, pt), 0.2 * pn, 1e-12 * pn) << alpha;
    // The normal impulse, from the change of yG': dyG' = (-P_n cos - P_t sin) / M.
    EXPECT_NEAR(-(c.mass * (out.velocity.y - in.velocity.y) + pt * c.sin_theta) / cs, pn, 1e-12 * pn) << alpha;
  }
}

TEST(Han2005, AngularImpulseIsTheMomentOfTheLinearOne) {
  // dw = R n x J / I: the X impulse turns the ball about Y and Z in the ratio
  // sin(theta) : -cos(theta).
  const Han2005Cushion c = han();
  const IncomingBall in = incoming(1.5, 25.0, -0.5, 2.0);
  const CushionRebound out = han_2005_rebound(in, c);
  const double px = c.mass * (out.velocity.x - in.velocity.x);
  const double k = 2.5 / (c.mass * c.radius);
  const double cs = std::sqrt(1.0 - c.sin_theta * c.sin_theta);
  EXPECT_NEAR(out.angular_velocity.y - in.angular_velocity.y, k * px * c.sin_theta, 1e-10);
  EXPECT_NEAR(out.angular_velocity.z - in.angular_velocity.z, -k * px * cs, 1e-10);
}

TEST(Han2005, EnergyNeverIncreases) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> speed(0.05, 6.0), angle(1.0, 90.0), spin(-3.0, 3.0), unit(0.0, 1.0);
  const BallParameters b = pool_ball();
  for (int i = 0; i < 20000; ++i) {
    const Han2005Cushion c = han(unit(rng), unit(rng));
    const IncomingBall in = incoming(speed(rng), angle(rng), spin(rng), spin(rng));
    const CushionRebound out = han_2005_rebound(in, c);
    const double before = energy(b, in.velocity, in.angular_velocity);
    ASSERT_LE(energy(b, out.velocity, out.angular_velocity), before * (1 + 1e-12)) << i;
  }
}

TEST(Han2005, LeavesTheCushionWithItsOwnConstantsButNotWithEveryE) {
  // With the published constants every ball leaves, even a hard draw into
  // the cushion; with e below 1/cos^2(theta) - 1 = 0.19 a frictionless ball
  // keeps (1 - (1 + e) cos^2(theta)) > 0 of its speed into it (the vertical
  // velocity Han drops is where the rest of the rebound went), which the
  // simulator takes as a resting contact with the cushion.
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> speed(0.05, 6.0), angle(1.0, 90.0), spin(-3.0, 3.0);
  for (int i = 0; i < 20000; ++i)
    ASSERT_LT(han_2005_rebound(incoming(speed(rng), angle(rng), spin(rng), spin(rng)), han()).velocity.y, 0.0) << i;
  EXPECT_GT(han_2005_rebound(incoming(1.0, 90.0, 0.0, 0.0), han(0.15, 0.0)).velocity.y, 0.0);
  EXPECT_LT(han_2005_rebound(incoming(1.0, 90.0, 0.0, 0.0), han(0.20, 0.0)).velocity.y, 0.0);
}

TEST(Han2005, MirrorImageAcrossTheNormalPlane) {
  // X -> -X: velocity (-vx, vy, vz); the spin, an axial vector, (wx, -wy, -wz).
  const Han2005Cushion c = han();
  const IncomingBall in = incoming(1.7, 33.0, 0.8, -1.3);
  const IncomingBall mirrored{{-in.velocity.x, in.velocity.y, 0.0},
                              {in.angular_velocity.x, -in.angular_velocity.y, -in.angular_velocity.z}};
  const CushionRebound a = han_2005_rebound(in, c), b = han_2005_rebound(mirrored, c);
  EXPECT_NEAR(b.velocity.x, -a.velocity.x, 1e-14);
  EXPECT_NEAR(b.velocity.y, a.velocity.y, 1e-14);
  EXPECT_NEAR(b.angular_velocity.x, a.angular_velocity.x, 1e-12);
  EXPECT_NEAR(b.angular_velocity.y, -a.angular_velocity.y, 1e-12);
  EXPECT_NEAR(b.angular_velocity.z, -a.angular_velocity.z, 1e-12);
}

TEST(Han2005, HeadOnStaysInItsPlaneAndScalesWithSpeed) {
  const Han2005Cushion c = han();
  const CushionRebound one = han_2005_rebound(incoming(1.0, 90.0, 0.6, 0.0), c);
  EXPECT_NEAR(one.velocity.x, 0.0, 1e-15);
  EXPECT_NEAR(one.angular_velocity.y, 0.0, 1e-12);
  EXPECT_NEAR(one.angular_velocity.z, 0.0, 1e-12);
  // H1-H5 are linear and homogeneous in the velocities within each regime.
  const CushionRebound a = han_2005_rebound(incoming(0.4, 37.0, 1.2, -0.7), c);
  const CushionRebound b = han_2005_rebound(incoming(2.8, 37.0, 1.2, -0.7), c);
  EXPECT_NEAR(b.velocity.x, 7.0 * a.velocity.x, 1e-13);
  EXPECT_NEAR(b.velocity.y, 7.0 * a.velocity.y, 1e-13);
  EXPECT_NEAR(b.angular_velocity.z, 7.0 * a.angular_velocity.z, 1e-10);
}

TEST(Han2005, ValidationNamesTheConstant) {
  Han2005Cushion c = han();
  EXPECT_NO_THROW(validate(c));
  c.friction = -0.1;
  try {
    validate(c);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "friction");
  }
  c = han();
  c.sin_theta = 1.0;
  EXPECT_THROW(validate(c), InvalidArgument);
  c = han();
  c.restitution = std::nan("");
  EXPECT_THROW(validate(c), InvalidArgument);
}

}  // namespace
}  // namespace cueball
