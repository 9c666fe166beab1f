// Tests of the Mathavan et al. (2014) ball-ball impact
// (src/models/ball_collision/mathavan_2014.cpp).
//
// The references are built here without the kernel's slip-age variable: the
// paper's own scheme (explicit Euler steps in the normal impulse, on the
// balls' velocities and spins in the table frame, with the rigid-body laws
// v += J/m, w += r x J / I at each contact), the paper's Tables 1 and 2, the
// existing resolve_ball_collision() (the same model without cloth friction),
// and conservation laws.
#include "cueball/models/ball_collision/mathavan_2014.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "cueball/models/ball_collision/coulomb_impulse.hpp"
#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/parameters.hpp"
#include "test_support.hpp"

namespace cueball {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

// The paper's ball: a snooker ball, M = 0.1406 kg, R = 26.25 mm.
const BallParameters kBall{0.1406, 0.02625};
const double kR = kBall.radius;

Vec3 lift(Vec2 v) { return {v.x, v.y, 0.0}; }
constexpr Vec3 kUp{0.0, 0.0, 1.0};

struct Pair {
  BallState a;
  BallState b;
};

// Cue ball a at the origin moving along +x at speed v, rolling (w = z^ x v / R)
// plus `extra` spin; object ball b at rest, touching, with the line of
// centres at the cut angle phi to the cue ball's path.
Pair rolling_cut(double v, double phi, Vec3 extra = {}) {
  Pair p;
  p.a = {{0.0, 0.0}, {v, 0.0}, Vec3{0.0, v / kR, 0.0} + extra};
  p.b = {{2.0 * kR * std::cos(phi), 2.0 * kR * std::sin(phi)}, {}, {}};
  return p;
}

// A random touching, approaching pair: speeds up to 4 m/s (b: 2 m/s), spins
// up to 2 v_max / R on each axis (b: half that).
Pair random_pair(std::mt19937_64& rng) {
  constexpr double v_max = 4.0;
  const double w_max = 2.0 * v_max / kR;
  Pair p{test::random_state(rng, v_max, w_max), test::random_state(rng, 0.5 * v_max, 0.5 * w_max)};
  const double theta = std::uniform_real_distribution<double>(-kPi, kPi)(rng);
  p.b.position = p.a.position + 2.0 * kR * Vec2{std::cos(theta), std::sin(theta)};
  if (!balls_approaching(p.a, p.b)) {
    p.a.velocity = -p.a.velocity;
    p.b.velocity = -p.b.velocity;
  }
  return p;
}

std::vector<Pair> random_pairs(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<Pair> out;
  while (static_cast<int>(out.size()) < count) {
    const Pair p = random_pair(rng);
    if (balls_approaching(p.a, p.b)) out.push_back(p);
  }
  return out;
}

// The ball's slip on the cloth, v + w x (-R z^).
Vec2 cloth_slip(const BallState& s) { return s.velocity - kR * horizontal(cross(s.angular_velocity, kUp)); }

// The velocity a sliding ball ends up rolling with: its slip keeps its
// direction while the cloth's friction removes it, and v changes by -2/7 of
// it (I = 2/5 m R^2); spin about the vertical plays no part.
Vec2 rolling_velocity(const BallState& s) { return s.velocity - (2.0 / 7.0) * cloth_slip(s); }

double kinetic_energy(const BallState& s) {
  const double i = 0.4 * kBall.mass * kR * kR;
  return 0.5 * kBall.mass * dot(s.velocity, s.velocity) + 0.5 * i * dot(s.angular_velocity, s.angular_velocity);
}

double state_distance(const BallCollisionResult& x, const BallCollisionResult& y) {
  return std::max({norm(x.a.velocity - y.a.velocity), norm(x.b.velocity - y.b.velocity),
                   kR * norm(x.a.angular_velocity - y.a.angular_velocity),
                   kR * norm(x.b.angular_velocity - y.b.angular_velocity)});
}

double velocity_scale(const Pair& p) {
  return std::max({norm(p.a.velocity), norm(p.b.velocity), kR * norm(p.a.angular_velocity),
                   kR * norm(p.b.angular_velocity)});
}

// ---------------------------------------------------------------- the paper's Euler scheme

// The paper's scheme, written on the balls' velocities and spins: N equal
// steps dp = (1 + e) u_n(0) / (2N) of the normal impulse (per unit mass; it
// ends when the work condition is met, after about N steps). Each step takes
// the friction directions at its start: at the ball-ball contact mu_b along
// the slip of a against b (impulse on b, the opposite on a); at the cloth,
// for the ball pushed down by the vertical part of that friction, mu_s times
// it against the ball's cloth slip. The normal work is summed by the
// trapezoid rule; compression ends at the first step with u_n <= 0, the
// impact where W = (1 - e^2) W_c (the last step cut short by linear
// interpolation of W, so that the end does not snap to the grid). Unlike the paper's
// scheme, a step whose friction would overshoot the ball-ball slip applies
// just the impulse that stops it, and the contact grips from then on (the
// paper's steps would chatter about zero slip, and each chattering step
// would press one ball or the other into the cloth: its cloth friction would
// not vanish with the step).
Pair paper_euler(const Pair& in, const Mathavan2014Contact& c, int steps) {
  Pair s = in;
  const Vec2 d = in.b.position - in.a.position;
  const Vec3 n = lift(d / norm(d));
  const Vec3 t = cross(kUp, n);
  const double k = 1.0 / (0.4 * kR * kR);  // m / I
  auto contact = [&] {
    const Vec3 on_a = lift(s.a.velocity) + cross(s.a.angular_velocity, kR * n);
    const Vec3 on_b = lift(s.b.velocity) + cross(s.b.angular_velocity, -kR * n);
    return on_a - on_b;
  };
  const double u0 = dot(contact(), n);
  const double dp = (1.0 + c.restitution) * u0 / (2.0 * steps);
  bool gripped = false;
  // One step of size h; returns u_n at its start.
  auto step = [&](double h) {
    const Vec3 cv = contact();
    const double un = dot(cv, n);
    const Vec3 slip = cv - un * n;
    Vec3 on_b = n;  // impulse on b at -R n, per unit normal impulse
    if (!gripped && norm(slip) > 0.0) {
      // The friction impulse that would stop the slip (7 across, 5 vertically, per unit mass).
      const Vec3 stop = (dot(slip, t) / 7.0) * t + (slip.z / 5.0) * kUp;
      if (c.ball_friction * h >= norm(stop)) {
        on_b = on_b + (1.0 / h) * stop;  // a grip: no friction after this step
        gripped = true;
      } else {
        on_b = on_b + (c.ball_friction / norm(slip)) * slip;
      }
    }
    const double vertical = on_b.z;
    // The cloth under the ball pushed down: normal |vertical|, friction against the cloth slip.
    Vec2 cloth_a{};
    Vec2 cloth_b{};
    if (vertical > 0.0 && norm(cloth_slip(s.a)) > 0.0) {
      cloth_a = -(c.cloth_friction * vertical / norm(cloth_slip(s.a))) * cloth_slip(s.a);
    } else if (vertical < 0.0 && norm(cloth_slip(s.b)) > 0.0) {
      cloth_b = -(c.cloth_friction * -vertical / norm(cloth_slip(s.b))) * cloth_slip(s.b);
    }
    const Vec3 down{0.0, 0.0, -kR};
    s.b.velocity = s.b.velocity + h * (horizontal(on_b) + cloth_b);
    s.a.velocity = s.a.velocity + h * (-horizontal(on_b) + cloth_a);
    s.b.angular_velocity = s.b.angular_velocity + (k * h) * (cross(-kR * n, on_b) + cross(down, lift(cloth_b)));
    s.a.angular_velocity = s.a.angular_velocity + (k * h) * (cross(kR * n, -1.0 * on_b) + cross(down, lift(cloth_a)));
    return un;
  };
  double work = 0.0;
  bool compressing = true;
  double target = 0.0;
  for (long it = 0; it < 100L * steps; ++it) {
    const Pair before = s;
    const bool gripped_before = gripped;
    const double un = step(dp);
    const double un_next = dot(contact(), n);
    const double work_next = work + 0.5 * (un + un_next) * dp;
    if (compressing && un_next <= 0.0) {
      compressing = false;
      target = (1.0 - c.restitution * c.restitution) * work_next;
    } else if (!compressing && work_next <= target) {
      // The last step only as far as the work condition, by linear interpolation.
      s = before;
      gripped = gripped_before;
      step(dp * (work - target) / (work - work_next));
      break;
    }
    work = work_next;
  }
  return s;
}

// ---------------------------------------------------------------- constants and validation

TEST(Mathavan2014, PaperConstants) {
  const Mathavan2014Contact c = mathavan_2014_contact();
  EXPECT_EQ(c.restitution, 0.89);
  EXPECT_EQ(c.ball_friction, 0.05);
  EXPECT_EQ(c.cloth_friction, 0.21);
  EXPECT_NO_THROW(validate(c));
}

TEST(Mathavan2014, ValidateNamesTheFieldTheValueAndTheRange) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    Mathavan2014Contact c;
    const char* field;
    const char* value;
    const char* range;
  };
  const std::vector<Case> cases{
      {{-0.1, 0.05, 0.21}, "restitution", "-0.1", "[0, 1]"},
      {{1.5, 0.05, 0.21}, "restitution", "1.5", "[0, 1]"},
      {{nan, 0.05, 0.21}, "restitution", "nan", "[0, 1]"},
      {{0.89, -0.01, 0.21}, "ball_friction", "-0.01", "[0, 0.5]"},
      {{0.89, 0.6, 0.21}, "ball_friction", "0.6", "[0, 0.5]"},
      {{0.89, inf, 0.21}, "ball_friction", "inf", "[0, 0.5]"},
      {{0.89, 0.05, -0.2}, "cloth_friction", "-0.2", "[0, 0.5]"},
      {{0.89, 0.05, 0.75}, "cloth_friction", "0.75", "[0, 0.5]"},
  };
  // The field named by validate()'s InvalidArgument, and its message ("" if none is thrown).
  auto rejection = [](const Mathavan2014Contact& c) -> std::pair<std::string, std::string> {
    try {
      validate(c);
    } catch (const InvalidArgument& e) {
      return {e.field(), e.what()};
    }
    return {};
  };
  for (const Case& k : cases) {
    const auto [field, message] = rejection(k.c);
    EXPECT_EQ(field, k.field) << "not rejected, or another field named: " << message;
    for (const char* part : {k.field, k.value, k.range}) {
      EXPECT_NE(message.find(part), std::string::npos) << message << " lacks " << part;
    }
  }
  EXPECT_NO_THROW(validate(Mathavan2014Contact{0.0, 0.0, 0.0}));
  EXPECT_NO_THROW(validate(Mathavan2014Contact{1.0, 0.5, 0.5}));
}

