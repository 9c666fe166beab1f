// Line of sight (src/table/line_of_sight.cpp): the grazing strokes and the
// full-ball view from the cue ball, past the other balls.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cueball/core/random.hpp"
#include "cueball/table/line_of_sight.hpp"

namespace cueball {
namespace {

constexpr double R = 0.02625;  // a snooker ball
const Vec2 kCue{0.0, 0.0};
const Vec2 kTarget{1.0, 0.0};

TEST(LineOfSight, NothingInTheWaySeesTheWholeBall) {
  const BallView v = view_of_ball(kCue, kTarget, {}, R);
  EXPECT_TRUE(v.left_edge);
  EXPECT_TRUE(v.right_edge);
  EXPECT_TRUE(v.full);
  EXPECT_TRUE(v.both_edges());
}

TEST(LineOfSight, ABallOnTheLineHidesBothEdges) {
  const BallView v = view_of_ball(kCue, kTarget, {{0.5, 0.0}}, R);
  EXPECT_FALSE(v.left_edge);
  EXPECT_FALSE(v.right_edge);
  EXPECT_FALSE(v.full);
  EXPECT_FALSE(v.any());
}

TEST(LineOfSight, ABallToOneSideHidesThatEdgeOnly) {
  // Half-way, 6 cm to the left (+y seen along +x): the left grazing stroke
  // passes 3.4 cm from its centre (< 2R), the right one 8.6 cm.
  const BallView left = view_of_ball(kCue, kTarget, {{0.5, 0.06}}, R);
  EXPECT_FALSE(left.left_edge);
  EXPECT_TRUE(left.right_edge);
  EXPECT_FALSE(left.full);
  const BallView right = view_of_ball(kCue, kTarget, {{0.5, -0.06}}, R);
  EXPECT_TRUE(right.left_edge);
  EXPECT_FALSE(right.right_edge);
  // Farther out it hides nothing.
  EXPECT_TRUE(view_of_ball(kCue, kTarget, {{0.5, 0.2}}, R).full);
}

TEST(LineOfSight, BallsBehindTheTargetDoNotObstruct) {
  EXPECT_TRUE(view_of_ball(kCue, kTarget, {{1.5, 0.0}}, R).full);
  EXPECT_TRUE(view_of_ball(kCue, kTarget, {{1.0 + 2.0 * R, 0.0}}, R).full);  // frozen to its far side
  EXPECT_TRUE(view_of_ball(kCue, kTarget, {{-0.3, 0.0}}, R).full);          // behind the cue ball
  // Frozen to its near side, it is in the way of every stroke.
  EXPECT_FALSE(view_of_ball(kCue, kTarget, {{1.0 - 2.0 * R, 0.0}}, R).any());
}

TEST(LineOfSight, JustClearOfTheGrazingStrokeDoesNotObstruct) {
  // The left grazing stroke's line is at angle asin(2R/d) from the centre
  // line; a ball whose centre is exactly 2R (+ 1 um) from it leaves it clear,
  // 1 um closer hides it.
  const double alpha = std::asin(2.0 * R / 1.0);
  const Vec2 dir{std::cos(alpha), std::sin(alpha)};
  const Vec2 normal{-dir.y, dir.x};
  const Vec2 on_path = 0.5 * dir;
  EXPECT_TRUE(view_of_ball(kCue, kTarget, {on_path + (2.0 * R + 1e-6) * normal}, R).left_edge);
  EXPECT_FALSE(view_of_ball(kCue, kTarget, {on_path + (2.0 * R - 1e-6) * normal}, R).left_edge);
}

TEST(LineOfSight, TouchingTheCueBallIsInFullView) {
  const BallView v = view_of_ball(kCue, {2.0 * R, 0.0}, {{R, 2.0 * R}}, R);
  EXPECT_TRUE(v.full);
}

TEST(LineOfSight, FullViewImpliesBothEdgesAndMirrorsSwapThem) {
  // Random layouts: a full view always has both edges; mirroring the table
  // about the centre line swaps left and right.
  RandomStream rng(7);
  int blocked = 0;
  for (int i = 0; i < 2000; ++i) {
    std::vector<Vec2> obstacles, mirrored;
    for (int k = 0; k < 3; ++k) {
      const Vec2 p{rng.uniform(-0.2, 1.3), rng.uniform(-0.3, 0.3)};
      if (norm(p - kCue) < 2.0 * R || norm(p - kTarget) < 2.0 * R) continue;
      obstacles.push_back(p);
      mirrored.push_back({p.x, -p.y});
    }
    const BallView v = view_of_ball(kCue, kTarget, obstacles, R);
    const BallView m = view_of_ball(kCue, kTarget, mirrored, R);
    if (v.full) {
      EXPECT_TRUE(v.both_edges());
    }
    EXPECT_EQ(v.left_edge, m.right_edge);
    EXPECT_EQ(v.right_edge, m.left_edge);
    EXPECT_EQ(v.full, m.full);
    blocked += v.full ? 0 : 1;
  }
  EXPECT_GT(blocked, 100);
}

}  // namespace
}  // namespace cueball
