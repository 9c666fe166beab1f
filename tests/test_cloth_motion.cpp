// Tests of the closed-form motion on the cloth (src/physics/cloth_motion.cpp) against
// an independent numerical integration of the equations of motion, paper
// 001's closed forms (eqs 8-10, 19-24), and conservation/symmetry laws.
#include "cueball/physics/cloth_motion.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "cueball/core/errors.hpp"
#include "test_support.hpp"

namespace cueball {
namespace {

// ---------------------------------------------------------------------------
// A direct numerical integration of the equations of motion, written from the
// forces alone: friction -mu_s m g u^ at the contact while it slips (paper 001
// eqs 2, 3), rolling resistance from dE/dt = -mu_r m g v (eqs 11, 12), and the
// vertical-spin torque (spec §1). Classical RK4 with the motion mode frozen
// over a step; a step that would carry a slip, a velocity or a vertical spin
// through zero is cut back by bisection to the instant it vanishes.
struct NumericBall {
  BallState s;
  const Parameters& p;

  enum Mode { kSlide, kRoll, kRest };

  Mode mode(const BallState& b) const {
    const Vec2 u = slip_velocity(b, p.ball.radius);
    if (norm(u) > 1e-8) return kSlide;
    if (norm(b.velocity) > 1e-8) return kRoll;
    return kRest;
  }

  // Time derivative of (position, velocity, angular velocity) in `m`.
  BallState rate(const BallState& b, Mode m, double wz_sign) const {
    const double g = p.cloth.gravity;
    const double radius = p.ball.radius;
    BallState d{b.velocity, {}, {}};
    if (m == kSlide) {
      const Vec2 u = slip_velocity(b, radius);
      const Vec2 u_hat = u / norm(u);
      d.velocity = -(p.cloth.sliding_friction * g) * u_hat;  // m dv/dt = f
      // I dw/dt = r x f with r = -R z^ (contact below the centre): (5 mu_s g / 2R) z^ x u^
      const Vec2 dw = (2.5 * p.cloth.sliding_friction * g / radius) * perp(u_hat);
      d.angular_velocity = {dw.x, dw.y, 0.0};
    } else if (m == kRoll) {
      // 7/5 m v dv/dt = -mu_r m g v, directed against v; spin follows the rolling constraint.
      const Vec2 a = -(5.0 / 7.0 * p.cloth.rolling_resistance * g) * (b.velocity / norm(b.velocity));
      d.velocity = a;
      d.angular_velocity = {-a.y / radius, a.x / radius, 0.0};
    } else {
      d.position = {};
    }
    d.angular_velocity.z = -wz_sign * 2.5 * p.cloth.spin_friction * g / radius;
    return d;
  }

  static BallState add(const BallState& a, const BallState& d, double h) {
    return {a.position + h * d.position, a.velocity + h * d.velocity, a.angular_velocity + h * d.angular_velocity};
  }

  // True if x has carried the quantity that defines a's mode (slip while
  // sliding, velocity while rolling) to within 1e-10 m/s of zero, or the
  // vertical spin through zero. (Closer to zero, the slip's direction is
  // round-off and the friction direction with it.)
  bool reversed(const BallState& a, const BallState& x) const {
    const Mode m = mode(a);
    const auto along = [](Vec2 now, Vec2 start) { return dot(now, start) / norm(start); };
    if (m == kSlide && along(slip_velocity(x, p.ball.radius), slip_velocity(a, p.ball.radius)) <= 1e-10) return true;
    if (m == kRoll && along(x.velocity, a.velocity) <= 1e-10) return true;
    return a.angular_velocity.z * x.angular_velocity.z < 0;
  }