// ---------------------------------------------------------------- the paper's tables

// Mathavan, Jackson & Parkin (2014), Tables 1 and 2: cut shots of a rolling
// cue ball into an object ball at rest (e_b = 0.89, mu_b = 0.05, mu_s = 0.21;
// snooker ball). The outcome is measured once both balls have stopped
// sliding on the cloth: Table 1 the speeds, Table 2 the angles of the cue
// ball's and the object ball's paths from the cue ball's incoming path.
// (The figures as pooltool's test of its port of the model quotes them:
// ekiefl/pooltool, tests/physics/resolve/ball_ball/test_frictional_mathavan.py.)
struct TableRow {
  double speed;        // cue ball, m/s
  double topspin;      // rad/s (rolling: speed / R)
  double cut;          // deg
  double cue_speed;    // Table 1, m/s
  double object_speed; // Table 1, m/s
  double cue_angle;    // Table 2, deg
  double object_angle; // Table 2, deg
};
constexpr TableRow kPaperTables[] = {
    {1.539, 58.63, 33.83, 0.914, 0.831, 31.93, 32.20}, {1.032, 39.31, 26.36, 0.520, 0.599, 32.45, 25.07},
    {1.364, 51.96, 40.52, 0.917, 0.676, 29.91, 38.62}, {1.731, 65.94, 46.50, 1.280, 0.780, 27.32, 44.38},
    {0.942, 35.89, 18.05, 0.383, 0.579, 29.47, 17.15},
};

