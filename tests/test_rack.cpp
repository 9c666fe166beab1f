// Tests of the racks (src/table/rack.cpp). Spot positions are recomputed here from
// the WPA and WPBSA numbers.
#include "cueball/table/rack.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "cueball/core/errors.hpp"
#include "cueball/table/table.hpp"

namespace cueball {
namespace {

constexpr double kTol = 1e-12;

using RackFn = std::vector<PlacedBall> (*)(const Table&, const RackOptions&);

struct Case {
  const char* name;
  RackFn rack;
  Table table;
  std::size_t balls;
  std::size_t touching_pairs;  // in the frozen rack
};

std::vector<Case> cases() {
  // Touching pairs on a triangular lattice: a 5-row triangle has 3 * (4 * 5 / 2)
  // = 30 edges; the 3 x 3 diamond (rhombus) has 2 * 3 * 2 + 2 * 2 = 16.
  return {{"nine", &rack_nine_ball, pool_table_9ft(), 10, 16},
          {"eight", &rack_eight_ball, pool_table_9ft(), 16, 30},
          {"snooker", &rack_snooker, snooker_table_12ft(), 22, 30}};
}

const PlacedBall& by_name(const std::vector<PlacedBall>& balls, const std::string& name) {
  const auto it = std::find_if(balls.begin(), balls.end(), [&](const PlacedBall& b) { return b.name == name; });
  EXPECT_NE(it, balls.end()) << name;
  return *it;
}

double min_pair_distance(const std::vector<PlacedBall>& balls) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::size_t k = i + 1; k < balls.size(); ++k) d = std::min(d, norm(balls[i].position - balls[k].position));
  }
  return d;
}

std::size_t count_pairs_at(const std::vector<PlacedBall>& balls, double distance, double tol) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::size_t k = i + 1; k < balls.size(); ++k) {
      if (std::abs(norm(balls[i].position - balls[k].position) - distance) <= tol) ++n;
    }
  }
  return n;
}

TEST(Rack, CountsIdsAndNames) {
  for (const Case& c : cases()) {
    const std::vector<PlacedBall> balls = c.rack(c.table, {});
    ASSERT_EQ(balls.size(), c.balls) << c.name;
    std::set<int> ids;
    std::set<std::string> names;
    for (const PlacedBall& b : balls) {
      ids.insert(b.id);
      names.insert(b.name);
    }
    EXPECT_EQ(ids.size(), c.balls) << c.name << ": ids must be unique";
    EXPECT_EQ(names.size(), c.balls) << c.name << ": names must be unique";
    EXPECT_EQ(*ids.begin(), 0) << c.name;
    EXPECT_EQ(*ids.rbegin(), static_cast<int>(c.balls) - 1) << c.name << ": ids are 0..n-1";
    EXPECT_EQ(by_name(balls, "cue").id, 0) << c.name;
  }
}

TEST(Rack, FrozenRacksTouchExactlyAndNeverOverlap) {
  for (const Case& c : cases()) {
    const std::vector<PlacedBall> balls = c.rack(c.table, {});
    const double two_r = 2.0 * c.table.ball.radius;
    EXPECT_GE(min_pair_distance(balls), two_r - kTol) << c.name;
    EXPECT_EQ(count_pairs_at(balls, two_r, kTol), c.touching_pairs) << c.name;
    // Every rack ball touches at least two others (the triangle is rigid).
    for (const PlacedBall& b : balls) {
      if (b.id == 0 || (c.balls == 22 && b.id > 15)) continue;  // cue, snooker colours
      int touching = 0;
      for (const PlacedBall& o : balls) {
        if (&o != &b && std::abs(norm(o.position - b.position) - two_r) <= kTol) ++touching;
      }
      EXPECT_GE(touching, 2) << c.name << " ball " << b.name;
    }
  }
}

TEST(Rack, EveryBallCanBePlaced) {
  for (const Case& c : cases()) {
    for (const PlacedBall& b : c.rack(c.table, {})) {
      EXPECT_TRUE(ball_on_table(c.table, b.position)) << c.name << " " << b.name;
    }
    for (const PlacedBall& b : c.rack(c.table, {0.001, 7})) {
      EXPECT_TRUE(ball_on_table(c.table, b.position)) << c.name << " " << b.name;
    }
  }
}