  // One RK4 step; *crossed is set when any stage state or the result has
  // passed a zero (the right-hand side is discontinuous there).
  BallState rk4(const BallState& a, double h, bool* crossed) const {
    const Mode m = mode(a);
    const double sz = a.angular_velocity.z > 0 ? 1.0 : (a.angular_velocity.z < 0 ? -1.0 : 0.0);
    const BallState s2 = add(a, rate(a, m, sz), h / 2);
    const BallState k1 = rate(a, m, sz);
    const BallState k2 = rate(s2, m, sz);
    const BallState s3 = add(a, k2, h / 2);
    const BallState k3 = rate(s3, m, sz);
    const BallState s4 = add(a, k3, h);
    const BallState k4 = rate(s4, m, sz);
    BallState out = a;
    out.position = a.position + (h / 6) * (k1.position + 2.0 * k2.position + 2.0 * k3.position + k4.position);
    out.velocity = a.velocity + (h / 6) * (k1.velocity + 2.0 * k2.velocity + 2.0 * k3.velocity + k4.velocity);
    out.angular_velocity = a.angular_velocity + (h / 6) * (k1.angular_velocity + 2.0 * k2.angular_velocity +
                                                           2.0 * k3.angular_velocity + k4.angular_velocity);
    *crossed = reversed(a, s2) || reversed(a, s3) || reversed(a, s4) || reversed(a, out);
    return out;
  }

