// Tests of the ball-ball collision kernel (src/ball_collision.cpp).
//
// Nothing here reuses the kernel's formulas. The reference quantities are
// derived in this file from the rigid-body impulse laws (v += J/m,
// w += r x J / I, contact velocity v + w x r), from conservation laws, from
// Alciatore's closed forms (TP 3.1, TP 3.3, TP A.14), and from a direct RK4
// integration of Coulomb friction over the normal impulse that works on the
// balls' velocities and spins (not on the kernel's "slip age" variable).
#include "cueball/models/ball_collision/coulomb_impulse.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

const BallParameters kBall = pool_parameters().ball;
const double kR = kBall.radius;
const double kInertiaPerMass = 0.4 * kR * kR;  // I/m of a solid sphere

Vec3 lift(Vec2 v) { return {v.x, v.y, 0.0}; }
constexpr Vec3 kUp{0.0, 0.0, 1.0};

BallCollisionParameters constant_friction(double restitution, double mu) {
  BallCollisionParameters p;
  p.restitution = restitution;
  p.friction = mu;
  return p;
}

// ---------------------------------------------------------------- set-ups

struct Pair {
  BallState a;
  BallState b;
};

// Cue ball a at the origin moving along +x at speed v with spin w; object
// ball b at rest, touching, with the line of centres at the cut angle phi to
// the cue ball's path (phi > 0: b is on the +y side).
Pair cut_shot(double v, double phi, Vec3 w = {}) {
  Pair p;
  p.a = {{0.0, 0.0}, {v, 0.0}, w};
  p.b = {{2.0 * kR * std::cos(phi), 2.0 * kR * std::sin(phi)}, {}, {}};
  return p;
}

// A random touching, approaching pair anywhere on the table, speeds up to
// 4 m/s and spins up to 2 v_max / R.
Pair random_pair(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  const double v_max = 4.0;
  const double w_max = 2.0 * v_max / kR;
  Pair p;
  const double theta = angle(rng);
  p.a.position = {unit(rng), 0.5 * unit(rng)};
  p.b.position = p.a.position + 2.0 * kR * Vec2{std::cos(theta), std::sin(theta)};
  p.a.velocity = v_max * Vec2{unit(rng), unit(rng)};
  p.b.velocity = 0.5 * v_max * Vec2{unit(rng), unit(rng)};
  p.a.angular_velocity = w_max * Vec3{unit(rng), unit(rng), unit(rng)};
  p.b.angular_velocity = 0.5 * w_max * Vec3{unit(rng), unit(rng), unit(rng)};
  if (!balls_approaching(p.a, p.b)) std::swap(p.a.velocity, p.b.velocity);
  if (!balls_approaching(p.a, p.b)) {
    p.a.velocity = -p.a.velocity;
    p.b.velocity = -p.b.velocity;
  }
  return p;
}

// The contact point's velocity on ball a (at r = +R n from its centre) minus
// that on ball b (at r = -R n): v + w x r for each ball.
Vec3 contact_velocity(const BallState& a, const BallState& b) {
  const Vec2 d = b.position - a.position;
  const Vec3 n = lift(d / norm(d));
  const Vec3 on_a = lift(a.velocity) + cross(a.angular_velocity, kR * n);
  const Vec3 on_b = lift(b.velocity) + cross(b.angular_velocity, -kR * n);
  return on_a - on_b;
}

// Its part across the line of centres: the slip.
Vec3 contact_slip(const BallState& a, const BallState& b) {
  const Vec2 d = b.position - a.position;
  const Vec3 n = lift(d / norm(d));
  const Vec3 c = contact_velocity(a, b);
  return c - dot(c, n) * n;
}

// Signed angle from u to v in the plane, rad.
double angle_between(Vec2 u, Vec2 v) { return std::atan2(cross(u, v), dot(u, v)); }

// The object ball's departure angle measured from the line of centres, rad
// (positive towards z^ x n).
double throw_angle(const Pair& before, const BallState& b_after) {
  return angle_between(before.b.position - before.a.position, b_after.velocity);
}

// ---------------------------------------------------------------- an independent integration

// Coulomb friction over the normal impulse, integrated by classical RK4 on the
// balls' velocities and spins (Stronge, Impact Mechanics, ch. 4-5; Mathavan,
// Jackson & Parkin 2014). Per unit mass and unit normal impulse dp, ball b
// receives the impulse n + mu s^ at its contact point -R n, ball a the
// opposite at +R n; s is the slip of a against b (contact_slip). The bed
// keeps both balls on it: the vertical part of each impulse does not move the
// centre (the bed's reaction passes through it), it turns the ball only.
// The normal impulse grows to (1 + e) u_n / 2 (Newton; the normal and
// tangential responses of spheres are uncoupled, so this is also Poisson's and
// Stronge's end of restitution). When the impulse that stops the slip fits
// in the friction available in the next step, the contact grips: that
// impulse is applied, and no friction is needed after.
struct Integrated {
  BallState a;
  BallState b;
  bool gripped;
};

std::array<double, 10> pack(const BallState& a, const BallState& b) {
  return {a.velocity.x, a.velocity.y, a.angular_velocity.x, a.angular_velocity.y, a.angular_velocity.z,
          b.velocity.x, b.velocity.y, b.angular_velocity.x, b.angular_velocity.y, b.angular_velocity.z};
}

void unpack(const std::array<double, 10>& x, BallState& a, BallState& b) {
  a.velocity = {x[0], x[1]};
  a.angular_velocity = {x[2], x[3], x[4]};
  b.velocity = {x[5], x[6]};
  b.angular_velocity = {x[7], x[8], x[9]};
}

// Change of the packed state under impulse J (per unit mass) on b at -R n and -J on a at +R n.
std::array<double, 10> response(Vec3 n, Vec3 j) {
  const Vec3 dwb = cross(-kR * n, j) / kInertiaPerMass;
  const Vec3 dwa = cross(kR * n, -j) / kInertiaPerMass;
  return {-j.x, -j.y, dwa.x, dwa.y, dwa.z, j.x, j.y, dwb.x, dwb.y, dwb.z};
}

