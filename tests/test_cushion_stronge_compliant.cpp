// Tests of the `stronge_compliant` ball-cushion model
// (src/models/cushion/stronge_compliant.cpp): pooltool's reference values; the
// closed forms of gross slip (S8), of the frictionless impact and of the
// rigid Coulomb impulse (Omega -> infinity); laws of the model (energy never
// increases, mirror symmetry, a head-on impact stays in its plane,
// homogeneity in the incoming velocities, continuity across the switches
// between slip and stick); the contact velocities after the impact; the
// defaults, the Poisson's-ratio relation and validation; no allocation;
// agreement with pooltool's three-case closed form where it applies.
#include "cueball/models/cushion/stronge_compliant.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "cueball/core/errors.hpp"
#include "cueball/core/parameters.hpp"
#include "count_allocations.hpp"
#include "expect_invalid.hpp"

namespace cueball {
namespace {

constexpr double kBeta = 3.5;  // 1 + M R^2 / I of a solid sphere
constexpr double kR = 0.028575;

StrongeCompliantCushion cushion(double e, double mu, double omega, double sin_theta = 0.0) {
  return {kR, e, mu, sin_theta, omega};
}

// Kinetic energy per unit mass, I / M = 2/5 R^2.
double energy(const Vec3& v, const Vec3& w) { return 0.5 * dot(v, v) + 0.2 * kR * kR * dot(w, w); }

// Tangential velocity of the contact point along X at the equator (sin(theta) = 0).
double slip_x(const Vec3& v, const Vec3& w) { return v.x - kR * w.z; }

// |difference| over velocities and R x spins.
double distance(const CushionRebound& a, const CushionRebound& b) {
  const Vec3 dv = a.velocity - b.velocity;
  const Vec3 dw = kR * (a.angular_velocity - b.angular_velocity);
  return std::max({std::abs(dv.x), std::abs(dv.y), std::abs(dv.z), std::abs(dw.x), std::abs(dw.y), std::abs(dw.z)});
}

// A random incoming ball: speed, angle to the cushion, spins up to 3 V / R on each axis.
IncomingBall random_ball(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double speed = 0.05 + 4.0 * unit(rng);
  const double angle = 0.02 + 1.55 * unit(rng);
  const double k = speed / kR;
  return {{speed * std::cos(angle), speed * std::sin(angle), 0.0},
          {k * (6.0 * unit(rng) - 3.0), k * (6.0 * unit(rng) - 3.0), k * (6.0 * unit(rng) - 3.0)}};
}

// Random valid constants (validate() also bounds sin_theta by e and mu).
StrongeCompliantCushion random_cushion(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (;;) {
    const double e = unit(rng) < 0.2 ? 1.0 : 0.05 + 0.95 * unit(rng);
    const double mu = unit(rng) < 0.1 ? 0.0 : unit(rng);
    const double omega = 1.01 + 5.0 * unit(rng);
    const double s = unit(rng) < 0.3 ? 0.0 : 0.6 * unit(rng);
    const StrongeCompliantCushion c = cushion(e, mu, omega, s);
    try {
      validate(c);
      return c;
    } catch (const InvalidArgument&) {
    }
  }
}

using test::expect_invalid;
using test::g_allocations;

// Calls check(i, ball, cushion, rebound) for n random impacts.
template <class Check>
void for_random_impacts(unsigned seed, int n, Check check) {
  std::mt19937_64 rng(seed);
  for (int i = 0; i < n; ++i) {
    const IncomingBall ball = random_ball(rng);
    const StrongeCompliantCushion c = random_cushion(rng);
    check(i, ball, c, stronge_compliant_rebound(ball, c));
  }
}

// ------------------------------------------------------------------ published values

// pooltool's scalar solver (resolve_collinear_compliant_frictional_inelastic_collision,
// pooltool/physics/resolve/stronge_compliant.py) as quoted by its TypeScript port's
// tests, tailuge/billiards test/model/physics/stronge.spec.ts ("high-precision
// reference data derived from the Python implementation", tailuge/billiards pull
// request #274): m = 0.23, e_n = 0.7, mu = 0.2, omega_ratio = 1.7, v_n0 = -1 and
// v_t0 = 0 -> (v_tf, v_nf) = (0, 0.7); v_t0 = -3 (gross slip) -> (-1.81, 0.7);
// v_t0 = -0.5 (slip-stick-slip) -> (0.32911428, 0.7). pooltool's v_t0 <= 0 is the
// slip opposite its tangent; here the slip is +X (sin(theta) = 0, no spin).
TEST(StrongeCompliant, ReproducesPooltoolReferenceValues) {
  const StrongeCompliantCushion c = cushion(0.7, 0.2, 1.7);
  struct Case {
    double v_t0;
    double v_tf;
  };
  for (const Case& k : {Case{0.0, 0.0}, Case{3.0, 1.81}, Case{0.5, -0.32911428}}) {
    const IncomingBall ball{{k.v_t0, 1.0, 0.0}, {}};
    const CushionRebound r = stronge_compliant_rebound(ball, c);
    EXPECT_NEAR(slip_x(r.velocity, r.angular_velocity), k.v_tf, 1e-7) << "v_t0 = " << k.v_t0;
    EXPECT_NEAR(r.velocity.y, -0.7, 1e-12) << "v_t0 = " << k.v_t0;
  }
}

// S8: an incoming slip above mu max(beta, (1 + e) beta - eta^2 / e) slides
// throughout, and its slip falls by mu beta (1 + e) per unit incoming normal
// speed (also where that reverses the contact point's velocity, e.g. e = 0.3).
TEST(StrongeCompliant, GrossSlipMatchesItsClosedForm) {
  for (double e : {0.3, 0.7, 1.0}) {
    for (double omega : {1.2, 1.8, 3.0}) {
      const double mu = 0.25;
      const double eta2 = kBeta / (omega * omega);
      const double threshold = mu * std::max(kBeta, (1.0 + e) * kBeta - eta2 / e);
      for (double factor : {1.001, 1.5, 4.0}) {
        const double v0 = factor * threshold;
        const IncomingBall ball{{0.0, 2.0, 0.0}, {0.0, 0.0, -2.0 * v0 / kR}};  // slip +2 v0 along X
        const CushionRebound r = stronge_compliant_rebound(ball, cushion(e, mu, omega));
        EXPECT_NEAR(slip_x(r.velocity, r.angular_velocity), 2.0 * (v0 - mu * kBeta * (1.0 + e)), 1e-12)
            << "e " << e << " Omega " << omega << " factor " << factor;
      }
    }
  }
}

// pooltool's scalar solution restated (resolve_collinear_compliant_frictional_
// inelastic_collision in pooltool/physics/resolve/stronge_compliant.py): three
// cases, the friction reversed after the stick. Written here independently of
// the phase loop, with bisection for the end of the stick (pooltool: TOMS 748 on
// [t_c, t_f]; here the search starts at the later of t_c and 1e-6 after the
// stick starts, where the stick is sure to hold).
// Velocities of I in units of the incoming normal speed, slip v0 >= 0.
double pooltool_exit_slip(double v0, double mu, double e, double omega) {
  const double pi = 3.14159265358979323846;
  const double eta2 = kBeta / (omega * omega);
  const double t_c = pi / 2.0;
  const double t_f = (1.0 + e) * t_c;
  auto phase = [&](double t) { return t <= t_c ? t : t_c + (t - t_c) / e; };
  auto bisect = [](auto f, double a, double b) {
    const bool left_negative = f(a) < 0.0;
    for (int i = 0; i < 200; ++i) {
      const double m = 0.5 * (a + b);
      if ((f(m) < 0.0) == left_negative) {
        a = m;
      } else {
        b = m;
      }
    }
    return 0.5 * (a + b);
  };
  if (v0 > mu * ((1.0 + e) * kBeta - eta2 / e)) return v0 - mu * kBeta * (1.0 + e);  // gross slip
  double t_stick = 0.0;
  double u_stick = 0.0;
  double v_stick = v0;
  if (v0 >= mu * eta2) {  // slip, then stick where the particle's slip stops
    const double r = v0 / mu;
    if (r <= kBeta) {
      t_stick = std::acos((r - kBeta) / (eta2 - kBeta));
    } else {
      t_stick = t_c + e * (std::acos((r - kBeta) / (eta2 / e - e * kBeta)) - t_c);
    }
    const double p = t_stick <= t_c ? 1.0 - std::cos(t_stick) : 1.0 - e * std::cos(phase(t_stick));
    v_stick = v0 - mu * kBeta * p;
    u_stick = -mu * eta2 * std::sin(phase(t_stick));
  }
  auto u = [&](double t) {
    return u_stick * std::cos(omega * (t - t_stick)) - v_stick / omega * std::sin(omega * (t - t_stick));
  };
  auto excess = [&](double t) { return std::abs(u(t)) - mu * eta2 * std::sin(phase(t)); };
  const double t_slip = bisect(excess, std::max(t_c, t_stick + 1e-6), t_f);
  const double v_slip =
      omega * u_stick * std::sin(omega * (t_slip - t_stick)) + v_stick * std::cos(omega * (t_slip - t_stick));
  return v_slip + mu * kBeta * e * (1.0 + std::cos(phase(t_slip)));  // reversed slip to separation
}

// Where pooltool's three cases suffice (e > 1/Omega, one stick ending in
// restitution; its defaults e = 0.85, Omega = 1.8 and the earlier 1.7), the
// phase loop gives the same exit slip across all incoming slips.
TEST(StrongeCompliant, AgreesWithPooltoolsThreeCaseSolution) {
  struct Constants {
    double mu, e, omega;
  };
  for (const Constants& k : {Constants{0.2, 0.85, 1.8}, Constants{0.2, 0.7, 1.7}, Constants{0.3, 0.95, 1.6}}) {
    const StrongeCompliantCushion c = cushion(k.e, k.mu, k.omega);
    const int n = 600;
    for (int i = 1; i < n; ++i) {
      const double v0 = 1.2 * k.mu * kBeta * (1.0 + k.e) * i / n;
      const IncomingBall ball{{v0, 1.0, 0.0}, {}};
      const CushionRebound r = stronge_compliant_rebound(ball, c);
      ASSERT_NEAR(slip_x(r.velocity, r.angular_velocity), pooltool_exit_slip(v0, k.mu, k.e, k.omega), 1e-9)
          << "mu " << k.mu << " e " << k.e << " Omega " << k.omega << " v0 " << v0;
    }
  }
}

// ------------------------------------------------------------------ limits

// Without friction only the normal impulse (1 + e) V along -n acts; the bed
// then removes its vertical part (S9): yG' -> -((1 + e) cos^2(theta) - 1) yG',
// i.e. -e yG' at the equator.
TEST(StrongeCompliant, FrictionlessImpactReversesOnlyTheNormalVelocity) {
  std::mt19937_64 rng(11);
  for (double s : {0.0, 0.2, 0.4}) {
    for (double e : {0.2, 0.85, 1.0}) {
      for (int i = 0; i < 50; ++i) {
        const IncomingBall ball = random_ball(rng);
        const CushionRebound r = stronge_compliant_rebound(ball, cushion(e, 0.0, 1.8, s));
        const double factor = (1.0 + e) * (1.0 - s * s) - 1.0;
        EXPECT_EQ(r.velocity.x, ball.velocity.x);
        EXPECT_NEAR(r.velocity.y, -factor * ball.velocity.y, 1e-15 * ball.velocity.y);
        EXPECT_EQ(r.velocity.z, 0.0);
        EXPECT_EQ(r.angular_velocity.x, ball.angular_velocity.x);
        EXPECT_EQ(r.angular_velocity.y, ball.angular_velocity.y);
        EXPECT_EQ(r.angular_velocity.z, ball.angular_velocity.z);
        if (s == 0.0) {
          EXPECT_NEAR(r.velocity.y, -e * ball.velocity.y, 1e-15 * ball.velocity.y);
        }
      }
    }
  }
}

// The rigid-body Coulomb impulse at I, derived by hand for a free sphere:
// the tangential velocity of I changes by beta j / M per tangential impulse j
// (S1), friction can give at most mu (1 + e) M V; so the slip q stops if
// q <= mu beta (1 + e) V (j = q M / beta), else falls by mu beta (1 + e) V.
CushionRebound rigid_coulomb(const IncomingBall& b, double e, double mu, double s) {
  const double c = std::sqrt(1.0 - s * s);
  const Vec3 v = b.velocity;
  const Vec3 w = b.angular_velocity;
  const double vn = v.y * c;
  const double sx = v.x + kR * (w.y * s - w.z * c);
  const double sy = -v.y * s + kR * w.x;
  const double q = std::hypot(sx, sy);
  const double j = std::min(q / kBeta, mu * (1.0 + e) * vn);  // per unit mass, against the slip
  const Vec3 n{0.0, c, s};
  const Vec3 t = q > 0.0 ? Vec3{sx / q, -s * sy / q, c * sy / q} : Vec3{};
  const Vec3 impulse = -(1.0 + e) * vn * n - j * t;
  Vec3 v2 = v + impulse;
  v2.z = 0.0;
  const Vec3 w2 = w + (2.5 / kR) * cross(n, impulse);  // r x J / I with r = R n, I / M = 2/5 R^2
  return {v2, w2};
}

// A very stiff tangential spring (Omega -> infinity, eta^2 -> 0) leaves no
// room for stick-slip oscillation: the model tends to the rigid impulse (here
// the largest difference, in units of the incoming normal speed, is 2.7e-4 at
// Omega = 100 and 2.9e-6 at Omega = 1000: about 1/Omega^2).
TEST(StrongeCompliant, StiffTangentialSpringGivesTheRigidCoulombImpulse) {
  std::mt19937_64 rng(5);
  double worst_100 = 0.0;
  double worst_1000 = 0.0;
  for (int i = 0; i < 300; ++i) {
    const IncomingBall ball = random_ball(rng);
    const double e = 0.5 + 0.5 * (i % 5) / 4.0;
    const double mu = 0.05 + 0.1 * (i % 4);
    const double s = (i % 3) * 0.2;
    const CushionRebound rigid = rigid_coulomb(ball, e, mu, s);
    const double scale = ball.velocity.y;
    worst_100 = std::max(worst_100, distance(stronge_compliant_rebound(ball, cushion(e, mu, 100.0, s)), rigid) / scale);
    worst_1000 =
        std::max(worst_1000, distance(stronge_compliant_rebound(ball, cushion(e, mu, 1000.0, s)), rigid) / scale);
  }
  EXPECT_LT(worst_100, 1e-3);
  EXPECT_LT(worst_1000, 1e-5);
  EXPECT_LT(worst_1000, 0.05 * worst_100);
}

// ------------------------------------------------------------------ laws

// (and the ball leaves the cushion, on the bed).
TEST(StrongeCompliant, EnergyNeverIncreases) {
  for_random_impacts(1, 20000, [](int i, const IncomingBall& ball, const StrongeCompliantCushion&,
                                  const CushionRebound& r) {
    const double before = energy(ball.velocity, ball.angular_velocity);
    const double after = energy(r.velocity, r.angular_velocity);
    ASSERT_LE(after, before * (1.0 + 1e-13)) << "case " << i;
    ASSERT_LT(r.velocity.y, 0.0) << "case " << i;
    ASSERT_EQ(r.velocity.z, 0.0);
  });
}

// At the equator, with e = 1, no energy leaves through the normal: the
// tangential speed of I must not grow (the spring ends unloaded and friction
// only dissipates; S7).
TEST(StrongeCompliant, TangentialSlipNeverGrows) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const double v0 = 3.0 * unit(rng);
    const StrongeCompliantCushion c = cushion(0.05 + 0.95 * unit(rng), unit(rng), 1.01 + 8.0 * unit(rng));
    const IncomingBall ball{{v0, 1.0, 0.0}, {}};
    const CushionRebound r = stronge_compliant_rebound(ball, c);
    ASSERT_LE(std::abs(slip_x(r.velocity, r.angular_velocity)), v0 * (1.0 + 1e-13) + 1e-15) << "case " << i;
  }
}