struct Outcome {
  double cue_speed, object_speed, cue_angle, object_angle;
};

Outcome table_outcome(const BallCollisionResult& r) {
  const Vec2 cue = rolling_velocity(r.a);
  const Vec2 object = rolling_velocity(r.b);
  return {norm(cue), norm(object), std::abs(std::atan2(cue.y, cue.x)) / kDegree,
          std::abs(std::atan2(object.y, object.x)) / kDegree};
}

Pair table_shot(const TableRow& row) {
  Pair p;
  const double phi = row.cut * kDegree;
  p.a = {{0.0, 0.0}, {row.speed, 0.0}, {0.0, row.topspin, 0.0}};
  p.b = {{2.0 * kR * std::cos(phi), 2.0 * kR * std::sin(phi)}, {}, {}};
  return p;
}

TEST(Mathavan2014, ReproducesThePapersTables1And2) {
  for (const TableRow& row : kPaperTables) {
    const Pair p = table_shot(row);
    const Outcome o = table_outcome(mathavan_2014_collision(p.a, p.b, kBall, mathavan_2014_contact()));
    SCOPED_TRACE("cut " + std::to_string(row.cut));
    EXPECT_NEAR(o.cue_speed, row.cue_speed, 0.01 * row.cue_speed);
    EXPECT_NEAR(o.object_speed, row.object_speed, 0.01 * row.object_speed);
    EXPECT_NEAR(o.cue_angle, row.cue_angle, 0.01 * row.cue_angle);
    EXPECT_NEAR(o.object_angle, row.object_angle, 0.01 * row.object_angle);
    // In fact within 0.2 % (the tables' figures are rounded).
    EXPECT_NEAR(o.cue_speed, row.cue_speed, 0.002 * row.cue_speed);
    EXPECT_NEAR(o.cue_angle, row.cue_angle, 0.002 * row.cue_angle);
    EXPECT_NEAR(o.object_angle, row.object_angle, 0.002 * row.object_angle);
  }
}