Integrated integrate_impact(const Pair& start, double restitution, double mu, int steps) {
  BallState a = start.a;
  BallState b = start.b;
  const Vec2 d = b.position - a.position;
  const Vec3 n = lift(d / norm(d));
  const double approach = dot(lift(a.velocity - b.velocity), n);
  const double total = 0.5 * (1.0 + restitution) * approach;
  const double dp = total / steps;
  bool gripped = false;

  auto rate = [&](const std::array<double, 10>& x) {
    BallState sa = a;
    BallState sb = b;
    unpack(x, sa, sb);
    const Vec3 s = contact_slip(sa, sb);
    const double speed = norm(s);
    const Vec3 friction = (gripped || speed == 0.0) ? Vec3{} : (mu / speed) * s;
    return response(n, n + friction);
  };

  for (int i = 0; i < steps; ++i) {
    std::array<double, 10> x = pack(a, b);
    if (!gripped && mu > 0.0) {
      // Impulse that zeroes the slip: find J (along the slip plane) with
      // slip(after J) = 0 by solving the 2x2 linear response, built from
      // `response` itself.
      const Vec3 s = contact_slip(a, b);
      const Vec3 t = cross(kUp, n);
      auto slip_change = [&](Vec3 j) {
        BallState sa = a;
        BallState sb = b;
        std::array<double, 10> y = x;
        const std::array<double, 10> r = response(n, j);
        for (std::size_t k = 0; k < y.size(); ++k) y[k] += r[k];
        unpack(y, sa, sb);
        return contact_slip(sa, sb) - s;
      };
      const Vec3 ct = slip_change(t);
      const Vec3 cz = slip_change(kUp);
      // s + jt ct + jz cz = 0 in the (t, z) plane.
      const double m11 = dot(ct, t), m12 = dot(cz, t), m21 = dot(ct, kUp), m22 = dot(cz, kUp);
      const double det = m11 * m22 - m12 * m21;
      const double rt = -dot(s, t), rz = -dot(s, kUp);
      const double jt = (rt * m22 - m12 * rz) / det;
      const double jz = (m11 * rz - m21 * rt) / det;
      if (std::hypot(jt, jz) <= mu * dp) {
        const std::array<double, 10> r = response(n, jt * t + jz * kUp);
        for (std::size_t k = 0; k < x.size(); ++k) x[k] += r[k];
        unpack(x, a, b);
        gripped = true;
      }
    }
    // One RK4 step of dx/dp.
    std::array<double, 10> k1 = rate(x), x2 = x, x3 = x, x4 = x, out = x;
    for (std::size_t k = 0; k < x.size(); ++k) x2[k] += 0.5 * dp * k1[k];
    const std::array<double, 10> k2 = rate(x2);
    for (std::size_t k = 0; k < x.size(); ++k) x3[k] += 0.5 * dp * k2[k];
    const std::array<double, 10> k3 = rate(x3);
    for (std::size_t k = 0; k < x.size(); ++k) x4[k] += dp * k3[k];
    const std::array<double, 10> k4 = rate(x4);
    for (std::size_t k = 0; k < x.size(); ++k) out[k] += dp / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
    unpack(out, a, b);
  }
  return {a, b, gripped};
}

// ---------------------------------------------------------------- parameters

TEST(BallCollisionParameters, PresetsAreValidAndMatchTheirSources) {
  const BallCollisionParameters p = ball_collision_alciatore();
  EXPECT_NO_THROW(validate(p));
  EXPECT_EQ(p.restitution, 0.95);
  EXPECT_EQ(p.friction, 9.951e-3);
  EXPECT_EQ(p.friction_excess, 0.108);
  EXPECT_EQ(p.friction_decay, 1.088);
  // Alciatore's fit: a + b exp(-c v).
  for (double v : {0.0, 0.2, 1.0, 3.0}) {
    EXPECT_DOUBLE_EQ(ball_friction(p, v), 9.951e-3 + 0.108 * std::exp(-1.088 * v));
  }
  // It spans the published constant range 0.03-0.08 over everyday slip speeds, falling with speed.
  EXPECT_GT(ball_friction(p, 0.3), 0.08);
  EXPECT_LT(ball_friction(p, 3.0), 0.03);
  EXPECT_GT(ball_friction(p, 0.5), ball_friction(p, 0.6));

  const BallCollisionParameters f = ball_collision_frictionless(0.93);
  EXPECT_NO_THROW(validate(f));
  EXPECT_EQ(f.restitution, 0.93);
  EXPECT_EQ(ball_friction(f, 0.0), 0.0);
  EXPECT_EQ(ball_friction(constant_friction(0.9, 0.06), 2.0), 0.06);
}

TEST(BallCollisionParameters, BadValuesAreRejectedByName) {
  struct Case {
    BallCollisionParameters p;
    const char* field;
    const char* range;
  };
  const double nan = std::nan("");
  const double inf = HUGE_VAL;
  const std::vector<Case> cases{
      {{-0.1, 0.05, 0.0, 0.0}, "restitution", "[0, 1]"},
      {{1.01, 0.05, 0.0, 0.0}, "restitution", "[0, 1]"},
      {{nan, 0.05, 0.0, 0.0}, "restitution", "[0, 1]"},
      {{0.95, -0.01, 0.0, 0.0}, "friction", "[0, 1]"},
      {{0.95, 1.5, 0.0, 0.0}, "friction", "[0, 1]"},
      {{0.95, inf, 0.0, 0.0}, "friction", "[0, 1]"},
      {{0.95, 0.01, -0.1, 1.0}, "friction_excess", "[0, 1]"},
      {{0.95, 0.01, nan, 1.0}, "friction_excess", "[0, 1]"},
      {{0.95, 0.01, 0.1, -1.0}, "friction_decay", "[0, 100]"},
      {{0.95, 0.01, 0.1, 1e3}, "friction_decay", "[0, 100]"},
      {{0.95, 0.01, 0.1, nan}, "friction_decay", "[0, 100]"},
      {{0.95, 0.6, 0.6, 1.0}, "friction_excess", "at most 1"},
  };
  for (const Case& c : cases) {
    try {
      validate(c.p);
      ADD_FAILURE() << "accepted a bad " << c.field;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field(), c.field);
      const std::string message = e.what();
      EXPECT_NE(message.find(c.field), std::string::npos) << message;
      EXPECT_NE(message.find(c.range), std::string::npos) << message;
    }
  }
  // The edges of the ranges are allowed.
  EXPECT_NO_THROW(validate(BallCollisionParameters{0.0, 0.0, 0.0, 0.0}));
  EXPECT_NO_THROW(validate(BallCollisionParameters{1.0, 0.5, 0.5, 100.0}));
}