// X -> -X with the spins mirrored (a pseudovector: w_x stays, w_y and w_z change sign).
TEST(StrongeCompliant, MirrorSymmetry) {
  for_random_impacts(3, 2000, [](int i, const IncomingBall& ball, const StrongeCompliantCushion& c,
                                 const CushionRebound& r) {
    const IncomingBall mirrored{{-ball.velocity.x, ball.velocity.y, 0.0},
                                {ball.angular_velocity.x, -ball.angular_velocity.y, -ball.angular_velocity.z}};
    const CushionRebound m = stronge_compliant_rebound(mirrored, c);
    ASSERT_EQ(m.velocity.x, -r.velocity.x) << "case " << i;
    ASSERT_EQ(m.velocity.y, r.velocity.y) << "case " << i;
    ASSERT_EQ(m.angular_velocity.x, r.angular_velocity.x) << "case " << i;
    ASSERT_EQ(m.angular_velocity.y, -r.angular_velocity.y) << "case " << i;
    ASSERT_EQ(m.angular_velocity.z, -r.angular_velocity.z) << "case " << i;
  });
}

// Head-on with topspin or draw only: nothing moves out of the Y-Z plane.
TEST(StrongeCompliant, HeadOnImpactStaysInItsPlane) {
  for (double s : {0.0, 0.4}) {
    for (double k : {-3.0, -1.0, 0.0, 0.3, 1.0, 2.5}) {
      const double v = 1.3;
      const IncomingBall ball{{0.0, v, 0.0}, {-k * v / kR, 0.0, 0.0}};
      const CushionRebound r = stronge_compliant_rebound(ball, stronge_compliant_cushion({0.17, kR}, {0.85, 0.2, s, 1.8}));
      EXPECT_EQ(r.velocity.x, 0.0) << k;
      EXPECT_EQ(r.angular_velocity.y, 0.0) << k;
      EXPECT_EQ(r.angular_velocity.z, 0.0) << k;
      EXPECT_LT(r.velocity.y, 0.0) << k;
    }
  }
}

