// Placement (src/table/placement.cpp): room, free spots, regions, random
// free spots and spotting on the long string, each against geometry worked
// out by hand.
#include "cueball/table/placement.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cueball/table/rack.hpp"

namespace cueball {
namespace {

const Table kPool = preset_table("pool_9ft");
const double R = kPool.ball.radius;

TEST(Placement, StringsAndSpots) {
  EXPECT_DOUBLE_EQ(head_string_x(kPool), kPool.length / 4.0);
  EXPECT_DOUBLE_EQ(long_string_y(kPool), kPool.width / 2.0);
  EXPECT_DOUBLE_EQ(foot_spot(kPool).x, 0.75 * kPool.length);
  EXPECT_DOUBLE_EQ(foot_spot(kPool).y, long_string_y(kPool));
}

TEST(Placement, ClearanceIsTheRoomBeyondTheNearestCushion) {
  const double d = cushion_contact_distance(kPool.cushions[0].contact_height, R);
  // Halfway along a long rail's first segment, far from the pockets: the rail is nearest.
  const Vec2 p{0.3 * kPool.length, d + 0.01};
  EXPECT_NEAR(clearance(kPool, p, R), 0.01, 1e-12);
  EXPECT_NEAR(clearance(kPool, {p.x, d}, R), 0.0, 1e-12);
  EXPECT_LT(clearance(kPool, {p.x, d - 1e-3}, R), 0.0);
  // Over a pocket's capture circle: negative.
  EXPECT_LT(clearance(kPool, kPool.pockets[0].centre, R), 0.0);
}

TEST(Placement, FreeSpotsAllowTouchingNotOverlapping) {
  const Vec2 a{1.0, 0.6};
  EXPECT_TRUE(is_free_spot(kPool, {a}, {a.x + 2.0 * R, a.y}, R));
  EXPECT_FALSE(is_free_spot(kPool, {a}, {a.x + 2.0 * R - 1e-6, a.y}, R));
  EXPECT_NEAR(ball_gap({a.x + 2.0 * R + 0.01, a.y}, {a}, R), 0.01, 1e-15);
  EXPECT_TRUE(std::isinf(ball_gap(a, {}, R)));
  EXPECT_FALSE(is_free_spot(kPool, {}, {-0.1, 0.6}, R));
  EXPECT_FALSE(is_free_spot(kPool, {}, {1.0, 0.6}, R, /*margin=*/1.0));  // no point has a metre of room
}

TEST(Placement, RegionsFollowTheirLines) {
  const PlacementRegion kitchen{PlacementRegion::Kind::behind_head_string};
  EXPECT_TRUE(in_region(kPool, kitchen, {head_string_x(kPool), 0.5}));
  EXPECT_FALSE(in_region(kPool, kitchen, {head_string_x(kPool) + 1e-6, 0.5}));
  EXPECT_TRUE(in_region(kPool, {}, {2.0, 1.0}));
  const PlacementRegion box{PlacementRegion::Kind::rectangle, 1.0, 1.2, 0.3, 0.4};
  EXPECT_TRUE(in_region(kPool, box, {1.1, 0.35}));
  EXPECT_FALSE(in_region(kPool, box, {1.1, 0.45}));

  const Table snooker = preset_table("snooker_12ft");
  const SnookerSpots s = snooker_spots(snooker);
  const PlacementRegion d{PlacementRegion::Kind::inside_d};
  EXPECT_TRUE(in_region(snooker, d, s.brown));
  EXPECT_TRUE(in_region(snooker, d, s.yellow));  // the D's corners are on its line
  EXPECT_TRUE(in_region(snooker, d, {s.baulk_line_x - s.d_radius, s.brown.y}));
  EXPECT_FALSE(in_region(snooker, d, {s.baulk_line_x + 1e-6, s.brown.y}));  // beyond the baulk line
  EXPECT_FALSE(in_region(snooker, d, {s.baulk_line_x - 0.8 * s.d_radius, s.brown.y + 0.8 * s.d_radius}));
  const PlacementRegion b = bounding_rectangle(snooker, d);
  EXPECT_DOUBLE_EQ(b.x_max, s.baulk_line_x);
  EXPECT_DOUBLE_EQ(b.y_max - b.y_min, 2.0 * s.d_radius);
}

TEST(Placement, RegionNames) {
  EXPECT_EQ(placement_region_from_string("kitchen"), PlacementRegion::Kind::behind_head_string);
  EXPECT_EQ(placement_region_from_string("behind_head_string"), PlacementRegion::Kind::behind_head_string);
  EXPECT_EQ(placement_region_from_string("d"), PlacementRegion::Kind::inside_d);
  EXPECT_EQ(placement_region_from_string("anywhere"), PlacementRegion::Kind::anywhere);
  EXPECT_FALSE(placement_region_from_string("nowhere"));
  for (const auto k : {PlacementRegion::Kind::anywhere, PlacementRegion::Kind::behind_head_string,
                       PlacementRegion::Kind::inside_d, PlacementRegion::Kind::rectangle})
    EXPECT_EQ(placement_region_from_string(to_string(k)), k);
}

TEST(Placement, RandomFreeSpotsAreFreeInTheRegionAndSeeded) {
  const Table snooker = preset_table("snooker_12ft");
  const double r = snooker.ball.radius;
  const SnookerSpots s = snooker_spots(snooker);
  const PlacementRegion d{PlacementRegion::Kind::inside_d};
  const std::vector<Vec2> balls{s.brown, s.green, s.yellow};
  RandomStream rng(splitmix64(7));
  for (int k = 0; k < 500; ++k) {
    const std::optional<Vec2> p = random_free_spot(snooker, balls, r, rng, 1000, d);
    ASSERT_TRUE(p);
    EXPECT_TRUE(in_region(snooker, d, *p));
    EXPECT_TRUE(is_free_spot(snooker, balls, *p, r));
  }
  RandomStream a(splitmix64(3)), b(splitmix64(3));
  const std::optional<Vec2> pa = random_free_spot(kPool, {}, R, a, 10), pb = random_free_spot(kPool, {}, R, b, 10);
  ASSERT_TRUE(pa && pb);
  EXPECT_EQ(pa->x, pb->x);
  EXPECT_EQ(pa->y, pb->y);
  // A rectangle covered by one ball has no free spot.
  const PlacementRegion tiny{PlacementRegion::Kind::rectangle, 1.0, 1.001, 0.6, 0.601};
  EXPECT_FALSE(random_free_spot(kPool, {{1.0005, 0.6005}}, R, a, 100, tiny));
}

TEST(Placement, SpottingOnAnEmptyLongStringUsesTheFootSpot) {
  const std::optional<Vec2> p = spot_on_long_string(kPool, {}, std::nullopt, R);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->x, foot_spot(kPool).x);
  EXPECT_EQ(p->y, foot_spot(kPool).y);
}

TEST(Placement, SpottingFreezesBehindABallOnTheFootSpotButNotToTheCueBall) {
  const Vec2 f = foot_spot(kPool);
  std::optional<Vec2> p = spot_on_long_string(kPool, {f}, std::nullopt, R);
  ASSERT_TRUE(p);
  EXPECT_GT(p->x, f.x);  // behind: towards the foot rail
  EXPECT_NEAR(norm(*p - f), 2.0 * R, 1e-12);
  // The cue ball on the foot spot: a visible gap.
  p = spot_on_long_string(kPool, {}, f, R);
  ASSERT_TRUE(p);
  EXPECT_NEAR(norm(*p - f), 2.0 * R + kSpottingGapToCue, 1e-12);
  // A ball just off the line, behind the spot: frozen to it on the line.
  const Vec2 off{f.x + R, f.y + R};
  p = spot_on_long_string(kPool, {off}, std::nullopt, R);
  ASSERT_TRUE(p);
  EXPECT_NEAR(norm(*p - off), 2.0 * R, 1e-12);
  EXPECT_EQ(p->y, f.y);
}

TEST(Placement, SpottingGoesInFrontWhenTheLineBehindIsFull) {
  const Vec2 f = foot_spot(kPool);
  std::vector<Vec2> line;
  for (double x = f.x; x < kPool.length; x += 2.0 * R) line.push_back({x, f.y});
  const std::optional<Vec2> p = spot_on_long_string(kPool, line, std::nullopt, R);
  ASSERT_TRUE(p);
  EXPECT_LT(p->x, f.x);
  EXPECT_NEAR(f.x - p->x, 2.0 * R, 1e-12);
  EXPECT_TRUE(is_free_spot(kPool, line, *p + Vec2{-1e-12, 0.0}, R));
}

}  // namespace
}  // namespace cueball
