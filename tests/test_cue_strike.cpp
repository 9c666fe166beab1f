// Tests of the cue strike (src/physics/cue_strike.cpp): the level-cue relations and
// the general strike against the impulse-momentum equations solved directly
// (a linear system, not the closed form), against Leckie & Greenspan's printed
// formulas after the change of parameters (C7), and against conservation and
// symmetry laws; validation and execution noise.
#include "cueball/physics/cue_strike.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/errors.hpp"

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


// ===========================================================================
// The general strike: CueStrike -> BallState.

constexpr double kPi = std::numbers::pi;

// Independent solution of the strike: the impulse-momentum and restitution
// equations written out in the table frame as an 8x8 linear system in
// x = (J, V', v_x, v_y, v_z, w_x, w_y, w_z), solved by Gaussian elimination.
// Geometry from the definitions: u the aim, d the cue's travel (u tilted down
// by theta), s = u x z the shooter's right, e_up = s x d, contact
// r = a s + b e_up - c d on the sphere.
struct Solved {
  double impulse;    // J, N s
  double cue_after;  // V', m/s
  Vec3 v;            // ball velocity before the bed absorbs the vertical part
  Vec3 w;            // ball angular velocity
  Vec3 r, d;         // contact point and cue direction
};

Solved solve_strike(const CueStrike& k, const BallParameters& ball, const CueParameters& cue) {
  const Vec3 z{0, 0, 1};
  const Vec3 u{std::cos(k.aim), std::sin(k.aim), 0};
  const Vec3 d = std::cos(k.elevation) * u - std::sin(k.elevation) * z;
  const Vec3 s = cross(u, z);
  const Vec3 e_up = cross(s, d);
  const double radius = ball.radius;
  const double c =
      std::sqrt(radius * radius - k.side_offset * k.side_offset - k.height_offset * k.height_offset);
  const Vec3 r = k.side_offset * s + k.height_offset * e_up - c * d;
  const Vec3 rxd = cross(r, d);
  const double m = ball.mass, big_m = cue.mass, inertia = moment_of_inertia(ball), e = cue.tip_restitution;

  std::array<std::array<double, 9>, 8> a{};  // augmented matrix
  // cue: M V' + J = M V
  a[0][0] = 1;
  a[0][1] = big_m;
  a[0][8] = big_m * k.speed;
  // ball momentum: m v_i - J d_i = 0
  const double dv[3] = {d.x, d.y, d.z};
  const double rv[3] = {rxd.x, rxd.y, rxd.z};
  for (int i = 0; i < 3; ++i) {
    a[static_cast<std::size_t>(1 + i)][0] = -dv[i];
    a[static_cast<std::size_t>(1 + i)][static_cast<std::size_t>(2 + i)] = m;
    // angular momentum about the centre: I w_i - J (r x d)_i = 0
    a[static_cast<std::size_t>(4 + i)][0] = -rv[i];
    a[static_cast<std::size_t>(4 + i)][static_cast<std::size_t>(5 + i)] = inertia;
  }
  // restitution along the cue: (v + w x r) . d - V' = e V, (w x r) . d = w . (r x d)
  a[7][1] = -1;
  for (int i = 0; i < 3; ++i) {
    a[7][static_cast<std::size_t>(2 + i)] = dv[i];
    a[7][static_cast<std::size_t>(5 + i)] = rv[i];
  }
  a[7][8] = e * k.speed;

  for (std::size_t col = 0; col < 8; ++col) {
    std::size_t pivot = col;
    for (std::size_t row = col + 1; row < 8; ++row)
      if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
    std::swap(a[col], a[pivot]);
    for (std::size_t row = 0; row < 8; ++row) {
      if (row == col) continue;
      const double f = a[row][col] / a[col][col];
      for (std::size_t k2 = col; k2 < 9; ++k2) a[row][k2] -= f * a[col][k2];
    }
  }
  std::array<double, 8> x{};
  for (std::size_t i = 0; i < 8; ++i) x[i] = a[i][8] / a[i][i];
  return {x[0], x[1], {x[2], x[3], x[4]}, {x[5], x[6], x[7]}, r, d};
}

void expect_vec_near(Vec2 got, Vec2 want, double tol, const char* what) {
  EXPECT_NEAR(got.x, want.x, tol) << what;
  EXPECT_NEAR(got.y, want.y, tol) << what;
}
void expect_vec_near(Vec3 got, Vec3 want, double tol, const char* what) {
  EXPECT_NEAR(got.x, want.x, tol) << what;
  EXPECT_NEAR(got.y, want.y, tol) << what;
  EXPECT_NEAR(got.z, want.z, tol) << what;
}