// ---------------------------------------------------------------- predicates and no-ops

TEST(BallCollision, ApproachingMeansTheCentresAreClosing) {
  const Pair p = cut_shot(1.0, 20.0 * kDegree);
  EXPECT_TRUE(balls_approaching(p.a, p.b));
  EXPECT_TRUE(balls_approaching(p.b, p.a));  // symmetric
  BallState away = p.a;
  away.velocity = -away.velocity;
  EXPECT_FALSE(balls_approaching(away, p.b));
  BallState grazing = p.a;
  grazing.velocity = perp(p.b.position - p.a.position);  // moving across the line of centres
  EXPECT_FALSE(balls_approaching(grazing, p.b));
  BallState same_place = p.b;
  same_place.velocity = {1.0, 0.0};
  EXPECT_FALSE(balls_approaching(same_place, p.b));  // no line of centres
  // The same relative motion seen from a moving frame.
  BallState a = p.a, b = p.b;
  a.velocity = a.velocity + Vec2{-3.0, 2.0};
  b.velocity = b.velocity + Vec2{-3.0, 2.0};
  EXPECT_TRUE(balls_approaching(a, b));
}

TEST(BallCollision, APairThatIsNotApproachingIsLeftAlone) {
  Pair p = cut_shot(1.0, 30.0 * kDegree, {10.0, -20.0, 30.0});
  p.a.velocity = -p.a.velocity;
  const BallCollisionResult r = resolve_ball_collision(p.a, p.b, kBall, ball_collision_alciatore());
  EXPECT_EQ(r.a.velocity, p.a.velocity);
  EXPECT_EQ(r.a.angular_velocity, p.a.angular_velocity);
  EXPECT_EQ(r.b.velocity, p.b.velocity);
  EXPECT_EQ(r.normal_impulse, 0.0);
  EXPECT_EQ(r.tangential_impulse, 0.0);
  EXPECT_EQ(r.vertical_impulse, 0.0);
}

TEST(BallCollision, PairFormMatchesTheDetailedResultAndKeepsPositions) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100; ++i) {
    const Pair p = random_pair(rng);
    const BallCollisionResult r = resolve_ball_collision(p.a, p.b, kBall, ball_collision_alciatore());
    const auto [a, b] = collide_balls(p.a, p.b, kBall, ball_collision_alciatore());
    EXPECT_EQ(a.velocity, r.a.velocity);
    EXPECT_EQ(b.angular_velocity, r.b.angular_velocity);
    EXPECT_EQ(a.position, p.a.position);
    EXPECT_EQ(b.position, p.b.position);
    // The reported impulses are those that changed b's momentum.
    const Vec2 n = (p.b.position - p.a.position) / norm(p.b.position - p.a.position);
    const Vec2 dv = r.b.velocity - p.b.velocity;
    EXPECT_NEAR(kBall.mass * dot(dv, n), r.normal_impulse, 1e-13);
    EXPECT_NEAR(kBall.mass * dot(dv, perp(n)), r.tangential_impulse, 1e-13);
    EXPECT_GT(r.normal_impulse, 0.0);
  }
}

// ---------------------------------------------------------------- conservation laws

struct ModelCase {
  const char* name;
  BallCollisionParameters p;
};

std::vector<ModelCase> models() {
  return {{"frictionless e=1", ball_collision_frictionless(1.0)},
          {"frictionless e=0.9", ball_collision_frictionless(0.9)},
          {"constant mu=0.06", constant_friction(0.94, 0.06)},
          {"constant mu=0.4 (grips often)", constant_friction(0.8, 0.4)},
          {"Alciatore", ball_collision_alciatore()},
          {"plastic, mu=1", constant_friction(0.0, 1.0)}};
}

TEST(BallCollision, LinearMomentumIsConserved) {
  std::mt19937_64 rng(1);
  for (const ModelCase& m : models()) {
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
      const Pair p = random_pair(rng);
      const auto [a, b] = collide_balls(p.a, p.b, kBall, m.p);
      const Vec2 before = p.a.velocity + p.b.velocity;
      const Vec2 after = a.velocity + b.velocity;
      const double scale = norm(p.a.velocity) + norm(p.b.velocity);
      worst = std::max(worst, norm(after - before) / scale);
    }
    EXPECT_LT(worst, 4e-16) << m.name;
  }
}