TEST(Rack, NineBallDiamond) {
  const Table t = pool_table_9ft();
  const std::vector<PlacedBall> balls = rack_nine_ball(t, {});
  const double R = t.ball.radius;
  const Vec2 foot{0.75 * 2.54, 0.5 * 1.27};  // WPA: foot spot on the long string, 2 diamonds from the foot rail
  EXPECT_NEAR(norm(by_name(balls, "1").position - foot), 0.0, kTol);
  // The 9 in the centre: two rows behind the apex, on the long string.
  EXPECT_NEAR(norm(by_name(balls, "9").position - (foot + Vec2{2.0 * std::sqrt(3.0) * R, 0.0})), 0.0, kTol);
  // ...which is the centroid of the diamond.
  Vec2 sum;
  for (const PlacedBall& b : balls) {
    if (b.id != 0) sum = sum + b.position;
  }
  EXPECT_NEAR(norm(sum / 9.0 - by_name(balls, "9").position), 0.0, 1e-12);
  // The apex is nearest the cue ball; the cue ball is behind the head string.
  for (const PlacedBall& b : balls) {
    if (b.id > 1) {
      EXPECT_GT(b.position.x, foot.x) << b.name;
    }
  }
  const Vec2 cue = by_name(balls, "cue").position;
  EXPECT_LT(cue.x, 0.25 * 2.54);
  EXPECT_NEAR(cue.y, 0.5 * 1.27, kTol);
}

TEST(Rack, EightBallTriangle) {
  const Table t = pool_table_9ft();
  const std::vector<PlacedBall> balls = rack_eight_ball(t, {});
  const double R = t.ball.radius;
  const Vec2 foot = foot_spot(t);
  EXPECT_NEAR(foot.x, 0.75 * 2.54, kTol);
  EXPECT_NEAR(norm(by_name(balls, "1").position - foot), 0.0, kTol);
  EXPECT_NEAR(norm(by_name(balls, "8").position - (foot + Vec2{2.0 * std::sqrt(3.0) * R, 0.0})), 0.0, kTol);
  // Back row: five balls 4 sqrt(3) R behind the apex; its corners one solid and one stripe.
  std::vector<int> back;
  for (const PlacedBall& b : balls) {
    if (std::abs(b.position.x - (foot.x + 4.0 * std::sqrt(3.0) * R)) < kTol) back.push_back(b.id);
  }
  ASSERT_EQ(back.size(), 5u);
  double y_min = 1e9, y_max = -1e9;
  int low = 0, high = 0;
  for (const PlacedBall& b : balls) {
    if (std::find(back.begin(), back.end(), b.id) == back.end()) continue;
    if (b.position.y < y_min) {
      y_min = b.position.y;
      low = b.id;
    }
    if (b.position.y > y_max) {
      y_max = b.position.y;
      high = b.id;
    }
  }
  EXPECT_NE(low < 8, high < 8) << "back corners " << low << " and " << high << " must be one solid, one stripe";
  EXPECT_NE(low, 8);
  EXPECT_NE(high, 8);
}