// Random strikes spanning the accepted ranges, the offset inside the miscue
// limit (uniform over the disc's area).
std::vector<CueStrike> random_strikes(const BallParameters& ball, int n, unsigned seed, double max_elevation = 1.5) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> speed(0.05, kMaxCueSpeed), aim(-kPi, kPi), elev(0.0, max_elevation),
      unit(0.0, 1.0);
  std::vector<CueStrike> out;
  for (int i = 0; i < n; ++i) {
    const double rho = kMiscueOffsetFraction * ball.radius * std::sqrt(unit(rng));
    const double angle = 2 * kPi * unit(rng);
    out.push_back({speed(rng), aim(rng), elev(rng), rho * std::cos(angle), rho * std::sin(angle)});
  }
  return out;
}

const BallParameters kPool = pool_parameters().ball;
const BallParameters kSnooker = snooker_parameters().ball;

TEST(StrikeBall, LevelCentreHitHasNoSpinAndGoesAlongTheAim) {
  const CueParameters cue;
  for (double aim : {0.0, 0.3, 1.2, -2.0, kPi}) {
    const CueStrike k{2.5, aim, 0.0, 0.0, 0.0};
    const BallState s = strike_ball(k, {0.4, 0.7}, kPool, cue);
    EXPECT_EQ(s.angular_velocity, (Vec3{0, 0, 0}));
    const Vec2 u{std::cos(aim), std::sin(aim)};
    EXPECT_NEAR(cross(u, s.velocity), 0.0, 1e-15);
    EXPECT_GT(dot(u, s.velocity), 0.0);
    // Momentum exchange of two bodies along a line: v = (1 + e) M V / (M + m).
    EXPECT_NEAR(norm(s.velocity), (1 + cue.tip_restitution) * cue.mass * 2.5 / (cue.mass + kPool.mass), 1e-14);
    EXPECT_EQ(s.position, (Vec2{0.4, 0.7}));
  }
}

TEST(StrikeBall, ElevatedCueAimedThroughTheCentreGivesNoSpin) {
  // a = b = 0 puts the cue's axis through the centre at every elevation: no
  // torque, and the bed takes the vertical part of the impulse.
  const CueParameters cue;
  const BallState level = strike_ball({3.0, 0.5, 0.0, 0.0, 0.0}, {}, kPool, cue);
  for (double theta : {0.1, 0.5, 1.0, 1.4}) {
    const BallState s = strike_ball({3.0, 0.5, theta, 0.0, 0.0}, {}, kPool, cue);
    EXPECT_EQ(s.angular_velocity, (Vec3{0, 0, 0}));
    expect_vec_near(s.velocity, std::cos(theta) * level.velocity, 1e-14, "horizontal part of the level strike");
  }
}

TEST(StrikeBall, LevelCueAgreesWithTheLevelCueRelations) {
  const CueParameters cue{0.5, 0.8};
  for (const BallParameters& ball : {kPool, kSnooker}) {
    for (double b_fraction : {-0.5, -0.25, 0.0, 0.1, 0.4, 0.5}) {
      const double b = b_fraction * ball.radius;
      for (double aim : {0.0, 2.2}) {
        const CueStrike k{4.0, aim, 0.0, 0.0, b};
        const BallState s = strike_ball(k, {}, ball, cue);
        const Vec2 u{std::cos(aim), std::sin(aim)};
        const double v0 = dot(s.velocity, u);
        // topspin about z x u (positive turns the ball the way it moves)
        const double w0 = dot(horizontal(s.angular_velocity), perp(u));
        EXPECT_NEAR(level_cue_speed(v0, b, ball, cue), 4.0, 1e-12);
        EXPECT_NEAR(level_cue_tip_height(v0, w0, ball), b, 1e-15);
        EXPECT_NEAR(s.angular_velocity.z, 0.0, 1e-12);
        // and the original test's level-cue solution
        const Strike ref = strike(4.0, b, ball, cue);
        EXPECT_NEAR(v0, ref.v0, 1e-13);
        EXPECT_NEAR(w0, ref.w0, 1e-10);
      }
    }
  }
}