// The impulse at K has no moment about K, and the bed's vertical impulses at
// the balls' feet (cancelling the vertical part, B3) have a moment about K
// along t = z^ x n only, the same for both balls (a couple). So about the
// contact point each ball keeps its angular momentum along n and along z,
// and the t-components change equally. About any point, the pair's total
// angular momentum about the vertical is conserved.
TEST(BallCollision, AngularMomentumAboutTheContactPoint) {
  std::mt19937_64 rng(2);
  for (const ModelCase& m : models()) {
    double worst = 0.0;
    for (int i = 0; i < 20000; ++i) {
      const Pair p = random_pair(rng);
      const auto [a, b] = collide_balls(p.a, p.b, kBall, m.p);
      const Vec2 d = p.b.position - p.a.position;
      const Vec3 n = lift(d / norm(d));
      const Vec3 t = cross(kUp, n);
      const Vec3 k = lift(p.a.position) + kR * n;  // centres and K at the same height
      auto moment = [&](const BallState& s) {  // per unit mass
        return cross(lift(s.position) - k, lift(s.velocity)) + kInertiaPerMass * s.angular_velocity;
      };
      const Vec3 da = moment(a) - moment(p.a);
      const Vec3 db = moment(b) - moment(p.b);
      const double scale = kR * (norm(p.a.velocity) + norm(p.b.velocity)) +
                           kInertiaPerMass * (norm(p.a.angular_velocity) + norm(p.b.angular_velocity));
      worst = std::max({worst, std::abs(dot(da, n)) / scale, std::abs(dot(da, kUp)) / scale,
                        std::abs(dot(db, n)) / scale, std::abs(dot(db, kUp)) / scale,
                        std::abs(dot(da, t) - dot(db, t)) / scale});
      // Total about the vertical, about an arbitrary point (the origin).
      auto total_z = [](const BallState& s1, const BallState& s2) {
        return cross(s1.position, s1.velocity) + cross(s2.position, s2.velocity) +
               kInertiaPerMass * (s1.angular_velocity.z + s2.angular_velocity.z);
      };
      const double lz_scale = scale + (norm(p.a.position) + norm(p.b.position)) *
                                          (norm(p.a.velocity) + norm(p.b.velocity));
      worst = std::max(worst, std::abs(total_z(a, b) - total_z(p.a, p.b)) / lz_scale);
    }
    EXPECT_LT(worst, 1e-14) << m.name;
  }
}

TEST(BallCollision, KineticEnergyNeverIncreases) {
  std::mt19937_64 rng(3);
  for (const ModelCase& m : models()) {
    double worst_gain = -1.0;
    for (int i = 0; i < 20000; ++i) {
      const Pair p = random_pair(rng);
      const auto [a, b] = collide_balls(p.a, p.b, kBall, m.p);
      const double before = kinetic_energy(p.a, kBall) + kinetic_energy(p.b, kBall);
      const double after = kinetic_energy(a, kBall) + kinetic_energy(b, kBall);
      worst_gain = std::max(worst_gain, (after - before) / before);
    }
    EXPECT_LE(worst_gain, 1e-15) << m.name;
    // Only the elastic frictionless collision keeps all of it.
    if (m.p.restitution == 1.0 && m.p.friction == 0.0) {
      EXPECT_GT(worst_gain, -1e-15) << m.name;
    }
  }
  // The normal part loses exactly (1 - e^2) m u_n^2 / 4 without friction.
  const Pair p = cut_shot(2.0, 35.0 * kDegree, {5.0, -7.0, 11.0});
  const auto [a, b] = collide_balls(p.a, p.b, kBall, ball_collision_frictionless(0.9));
  const double u_n = 2.0 * std::cos(35.0 * kDegree);
  const double loss = kinetic_energy(p.a, kBall) + kinetic_energy(p.b, kBall) - kinetic_energy(a, kBall) -
                      kinetic_energy(b, kBall);
  EXPECT_NEAR(loss, (1.0 - 0.81) * kBall.mass * u_n * u_n / 4.0, 1e-15);
}

// Coulomb's law as the impulses show it: the friction impulse (horizontal
// part from b's momentum, vertical part from b's spin about t) is at most mu
// times the normal impulse; each slip component keeps its sign and does not
// grow; a gripping contact leaves with zero slip.
TEST(BallCollision, FrictionObeysCoulombAndNeverReversesTheSlip) {
  std::mt19937_64 rng(4);
  int gripped = 0;
  int slid = 0;
  for (const ModelCase& m : models()) {
    for (int i = 0; i < 20000; ++i) {
      const Pair p = random_pair(rng);
      const BallCollisionResult r = resolve_ball_collision(p.a, p.b, kBall, m.p);
      const Vec2 d = p.b.position - p.a.position;
      const Vec3 n = lift(d / norm(d));
      const Vec3 t = cross(kUp, n);
      const Vec3 s0 = contact_slip(p.a, p.b);
      const Vec3 s1 = contact_slip(r.a, r.b);
      EXPECT_NEAR(r.slip_speed, norm(s0), 1e-12);
      const double mu = ball_friction(m.p, norm(s0));
      EXPECT_NEAR(r.friction, mu, 1e-15);
      // Impulses per unit mass on b.
      const double p_n = dot(lift(r.b.velocity - p.b.velocity), n);
      const double p_t = dot(lift(r.b.velocity - p.b.velocity), t);
      // I dw_b = (-R n) x (p_z z) = R p_z t  (per unit mass).
      const double p_z = kInertiaPerMass * dot(r.b.angular_velocity - p.b.angular_velocity, t) / kR;
      EXPECT_NEAR(kBall.mass * p_z, r.vertical_impulse, 1e-13);
      EXPECT_LE(std::hypot(p_t, p_z), mu * p_n * (1.0 + 1e-12) + 1e-15);
      // No reversal, no growth, up to the round-off of the velocities (scale).
      const double scale = norm(p.a.velocity) + norm(p.b.velocity) +
                           kR * (norm(p.a.angular_velocity) + norm(p.b.angular_velocity));
      const double round_off = 1e-14 * scale;
      auto sign = [](double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); };
      EXPECT_GE(sign(dot(s0, t)) * dot(s1, t), -round_off);
      EXPECT_GE(sign(dot(s0, kUp)) * dot(s1, kUp), -round_off);
      EXPECT_LE(std::abs(dot(s1, t)), std::abs(dot(s0, t)) + round_off);
      EXPECT_LE(std::abs(dot(s1, kUp)), std::abs(dot(s0, kUp)) + round_off);
      if (r.gripped) {
        ++gripped;
        EXPECT_LT(norm(s1), round_off) << m.name;
      } else if (mu > 0.0) {
        ++slid;
        // Friction was not enough: it acted at its full Coulomb value all along,
        // so only a turning slip direction can make the total fall short of mu p_n.
        EXPECT_GT(norm(s1), 0.0);
      }
    }
  }
  EXPECT_GT(gripped, 1000);
  EXPECT_GT(slid, 1000);
}