TEST(Mathavan2014, ClothFrictionIsWhatTurnsTheCueBallAQuarterDegreeMore) {
  // The 18 degree cut of Table 2: 29.47 degrees with cloth friction; the
  // same model without it (cueball's resolve_ball_collision) gives 29.12.
  const TableRow& row = kPaperTables[4];
  const Pair p = table_shot(row);
  Mathavan2014Contact no_cloth = mathavan_2014_contact();
  no_cloth.cloth_friction = 0.0;
  const Outcome with = table_outcome(mathavan_2014_collision(p.a, p.b, kBall, mathavan_2014_contact()));
  const Outcome without = table_outcome(mathavan_2014_collision(p.a, p.b, kBall, no_cloth));
  const BallCollisionParameters existing{0.89, 0.05, 0.0, 0.0};
  const Outcome old = table_outcome(resolve_ball_collision(p.a, p.b, kBall, existing));
  EXPECT_NEAR(with.cue_angle, 29.47, 0.02);
  EXPECT_NEAR(without.cue_angle, 29.12, 0.01);
  EXPECT_NEAR(old.cue_angle, without.cue_angle, 1e-9);
}

// ---------------------------------------------------------------- limits

TEST(Mathavan2014, WithoutClothFrictionItIsResolveBallCollision) {
  for (const double mu : {0.01, 0.05, 0.2, 0.5}) {
    for (const double e : {0.0, 0.5, 0.89, 1.0}) {
      const Mathavan2014Contact c{e, mu, 0.0};
      const BallCollisionParameters existing{e, mu, 0.0, 0.0};
      for (const Pair& p : random_pairs(300, 7)) {
        const BallCollisionResult x = mathavan_2014_collision(p.a, p.b, kBall, c);
        const BallCollisionResult y = resolve_ball_collision(p.a, p.b, kBall, existing);
        const double scale = velocity_scale(p);
        ASSERT_LE(state_distance(x, y), 1e-9 * scale) << "mu " << mu << " e " << e;
        EXPECT_NEAR(x.normal_impulse, y.normal_impulse, 1e-9 * kBall.mass * scale);
        EXPECT_NEAR(x.tangential_impulse, y.tangential_impulse, 1e-9 * kBall.mass * scale);
        EXPECT_NEAR(x.vertical_impulse, y.vertical_impulse, 1e-9 * kBall.mass * scale);
        EXPECT_EQ(x.gripped, y.gripped);
        EXPECT_NEAR(x.slip_speed, y.slip_speed, 1e-12 * scale);
      }
    }
  }
}