TEST(StrikeBall, SatisfiesTheImpulseMomentumAndRestitutionEquations) {
  // The impulse along the cue alone: squirt off (end mass 0; SquirtSatisfies... below).
  for (const CueParameters cue : {CueParameters{0.54, 0.75, 0.0}, CueParameters{0.45, 0.71, 0.0},
                                  CueParameters{0.65, 0.87, 0.0}, CueParameters{0.2, 1.0, 0.0}}) {
    for (const CueStrike& k : random_strikes(kPool, 400, 7)) {
      const Solved ref = solve_strike(k, kPool, cue);
      const BallState s = strike_ball(k, {}, kPool, cue);
      const double vs = 1e-13 * k.speed, ws = vs / kPool.radius;
      // The bed removes only the vertical velocity; the spin is untouched.
      expect_vec_near(s.velocity, horizontal(ref.v), vs, "v");
      expect_vec_near(s.angular_velocity, ref.w, ws, "w");
      EXPECT_LE(ref.v.z, 0.0);  // the cue pushes the ball into the bed, never up
      // Re-check the laws from the returned state alone: J = m |v| / cos(theta).
      const double j = kPool.mass * norm(s.velocity) / std::cos(k.elevation);
      EXPECT_NEAR(j, ref.impulse, 1e-12 * ref.impulse + 1e-15);
      const Vec3 l = moment_of_inertia(kPool) * s.angular_velocity;  // I w = r x J d
      expect_vec_near(l, j * cross(ref.r, ref.d), 1e-12 * j * kPool.radius, "angular momentum");
      const double cue_after = k.speed - j / cue.mass;
      const Vec3 v3{s.velocity.x, s.velocity.y, -j * std::sin(k.elevation) / kPool.mass};
      const double separation = dot(v3 + cross(s.angular_velocity, ref.r), ref.d) - cue_after;
      EXPECT_NEAR(separation, cue.tip_restitution * k.speed, 1e-12 * k.speed);
    }
  }
}

TEST(StrikeBall, LeckieGreenspanFormulasAgreeAfterTheChangeOfParameters) {
  // [LG]'s printed strike, with their constant 2 written (1 + e): ball frame
  // with the cue along -y and x to the shooter's left; contact (a_LG, c_LG, b_LG)
  // with b_LG the height above the centre. Rotated into the table by phi + pi/2.
  // [LG] has no squirt: end mass 0.
  const CueParameters cue{0.54, 0.8, 0.0};
  const double radius = kSnooker.radius, m = kSnooker.mass, inertia = moment_of_inertia(kSnooker);
  for (const CueStrike& k : random_strikes(kSnooker, 300, 11)) {
    const double th = k.elevation;
    const double c = std::sqrt(radius * radius - k.side_offset * k.side_offset - k.height_offset * k.height_offset);
    const double a_lg = -k.side_offset;                                        // (C7)
    const double b_lg = k.height_offset * std::cos(th) + c * std::sin(th);     // (C7)
    const double c_lg = c * std::cos(th) - k.height_offset * std::sin(th);     // (C7)
    ASSERT_NEAR(a_lg * a_lg + b_lg * b_lg + c_lg * c_lg, radius * radius, 1e-18);
    const double bracket = a_lg * a_lg + b_lg * b_lg * std::cos(th) * std::cos(th) +
                           c_lg * c_lg * std::sin(th) * std::sin(th) - 2 * b_lg * c_lg * std::cos(th) * std::sin(th);
    const double f = (1 + cue.tip_restitution) * m * k.speed / (1 + m / cue.mass + 5 / (2 * radius * radius) * bracket);
    const Vec3 v_b{0, -f / m * std::cos(th), 0};
    const Vec3 w_b = (f / inertia) * Vec3{-c_lg * std::sin(th) + b_lg * std::cos(th), a_lg * std::sin(th),
                                          -a_lg * std::cos(th)};
    const double rot = k.aim + kPi / 2;
    const auto rotate = [rot](Vec3 p) {
      return Vec3{std::cos(rot) * p.x - std::sin(rot) * p.y, std::sin(rot) * p.x + std::cos(rot) * p.y, p.z};
    };
    const BallState s = strike_ball(k, {}, kSnooker, cue);
    expect_vec_near(s.velocity, horizontal(rotate(v_b)), 1e-13 * k.speed, "v");
    expect_vec_near(s.angular_velocity, rotate(w_b), 1e-13 * k.speed / radius, "w");
  }
}