// ---------------------------------------------------------------- the classic rules

// TP 3.1, the 90 degree rule: a stun cue ball (no spin) hitting a ball at rest,
// e = 1 and no friction: the impulse along n takes the cue ball's n-component
// and leaves its t-component, so the two leave at right angles for every cut.
TEST(BallCollision, NinetyDegreeRule) {
  for (double deg = 1.0; deg < 90.0; deg += 1.0) {
    const double phi = deg * kDegree;
    for (double v : {0.3, 1.5, 6.0}) {
      const Pair p = cut_shot(v, phi);
      const auto [a, b] = collide_balls(p.a, p.b, kBall, ball_collision_frictionless(1.0));
      EXPECT_NEAR(dot(a.velocity, b.velocity) / (v * v), 0.0, 1e-15) << deg;  // round-off
      EXPECT_NEAR(norm(a.velocity), v * std::sin(phi), 1e-15 * v) << deg;
      EXPECT_NEAR(norm(b.velocity), v * std::cos(phi), 1e-15 * v) << deg;
      EXPECT_EQ(a.angular_velocity, Vec3{});
      EXPECT_EQ(b.angular_velocity, Vec3{});
    }
  }
  // With e < 1 the cue ball keeps some of its n-component: less than 90 degrees.
  const Pair p = cut_shot(1.0, 30.0 * kDegree);
  const auto [a, b] = collide_balls(p.a, p.b, kBall, ball_collision_frictionless(0.9));
  EXPECT_LT(std::abs(angle_between(a.velocity, b.velocity)), 89.0 * kDegree);
}

TEST(BallCollision, HeadOnStunShotStopsTheCueBall) {
  for (double v : {0.1, 1.0, 8.0}) {
    const Pair p = cut_shot(v, 0.0);
    const std::array<BallCollisionParameters, 3> elastic{ball_collision_frictionless(1.0), constant_friction(1.0, 0.3),
                                                         BallCollisionParameters{1.0, 0.01, 0.1, 1.0}};
    for (const BallCollisionParameters& c : elastic) {
      const auto [a, b] = collide_balls(p.a, p.b, kBall, c);
      EXPECT_EQ(norm(a.velocity), 0.0);
      EXPECT_EQ(b.velocity.x, v);
      EXPECT_EQ(b.velocity.y, 0.0);
      EXPECT_EQ(a.angular_velocity, Vec3{});  // no slip, so no friction
      EXPECT_EQ(b.angular_velocity, Vec3{});
    }
    // Newton's e: the cue ball keeps (1 - e)/2 of v, the object ball takes (1 + e)/2.
    const auto [a, b] = collide_balls(p.a, p.b, kBall, ball_collision_alciatore());
    EXPECT_NEAR(a.velocity.x, 0.025 * v, 1e-15 * v);
    EXPECT_NEAR(b.velocity.x, 0.975 * v, 1e-15 * v);
  }
}

// TP 3.3 (and TP A.4), the 30 degree rule. A rolling cue ball (R w = v, no
// side spin), e = 1, no friction: the collision takes away the n-component
// v cos(phi) and leaves the spin, so the cue ball slides with slip
// u0 = -v cos(phi) n; the cloth's friction then ends the sliding at
// v1 = v0 - 2/7 u0 (paper 001 eq. 9), i.e. v1 = v sin(phi) t^ + 2/7 v cos(phi) n
// with n, t^ the unit vectors of the line of centres and the tangent line.
// Its angle to the original line v = v (cos(phi) n + sin(phi) t^) follows
// from tan(angle of v1 from n) = 7/2 tan(phi):
//   tan(theta) = (5/2 tan(phi)) / (1 + 7/2 tan^2(phi))
//              = sin(phi) cos(phi) / (sin^2(phi) + 2/5).
// Half-ball hit (sin(phi) = 1/2): tan(theta) = (sqrt(3)/4) / (13/20) =
// 5 sqrt(3) / 13, theta = 33.67 deg. The maximum is at sin^2(phi) = 2/9
// (d/dphi = 0 gives sin^2 = k/(1 + 2k), k = 2/5): tan = sqrt(14)/5.6,
// 33.75 deg; between the 3/4-ball and 1/4-ball hits (sin(phi) = 1/4 .. 3/4)
// the deflection stays within 27.2-33.75 deg: the 30 degree rule.
double rolled_out_deflection(double phi) {
  const Parameters table = pool_parameters();
  const double v = 1.5;
  const Pair p = cut_shot(v, phi, {0.0, v / kR, 0.0});  // rolling along +x: w = z^ x v / R
  EXPECT_EQ(motion_phase(p.a, table), MotionPhase::rolling);
  const auto [a, b] = collide_balls(p.a, p.b, kBall, ball_collision_frictionless(1.0));
  const NextTransition next = next_transition(a, table);
  EXPECT_EQ(next.kind, Transition::sliding_ends);
  const BallState rolled = evolve(a, next.time, table);
  EXPECT_EQ(motion_phase(rolled, table), MotionPhase::rolling);
  return std::abs(angle_between(p.a.velocity, rolled.velocity));
}

double thirty_degree_rule(double phi) {
  const double s = std::sin(phi);
  return std::atan(s * std::cos(phi) / (s * s + 0.4));
}