// All incoming velocities x lambda -> the result x lambda (no rate dependence).
TEST(StrongeCompliant, HomogeneousInTheIncomingVelocities) {
  for_random_impacts(4, 2000, [](int i, const IncomingBall& ball, const StrongeCompliantCushion& c,
                                 const CushionRebound& r) {
    for (double lambda : {0.01, 0.37, 8.0}) {
      const IncomingBall scaled{lambda * ball.velocity, lambda * ball.angular_velocity};
      const CushionRebound q = stronge_compliant_rebound(scaled, c);
      const CushionRebound expected{lambda * r.velocity, lambda * r.angular_velocity};
      const double scale = lambda * (norm(ball.velocity) + kR * norm(ball.angular_velocity));
      ASSERT_LE(distance(q, expected), 1e-12 * scale) << "case " << i << " lambda " << lambda;
    }
  });
}

// The exit slip is continuous in the incoming slip, also where the first phase
// changes from stick to slip (v0 = mu eta^2) and where gross slip starts.
TEST(StrongeCompliant, ContinuousAcrossStickSlipSwitches) {
  for (double e : {0.4, 0.85, 1.0}) {
    for (double omega : {1.2, 1.7, 2.5, 6.0}) {
      const double mu = 0.2;
      const StrongeCompliantCushion c = cushion(e, mu, omega);
      const double top = 1.2 * mu * (1.0 + e) * kBeta;
      const int n = 20000;
      const double step = top / n;
      double previous = 0.0;
      double worst = 0.0;
      for (int i = 0; i <= n; ++i) {
        const IncomingBall ball{{i * step, 1.0, 0.0}, {}};
        const CushionRebound r = stronge_compliant_rebound(ball, c);
        const double exit = slip_x(r.velocity, r.angular_velocity);
        if (i > 0) worst = std::max(worst, std::abs(exit - previous));
        previous = exit;
      }
      EXPECT_LT(worst, 20.0 * step) << "e " << e << " Omega " << omega;
    }
  }
}