TEST(StrikeBall, RotatingTheAimRotatesTheResult) {
  const CueParameters cue;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> turn(-10.0, 10.0);
  for (CueStrike k : random_strikes(kPool, 200, 5)) {
    k.aim = 0.0;
    const BallState base = strike_ball(k, {}, kPool, cue);
    const double phi = turn(rng);
    k.aim = phi;
    const BallState s = strike_ball(k, {}, kPool, cue);
    const auto rot = [phi](Vec2 p) {
      return Vec2{std::cos(phi) * p.x - std::sin(phi) * p.y, std::sin(phi) * p.x + std::cos(phi) * p.y};
    };
    const double vs = 1e-13 * k.speed, ws = vs / kPool.radius;
    expect_vec_near(s.velocity, rot(base.velocity), vs, "v");
    expect_vec_near(horizontal(s.angular_velocity), rot(horizontal(base.angular_velocity)), ws, "w horizontal");
    EXPECT_NEAR(s.angular_velocity.z, base.angular_velocity.z, ws);
    EXPECT_NEAR(norm(s.velocity), norm(base.velocity), vs);
  }
}

TEST(StrikeBall, MirroringTheSideOffsetMirrorsTheSpin) {
  // Reflection in the vertical plane of the cue (aim along +x: y -> -y). A
  // polar vector flips its y; the angular velocity (axial) keeps w_y and
  // flips w_x and w_z.
  const CueParameters cue;
  for (CueStrike k : random_strikes(kPool, 200, 9)) {
    k.aim = 0.0;
    const BallState s = strike_ball(k, {}, kPool, cue);
    k.side_offset = -k.side_offset;
    const BallState m = strike_ball(k, {}, kPool, cue);
    const double vs = 1e-13 * k.speed, ws = vs / kPool.radius;
    expect_vec_near(m.velocity, {s.velocity.x, -s.velocity.y}, vs, "v");
    expect_vec_near(m.angular_velocity, {-s.angular_velocity.x, s.angular_velocity.y, -s.angular_velocity.z}, ws, "w");
  }
}

TEST(StrikeBall, StrikingAtSevenTenthsOfTheHeightGivesNaturalRoll) {
  const CueParameters cue;
  for (const BallParameters& ball : {kPool, kSnooker}) {
    for (double aim : {0.0, 0.7, -2.9}) {
      const double b = 0.4 * ball.radius;
      const BallState s = strike_ball({3.0, aim, 0.0, 0.0, b}, {}, ball, cue);
      const Vec2 slip = slip_velocity(s, ball.radius);  // cloth_motion.hpp's convention
      EXPECT_LT(norm(slip), 1e-14);
      Parameters p = pool_parameters();
      p.ball = ball;
      EXPECT_EQ(motion_phase(s, p), MotionPhase::rolling);
      // Above 2R/5 the ball is overspun (slip against the motion), below it
      // slips forward, most of all for draw.
      const Vec2 u{std::cos(aim), std::sin(aim)};
      const double v = norm(s.velocity);
      const BallState over = strike_ball({3.0, aim, 0.0, 0.0, 0.45 * ball.radius}, {}, ball, cue);
      EXPECT_LT(dot(slip_velocity(over, ball.radius), u), 0.0);
      const BallState stun = strike_ball({3.0, aim, 0.0, 0.0, 0.0}, {}, ball, cue);
      EXPECT_NEAR(dot(slip_velocity(stun, ball.radius), u), norm(stun.velocity), 1e-14);
      const BallState draw = strike_ball({3.0, aim, 0.0, 0.0, -0.3 * ball.radius}, {}, ball, cue);
      EXPECT_GT(dot(slip_velocity(draw, ball.radius), u), norm(draw.velocity));
      EXPECT_GT(v, 0.0);
    }
  }
}

TEST(StrikeBall, RightEnglishSpinsAnticlockwiseSeenFromAbove) {
  // Convention: a > 0 is right english and gives w_z > 0 (anticlockwise seen
  // from above, cloth_motion.hpp): the tip pushes the ball's right side forward.
  const CueParameters cue;
  for (double aim : {0.0, 1.0, 2.5, -1.7}) {
    for (double theta : {0.0, 0.3, 1.2}) {
      const double a = 0.3 * kPool.radius;
      const BallState right = strike_ball({2.0, aim, theta, a, 0.1 * kPool.radius}, {}, kPool, cue);
      const BallState left = strike_ball({2.0, aim, theta, -a, 0.1 * kPool.radius}, {}, kPool, cue);
      EXPECT_GT(right.angular_velocity.z, 0.0);
      EXPECT_LT(left.angular_velocity.z, 0.0);
      // Torque check from first principles: the contact is to the right of
      // the cue line (-y for aim +x), the push forward; z . (r x F) > 0.
      const Vec2 u{std::cos(aim), std::sin(aim)};
      const Vec2 right_side = -perp(u);
      EXPECT_GT(cross(a * right_side, u), 0.0);
    }
  }
}

