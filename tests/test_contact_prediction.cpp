// Tests of collision-time prediction (src/physics/contact_prediction.cpp): predicted contacts are
// real contacts, none is missed or early (checked by dense sampling of the
// closed-form trajectories), separating pairs never collide, and the
// degenerate and grazing cases of equipment-and-pitfalls.md items 2-4.
#include "cueball/physics/contact_prediction.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "test_support.hpp"

namespace cueball {
namespace {

double horizon_of(const BallState& a, const BallState& b, const Parameters& p) {
  return std::min(next_transition(a, p).time, next_transition(b, p).time);
}

double gap(const BallState& a, const BallState& b, double t, const Parameters& p) {
  return norm(evolve(b, t, p).position - evolve(a, t, p).position) - 2 * p.ball.radius;
}

// A random pair near each other, both moving in any phase.
std::pair<BallState, BallState> random_pair(std::mt19937_64& rng, const Parameters& p) {
  BallState a = test::random_state(rng, 2.0, 80.0);
  BallState b = test::random_state(rng, 2.0, 80.0);
  std::uniform_real_distribution<double> offset(-0.3, 0.3);
  a.position = {0, 0};
  do {
    b.position = {offset(rng), offset(rng)};
  } while (norm(b.position) < 2.0 * p.ball.radius + 1e-6);
  return {a, b};
}

TEST(Events, BallBallPredictionsAreNeitherEarlyNorMissed) {
  std::mt19937_64 rng(2024);
  const Parameters p = pool_parameters();
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    auto [a, b] = random_pair(rng, p);
    const double horizon = horizon_of(a, b, p);
    const auto t = predict_ball_ball_contact(a, b, p, horizon);
    const double end = t ? *t : std::min(horizon, 5.0);
    // Dense sampling up to the predicted contact (or the horizon): no overlap.
    for (int i = 0; i < 400; ++i) {
      const double ti = end * i / 400.0;
      ASSERT_GT(gap(a, b, ti, p), -1e-9) << "trial " << trial << " overlap at t = " << ti
                                         << (t ? " before the predicted contact" : " but no contact predicted");
    }
    if (t) {
      ++hits;
      EXPECT_NEAR(gap(a, b, *t, p), 0.0, 1e-9) << "trial " << trial;
      // Approaching at the contact.
      const BallState sa = evolve(a, *t, p), sb = evolve(b, *t, p);
      EXPECT_LT(dot(sb.position - sa.position, sb.velocity - sa.velocity), 0.0);
    } else {
      ++misses;
    }
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(misses, 100);
}

TEST(Events, TouchingPairsCollideOnlyWhenApproaching) {
  const Parameters p = snooker_parameters();
  const double r = p.ball.radius;
  const BallState a{{0, 0}, {1, 0}, {0, 1 / r, 0}};
  const BallState b_ahead{{2 * r, 0}, {0, 0}, {}};
  const BallState b_behind{{-2 * r, 0}, {0, 0}, {}};
  const auto now = predict_ball_ball_contact(a, b_ahead, p, horizon_of(a, b_ahead, p));
  ASSERT_TRUE(now);
  EXPECT_EQ(*now, 0.0);
  EXPECT_FALSE(predict_ball_ball_contact(a, b_behind, p, horizon_of(a, b_behind, p)));
  // Overlapping by round-off and separating: no collision either.
  const BallState b_overlap{{-2 * r + 1e-15, 0}, {0, 0}, {}};
  EXPECT_FALSE(predict_ball_ball_contact(a, b_overlap, p, horizon_of(a, b_overlap, p)));
  // A frozen pair at rest never collides.
  EXPECT_FALSE(predict_ball_ball_contact(BallState{{0, 0}, {}, {}}, b_ahead, p, std::numeric_limits<double>::infinity()));
}

TEST(Events, EqualAccelerationsDegenerateToLowerDegree) {
  const Parameters p = pool_parameters();
  const double r = p.ball.radius;
  // Both rolling along +x: identical accelerations, the quartic's t^4 and t^3
  // terms are exactly zero. The faster one behind catches up.
  const BallState behind{{0, 0}, {2.0, 0}, {0, 2.0 / r, 0}};
  const BallState ahead{{0.5, 0}, {1.0, 0}, {0, 1.0 / r, 0}};
  const auto t = predict_ball_ball_contact(behind, ahead, p, horizon_of(behind, ahead, p));
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, (0.5 - 2 * r) / 1.0, 1e-12);  // relative speed 1 m/s, constant
  // Same speed: no relative motion at all.
  const BallState twin{{0.5, 0}, {2.0, 0}, {0, 2.0 / r, 0}};
  EXPECT_FALSE(predict_ball_ball_contact(behind, twin, p, horizon_of(behind, twin, p)));
}

TEST(Events, GrazingContactIsDecidedByTheGeometry) {
  const Parameters p = pool_parameters();
  const double r = p.ball.radius;
  // A ball sliding without spin along x past a resting ball whose centre is
  // 2R + offset off the line. Sliding straight: the path is a line.
  for (double offset : {-1e-7, -1e-9, 1e-9, 1e-7}) {
    const BallState mover{{-0.5, 0}, {1.5, 0}, {0, 1.5 / r, 0}};
    const BallState target{{0.0, 2 * r + offset}, {}, {}};
    const auto t = predict_ball_ball_contact(mover, target, p, horizon_of(mover, target, p));
    if (offset < 0) {
      ASSERT_TRUE(t) << "a thin cut must not be missed, offset " << offset;
      EXPECT_NEAR(gap(mover, target, *t, p), 0.0, 1e-12);
    } else {
      EXPECT_FALSE(t) << "a clean miss must not collide, offset " << offset;
    }
  }
}

TEST(Events, LineContactMatchesTheClosedForm) {
  const Parameters p = snooker_parameters();
  const double r = p.ball.radius;
  // Cushion along y = 1 from x = 2 to x = 0 (playing surface below it, on the left of start->end).
  const Vec2 start{2.0, 1.0}, end{0.0, 1.0};
  const double d = 0.9 * r;
  const BallState rolling{{1.0, 0.5}, {0.0, 1.2}, {-1.2 / r, 0, 0}};
  const auto t = predict_ball_line_contact(rolling, p, start, end, d, next_transition(rolling, p).time);
  ASSERT_TRUE(t);
  // 1.0 - d - 0.5 = 1.2 t - a t^2 / 2 with a = (5/7) mu_r g.
  const double a = rolling_deceleration(p);
  const double distance = 0.5 - d;
  const double expected = (1.2 - std::sqrt(1.2 * 1.2 - 2 * a * distance)) / a;
  EXPECT_NEAR(*t, expected, 1e-12);
  EXPECT_NEAR(evolve(rolling, *t, p).position.y, 1.0 - d, 1e-12);
  // Moving away, parallel, or passing beyond the segment's end: no contact.
  const BallState away{{1.0, 0.5}, {0.0, -1.2}, {1.2 / r, 0, 0}};
  EXPECT_FALSE(predict_ball_line_contact(away, p, start, end, d, next_transition(away, p).time));
  const BallState parallel{{1.0, 0.5}, {1.2, 0.0}, {0, 1.2 / r, 0}};
  EXPECT_FALSE(predict_ball_line_contact(parallel, p, start, end, d, next_transition(parallel, p).time));
  const BallState beyond{{2.5, 0.5}, {0.0, 1.2}, {-1.2 / r, 0, 0}};
  EXPECT_FALSE(predict_ball_line_contact(beyond, p, start, end, d, next_transition(beyond, p).time));
  // Touching and leaving: no contact; touching and arriving: contact now.
  const BallState leaving{{1.0, 1.0 - d}, {0.0, -1.0}, {1.0 / r, 0, 0}};
  EXPECT_FALSE(predict_ball_line_contact(leaving, p, start, end, d, next_transition(leaving, p).time));
  const BallState arriving{{1.0, 1.0 - d + 1e-16}, {0.0, 1.0}, {-1.0 / r, 0, 0}};
  const auto now = predict_ball_line_contact(arriving, p, start, end, d, next_transition(arriving, p).time);
  ASSERT_TRUE(now);
  EXPECT_EQ(*now, 0.0);
}

TEST(Events, SlidingBallCurvesIntoACushion) {
  // A parabola: the ball starts parallel to the cushion, slip pushes it in.
  const Parameters p = pool_parameters();
  const double r = p.ball.radius;
  const Vec2 start{3.0, 1.0}, end{-1.0, 1.0};
  const BallState curving{{0.0, 0.95}, {1.0, 0.0}, {-40.0, 1.0 / r, 0}};
  ASSERT_EQ(motion_phase(curving, p), MotionPhase::sliding);
  const double horizon = next_transition(curving, p).time;
  const auto t = predict_ball_line_contact(curving, p, start, end, r, horizon);
  ASSERT_TRUE(t);
  EXPECT_NEAR(evolve(curving, *t, p).position.y, 1.0 - r, 1e-12);
  for (int i = 0; i < 100; ++i) EXPECT_LT(evolve(curving, *t * i / 100.0, p).position.y, 1.0 - r + 1e-12);
}

TEST(Events, CircleContactIsTheFirstEntry) {
  std::mt19937_64 rng(77);
  const Parameters p = pool_parameters();
  int hits = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const BallState s = test::random_state(rng, 2.0, 100.0);
    std::uniform_real_distribution<double> where(-0.25, 0.25);
    const Vec2 centre{where(rng), where(rng)};
    const double radius = 0.06;
    if (norm(s.position - centre) <= radius) continue;
    const double horizon = next_transition(s, p).time;
    const auto t = predict_ball_circle_contact(s, p, centre, radius, horizon);
    const double end = t ? *t : std::min(horizon, 5.0);
    for (int i = 0; i < 300; ++i) {
      ASSERT_GT(norm(evolve(s, end * i / 300.0, p).position - centre), radius - 1e-9) << trial;
    }
    if (t) {
      ++hits;
      EXPECT_NEAR(norm(evolve(s, *t, p).position - centre), radius, 1e-9);
    }
  }
  EXPECT_GT(hits, 30);
}