// The contact velocities after the impact are what the scalar solution says:
// at the equator, the tangential velocity of I stays along the incoming slip
// (collinear), the normal velocity of I is -e V.
TEST(StrongeCompliant, SlipStaysOnItsLine) {
  std::mt19937_64 rng(6);
  for (int i = 0; i < 2000; ++i) {
    IncomingBall ball = random_ball(rng);
    ball.angular_velocity.x = 0.0;  // no vertical slip at the equator: the bed removes none
    const StrongeCompliantCushion c = random_cushion(rng);
    const StrongeCompliantCushion equator{c.radius, c.restitution, c.friction, 0.0, c.frequency_ratio};
    const CushionRebound r = stronge_compliant_rebound(ball, equator);
    EXPECT_NEAR(r.velocity.y, -c.restitution * ball.velocity.y, 1e-14 * ball.velocity.y);
    const double before = slip_x(ball.velocity, ball.angular_velocity);
    const double after = slip_x(r.velocity, r.angular_velocity);
    EXPECT_NEAR(kR * r.angular_velocity.x, 0.0, 1e-14 * norm(ball.velocity)) << "case " << i;
    // The change of slip is the friction impulse times beta; the impulse is
    // along the slip, so v.x changes by (after - before) / beta.
    EXPECT_NEAR(r.velocity.x - ball.velocity.x, (after - before) / kBeta, 1e-13 * norm(ball.velocity)) << i;
  }
}