TEST(StrikeBall, ElevatedRightEnglishSwervesToTheRight) {
  // With the butt raised, right english spins the ball about the aim too: the
  // bottom of the ball slips to the left, cloth friction pushes it right, and
  // the path curves right of the aim line (cloth_motion.hpp's evolve()).
  const CueParameters cue;
  const Parameters p = pool_parameters();
  for (double aim : {0.0, 0.9, -2.4}) {
    const Vec2 u{std::cos(aim), std::sin(aim)};
    const Vec2 right_side = -perp(u);
    const BallState s = strike_ball({2.0, aim, 1.2, 0.4 * p.ball.radius, 0.0}, {1.0, 0.5}, p.ball, cue);
    EXPECT_LT(dot(slip_velocity(s, p.ball.radius), right_side), 0.0);
    const BallState later = evolve(s, 0.5, p);
    EXPECT_GT(dot(later.position - s.position, right_side), 1e-3);
    // A level cue does not swerve: the slip stays on the line the ball
    // leaves along (the aim line turned by the squirt), so friction only
    // slows it.
    const BallState level = strike_ball({2.0, aim, 0.0, 0.4 * p.ball.radius, 0.0}, {1.0, 0.5}, p.ball, cue);
    EXPECT_NEAR(cross(slip_velocity(level, p.ball.radius), level.velocity), 0.0, 1e-14);
  }
}

// Squirt (C8): Alciatore's TP A.31 formula, for a level cue without height offset,
//     tan(alpha) = (5/2) x sqrt(1 - x^2) / (1 + m_b/m_e + (5/2)(1 - x^2)).
double alciatore_squirt_deg(double x, double mass_ratio) {
  return std::atan(2.5 * x * std::sqrt(1 - x * x) / (1 + mass_ratio + 2.5 * (1 - x * x))) * 180.0 / kPi;
}

TEST(Squirt, MatchesAlciatoresFormula) {
  // The issue's value: m_b/m_e = 20, x = 0.2 gives 1.1994 degrees.
  EXPECT_NEAR(alciatore_squirt_deg(0.2, 20.0), 1.1994, 5e-5);
  for (double ratio : {10.0, 20.0, 35.0}) {
    for (double x : {0.05, 0.2, 0.35, 0.5}) {
      const CueParameters cue{0.54, 0.75, kPool.mass / ratio};
      const double alpha = squirt_angle(x * kPool.radius, 0.0, kPool, cue) * 180.0 / kPi;
      EXPECT_NEAR(alpha, alciatore_squirt_deg(x, ratio), 1e-12) << ratio << " " << x;
      // Right english (x > 0) squirts left of the aim; left english right.
      EXPECT_GT(alpha, 0.0);
      EXPECT_NEAR(squirt_angle(-x * kPool.radius, 0.0, kPool, cue), -alpha * kPi / 180.0, 1e-15);
    }
  }
  // The default end mass: 2.6 degrees at half a radius of english.
  EXPECT_NEAR(squirt_angle(0.5 * kPool.radius, 0.0, kPool, CueParameters{}) * 180.0 / kPi, 2.57, 0.01);
  // No end mass, no squirt; no side offset, no squirt.
  EXPECT_EQ(squirt_angle(0.3 * kPool.radius, 0.1 * kPool.radius, kPool, CueParameters{0.54, 0.75, 0.0}), 0.0);
  EXPECT_EQ(squirt_angle(0.0, 0.3 * kPool.radius, kPool, CueParameters{}), 0.0);
}