  void advance(double duration, double h) {
    double t = 0;
    while (t < duration) {
      double step = std::min(h, duration - t);
      bool crossed = false;
      BallState next = rk4(s, step, &crossed);
      if (crossed) {
        // Largest step that does not cross: it ends where the slip, the
        // velocity or the spin vanishes.
        double lo = 0, hi = step;
        for (int i = 0; i < 200 && hi - lo > 1e-16; ++i) {
          const double mid = 0.5 * (lo + hi);
          rk4(s, mid, &crossed);
          (crossed ? hi : lo) = mid;
        }
        step = lo;
        next = rk4(s, step, &crossed);
        if (std::abs(next.angular_velocity.z) < 1e-9) next.angular_velocity.z = 0;
        if (mode(s) == kRoll && norm(next.velocity) < 1e-8) next = {next.position, {}, {0, 0, next.angular_velocity.z}};
      }
      s = next;
      t += step;
    }
  }
};

void expect_near_state(const BallState& a, const BallState& b, double tol, const char* what) {
  EXPECT_NEAR(a.position.x, b.position.x, tol) << what;
  EXPECT_NEAR(a.position.y, b.position.y, tol) << what;
  EXPECT_NEAR(a.velocity.x, b.velocity.x, tol) << what;
  EXPECT_NEAR(a.velocity.y, b.velocity.y, tol) << what;
  EXPECT_NEAR(a.angular_velocity.x, b.angular_velocity.x, tol / 0.02) << what;
  EXPECT_NEAR(a.angular_velocity.y, b.angular_velocity.y, tol / 0.02) << what;
  EXPECT_NEAR(a.angular_velocity.z, b.angular_velocity.z, tol / 0.02) << what;
}

TEST(ClothMotion, ClosedFormMatchesNumericalIntegrationForRandomStates) {
  std::mt19937_64 rng(20261121);
  for (const Parameters& p : {snooker_parameters(), pool_parameters()}) {
    for (int trial = 0; trial < 60; ++trial) {
      const BallState s0 = test::random_state(rng);
      const double end = std::min(next_transition(s0, p).time * 1.5 + 2.0, 40.0);
      NumericBall numeric{s0, p};
      double t = 0;
      for (double target : {0.05, 0.3, 1.0, 3.0, end}) {
        if (target <= t) continue;
        numeric.advance(target - t, 1e-3);
        t = target;
        // The reference stops 1e-10 m/s short of each zero; over 40 s that is
        // a few 1e-9 m. Any error in a closed form would be orders larger.
        expect_near_state(evolve(s0, t, p), numeric.s, 1e-8, "closed form vs RK4");
      }
    }
  }
}

TEST(ClothMotion, SlipAtAnAngleCurvesOnAParabola) {
  const Parameters p = pool_parameters();
  // Moving along +x with side-to-side slip: u has a y component.
  const BallState s0{{0, 0}, {2.0, 0.0}, {60.0, 20.0, 0.0}};
  ASSERT_EQ(motion_phase(s0, p), MotionPhase::sliding);
  const double t1 = next_transition(s0, p).time;
  // Constant acceleration: equal second differences, and not along v0.
  const double h = t1 / 10;
  std::vector<Vec2> r;
  for (int i = 0; i <= 10; ++i) r.push_back(evolve(s0, i * h, p).position);
  const Vec2 second = r[2] - 2.0 * r[1] + r[0];
  for (int i = 1; i < 10; ++i) {
    const Vec2 d = r[static_cast<std::size_t>(i) + 1] - 2.0 * r[static_cast<std::size_t>(i)] +
                   r[static_cast<std::size_t>(i) - 1];
    EXPECT_NEAR(d.x, second.x, 1e-12);
    EXPECT_NEAR(d.y, second.y, 1e-12);
  }
  EXPECT_GT(std::abs(r[10].y), 1e-3) << "the path must curve away from the initial line";
  // The acceleration is -mu_s g u^ (eq. 2).
  const Vec2 u = slip_velocity(s0, p.ball.radius);
  const Vec2 expected = -(sliding_deceleration(p) * h * h) * (u / norm(u));
  EXPECT_NEAR(second.x, expected.x, 1e-12);
  EXPECT_NEAR(second.y, expected.y, 1e-12);
}

TEST(ClothMotion, EndOfSlidingFollowsPaperEquations8To10InTheVectorForm) {
  std::mt19937_64 rng(7);
  const Parameters p = snooker_parameters();
  for (int trial = 0; trial < 200; ++trial) {
    const BallState s0 = test::random_state(rng);
    const Vec2 u0 = slip_velocity(s0, p.ball.radius);
    const double mu_s_g = sliding_deceleration(p);
    const double t1 = 2.0 * norm(u0) / (7.0 * mu_s_g);  // (8)
    const NextTransition next = next_transition(s0, p);
    if (next.kind != Transition::sliding_ends) continue;
    EXPECT_NEAR(next.time, t1, 1e-14);
    const BallState s1 = evolve(s0, t1, p);
    const Vec2 zxw0 = perp(horizontal(s0.angular_velocity));
    const Vec2 v1 = (5.0 / 7.0) * s0.velocity - (2.0 / 7.0 * p.ball.radius) * zxw0;  // (9)
    const Vec2 x1 = s0.position + (2.0 * norm(u0) / (49.0 * mu_s_g)) * (6.0 * s0.velocity - p.ball.radius * zxw0);  // (10)
    EXPECT_NEAR(s1.velocity.x, v1.x, 1e-12);
    EXPECT_NEAR(s1.velocity.y, v1.y, 1e-12);
    EXPECT_NEAR(s1.position.x, x1.x, 1e-12);
    EXPECT_NEAR(s1.position.y, x1.y, 1e-12);
    EXPECT_NE(motion_phase(s1, p), MotionPhase::sliding) << "snapped onto rolling at t1";
  }
}

TEST(ClothMotion, StunBallRollsAtFiveSeventhsWhateverTheFriction) {
  for (double mu_s : {0.05, 0.212, 0.4, 0.9}) {
    Parameters p = snooker_parameters();
    p.cloth.sliding_friction = mu_s;
    for (double v0 : {0.3, 1.0, 4.0, 9.0}) {
      const StraightShot shot = straight_shot(v0, 0.0, 0.0, p);
      EXPECT_NEAR(shot.v1, 5.0 / 7.0 * v0, 1e-13 * v0) << "mu_s " << mu_s << " v0 " << v0;
      const BallState rolling = straight_shot_state(v0, 0.0, 0.0, shot.t1, p);
      EXPECT_NEAR(rolling.angular_velocity.y * p.ball.radius, rolling.velocity.x, 1e-13);
    }
  }
}

// Paper 001 eqs 17-24 in their own 1D form, for Z >= 0 and N >= 0.
TEST(ClothMotion, StraightShotReproducesPaperEquations19To24) {
  for (const Parameters& p : {snooker_parameters(), pool_parameters()}) {
    const double mu_s_g = p.cloth.sliding_friction * p.cloth.gravity;
    const double mu_r_g = p.cloth.rolling_resistance * p.cloth.gravity;
    for (double v0 : {0.2, 1.0, 2.5, 6.0}) {
      for (double k : {-2.5, -1.5, -0.5, 0.0, 0.5, 0.9, 1.0}) {  // R w0 = k v0
        const double w0 = k * v0 / p.ball.radius;
        const double z = v0 - p.ball.radius * w0;      // (17)
        const double n = 5 * v0 + 2 * p.ball.radius * w0;  // (18)
        const StraightShot shot = straight_shot(v0, w0, 0.0, p);
        const double t1 = 2.0 / 7.0 * z / mu_s_g;            // (19)
        const double v1 = n / 7.0;                           // (20)
        const double x1 = 2.0 / 49.0 * z * (n + z) / mu_s_g;  // (21)
        const double t2 = t1 + 7.0 * v1 / (5.0 * mu_r_g);     // (22), v2 = 0
        const double x2 = x1 + 7.0 * v1 * v1 / (10.0 * mu_r_g);  // (24), v2 = 0
        const double scale = 1e-12 * (1 + x2);
        EXPECT_NEAR(shot.t1, t1, 1e-12) << v0 << " " << k;
        EXPECT_NEAR(shot.v1, v1, 1e-12) << v0 << " " << k;
        EXPECT_NEAR(shot.x1, x1, scale) << v0 << " " << k;
        EXPECT_NEAR(shot.t2, t2, 1e-12 * (1 + t2)) << v0 << " " << k;
        EXPECT_NEAR(shot.x2, x2, scale) << v0 << " " << k;
        // Eq. 23 at an intermediate speed v2: position when the speed is v2.
        const double v2 = 0.5 * v1;
        const double t2v = t1 + 7.0 * (v1 - v2) / (5.0 * mu_r_g);  // (22)
        const double x2v = x1 + v1 * (t2v - t1) - 5.0 / 14.0 * mu_r_g * (t2v - t1) * (t2v - t1);  // (23)
        const BallState at = straight_shot_state(v0, w0, 0.0, t2v, p);
        EXPECT_NEAR(at.position.x, x2v, scale);
        EXPECT_NEAR(at.velocity.x, v2, 1e-12);
      }
    }
  }
}

TEST(ClothMotion, StopShotComesToRestWhenSlidingEnds) {
  const Parameters p = snooker_parameters();
  const double v0 = 1.2;
  const double w0 = -2.5 * v0 / p.ball.radius;  // N = 0: R w0 = -5/2 v0
  const StraightShot shot = straight_shot(v0, w0, 0.0, p);
  EXPECT_NEAR(shot.v1, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(shot.t2, shot.t1);
  EXPECT_DOUBLE_EQ(shot.x2, shot.x1);
  EXPECT_EQ(motion_phase(straight_shot_state(v0, w0, 0.0, shot.t1, p), p), MotionPhase::stationary);
}

TEST(ClothMotion, StrongDrawReversesTheBallWhileItSlides) {
  const Parameters p = snooker_parameters();
  const double v0 = 1.0;
  const double w0 = -6.0 * v0 / p.ball.radius;
  const StraightShot shot = straight_shot(v0, w0, 0.0, p);
  EXPECT_LT(shot.v1, 0.0);
  EXPECT_NEAR(shot.v1, (5 * v0 + 2 * p.ball.radius * w0) / 7, 1e-12);
  EXPECT_LT(shot.x2, shot.x1);
}

TEST(ClothMotion, OverspinAcceleratesTheBallWhileItSlides) {
  const Parameters p = pool_parameters();
  const double v0 = 1.0;
  const double w0 = 3.0 * v0 / p.ball.radius;
  const StraightShot shot = straight_shot(v0, w0, 0.0, p);
  EXPECT_GT(shot.v1, v0);
  EXPECT_NEAR(shot.v1, (5 * v0 + 2 * p.ball.radius * w0) / 7, 1e-12);
}

TEST(ClothMotion, VerticalSpinDecaysLinearlyAndNeverReverses) {
  const Parameters p = pool_parameters();
  const double alpha = 2.5 * p.cloth.spin_friction * p.cloth.gravity / p.ball.radius;
  for (double wz : {-50.0, -3.0, 4.0, 80.0}) {
    const BallState s0{{0.3, 0.2}, {0, 0}, {0, 0, wz}};
    ASSERT_EQ(motion_phase(s0, p), MotionPhase::spinning);
    const NextTransition next = next_transition(s0, p);
    EXPECT_EQ(next.kind, Transition::vertical_spin_ends);
    EXPECT_NEAR(next.time, std::abs(wz) / alpha, 1e-12);
    EXPECT_NEAR(evolve(s0, 0.5 * next.time, p).angular_velocity.z, 0.5 * wz, 1e-12);
    for (double t : {next.time, next.time * 1.0001, next.time * 3}) {
      const BallState s = evolve(s0, t, p);
      EXPECT_EQ(s.angular_velocity.z, 0.0);
      EXPECT_EQ(motion_phase(s, p), MotionPhase::stationary);
      EXPECT_EQ(s.position, s0.position);
    }
  }
}

TEST(ClothMotion, SideSpinDoesNotBendAStraightShot) {
  const Parameters p = snooker_parameters();
  for (double t : {0.05, 0.4, 2.0, 30.0}) {
    const BallState s = straight_shot_state(2.0, 10.0, 60.0, t, p);
    EXPECT_EQ(s.position.y, 0.0);
    EXPECT_EQ(s.velocity.y, 0.0);
  }
}

TEST(ClothMotion, KineticEnergyNeverIncreases) {
  std::mt19937_64 rng(99);
  for (const Parameters& p : {snooker_parameters(), pool_parameters()}) {
    for (int trial = 0; trial < 100; ++trial) {
      const BallState s0 = test::random_state(rng, 5.0, 300.0);
      double previous = kinetic_energy(s0, p.ball);
      // Fine steps through the sliding phase (< 2 s), then coarse to 100 s.
      for (int i = 1; i <= 1400; ++i) {
        const double t = i <= 1000 ? 0.002 * i : 2.0 + 0.245 * (i - 1000);
        const double e = kinetic_energy(evolve(s0, t, p), p.ball);
        EXPECT_LE(e, previous * (1 + 1e-13) + 1e-15) << "trial " << trial << " step " << i;
        previous = e;
      }
      EXPECT_EQ(previous, 0.0) << "after 100 s every ball is at rest";
    }
  }
}

TEST(ClothMotion, EvolutionComposes) {
  std::mt19937_64 rng(5);
  const Parameters p = pool_parameters();
  for (int trial = 0; trial < 200; ++trial) {
    const BallState s0 = test::random_state(rng);
    std::uniform_real_distribution<double> time(0.0, 4.0);
    const double a = time(rng), b = time(rng);
    expect_near_state(evolve(evolve(s0, a, p), b, p), evolve(s0, a + b, p), 1e-12, "evolve(a) then evolve(b)");
  }
}

TEST(ClothMotion, RotatingTheStateRotatesTheMotion) {
  std::mt19937_64 rng(11);
  const Parameters p = snooker_parameters();
  const auto rotate = [](const BallState& s, double c, double sn) {
    const auto r2 = [&](Vec2 v) { return Vec2{c * v.x - sn * v.y, sn * v.x + c * v.y}; };
    const Vec2 wh = r2(horizontal(s.angular_velocity));
    return BallState{r2(s.position), r2(s.velocity), {wh.x, wh.y, s.angular_velocity.z}};
  };
  for (int trial = 0; trial < 100; ++trial) {
    const BallState s0 = test::random_state(rng);
    const double angle = 0.37 * trial;
    const double c = std::cos(angle), sn = std::sin(angle);
    for (double t : {0.1, 0.7, 5.0}) {
      expect_near_state(evolve(rotate(s0, c, sn), t, p), rotate(evolve(s0, t, p), c, sn), 1e-12, "rotation");
    }
  }
}

TEST(ClothMotion, MirroringTheStateMirrorsTheMotion) {
  // Reflection y -> -y: positions and velocities flip y; the angular velocity
  // is a pseudovector (w -> -M w for the reflection M), so w_y stays and w_x, w_z flip.
  std::mt19937_64 rng(13);
  const Parameters p = pool_parameters();
  const auto mirror = [](const BallState& s) {
    return BallState{{s.position.x, -s.position.y},
                     {s.velocity.x, -s.velocity.y},
                     {-s.angular_velocity.x, s.angular_velocity.y, -s.angular_velocity.z}};
  };
  for (int trial = 0; trial < 100; ++trial) {
    const BallState s0 = test::random_state(rng);
    for (double t : {0.1, 0.7, 5.0}) expect_near_state(evolve(mirror(s0), t, p), mirror(evolve(s0, t, p)), 1e-12, "mirror");
  }
}

TEST(ClothMotion, PhasesAreDerivedFromTheKinematics) {
  const Parameters p = snooker_parameters();
  const double r = p.ball.radius;
  EXPECT_EQ(motion_phase({{}, {1, 0}, {0, 0, 0}}, p), MotionPhase::sliding);
  EXPECT_EQ(motion_phase({{}, {1, 0}, {0, 1 / r, 0}}, p), MotionPhase::rolling);
  EXPECT_EQ(motion_phase({{}, {0, 1}, {-1 / r, 0, 5}}, p), MotionPhase::rolling);
  EXPECT_EQ(motion_phase({{}, {0, 0}, {0, 0, 5}}, p), MotionPhase::spinning);
  EXPECT_EQ(motion_phase({{}, {0, 0}, {0, 0, 0}}, p), MotionPhase::stationary);
  EXPECT_EQ(motion_phase({{}, {0, 0}, {0, 3, 0}}, p), MotionPhase::sliding) << "pure backspin in place slides";
  const NextTransition none = next_transition({{}, {}, {}}, p);
  EXPECT_EQ(none.kind, Transition::none);
  EXPECT_TRUE(std::isinf(none.time));
}

TEST(ClothMotion, NextTransitionIsTheEarlierOfPhaseEndAndSpinEnd) {
  const Parameters p = snooker_parameters();
  const double r = p.ball.radius;
  // Rolling at 2 m/s lasts ~16 s; a small side spin ends much earlier.
  const BallState rolling{{}, {2, 0}, {0, 2 / r, 1.0}};
  const NextTransition a = next_transition(rolling, p);
  EXPECT_EQ(a.kind, Transition::vertical_spin_ends);
  const BallState after = evolve(rolling, a.time, p);
  EXPECT_EQ(after.angular_velocity.z, 0.0);
  EXPECT_EQ(motion_phase(after, p), MotionPhase::rolling);
  EXPECT_EQ(next_transition(after, p).kind, Transition::rolling_ends);
  // A big side spin outlasts the roll: the ball ends spinning in place.
  const BallState spinner{{}, {0.5, 0}, {0, 0.5 / r, 200.0}};
  const NextTransition b = next_transition(spinner, p);
  EXPECT_EQ(b.kind, Transition::rolling_ends);
  EXPECT_EQ(motion_phase(evolve(spinner, b.time, p), p), MotionPhase::spinning);
}

TEST(ClothMotion, ValidateRejectsNonFiniteAndImplausibleStates) {
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  const auto field_of = [](const BallState& s) {
    try {
      validate(s);
    } catch (const InvalidArgument& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(field_of({{0, 0}, {1, 0}, {0, 0, 0}}), "accepted");
  EXPECT_EQ(field_of({{nan, 0}, {1, 0}, {0, 0, 0}}), "position");
  EXPECT_EQ(field_of({{0, 0}, {inf, 0}, {0, 0, 0}}), "velocity");
  EXPECT_EQ(field_of({{0, 0}, {1, 0}, {0, nan, 0}}), "angular_velocity");
  EXPECT_EQ(field_of({{0, 0}, {100, 0}, {0, 0, 0}}), "speed");
  EXPECT_EQ(field_of({{0, 0}, {1, 0}, {0, 0, 1e5}}), "angular speed");
}

}  // namespace
}  // namespace cueball