TEST(Mathavan2014, FrictionlessIsTheNormalImpulseAlone) {
  for (const double cloth : {0.0, 0.21, 0.5}) {
    const Mathavan2014Contact c{0.89, 0.0, cloth};
    for (const Pair& p : random_pairs(100, 11)) {
      const BallCollisionResult r = mathavan_2014_collision(p.a, p.b, kBall, c);
      const Vec2 d = p.b.position - p.a.position;
      const Vec2 n = d / norm(d);
      const double un = dot(p.a.velocity - p.b.velocity, n);
      const double impulse = 0.5 * (1.0 + c.restitution) * un;  // Newton = energetic here
      const Vec2 expected_b = p.b.velocity + impulse * n;
      EXPECT_LE(norm(r.b.velocity - expected_b), 1e-13 * velocity_scale(p));
      EXPECT_LE(norm(r.a.velocity - (p.a.velocity - impulse * n)), 1e-13 * velocity_scale(p));
      EXPECT_EQ(r.a.angular_velocity, p.a.angular_velocity);
      EXPECT_EQ(r.b.angular_velocity, p.b.angular_velocity);
      EXPECT_NEAR(dot(r.a.velocity - r.b.velocity, n), -c.restitution * un, 1e-13 * velocity_scale(p));
      EXPECT_EQ(r.tangential_impulse, 0.0);
      EXPECT_EQ(r.vertical_impulse, 0.0);
    }
  }
}

TEST(Mathavan2014, PairsThatAreNotApproachingAreReturnedUnchanged) {
  Pair p = rolling_cut(1.0, 20.0 * kDegree);
  p.a.velocity = -p.a.velocity;
  const BallCollisionResult r = mathavan_2014_collision(p.a, p.b, kBall, mathavan_2014_contact());
  for (const auto& [before, after] : {std::pair{p.a, r.a}, std::pair{p.b, r.b}}) {
    EXPECT_TRUE(after.velocity == before.velocity && after.angular_velocity == before.angular_velocity);
  }
  EXPECT_EQ(r.normal_impulse + r.tangential_impulse + r.vertical_impulse, 0.0);
  Pair same = p;
  same.b.position = same.a.position;  // coincident centres
  EXPECT_EQ(mathavan_2014_collision(same.a, same.b, kBall, mathavan_2014_contact()).normal_impulse, 0.0);
}

// ---------------------------------------------------------------- conservation and symmetry