TEST(Squirt, SatisfiesTheMomentumEquationsAndTheNoSlipConditionAcrossTheCue) {
  // Two impulses, J along the cue (C3) and J_s across it (C8): the returned
  // state must satisfy m v = horizontal(J d + J_s s), I w = r x (J d + J_s s)
  // and, across the cue, the contact point moving with the end mass:
  // (v + w x r) . s = -J_s / m_e. J comes from the rigid strike (end mass 0).
  for (double end_mass : {0.004, kDefaultCueEndMass, 0.03}) {
    const CueParameters cue{0.54, 0.75, end_mass};
    for (const CueStrike& k : random_strikes(kPool, 300, 17)) {
      const Solved ref = solve_strike(k, kPool, CueParameters{cue.mass, cue.tip_restitution, 0.0});
      const BallState st = strike_ball(k, {}, kPool, cue);
      const Vec3 z{0, 0, 1};
      const Vec3 u{std::cos(k.aim), std::sin(k.aim), 0};
      const Vec3 s = cross(u, z);
      const double js = kPool.mass * dot(Vec3{st.velocity.x, st.velocity.y, 0.0}, s);
      const Vec3 impulse = ref.impulse * ref.d + js * s;
      const double vs = 1e-12 * k.speed;
      expect_vec_near(st.velocity, horizontal(impulse) / kPool.mass, vs, "v");
      expect_vec_near(moment_of_inertia(kPool) * st.angular_velocity, cross(ref.r, impulse),
                      1e-12 * ref.impulse * kPool.radius, "angular momentum");
      const Vec3 v3{st.velocity.x, st.velocity.y, impulse.z / kPool.mass};
      EXPECT_NEAR(dot(v3 + cross(st.angular_velocity, ref.r), s), -js / end_mass, vs);
      // Right english (a > 0) pushes the ball to the left (-s).
      if (k.side_offset != 0.0) {
        EXPECT_EQ(std::signbit(js), k.side_offset > 0.0);
      }
    }
  }
}

TEST(Squirt, TheSimulatedCueBallLeavesAtTheSquirtAngle) {
  // Through the engine: the cue ball's path, struck level with right english
  // along +x, departs to the left of the aim at alpha, and straight.
  const Parameters p = pool_parameters();
  const CueParameters cue;
  const double a = 0.4 * p.ball.radius;
  const BallState s = strike_ball({2.0, 0.0, 0.0, a, 0.0}, {0.5, 0.6}, p.ball, cue);
  const double alpha = squirt_angle(a, 0.0, p.ball, cue);
  EXPECT_NEAR(std::atan2(s.velocity.y, s.velocity.x), alpha, 1e-15);
  const BallState later = evolve(s, 0.3, p);
  const Vec2 moved = later.position - s.position;
  EXPECT_GT(moved.y, 0.0);
  EXPECT_NEAR(std::atan2(moved.y, moved.x), alpha, 1e-12);
}

TEST(StrikeBall, BallEnergyNeverExceedsTheCues) {
  for (const CueParameters cue : {CueParameters{}, CueParameters{0.1, 1.0}, CueParameters{2.0, 0.87},
                                  CueParameters{0.17, 1.0}}) {
    for (const BallParameters& ball : {kPool, kSnooker}) {
      for (const CueStrike& k : random_strikes(ball, 300, 13)) {
        const double cue_energy = 0.5 * cue.mass * k.speed * k.speed;
        const BallState s = strike_ball(k, {}, ball, cue);
        const double ball_energy = kinetic_energy(s, ball);
        EXPECT_LE(ball_energy, cue_energy * (1 + 1e-12));
        // And the cue keeps what the ball did not take (free ball, before the bed):
        const Solved ref = solve_strike(k, ball, cue);
        const double after = 0.5 * cue.mass * ref.cue_after * ref.cue_after + 0.5 * ball.mass * dot(ref.v, ref.v) +
                             0.5 * moment_of_inertia(ball) * dot(ref.w, ref.w);
        EXPECT_LE(after, cue_energy * (1 + 1e-12));
        if (cue.tip_restitution == 1.0) {
          EXPECT_NEAR(after, cue_energy, 1e-12 * cue_energy);
        }
      }
    }
  }
  // Equal masses, e = 1, centre hit: the whole energy passes to the ball,
  // the bound is reached exactly (Newton's cradle).
  const BallParameters ball = kPool;
  const CueParameters same{ball.mass, 1.0};
  const BallState s = strike_ball({3.0, 0.2, 0.0, 0.0, 0.0}, {}, ball, same);
  EXPECT_NEAR(kinetic_energy(s, ball), 0.5 * same.mass * 9.0, 1e-13);
}

TEST(StrikeBall, CheckedAndUncheckedKernelsAgree) {
  const CueParameters cue;
  for (const CueStrike& k : random_strikes(kSnooker, 50, 17)) {
    const BallState a = strike_ball(k, {0.1, 0.2}, kSnooker, cue);
    const BallState b = strike_ball_unchecked(k, {0.1, 0.2}, kSnooker, cue);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.velocity, b.velocity);
    EXPECT_EQ(a.angular_velocity, b.angular_velocity);
  }
}