TEST(BallCollision, ThirtyDegreeRule) {
  const double half_ball = std::asin(0.5);
  EXPECT_NEAR(rolled_out_deflection(half_ball), std::atan(5.0 * std::sqrt(3.0) / 13.0), 1e-12);
  EXPECT_NEAR(rolled_out_deflection(half_ball) / kDegree, 33.67, 0.005);

  double largest = 0.0;
  for (double s = 0.25; s <= 0.75 + 1e-12; s += 0.01) {
    const double phi = std::asin(s);
    const double deflection = rolled_out_deflection(phi);
    EXPECT_NEAR(deflection, thirty_degree_rule(phi), 1e-12) << s;
    EXPECT_GE(deflection / kDegree, 27.0) << s;
    EXPECT_LE(deflection / kDegree, 34.0) << s;
    largest = std::max(largest, deflection);
  }
  const double peak = std::atan(std::sqrt(14.0) / 5.6);
  EXPECT_NEAR(rolled_out_deflection(std::asin(std::sqrt(2.0 / 9.0))), peak, 1e-12);
  EXPECT_LE(largest, peak + 1e-12);
  EXPECT_NEAR(peak / kDegree, 33.75, 0.005);
}

// ---------------------------------------------------------------- throw

// TP A.14, stun shots (no follow or draw, so the slip at the contact is
// horizontal): the object ball is thrown off the line of centres by
//   theta = atan(min(mu v cos(phi) / v_rel, 1/7) (v sin(phi) - R w_z) / (v cos(phi))),
//   v_rel = |v sin(phi) - R w_z|, mu = mu(v_rel),
// for the elastic normal impulse m v cos(phi) that TP A.14 assumes (e = 1).
// Its origin, for any e: normal impulse F_n = (1 + e)/2 m v cos(phi); the
// tangential impulse F_t that stops the slip changes it by 2 (F_t/m)(1 + 5/2)
// = 7 F_t/m (both balls, translation and rotation), so F_t = min(mu F_n,
// m v_rel / 7), and tan(theta) = F_t / F_n. It throws the object ball to the
// side the cue ball's surface moves at the contact. In cut_shot's layout
// (t = z^ x n) the cue ball's contact point moves along t at
// R w_z - v sin(phi), so the signed throw (from n towards t) is
// -atan(min(mu F_n, m v_rel / 7) / F_n * sign(v sin(phi) - R w_z)).
double alciatore_stun_throw(double v, double phi, double wz, double restitution, const BallCollisionParameters& c) {
  const double slip = v * std::sin(phi) - kR * wz;  // Alciatore's v sin(phi) - R w_z
  const double v_rel = std::abs(slip);
  if (v_rel == 0.0) return 0.0;
  const double mu = ball_friction(c, v_rel);  // Alciatore's fit is checked in the presets test
  const double f_n = 0.5 * (1.0 + restitution) * v * std::cos(phi);
  const double f_t = std::min(mu * f_n, v_rel / 7.0);
  return -std::atan(f_t / f_n) * (slip > 0.0 ? 1.0 : -1.0);
}

double alciatore_formula_as_printed(double v, double phi, double wz, const BallCollisionParameters& c) {
  const double v_rel = std::abs(v * std::sin(phi) - kR * wz);
  const double mu = ball_friction(c, v_rel);
  return std::atan(std::min(mu * v * std::cos(phi) / v_rel, 1.0 / 7.0) * (v * std::sin(phi) - kR * wz) /
                   (v * std::cos(phi)));
}

TEST(BallCollision, CutInducedThrowMatchesAlciatore) {
  BallCollisionParameters elastic = ball_collision_alciatore();
  elastic.restitution = 1.0;
  int gripping = 0;
  for (double v : {0.447, 1.341, 3.129}) {  // TP A.14's slow, medium and fast: 1, 3, 7 mph
    for (double deg = 2.0; deg <= 70.0; deg += 2.0) {
      const double phi = deg * kDegree;
      const Pair p = cut_shot(v, phi);
      const BallCollisionResult r = resolve_ball_collision(p.a, p.b, kBall, elastic);
      const double expected = alciatore_stun_throw(v, phi, 0.0, 1.0, elastic);
      EXPECT_NEAR(throw_angle(p, r.b), expected, 1e-13) << v << " m/s, " << deg << " deg";
      EXPECT_NEAR(-throw_angle(p, r.b), alciatore_formula_as_printed(v, phi, 0.0, elastic), 1e-13);
      EXPECT_LT(throw_angle(p, r.b), 0.0);  // towards the cue ball's motion, -t here
      if (r.gripped) ++gripping;
    }
  }
  EXPECT_GT(gripping, 5);  // small cuts grip: throw atan(tan(phi)/7), independent of speed
  // The same law with inelastic normal impulses and a constant coefficient (TP A.5's 0.06).
  for (double e : {0.0, 0.5, 0.94}) {
    for (double deg = 5.0; deg <= 80.0; deg += 5.0) {
      const Pair p = cut_shot(1.0, deg * kDegree);
      const auto [a, b] = collide_balls(p.a, p.b, kBall, constant_friction(e, 0.06));
      EXPECT_NEAR(throw_angle(p, b), alciatore_stun_throw(1.0, deg * kDegree, 0.0, e, constant_friction(e, 0.06)),
                  1e-13)
          << e << ", " << deg;
    }
  }
  // At 30 degrees, mu = 0.06 slides: tan(theta) = mu exactly (TP A.5).
  const Pair p = cut_shot(1.0, 30.0 * kDegree);
  const auto [a, b] = collide_balls(p.a, p.b, kBall, constant_friction(0.94, 0.06));
  EXPECT_NEAR(std::tan(-throw_angle(p, b)), 0.06, 1e-14);
}