// ------------------------------------------------------------------ constants

TEST(StrongeCompliant, DefaultsArePooltools) {
  const BallParameters ball = pool_parameters().ball;
  const StrongeCompliantCushion c = stronge_compliant_cushion(ball);
  EXPECT_EQ(c.radius, ball.radius);
  EXPECT_EQ(c.restitution, 0.85);
  EXPECT_EQ(c.friction, 0.2);
  EXPECT_EQ(c.sin_theta, 0.0);
  EXPECT_EQ(c.frequency_ratio, 1.8);
}

// eta^2 = (2 - nu) / (2 (1 - nu)), Omega = sqrt(beta / eta^2): nu = 0.3 gives
// 1.698, pooltool's first default 1.7; nu = 0 gives sqrt(3.5).
TEST(StrongeCompliant, FrequencyRatioFromPoissonsRatio) {
  EXPECT_NEAR(stronge_frequency_ratio(0.0), std::sqrt(3.5), 1e-15);
  EXPECT_NEAR(stronge_frequency_ratio(0.3), std::sqrt(3.5 * 1.4 / 1.7), 1e-15);
  EXPECT_NEAR(stronge_frequency_ratio(0.3), 1.7, 3e-3);
  expect_invalid("nu", [] { stronge_frequency_ratio(0.5); });
  expect_invalid("nu", [] { stronge_frequency_ratio(-0.1); });
}