// Issue 11: a pair touching with no normal speed that its acceleration drives
// together is a contact now; the root rule alone missed it for the whole
// segment (a double root at 0, never crossed decreasing).
TEST(Events, PressedContactsAreContactsNow) {
  const Parameters p = pool_parameters();
  const double r = p.ball.radius;
  const Vec2 start{3.0, 1.0}, end{-1.0, 1.0};  // inward normal -y: the table is below y = 1
  const double d = r;
  // Sliding along the cushion, slip pulling it in (a swerve along a frozen rail).
  const BallState swerve{{0.0, 1.0 - d}, {1.0, 0.0}, {-30.0, 1.0 / r, 0}};
  const double h = next_transition(swerve, p).time;
  const auto now = predict_ball_line_contact(swerve, p, start, end, d, h);
  ASSERT_TRUE(now);
  EXPECT_EQ(*now, 0.0);
  // The same just beyond the tolerance is found by its root, at
  // sqrt(2 gap / a): not now, not missed.
  BallState near = swerve;
  near.position.y -= 4e-9;
  const auto soon = predict_ball_line_contact(near, p, start, end, d, h);
  ASSERT_TRUE(soon);
  const double a_n = -phase_acceleration(near, p).y;
  EXPECT_NEAR(*soon, std::sqrt(2 * 4e-9 / -a_n), 1e-9);
  // Slip pulling it off the cushion: no contact.
  BallState off = swerve;
  off.angular_velocity.x = 30.0;
  EXPECT_FALSE(predict_ball_line_contact(off, p, start, end, d, h));
  // Rolling along the cushion: nothing presses.
  const BallState rolling{{0.0, 1.0 - d}, {1.0, 0.0}, {0, 1.0 / r, 0}};
  EXPECT_FALSE(predict_ball_line_contact(rolling, p, start, end, d, next_transition(rolling, p).time));

  // Two balls: a spinning ball against a resting one, touching, overlapping
  // by round-off and parting at 1e-9 m/s (its spin turns it back at once).
  const BallState resting{{0.0, 0.0}, {0, 0}, {0, 0, 0}};
  const BallState spun{{2 * r - 1e-15, 0.0}, {1e-9, 0}, {0, -30, 0}};
  const double hs = next_transition(spun, p).time;
  const auto pressed = predict_ball_ball_contact(resting, spun, p, hs);
  ASSERT_TRUE(pressed);
  EXPECT_EQ(*pressed, 0.0);
  // Parting at 1 mm/s it clears the contact first: the return is a later root.
  BallState parting = spun;
  parting.velocity.x = 1e-3;
  const auto later = predict_ball_ball_contact(resting, parting, p, next_transition(parting, p).time);
  ASSERT_TRUE(later);
  EXPECT_GT(*later, 1e-4);
  // A ball rolling past along the tangent of a touching one parts by the
  // curvature of the contact circle: no contact.
  const BallState passing{{0.0, 2 * r}, {1.0, 0}, {0, 1.0 / r, 0}};
  EXPECT_FALSE(predict_ball_ball_contact(resting, passing, p, next_transition(passing, p).time));
}

}  // namespace
}  // namespace cueball