TEST(Rack, SnookerColoursOnTheirSpots) {
  const Table t = snooker_table_12ft();
  const std::vector<PlacedBall> balls = rack_snooker(t, {});
  const double L = 3.569, W = 1.778, R = t.ball.radius;
  // WPBSA Rules 1(d)-(f), from the bottom (baulk) cushion at x = 0.
  const auto at = [&](const char* name, Vec2 expected) {
    EXPECT_NEAR(norm(by_name(balls, name).position - expected), 0.0, 1e-12) << name;
  };
  at("black", {L - 0.324, W / 2});
  at("pink", {(L / 2 + L) / 2, W / 2});
  at("blue", {L / 2, W / 2});
  at("brown", {0.737, W / 2});
  at("yellow", {0.737, W / 2 - 0.292});  // right of the D seen from baulk (y to the left)
  at("green", {0.737, W / 2 + 0.292});
  // The apex red just behind the pink, not touching it; the reds towards the top cushion.
  const Vec2 pink = by_name(balls, "pink").position;
  const double gap = norm(by_name(balls, "red1").position - pink) - 2.0 * R;
  EXPECT_GT(gap, 0.0);
  EXPECT_LE(gap, 0.002);
  for (const PlacedBall& b : balls) {
    if (b.id >= 1 && b.id <= 15) {
      EXPECT_GT(b.position.x, pink.x) << b.name;
      EXPECT_LT(b.position.x, L - 0.324 - 2.0 * R) << b.name << " must stay clear of the black";
    }
  }
  // Base row parallel to the top cushion: the last five reds share x.
  for (int id = 12; id <= 15; ++id) {
    EXPECT_NEAR(balls[static_cast<std::size_t>(id)].position.x, balls[11].position.x, kTol);
  }
  // The cue ball inside the D: behind the baulk line, within 292 mm of the brown spot.
  const Vec2 cue = by_name(balls, "cue").position;
  EXPECT_LE(cue.x, 0.737);
  EXPECT_LE(norm(cue - Vec2{0.737, W / 2}), 0.292);
  const SnookerSpots s = snooker_spots(t);
  EXPECT_NEAR(s.baulk_line_x, 0.737, kTol);
  EXPECT_NEAR(s.d_radius, 0.292, kTol);
}

TEST(Rack, RandomGapsAreDeterministicAndNeverOverlap) {
  for (const Case& c : cases()) {
    const double two_r = 2.0 * c.table.ball.radius;
    const std::vector<PlacedBall> frozen = c.rack(c.table, {});
    for (double sigma : {1e-5, 2e-4, 1e-3, kMaxGapSigma}) {
      for (std::uint64_t seed : {0ull, 1ull, 42ull, 0xdeadbeefull}) {
        const std::vector<PlacedBall> a = c.rack(c.table, {sigma, seed});
        const std::vector<PlacedBall> b = c.rack(c.table, {sigma, seed});
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
          EXPECT_EQ(a[i].id, b[i].id);
          EXPECT_TRUE(a[i].position == b[i].position) << c.name << " seed " << seed;
        }
        EXPECT_GE(min_pair_distance(a), two_r - kTol) << c.name << " sigma " << sigma << " seed " << seed;
        // Gaps are small: each rack ball has a neighbour within 2R + 8 sigma,
        // and the apex stays on its spot.
        for (std::size_t i = 0; i < a.size(); ++i) {
          if (a[i].id == 0 || (c.balls == 22 && a[i].id > 15)) {
            EXPECT_TRUE(a[i].position == frozen[i].position) << c.name << " " << a[i].name << " is not in the rack";
            continue;
          }
          double nearest = std::numeric_limits<double>::infinity();
          for (std::size_t k = 0; k < a.size(); ++k) {
            if (k != i) nearest = std::min(nearest, norm(a[k].position - a[i].position));
          }
          EXPECT_LE(nearest, two_r + 8.0 * sigma + kTol) << c.name << " " << a[i].name;
        }
        EXPECT_TRUE(a[1].position == frozen[1].position) << c.name << ": the apex ball stays on its spot";
      }
      // Seeds differ.
      const std::vector<PlacedBall> x = c.rack(c.table, {sigma, 1});
      const std::vector<PlacedBall> y = c.rack(c.table, {sigma, 2});
      bool differ = false;
      for (std::size_t i = 0; i < x.size(); ++i) differ = differ || !(x[i].position == y[i].position);
      EXPECT_TRUE(differ) << c.name << " sigma " << sigma;
    }
    // Zero sigma is the frozen rack whatever the seed.
    const std::vector<PlacedBall> z = c.rack(c.table, {0.0, 99});
    for (std::size_t i = 0; i < z.size(); ++i) EXPECT_TRUE(z[i].position == frozen[i].position) << c.name;
  }
}