TEST(Mathavan2014, HorizontalMomentumChangesOnlyByTheClothsFriction) {
  for (const double cloth : {0.0, 0.21, 0.5}) {
    const Mathavan2014Contact c{0.89, 0.2, cloth};
    double largest_ratio = 0.0;
    for (const Pair& p : random_pairs(400, 13)) {
      const BallCollisionResult r = mathavan_2014_collision(p.a, p.b, kBall, c);
      const Vec2 change = (r.a.velocity + r.b.velocity) - (p.a.velocity + p.b.velocity);
      // The cloth's friction impulse is at most mu_s times its normal
      // reaction, the vertical friction impulse |m P_z| (M3, M7).
      const double bound = cloth * std::abs(r.vertical_impulse) / kBall.mass;
      ASSERT_LE(norm(change), bound * (1.0 + 1e-9) + 1e-13 * velocity_scale(p));
      if (bound > 1e-6) largest_ratio = std::max(largest_ratio, norm(change) / bound);
      // Only one ball is pressed into the cloth; angular momentum about each
      // ball's cloth contact is not conserved, but the ball-ball impulse is
      // equal and opposite: the spins about the vertical change alike.
      EXPECT_NEAR(r.a.angular_velocity.z - p.a.angular_velocity.z, r.b.angular_velocity.z - p.b.angular_velocity.z,
                  1e-9 * velocity_scale(p) / kR);
    }
    // The bound is reached when the cloth slip keeps its direction.
    if (cloth > 0.0) {
      EXPECT_GT(largest_ratio, 0.99);
    }
  }
}

TEST(Mathavan2014, EnergyNeverIncreases) {
  for (const Mathavan2014Contact& c :
       {mathavan_2014_contact(), Mathavan2014Contact{1.0, 0.5, 0.5}, Mathavan2014Contact{1.0, 0.05, 0.21},
        Mathavan2014Contact{0.0, 0.3, 0.5}}) {
    for (const Pair& p : random_pairs(500, 17)) {
      const BallCollisionResult r = mathavan_2014_collision(p.a, p.b, kBall, c);
      const double before = kinetic_energy(p.a) + kinetic_energy(p.b);
      const double after = kinetic_energy(r.a) + kinetic_energy(r.b);
      ASSERT_LE(after, before * (1.0 + 1e-12)) << "e " << c.restitution << " mu_b " << c.ball_friction;
    }
  }
}

TEST(Mathavan2014, MirrorSymmetry) {
  // Reflection y -> -y: positions and velocities mirror, spins (axial
  // vectors) become (-w_x, w_y, -w_z).
  auto mirror = [](BallState s) {
    s.position.y = -s.position.y;
    s.velocity.y = -s.velocity.y;
    s.angular_velocity = {-s.angular_velocity.x, s.angular_velocity.y, -s.angular_velocity.z};
    return s;
  };
  for (const Pair& p : random_pairs(300, 19)) {
    const BallCollisionResult r = mathavan_2014_collision(p.a, p.b, kBall, mathavan_2014_contact());
    const BallCollisionResult m = mathavan_2014_collision(mirror(p.a), mirror(p.b), kBall, mathavan_2014_contact());
    BallCollisionResult back = m;
    back.a = mirror(m.a);
    back.b = mirror(m.b);
    EXPECT_LE(state_distance(back, r), 1e-10 * velocity_scale(p));
    EXPECT_NEAR(m.normal_impulse, r.normal_impulse, 1e-10 * kBall.mass * velocity_scale(p));
  }
  // A head-on rolling shot is its own mirror image: nothing leaves the plane.
  const Pair head_on = rolling_cut(2.0, 0.0);
  const BallCollisionResult r = mathavan_2014_collision(head_on.a, head_on.b, kBall, mathavan_2014_contact());
  EXPECT_EQ(r.a.velocity.y, 0.0);
  EXPECT_EQ(r.b.velocity.y, 0.0);
  EXPECT_EQ(r.b.angular_velocity.x, 0.0);
  EXPECT_EQ(r.b.angular_velocity.z, 0.0);
  EXPECT_LT(r.b.angular_velocity.y, 0.0);  // the object ball is dragged down in front: a little back spin...
}

TEST(Mathavan2014, ScalesWithSpeed) {
  for (const Pair& p : random_pairs(100, 23)) {
    Pair q = p;
    for (BallState* s : {&q.a, &q.b}) {
      s->velocity = 3.0 * s->velocity;
      s->angular_velocity = 3.0 * s->angular_velocity;
    }
    BallCollisionResult r = mathavan_2014_collision(p.a, p.b, kBall, mathavan_2014_contact());
    const BallCollisionResult s = mathavan_2014_collision(q.a, q.b, kBall, mathavan_2014_contact());
    for (BallState* x : {&r.a, &r.b}) {
      x->velocity = 3.0 * x->velocity;
      x->angular_velocity = 3.0 * x->angular_velocity;
    }
    EXPECT_LE(state_distance(r, s), 1e-9 * velocity_scale(q));
  }
}