// --------------------------------------------------------------- validation

// The InvalidArgument thrown for `k`, or a failure if none.
void expect_rejected(const CueStrike& k, const std::string& field, const std::string& range,
                     const BallParameters& ball = kPool, const CueParameters& cue = {}) {
  try {
    (void)strike_ball(k, {}, ball, cue);
    ADD_FAILURE() << "accepted a strike with bad " << field;
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), field) << e.what();
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(range), std::string::npos) << e.what();
  }
}

TEST(StrikeBallValidation, MiscueBeyondHalfTheRadiusIsAnErrorNamingTheTipOffset) {
  const double radius = kPool.radius;
  const std::string limit = "[0, 0.5 R] = [0, 0.0142875] m";
  expect_rejected({2.0, 0.0, 0.0, 0.51 * radius, 0.0}, "tip offset", limit);
  expect_rejected({2.0, 0.0, 0.0, 0.0, -0.51 * radius}, "tip offset", limit);
  expect_rejected({2.0, 0.0, 0.3, 0.4 * radius, 0.4 * radius}, "tip offset", limit);  // |(a, b)| = 0.57 R
  expect_rejected({2.0, 0.0, 0.0, 2.0 * radius, 0.0}, "tip offset", limit);           // off the ball
  EXPECT_NO_THROW((void)strike_ball({2.0, 0.0, 0.0, 0.3 * radius, 0.4 * radius}, {}, kPool, {}));  // exactly 0.5 R
  EXPECT_TRUE(cue_tip_offset_ok(CueStrike{2.0, 0.0, 0.0, 0.3 * radius, -0.4 * radius}, kPool));
  EXPECT_FALSE(cue_tip_offset_ok(CueStrike{2.0, 0.0, 0.0, 0.36 * radius, 0.36 * radius}, kPool));
}

TEST(StrikeBallValidation, EachBadFieldIsNamedWithItsRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::string speed_range = "(0, 12] m/s";
  for (double v : {0.0, -1.0, 12.5, nan, inf}) expect_rejected({v, 0.0, 0.0, 0.0, 0.0}, "speed", speed_range);
  EXPECT_NO_THROW((void)strike_ball({12.0, 0.0, 0.0, 0.0, 0.0}, {}, kPool, {}));
  const std::string elevation_range = "[0, 90) degrees";
  for (double t : {-0.01, kPi / 2, 2.0, nan}) expect_rejected({2.0, 0.0, t, 0.0, 0.0}, "elevation", elevation_range);
  EXPECT_NO_THROW((void)strike_ball({2.0, 0.0, std::nextafter(kPi / 2, 0.0), 0.0, 0.0}, {}, kPool, {}));
  expect_rejected({2.0, nan, 0.0, 0.0, 0.0}, "aim", "finite");
  expect_rejected({2.0, inf, 0.0, 0.0, 0.0}, "aim", "finite");
  expect_rejected({2.0, 0.0, 0.0, nan, 0.0}, "side_offset", "finite");
  expect_rejected({2.0, 0.0, 0.0, 0.0, -inf}, "height_offset", "finite");
  const CueStrike ok{2.0, 0.0, 0.0, 0.0, 0.0};
  expect_rejected(ok, "cue_mass", "[0.1, 2]", kPool, CueParameters{0.0, 0.75});
  expect_rejected(ok, "cue_tip_e", "[0, 1]", kPool, CueParameters{0.54, 1.2});
  expect_rejected(ok, "mass", "[0.01, 2]", BallParameters{-0.17, 0.028575});
  expect_rejected(ok, "radius", "[0.005, 0.1]", BallParameters{0.17, nan});
}

// ------------------------------------------------------------- execution noise

TEST(CueStrikeNoise, ZeroSigmaIsTheIdentity) {
  const CueStrike k{3.1, -0.7, 0.2, 0.004, -0.006};
  using Draws = std::array<double, 5>;
  for (const Draws& z : {Draws{0, 0, 0, 0, 0}, Draws{1.5, -2, 0.3, 4, -1}}) {
    const CueStrike n = with_noise(k, CueStrikeNoise{}, z);
    EXPECT_EQ(n.speed, k.speed);
    EXPECT_EQ(n.aim, k.aim);
    EXPECT_EQ(n.elevation, k.elevation);
    EXPECT_EQ(n.side_offset, k.side_offset);
    EXPECT_EQ(n.height_offset, k.height_offset);
  }
}