TEST(Rack, GapsOpenUp) {
  // With gaps the touching pairs mostly disappear.
  const Table t = pool_table_9ft();
  const std::vector<PlacedBall> a = rack_eight_ball(t, {1e-3, 5});
  EXPECT_LT(count_pairs_at(a, 2.0 * t.ball.radius, 1e-9), 5u);
}

TEST(Rack, BadOptionsAndTablesAreRejected) {
  const Table t = pool_table_9ft();
  const auto field = [&](RackOptions o) {
    try {
      rack_nine_ball(t, o);
    } catch (const InvalidArgument& e) {
      return e.field();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(field({-1e-4, 0}), "gap_sigma");
  EXPECT_EQ(field({0.01, 0}), "gap_sigma");
  EXPECT_EQ(field({std::numeric_limits<double>::quiet_NaN(), 0}), "gap_sigma");
  EXPECT_EQ(field({kMaxGapSigma, 0}), "accepted");
  // A table too short for the triangle: see RackTooBigForTheTableNamesTheRack.
  TableSpec s = carom_table_10ft_spec();
  s.length = 0.4;
  s.width = 0.2;
  EXPECT_THROW(rack_eight_ball(build_table(s), {}), InvalidArgument);
  // An invalid table is rejected before racking.
  Table broken = t;
  broken.ball.radius = -1.0;
  EXPECT_THROW(rack_snooker(broken, {}), InvalidArgument);
}

std::string rack_error(RackFn rack, const Table& t, std::string* field = nullptr) {
  try {
    rack(t, {});
  } catch (const InvalidArgument& e) {
    if (field != nullptr) *field = e.field();
    return e.what();
  }
  if (field != nullptr) *field = "accepted";
  return {};
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(Rack, RackTooBigForTheTableNamesTheRack) {
  // Too short and narrow: the field is the rack, the message says which ball,
  // where, the range its centre must be in and the size the rack needs.
  TableSpec s = carom_table_10ft_spec();
  s.length = 0.4;
  s.width = 0.2;
  const Table small = build_table(s);
  std::string field;
  const std::string m = rack_error(&rack_eight_ball, small, &field);
  EXPECT_EQ(field, "rack");
  EXPECT_TRUE(has(m, "rack: the eight_ball rack does not fit on table 'carom 10 ft (UMB)' (length 0.4 m, width 0.2 m)")) << m;
  EXPECT_TRUE(has(m, "every centre must lie in [")) << m;
  EXPECT_TRUE(has(m, "needs length >= ")) << m;
  // The size it asks for is enough (on a carom table: nothing but the rails
  // in the way), and a little less is not.
  const auto needed = [](const std::string& msg, const std::string& key) {
    const std::size_t at = msg.find(key);
    EXPECT_NE(at, std::string::npos) << msg;
    return std::stod(msg.substr(at + key.size()));
  };
  for (RackFn rack : {&rack_eight_ball, &rack_nine_ball}) {
    const std::string msg = rack_error(rack, small);
    TableSpec fits = s;
    fits.length = needed(msg, "needs length >= ") * (1 + 1e-9);
    fits.width = needed(msg, "and width >= ") * (1 + 1e-9);
    EXPECT_EQ(rack_error(rack, build_table(fits), &field), "") << msg;
    EXPECT_EQ(field, "accepted");
    TableSpec narrow = fits;
    narrow.width *= 0.99;
    EXPECT_EQ((rack_error(rack, build_table(narrow), &field), field), "rack");
    TableSpec short_table = fits;
    short_table.length *= 0.99;
    EXPECT_EQ((rack_error(rack, build_table(short_table), &field), field), "rack");
  }
  // Snooker on a pool-sized table: the reds reach past the black spot, and
  // the overlapping pair is named with their distance.
  TableSpec cramped = snooker_table_12ft_spec();
  cramped.length = 1.2;
  cramped.width = 1.0;
  const std::string overlap = rack_error(&rack_snooker, build_table(cramped), &field);
  EXPECT_EQ(field, "rack") << overlap;
  EXPECT_TRUE(has(overlap, "rack: the snooker rack does not fit")) << overlap;
}

}  // namespace
}  // namespace cueball