TEST(BallCollision, SpinInducedThrowMatchesAlciatore) {
  BallCollisionParameters elastic = ball_collision_alciatore();
  elastic.restitution = 1.0;
  for (double v : {0.447, 1.341, 3.129}) {
    for (double english : {-1.0, -0.5, -0.25, 0.25, 0.5, 1.0}) {  // R w_z = english x v
      for (double deg : {0.0, 10.0, 30.0}) {
        const double phi = deg * kDegree;
        const double wz = english * v / kR;
        const Pair p = cut_shot(v, phi, {0.0, 0.0, wz});
        const auto [a, b] = collide_balls(p.a, p.b, kBall, elastic);
        EXPECT_NEAR(throw_angle(p, b), alciatore_stun_throw(v, phi, wz, 1.0, elastic), 1e-13)
            << v << " " << english << " " << deg;
      }
    }
  }
  // Gearing English, R w_z = v sin(phi): no slip, no throw, no spin transfer.
  for (double deg : {15.0, 30.0, 45.0}) {
    const double phi = deg * kDegree;
    const Pair p = cut_shot(1.341, phi, {0.0, 0.0, 1.341 * std::sin(phi) / kR});
    const BallCollisionResult r = resolve_ball_collision(p.a, p.b, kBall, ball_collision_alciatore());
    EXPECT_NEAR(throw_angle(p, r.b), 0.0, 1e-14);
    EXPECT_NEAR(norm(r.b.angular_velocity), 0.0, 1e-12);
    EXPECT_NEAR(r.slip_speed, 0.0, 1e-14);
  }
  // Spin transfer: friction gives both balls the same angular impulse, here
  // about the vertical, opposite to the cue ball's side spin.
  const Pair p = cut_shot(1.0, 0.0, {0.0, 0.0, 20.0});
  const auto [a, b] = collide_balls(p.a, p.b, kBall, ball_collision_alciatore());
  EXPECT_LT(b.angular_velocity.z, 0.0);
  EXPECT_NEAR(a.angular_velocity.z - 20.0, b.angular_velocity.z, 1e-12);
}

// With follow or draw the slip also has a vertical component R w cos(phi),
// which the bed makes stiffer than the horizontal one (rotation only, 5/m,
// against 7/m), so the slip direction turns during the impact and there is
// no one-line formula: compare with the direct integration.
TEST(BallCollision, MatchesADirectIntegrationOfCoulombFriction) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int gripped = 0;
  int slid = 0;
  for (int i = 0; i < 300; ++i) {
    Pair p = random_pair(rng);
    const double e = 0.85 + 0.15 * uniform(rng);
    const double mu = std::array<double, 4>{0.02, 0.06, 0.15, 0.35}[static_cast<std::size_t>(i % 4)];
    const BallCollisionResult r = resolve_ball_collision(p.a, p.b, kBall, constant_friction(e, mu));
    const Integrated x = integrate_impact(p, e, mu, 4000);
    const double v_scale = norm(p.a.velocity) + norm(p.b.velocity) +
                           kR * (norm(p.a.angular_velocity) + norm(p.b.angular_velocity));
    EXPECT_LT(norm(r.a.velocity - x.a.velocity) / v_scale, 1e-9) << i;
    EXPECT_LT(norm(r.b.velocity - x.b.velocity) / v_scale, 1e-9) << i;
    EXPECT_LT(kR * norm(r.a.angular_velocity - x.a.angular_velocity) / v_scale, 1e-9) << i;
    EXPECT_LT(kR * norm(r.b.angular_velocity - x.b.angular_velocity) / v_scale, 1e-9) << i;
    EXPECT_EQ(r.gripped, x.gripped) << i;
    (r.gripped ? gripped : slid)++;
  }
  EXPECT_GT(gripped, 30);
  EXPECT_GT(slid, 30);

  // Cut shots with follow and draw, speed-dependent friction evaluated at the incoming slip speed.
  for (double follow : {-1.0, -0.5, 0.5, 1.0, 2.0}) {
    for (double deg : {5.0, 20.0, 30.0, 50.0}) {
      for (double v : {0.447, 1.341, 3.129}) {
        const Pair p = cut_shot(v, deg * kDegree, {0.0, follow * v / kR, 0.0});
        const BallCollisionParameters c = ball_collision_alciatore();
        const BallCollisionResult r = resolve_ball_collision(p.a, p.b, kBall, c);
        const double mu = ball_friction(c, norm(contact_slip(p.a, p.b)));
        const Integrated x = integrate_impact(p, c.restitution, mu, 4000);
        EXPECT_LT(norm(r.b.velocity - x.b.velocity) / v, 1e-9) << follow << " " << deg << " " << v;
        EXPECT_LT(kR * norm(r.a.angular_velocity - x.a.angular_velocity) / v, 1e-9) << follow << " " << deg;
      }
    }
  }
}

// Follow and draw of the same strength throw the object ball equally (the
// vertical slip enters through its magnitude only), and less than stun.
TEST(BallCollision, FollowAndDrawReduceThrowEqually) {
  const BallCollisionParameters c = ball_collision_alciatore();
  for (double deg : {10.0, 30.0, 45.0}) {
    for (double v : {0.447, 1.341, 3.129}) {
      const double phi = deg * kDegree;
      const Pair stun = cut_shot(v, phi);
      const double stun_throw = throw_angle(stun, collide_balls(stun.a, stun.b, kBall, c).second);
      for (double k : {0.5, 1.0}) {
        const Pair follow = cut_shot(v, phi, {0.0, k * v / kR, 0.0});
        const Pair draw = cut_shot(v, phi, {0.0, -k * v / kR, 0.0});
        const double f = throw_angle(follow, collide_balls(follow.a, follow.b, kBall, c).second);
        const double d = throw_angle(draw, collide_balls(draw.a, draw.b, kBall, c).second);
        EXPECT_NEAR(f, d, 1e-14 * std::abs(f));
        EXPECT_LT(std::abs(f), std::abs(stun_throw));
      }
    }
  }
}