TEST(CueStrikeNoise, EachFieldShiftsBySigmaTimesItsOwnDraw) {
  const CueStrike k{3.1, -0.7, 0.2, 0.004, -0.006};
  const CueStrikeNoise sigma{0.05, 0.002, 0.01, 0.0005, 0.0007};
  const std::array<double, 5> z{0.8, -1.3, 2.1, -0.4, 1.7};
  const CueStrike n = with_noise(k, sigma, z);
  EXPECT_EQ(n.speed, k.speed + 0.05 * 0.8);
  EXPECT_EQ(n.aim, k.aim + 0.002 * -1.3);
  EXPECT_EQ(n.elevation, k.elevation + 0.01 * 2.1);
  EXPECT_EQ(n.side_offset, k.side_offset + 0.0005 * -0.4);
  EXPECT_EQ(n.height_offset, k.height_offset + 0.0007 * 1.7);
  // The draws are matched to the fields in order: one draw moves one field.
  for (std::size_t i = 0; i < 5; ++i) {
    std::array<double, 5> one{};
    one[i] = 1.0;
    const CueStrike m = with_noise(k, sigma, one);
    const std::array<double, 5> shift{m.speed - k.speed, m.aim - k.aim, m.elevation - k.elevation,
                                      m.side_offset - k.side_offset, m.height_offset - k.height_offset};
    const std::array<double, 5> sig{sigma.speed, sigma.aim, sigma.elevation, sigma.side_offset, sigma.height_offset};
    for (std::size_t j = 0; j < 5; ++j) {
      EXPECT_NEAR(shift[j], i == j ? sig[j] : 0.0, 1e-15 * (1 + std::abs(k.speed))) << i << ' ' << j;
    }
  }
}

TEST(CueStrikeNoise, SampleStatisticsMatchTheSigmas) {
  // Driven by the caller's generator: mean and spread of the played strikes.
  const CueStrike k{3.0, 0.5, 0.1, 0.0, 0.002};
  const CueStrikeNoise sigma{0.1, 0.01, 0.02, 0.001, 0.0015};
  std::mt19937_64 rng(21);
  std::normal_distribution<double> normal;
  const int n = 20000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const CueStrike p = with_noise(k, sigma, {normal(rng), normal(rng), normal(rng), normal(rng), normal(rng)});
    sum += p.aim - k.aim;
    sum2 += (p.aim - k.aim) * (p.aim - k.aim);
  }
  const double mean = sum / n, sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 4 * sigma.aim / std::sqrt(n));
  EXPECT_NEAR(sd, sigma.aim, 0.03 * sigma.aim);
}

TEST(CueStrikeNoise, BadSigmaOrDrawIsNamed) {
  const CueStrike k{3.0, 0.0, 0.0, 0.0, 0.0};
  const std::array<double, 5> z{};
  try {
    (void)with_noise(k, CueStrikeNoise{0.1, -0.01, 0, 0, 0}, z);
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "sigma aim");
  }
  try {
    (void)with_noise(k, CueStrikeNoise{0, 0, 0, 0, std::numeric_limits<double>::infinity()}, z);
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "sigma height_offset");
  }
  try {
    (void)with_noise(k, CueStrikeNoise{}, {0, 0, std::numeric_limits<double>::quiet_NaN(), 0, 0});
    ADD_FAILURE();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "standard_normals[2]");
  }
  // A large error can make a miscue; strike_ball reports it, not with_noise.
  const CueStrike wild = with_noise(k, CueStrikeNoise{0, 0, 0, 0.01, 0}, {0, 0, 0, 3.0, 0});
  EXPECT_FALSE(cue_tip_offset_ok(wild, kPool));
  expect_rejected(wild, "tip offset", "0.5 R");
}

TEST(CueStrike, PositionMustBeFiniteAndOnATable) {
  // Once strike_ball(position = (nan, 0)) returned a NaN state.
  const CueStrike s{2.0, 0.0, 0.0, 0.0, 0.0};
  const BallParameters ball = snooker_parameters().ball;
  for (const Vec2 bad : {Vec2{std::nan(""), 0.0}, Vec2{0.0, std::numeric_limits<double>::infinity()}, Vec2{1e9, 0.0}}) {
    try {
      strike_ball(s, bad, ball, CueParameters{});
      ADD_FAILURE() << "no error";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field().rfind("position[", 0), 0u) << e.field();
    }
  }
  EXPECT_NO_THROW(strike_ball(s, {1.0, 0.5}, ball, CueParameters{}));
}

}  // namespace
}  // namespace cueball