TEST(StrongeCompliant, RejectsBadConstantsNamingTheField) {
  const StrongeCompliantCushion good = cushion(0.85, 0.2, 1.8, 0.4);
  EXPECT_NO_THROW(validate(good));
  auto with = [&](auto change) {
    StrongeCompliantCushion c = good;
    change(c);
    return c;
  };
  const double nan = std::nan("");
  expect_invalid("radius", [&] { validate(with([](auto& c) { c.radius = 0.0; })); });
  expect_invalid("radius", [&] { validate(with([&](auto& c) { c.radius = nan; })); });
  expect_invalid("e", [&] { validate(with([](auto& c) { c.restitution = 0.0; })); });
  expect_invalid("e", [&] { validate(with([](auto& c) { c.restitution = 1.01; })); });
  expect_invalid("mu", [&] { validate(with([](auto& c) { c.friction = -0.01; })); });
  expect_invalid("mu", [&] { validate(with([](auto& c) { c.friction = 1.5; })); });
  expect_invalid("sin_theta", [&] { validate(with([](auto& c) { c.sin_theta = 1.0; })); });
  expect_invalid("sin_theta", [&] { validate(with([](auto& c) { c.sin_theta = -0.1; })); });
  expect_invalid("Omega", [&] { validate(with([](auto& c) { c.frequency_ratio = 1.0; })); });
  expect_invalid("Omega", [&] { validate(with([](auto& c) { c.frequency_ratio = 1001.0; })); });
  expect_invalid("Omega", [&] { validate(with([&](auto& c) { c.frequency_ratio = nan; })); });
  expect_invalid("e", [] { stronge_compliant_cushion({0.17, kR}, {0.0, 0.2, 0.0, 1.8}); });
  expect_invalid("radius", [] { stronge_compliant_cushion({0.17, -1.0}); });
  try {
    validate(with([](auto& c) { c.frequency_ratio = 0.5; }));
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("0.5"), std::string::npos) << what;
    EXPECT_NE(what.find("(1, 1000]"), std::string::npos) << what;
  }
}

TEST(StrongeCompliant, AllocatesNothingAndIsDeterministic) {
  std::mt19937_64 rng(9);
  const IncomingBall ball = random_ball(rng);
  const StrongeCompliantCushion c = stronge_compliant_cushion({0.17, kR});
  const long before = g_allocations.load();
  const CushionRebound a = stronge_compliant_rebound(ball, c);
  const CushionRebound b = stronge_compliant_rebound(ball, c);
  EXPECT_EQ(g_allocations.load(), before);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.angular_velocity, b.angular_velocity);
}

}  // namespace
}  // namespace cueball