// Weak friction: the slip direction has no time to turn, and the horizontal
// friction impulse tends to TP A.14's fixed-direction mu p_n s_t/|s0|. The
// first correction, from Coulomb's law ds/dp = -mu diag(7, 5) s/|s| expanded
// in p: with a = (s_t/|s0|)^2, b = (s_z/|s0|)^2 (a + b = 1),
//   d|s|/dp = -mu (7a + 5b) at p = 0, and ds_t/dp = -7 mu s_t/|s|, so
//   s_t(p) = s_t0 (1 - 7 x - 7 (7a + 5b - 7) x^2 / 2 + ...) = s_t0 (1 - 7 x + 7 b x^2 + ...)
// with x = mu p/|s0| (the x^2 term from 1/|s| growing as |s| shrinks;
// 7a + 5b - 7 = -2b). The friction impulse p_t = (s_t0 - s_t(p_n))/7 is then
//   p_t = mu p_n (s_t0/|s0|) (1 - b tau + O(tau^2)),  tau = mu p_n/|s0|.
TEST(BallCollision, WeakFrictionTendsToTheFixedDirectionLaw) {
  for (double mu : {1e-3, 1e-4}) {
    for (double follow : {0.3, 1.0, 3.0}) {
      const double v = 1.0;
      const double phi = 30.0 * kDegree;
      const Pair p = cut_shot(v, phi, {0.0, follow * v / kR, 0.0});
      const BallCollisionResult r = resolve_ball_collision(p.a, p.b, kBall, constant_friction(1.0, mu));
      const Vec3 s0 = contact_slip(p.a, p.b);
      const Vec2 n = (p.b.position - p.a.position) / (2.0 * kR);
      const double s_t = dot(s0, lift(perp(n)));
      const double p_n = v * std::cos(phi);
      const double tau = mu * p_n / norm(s0);
      const double b = s0.z * s0.z / dot(s0, s0);
      const double fixed_direction = mu * p_n * s_t / norm(s0);
      const double p_t = r.tangential_impulse / kBall.mass;
      EXPECT_NEAR(p_t / fixed_direction, 1.0 - b * tau, 3.0 * tau * tau) << mu << " " << follow;
    }
  }
}

// ---------------------------------------------------------------- symmetries

void expect_same_state(const BallState& x, const BallState& y, double tolerance, const char* what) {
  const double v = norm(x.velocity) + norm(y.velocity) + 1.0;
  const double w = norm(x.angular_velocity) + norm(y.angular_velocity) + 1.0;
  EXPECT_LT(norm(x.velocity - y.velocity), tolerance * v) << what;
  EXPECT_LT(norm(x.angular_velocity - y.angular_velocity), tolerance * w) << what;
}

// Reflection y -> -y: positions and velocities reflect; the angular
// velocity is an axial vector, w -> (-w_x, w_y, -w_z).
BallState mirrored(const BallState& s) {
  return {{s.position.x, -s.position.y},
          {s.velocity.x, -s.velocity.y},
          {-s.angular_velocity.x, s.angular_velocity.y, -s.angular_velocity.z}};
}

BallState rotated(const BallState& s, double angle) {
  const double c = std::cos(angle);
  const double sn = std::sin(angle);
  auto turn = [&](Vec2 v) { return Vec2{c * v.x - sn * v.y, sn * v.x + c * v.y}; };
  const Vec2 wh = turn(horizontal(s.angular_velocity));
  return {turn(s.position), turn(s.velocity), {wh.x, wh.y, s.angular_velocity.z}};
}

BallState boosted(BallState s, Vec2 frame_velocity) {
  s.velocity = s.velocity + frame_velocity;
  return s;
}

TEST(BallCollision, Symmetries) {
  std::mt19937_64 rng(6);
  for (const ModelCase& m : models()) {
    for (int i = 0; i < 2000; ++i) {
      const Pair p = random_pair(rng);
      const auto [a, b] = collide_balls(p.a, p.b, kBall, m.p);

      const auto [ma, mb] = collide_balls(mirrored(p.a), mirrored(p.b), kBall, m.p);
      expect_same_state(ma, mirrored(a), 1e-13, "mirror");
      expect_same_state(mb, mirrored(b), 1e-13, "mirror");

      const double angle = 0.7 + i;
      const auto [ra, rb] = collide_balls(rotated(p.a, angle), rotated(p.b, angle), kBall, m.p);
      expect_same_state(ra, rotated(a, angle), 1e-12, "rotation");
      expect_same_state(rb, rotated(b, angle), 1e-12, "rotation");

      const auto [sb, sa] = collide_balls(p.b, p.a, kBall, m.p);
      expect_same_state(sa, a, 1e-14, "swap");
      expect_same_state(sb, b, 1e-14, "swap");

      // Galilean invariance: the same collision seen from b's rest frame.
      const Vec2 u = p.b.velocity;
      const auto [ga, gb] = collide_balls(boosted(p.a, -u), boosted(p.b, -u), kBall, m.p);
      EXPECT_EQ(norm(boosted(p.b, -u).velocity), 0.0);
      expect_same_state(boosted(ga, u), a, 1e-14, "Galilean");
      expect_same_state(boosted(gb, u), b, 1e-14, "Galilean");
    }
  }
}

// The kernel depends on the mass only through the reported impulses.
TEST(BallCollision, VelocitiesDoNotDependOnTheMass) {
  std::mt19937_64 rng(8);
  BallParameters heavy = kBall;
  heavy.mass = 0.5;
  for (int i = 0; i < 200; ++i) {
    const Pair p = random_pair(rng);
    const BallCollisionResult light = resolve_ball_collision(p.a, p.b, kBall, ball_collision_alciatore());
    const BallCollisionResult h = resolve_ball_collision(p.a, p.b, heavy, ball_collision_alciatore());
    EXPECT_EQ(light.a.velocity, h.a.velocity);
    EXPECT_EQ(light.b.angular_velocity, h.b.angular_velocity);
    EXPECT_NEAR(h.normal_impulse / light.normal_impulse, 0.5 / kBall.mass, 1e-12);
  }
}

}  // namespace
}  // namespace cueball