// ---------------------------------------------------------------- grip and the cloth slip at zero

TEST(Mathavan2014, AGripLeavesNoSlipAtTheBallBallContact) {
  const Mathavan2014Contact c{0.89, 0.5, 0.5};
  int gripped = 0;
  for (const double cut : {0.0, 5.0, 15.0, 30.0}) {
    const Pair p = rolling_cut(1.5, cut * kDegree);
    const BallCollisionResult r = mathavan_2014_collision(p.a, p.b, kBall, c);
    if (!r.gripped) continue;
    ++gripped;
    const Vec2 n = p.b.position / norm(p.b.position);
    const Vec3 on_a = lift(r.a.velocity) + cross(r.a.angular_velocity, kR * lift(n));
    const Vec3 on_b = lift(r.b.velocity) + cross(r.b.angular_velocity, -kR * lift(n));
    const Vec3 slip = (on_a - on_b) - dot(on_a - on_b, lift(n)) * lift(n);
    EXPECT_LE(norm(slip), 1e-9 * 1.5) << "cut " << cut;
  }
  EXPECT_GE(gripped, 2);
}

TEST(Mathavan2014, HeadOnDrawWhoseClothSlipPassesThroughZero) {
  // Head on, both balls moving, e = 1, the cue ball with draw: it is pressed
  // into the cloth (its front surface moves up against b's), and its cloth
  // slip, along n, runs through zero during the impact and reverses.
  const Mathavan2014Contact c{1.0, 0.05, 0.21};
  Pair p;
  p.a = {{0.0, 0.0}, {1.0, 0.0}, {0.0, -0.8 / kR, 0.0}};
  p.b = {{2.0 * kR, 0.0}, {-1.0, 0.0}, {}};
  const BallCollisionResult r = mathavan_2014_collision(p.a, p.b, kBall, c);
  const Pair euler = paper_euler(p, c, 200000);
  EXPECT_LT(cloth_slip(r.a).x, 0.0);  // reversed
  EXPECT_LE(norm(r.a.velocity - euler.a.velocity), 2e-5 * 2.0);
  EXPECT_LE(kR * norm(r.a.angular_velocity - euler.a.angular_velocity), 2e-5 * 2.0);
  EXPECT_LE(norm(r.b.velocity - euler.b.velocity), 2e-5 * 2.0);
}

// ---------------------------------------------------------------- the paper's Euler scheme converges to it

TEST(Mathavan2014, ThePapersEulerSchemeConvergesToTheExactSolution) {
  std::vector<Pair> shots;
  for (const TableRow& row : kPaperTables) shots.push_back(table_shot(row));
  for (const Pair& p : random_pairs(4, 29)) shots.push_back(p);
  shots.push_back(rolling_cut(1.0, 0.0, {0.0, -3.0 / kR, 20.0}));  // head-on, heavy draw, side
  const Mathavan2014Contact c = mathavan_2014_contact();
  for (std::size_t i = 0; i < shots.size(); ++i) {
    const Pair& p = shots[i];
    const BallCollisionResult exact = mathavan_2014_collision(p.a, p.b, kBall, c);
    double previous = std::numeric_limits<double>::infinity();
    for (const int steps : {1000, 10000, 100000}) {
      const Pair e = paper_euler(p, c, steps);
      BallCollisionResult as_result = exact;
      as_result.a = e.a;
      as_result.b = e.b;
      const double error = state_distance(as_result, exact) / velocity_scale(p);
      // First order: ten times the steps, about a tenth of the error.
      EXPECT_LT(error, std::max(0.3 * previous, 1e-7)) << "shot " << i << ", " << steps << " steps";
      EXPECT_LT(error, 20.0 / steps) << "shot " << i << ", " << steps << " steps";
      previous = error;
    }
  }
}

}  // namespace
}  // namespace cueball
