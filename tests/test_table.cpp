// Tests of table geometry, presets, validation and JSON (src/table/table.cpp).
//
// Expected values are computed here from the published numbers (inches,
// millimetres), independently of the construction in src/table/table.cpp; the lips,
// cut angles and mouths are measured back from the built segments.
#include "cueball/io/table_json.hpp"
#include "cueball/table/table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cueball/core/errors.hpp"

namespace cueball {
namespace {

constexpr double kIn = 0.0254;
constexpr double kTol = 1e-12;

struct Caught {
  std::string field;
  std::string message;
};

template <class F>
Caught catch_invalid(F f) {
  try {
    f();
  } catch (const InvalidArgument& e) {
    return {e.field(), e.what()};
  }
  return {"accepted", ""};
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// ------------------------------------------------------------------ geometry helpers (independent of table.cpp)

double contact_distance(double h, double R) {
  const double sin_theta = (h - R) / R;
  return R * std::sqrt(1.0 - sin_theta * sin_theta);
}

std::optional<Vec2> line_intersection(Vec2 p, Vec2 d, Vec2 q, Vec2 e) {
  const double den = cross(d, e);
  if (std::abs(den) < 1e-15) return std::nullopt;
  const double t = cross(q - p, e) / den;
  return p + t * d;
}

// The segment end touching the jaw (within 1e-12), and the other end.
struct Touch {
  const CushionSegment* segment;
  Vec2 at;     // endpoint on the arc
  Vec2 other;  // far endpoint
};

std::vector<Touch> touching(const Table& t, const JawArc& j) {
  std::vector<Touch> out;
  for (const CushionSegment& s : t.cushions) {
    if (std::abs(norm(s.start - j.centre) - j.radius) < kTol) out.push_back({&s, s.start, s.end});
    if (std::abs(norm(s.end - j.centre) - j.radius) < kTol) out.push_back({&s, s.end, s.start});
  }
  return out;
}

bool on_rectangle_edge(const Table& t, const CushionSegment& s) {
  const auto on = [&](Vec2 p) {
    return std::abs(p.y) < kTol || std::abs(p.y - t.width) < kTol || std::abs(p.x) < kTol ||
           std::abs(p.x - t.length) < kTol;
  };
  return on(s.start) && on(s.end) &&
         (std::abs(s.start.x - s.end.x) < kTol || std::abs(s.start.y - s.end.y) < kTol);
}

const Pocket& nearest_pocket(const Table& t, Vec2 p) {
  const Pocket* best = &t.pockets.front();
  for (const Pocket& q : t.pockets) {
    if (norm(q.centre - p) < norm(best->centre - p)) best = &q;
  }
  return *best;
}

// Smallest clearance (distance minus contact distance) of a ball centred at p
// to every cushion segment and jaw.
double clearance(const Table& t, Vec2 p) {
  const double R = t.ball.radius;
  double c = std::numeric_limits<double>::infinity();
  for (const CushionSegment& s : t.cushions) {
    c = std::min(c, distance_to_segment(s, p) - contact_distance(s.contact_height, R));
  }
  for (const JawArc& j : t.jaws) c = std::min(c, norm(p - j.centre) - j.radius - contact_distance(j.contact_height, R));
  return c;
}

// The site (corner or side midpoint) a pocket belongs to.
Vec2 pocket_site(const Table& t, const Pocket& p) {
  const std::vector<Vec2> sites{{0, 0}, {t.length / 2, 0}, {t.length, 0}, {t.length, t.width}, {t.length / 2, t.width},
                                {0, t.width}};
  Vec2 best = sites[0];
  for (Vec2 s : sites) {
    if (norm(s - p.centre) < norm(best - p.centre)) best = s;
  }
  return best;
}

// Rolls a ball along a line parallel to the pocket's axis (offset `lateral`
// m) from 0.3 m inside the table towards the pocket; true when it reaches the
// capture circle with a non-negative clearance at every 0.05 mm step.
bool ball_reaches_pocket(const Table& t, const Pocket& p, double lateral, double* min_clearance = nullptr) {
  const Vec2 site = pocket_site(t, p);
  const Vec2 u = (site - p.centre) / norm(site - p.centre);  // into the table
  const Vec2 side = perp(u);
  const Vec2 start = p.centre + (norm(site - p.centre) + 0.3) * u + lateral * side;
  double worst = std::numeric_limits<double>::infinity();
  const double step = 5e-5;
  for (int i = 0; i < 20000; ++i) {
    const Vec2 q = start - (i * step) * u;
    if (in_pocket(p, q)) {
      if (min_clearance != nullptr) *min_clearance = worst;
      return worst >= 0.0;
    }
    worst = std::min(worst, clearance(t, q));
    if (worst < 0.0) break;
  }
  if (min_clearance != nullptr) *min_clearance = worst;
  return false;
}

std::vector<Table> pocketed_presets() { return {pool_table_9ft(), snooker_table_12ft()}; }
std::vector<Table> all_presets() { return {pool_table_9ft(), snooker_table_12ft(), carom_table_10ft()}; }

// For each jaw: the lip (nose line meets facing line), the nose and facing
// directions away from the lip.
struct Lip {
  Vec2 vertex;
  double cut_angle_deg;
};

Lip lip_of(const Table& t, const JawArc& j) {
  const std::vector<Touch> ends = touching(t, j);
  EXPECT_EQ(ends.size(), 2u);
  const Touch* nose = on_rectangle_edge(t, *ends[0].segment) ? &ends[0] : &ends[1];
  const Touch* facing = nose == &ends[0] ? &ends[1] : &ends[0];
  const Vec2 dn = nose->other - nose->at;
  const Vec2 df = facing->other - facing->at;
  const auto v = line_intersection(nose->at, dn, facing->at, df);
  EXPECT_TRUE(v.has_value());
  const Vec2 a = nose->other - *v;
  const Vec2 b = facing->other - *v;
  const double angle = std::acos(dot(a, b) / (norm(a) * norm(b))) * 180.0 / std::numbers::pi;
  return {*v, angle};
}

// ------------------------------------------------------------------ contact rules

TEST(TableContact, ContactDistanceIsRCosTheta) {
  const double R = 0.02625;
  // Mathavan: h = 7R/5, sin(theta) = 2/5, cos(theta) = sqrt(21)/5.
  EXPECT_NEAR(cushion_contact_distance(1.4 * R, R), R * std::sqrt(21.0) / 5.0, 1e-15);
  // h = R: the nose at the equator touches at distance R.
  EXPECT_NEAR(cushion_contact_distance(R, R), R, 1e-15);
  // Pool: nose 1 7/16 in, ball 2.25 in.
  const double Rp = 1.125 * kIn;
  EXPECT_NEAR(cushion_contact_distance(1.4375 * kIn, Rp), contact_distance(1.4375 * kIn, Rp), 1e-15);
  const JawArc jaw{{0, 0}, 0.01, 1.4 * R, {}};
  EXPECT_NEAR(jaw_contact_distance(jaw, R), 0.01 + R * std::sqrt(21.0) / 5.0, 1e-15);
}

TEST(TableContact, InwardNormalIsOnTheLeft) {
  const CushionSegment s{{0, 0}, {2, 0}, 0.03, {}};
  EXPECT_NEAR(inward_normal(s).x, 0.0, 1e-15);
  EXPECT_NEAR(inward_normal(s).y, 1.0, 1e-15);
  EXPECT_NEAR(distance_to_segment(s, {1, 0.5}), 0.5, 1e-15);
  EXPECT_NEAR(distance_to_segment(s, {3, 0}), 1.0, 1e-15);  // past the end: to the endpoint
}

// ------------------------------------------------------------------ presets

TEST(TablePresets, PoolMatchesWpa) {
  const Table t = pool_table_9ft();
  EXPECT_NEAR(t.length, 2.54, kTol);  // 100 in
  EXPECT_NEAR(t.width, 1.27, kTol);   // 50 in
  EXPECT_NEAR(2 * t.ball.radius, 0.05715, kTol);
  EXPECT_EQ(t.pockets.size(), 6u);
  EXPECT_EQ(t.jaws.size(), 12u);
  EXPECT_EQ(t.cushions.size(), 18u);
  EXPECT_EQ(t.diamonds.size(), 18u);  // WPA: 18 sights
  for (const CushionSegment& s : t.cushions) EXPECT_NEAR(s.contact_height, 0.0365125, kTol);  // 1 7/16 in
  // Every sight 3 11/16 in behind a nose line.
  for (Vec2 d : t.diamonds) {
    const double off = std::max({-d.y, d.y - t.width, -d.x, d.x - t.length});
    EXPECT_NEAR(off, 0.0936625, kTol);
  }
}

TEST(TablePresets, PoolMouthsAndCutAnglesMeasuredFromTheSegments) {
  const Table t = pool_table_9ft();
  for (const Pocket& p : t.pockets) {
    const Vec2 site = pocket_site(t, p);
    const bool corner = site.x == 0.0 || site.x == t.length;
    std::vector<Lip> lips;
    for (const JawArc& j : t.jaws) {
      if (&nearest_pocket(t, j.centre) == &p) lips.push_back(lip_of(t, j));
    }
    ASSERT_EQ(lips.size(), 2u) << p.name;
    const double mouth = norm(lips[0].vertex - lips[1].vertex);
    if (corner) {
      EXPECT_GE(mouth, 4.5 * kIn - kTol) << p.name;
      EXPECT_LE(mouth, 4.625 * kIn + kTol) << p.name;
      EXPECT_NEAR(lips[0].cut_angle_deg, 142.0, 1e-9) << p.name;
      EXPECT_NEAR(lips[1].cut_angle_deg, 142.0, 1e-9) << p.name;
    } else {
      EXPECT_GE(mouth, 5.0 * kIn - kTol) << p.name;
      EXPECT_LE(mouth, 5.125 * kIn + kTol) << p.name;
      EXPECT_NEAR(lips[0].cut_angle_deg, 104.0, 1e-9) << p.name;
      EXPECT_NEAR(lips[1].cut_angle_deg, 104.0, 1e-9) << p.name;
    }
    // The lips lie on the rectangle's edges.
    for (const Lip& l : lips) {
      const bool on_edge = std::abs(l.vertex.x) < kTol || std::abs(l.vertex.x - t.length) < kTol ||
                           std::abs(l.vertex.y) < kTol || std::abs(l.vertex.y - t.width) < kTol;
      EXPECT_TRUE(on_edge) << p.name;
    }
    // BCA shelf: the capture circle's nearest point lies `shelf` behind the
    // middle of the mouth, corner 1 5/8 - 1 7/8 in, side 0 - 3/8 in.
    const Vec2 mid = 0.5 * (lips[0].vertex + lips[1].vertex);
    const double shelf = norm(p.centre - mid) - p.radius;
    if (corner) {
      EXPECT_GE(shelf, 1.625 * kIn - kTol) << p.name;
      EXPECT_LE(shelf, 1.875 * kIn + kTol) << p.name;
    } else {
      EXPECT_GE(shelf, 0.0 - kTol) << p.name;
      EXPECT_LE(shelf, 0.375 * kIn + kTol) << p.name;
    }
  }
}

TEST(TablePresets, SnookerMatchesWpbsa) {
  const Table t = snooker_table_12ft();
  // 11 ft 8.5 in x 5 ft 10 in = 3569 x 1778 mm (to the mm).
  EXPECT_NEAR(t.length, 3.569, kTol);
  EXPECT_NEAR(t.width, 1.778, kTol);
  EXPECT_NEAR(t.length, (11 * 12 + 8.5) * kIn, 0.5e-3);
  EXPECT_NEAR(t.width, (5 * 12 + 10) * kIn, 0.5e-3);
  EXPECT_NEAR(2 * t.ball.radius, 0.0525, kTol);
  EXPECT_EQ(t.pockets.size(), 6u);
  EXPECT_TRUE(t.diamonds.empty());
  for (const CushionSegment& s : t.cushions) EXPECT_NEAR(s.contact_height, 7.0 * t.ball.radius / 5.0, kTol);
  for (const JawArc& j : t.jaws) EXPECT_NEAR(j.contact_height, 7.0 * t.ball.radius / 5.0, kTol);
}

TEST(TablePresets, CaromMatchesUmb) {
  const Table t = carom_table_10ft();
  EXPECT_NEAR(t.length, 2.84, kTol);
  EXPECT_NEAR(t.width, 1.42, kTol);
  EXPECT_NEAR(2 * t.ball.radius, 0.0615, kTol);
  EXPECT_GE(t.ball.mass, 0.205);
  EXPECT_LE(t.ball.mass, 0.220);
  EXPECT_TRUE(t.pockets.empty());
  EXPECT_TRUE(t.jaws.empty());
  ASSERT_EQ(t.cushions.size(), 4u);
  const std::vector<Vec2> corners{{0, 0}, {2.84, 0}, {2.84, 1.42}, {0, 1.42}};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(norm(t.cushions[i].start - corners[i]), 0.0, kTol);
    EXPECT_NEAR(norm(t.cushions[i].end - corners[(i + 1) % 4]), 0.0, kTol);
    EXPECT_NEAR(t.cushions[i].contact_height, 0.037, kTol);
  }
  EXPECT_EQ(t.diamonds.size(), 20u);
}

TEST(TablePresets, PresetByName) {
  for (std::string_view name : kTablePresetNames) EXPECT_NO_THROW(validate(preset_table(name))) << name;
  EXPECT_EQ(preset_table("pool_9ft"), pool_table_9ft());
  const Caught c = catch_invalid([] { preset_table("croquet"); });
  EXPECT_EQ(c.field, "preset");
  EXPECT_TRUE(contains(c.message, "snooker_12ft")) << c.message;
}

// ------------------------------------------------------------------ layout

TEST(TableLayout, PocketsSitAtTheCornersAndSides) {
  for (const Table& t : pocketed_presets()) {
    std::vector<Vec2> sites;
    for (const Pocket& p : t.pockets) {
      const Vec2 site = pocket_site(t, p);
      sites.push_back(site);
      EXPECT_LT(norm(p.centre - site), 0.15) << t.name << " " << p.name;
      EXPECT_FALSE(p.centre.x > 0 && p.centre.x < t.length && p.centre.y > 0 && p.centre.y < t.width)
          << "capture circle centre should lie behind the nose lines: " << p.name;
      if (site.x == t.length / 2) {
        EXPECT_NEAR(p.centre.x, t.length / 2, kTol) << p.name;  // side pocket on the cross line
      } else {
        // Corner pocket on the corner's diagonal.
        EXPECT_NEAR(std::abs(p.centre.x - site.x), std::abs(p.centre.y - site.y), kTol) << p.name;
      }
    }
    // One pocket per site.
    for (std::size_t i = 0; i < sites.size(); ++i) {
      for (std::size_t k = i + 1; k < sites.size(); ++k) EXPECT_FALSE(sites[i] == sites[k]) << t.name;
    }
  }
}

TEST(TableLayout, PlayingSurfaceIsOnTheLeftOfEverySegment) {
  for (const Table& t : all_presets()) {
    const Vec2 centre{t.length / 2, t.width / 2};
    for (std::size_t i = 0; i < t.cushions.size(); ++i) {
      const CushionSegment& s = t.cushions[i];
      const Vec2 mid = 0.5 * (s.start + s.end);
      if (on_rectangle_edge(t, s)) {
        EXPECT_GT(dot(centre - mid, inward_normal(s)), 0.0) << t.name << " cushions[" << i << "]";
      } else {
        // A facing: its pocket's axis (and capture centre) is on the playing side.
        const Pocket& p = nearest_pocket(t, mid);
        EXPECT_GT(dot(p.centre - mid, inward_normal(s)), 0.0) << t.name << " cushions[" << i << "]";
      }
    }
  }
}

TEST(TableLayout, JawsAreTangentToTheCushionEndsTheyJoin) {
  for (const Table& t : pocketed_presets()) {
    for (std::size_t i = 0; i < t.jaws.size(); ++i) {
      const JawArc& j = t.jaws[i];
      const std::vector<Touch> ends = touching(t, j);
      ASSERT_EQ(ends.size(), 2u) << t.name << " jaws[" << i << "]";
      int noses = 0;
      for (const Touch& e : ends) {
        const Vec2 d = e.segment->end - e.segment->start;
        // Tangent: the radius to the end is perpendicular to the segment...
        EXPECT_NEAR(dot(e.at - j.centre, d) / norm(d), 0.0, 1e-12) << t.name << " jaws[" << i << "]";
        // ...and the arc's centre is behind the segment (in the cushion).
        EXPECT_NEAR(dot(j.centre - e.at, inward_normal(*e.segment)), -j.radius, 1e-12) << t.name;
        if (on_rectangle_edge(t, *e.segment)) ++noses;
      }
      EXPECT_EQ(noses, 1) << "a jaw joins one nose and one facing: " << t.name << " jaws[" << i << "]";
    }
  }
}

TEST(TableLayout, EverySegmentEndIsAccountedFor) {
  // Each end has a tangent jaw, meets another segment's end (carom corners),
  // or lies inside or on a capture circle (the deep end of a facing; on it
  // when the facings are parallel).
  for (const Table& t : all_presets()) {
    for (std::size_t i = 0; i < t.cushions.size(); ++i) {
      for (Vec2 end : {t.cushions[i].start, t.cushions[i].end}) {
        bool ok = false;
        for (const JawArc& j : t.jaws) ok = ok || std::abs(norm(end - j.centre) - j.radius) < kTol;
        for (std::size_t k = 0; k < t.cushions.size(); ++k) {
          if (k == i) continue;
          ok = ok || norm(end - t.cushions[k].start) < kTol || norm(end - t.cushions[k].end) < kTol;
        }
        for (const Pocket& p : t.pockets) ok = ok || norm(end - p.centre) <= p.radius + kTol;
        EXPECT_TRUE(ok) << t.name << " cushions[" << i << "] end (" << end.x << ", " << end.y << ")";
      }
    }
  }
}

TEST(TableLayout, BallRollingDownAPocketAxisReachesTheCaptureCircle) {
  for (const Table& t : pocketed_presets()) {
    for (const Pocket& p : t.pockets) {
      for (double lateral : {-0.005, 0.0, 0.005}) {
        double worst = 0.0;
        EXPECT_TRUE(ball_reaches_pocket(t, p, lateral, &worst))
            << t.name << " " << p.name << " lateral " << lateral << " clearance " << worst;
      }
      // The mouth is at least one ball wide: the narrowest clearance along the
      // axis is positive, not merely zero.
      double worst = 0.0;
      ball_reaches_pocket(t, p, 0.0, &worst);
      EXPECT_GT(worst, 1e-3) << t.name << " " << p.name;
    }
  }
}

TEST(TableLayout, ReachableBallsMeetJawsOnlyOnTheirExposedArc) {
  // The simulator may treat a jaw as a full circle: flood-fill the ball
  // centres reachable from the table near each pocket (1 mm grid, cushions,
  // jaws and the capture circle as obstacles) and check that every reachable
  // centre close to a jaw's contact circle faces the jaw's exposed arc (the
  // arc between its two tangent points on the lip's side), widened by the
  // angle a 1.5 mm band can add.
  const double step = 1e-3;
  const int n = 400;  // 0.4 m box
  for (const Table& t : pocketed_presets()) {
    const double R = t.ball.radius;
    for (const Pocket& p : t.pockets) {
      const Vec2 site = pocket_site(t, p);
      const Vec2 origin = site - Vec2{0.2, 0.2};
      const auto cell = [&](int i, int k) { return origin + Vec2{i * step, k * step}; };
      const auto free = [&](Vec2 q) { return clearance(t, q) >= 0.0 && !in_pocket(p, q); };
      std::vector<char> seen(static_cast<std::size_t>(n * n), 0);
      const Vec2 u = (site - p.centre) / norm(site - p.centre);
      const Vec2 seed_point = site + 0.15 * u;
      std::vector<std::pair<int, int>> todo{{static_cast<int>(std::lround((seed_point.x - origin.x) / step)),
                                             static_cast<int>(std::lround((seed_point.y - origin.y) / step))}};
      ASSERT_TRUE(free(cell(todo[0].first, todo[0].second))) << p.name;
      std::size_t reachable = 0, near_jaw = 0;
      while (!todo.empty()) {
        const auto [i, k] = todo.back();
        todo.pop_back();
        if (i < 0 || k < 0 || i >= n || k >= n) continue;
        char& mark = seen[static_cast<std::size_t>(i * n + k)];
        if (mark != 0) continue;
        mark = 1;
        const Vec2 q = cell(i, k);
        if (!free(q)) continue;
        ++reachable;
        for (const JawArc& j : t.jaws) {
          const double d = norm(q - j.centre) - j.radius - contact_distance(j.contact_height, R);
          if (d > 1.5e-3) continue;
          ++near_jaw;
          const std::vector<Touch> ends = touching(t, j);
          ASSERT_EQ(ends.size(), 2u);
          const Vec2 a = ends[0].at - j.centre, b = ends[1].at - j.centre, dir = q - j.centre;
          const double slack = std::sqrt(2.0 * 1.5e-3 / (j.radius + contact_distance(j.contact_height, R))) + 0.02;
          const double span = std::atan2(std::abs(cross(a, b)), dot(a, b));
          const double to_a = std::atan2(std::abs(cross(a, dir)), dot(a, dir));
          const double to_b = std::atan2(std::abs(cross(b, dir)), dot(b, dir));
          EXPECT_LE(to_a + to_b, span + 2.0 * slack)
              << t.name << " " << p.name << ": reachable centre (" << q.x << ", " << q.y
              << ") meets the hidden part of the jaw at (" << j.centre.x << ", " << j.centre.y << ")";
        }
        todo.push_back({i + 1, k});
        todo.push_back({i - 1, k});
        todo.push_back({i, k + 1});
        todo.push_back({i, k - 1});
      }
      EXPECT_GT(reachable, 1000u) << p.name;
      EXPECT_GT(near_jaw, 10u) << p.name << ": the fill should run along the jaws";
    }
  }
}

TEST(TableLayout, BlockedMouthIsDetected) {
  // The check above can fail: a cushion across a mouth stops the ball.
  Table t = pool_table_9ft();
  const Pocket p = t.pockets[1];  // bottom side pocket
  t.cushions.push_back({{t.length / 2 + 0.1, 0.0}, {t.length / 2 - 0.1, 0.0}, t.cushions[0].contact_height, {}});
  EXPECT_FALSE(ball_reaches_pocket(t, p, 0.0));
}

TEST(TableLayout, TooNarrowMouthIsRejected) {
  TableSpec s = pool_table_9ft_spec();
  s.corner_pockets.mouth = 2.0 * kIn;  // under two contact distances (~2.16 in)
  EXPECT_EQ(catch_invalid([&] { build_table(s); }).field, "corner_pockets.mouth");
  s = snooker_table_12ft_spec();
  s.side_pockets.mouth = 0.045;
  EXPECT_EQ(catch_invalid([&] { validate(s); }).field, "side_pockets.mouth");
}

TEST(TableLayout, FacingsThatCloseBeforeTheHoleAreRejected) {
  // A side pocket's facings turned in by 45 deg or more meet (or cross)
  // before the capture circle's centre: the geometry would be open or
  // self-crossing, so the spec is rejected by the field that does it.
  TableSpec s = pool_table_9ft_spec();
  s.side_pockets.cut_angle_deg = 160.0;
  Caught c = catch_invalid([&] { build_table(s); });
  EXPECT_EQ(c.field, "side_pockets.cut_angle_deg") << c.message;
  EXPECT_TRUE(contains(c.message, "allowed < 135 deg")) << c.message;
  s.side_pockets.cut_angle_deg = 135.0;
  EXPECT_EQ(catch_invalid([&] { build_table(s); }).field, "side_pockets.cut_angle_deg");
  s.side_pockets.cut_angle_deg = 134.0;
  EXPECT_EQ(catch_invalid([&] { build_table(s); }).field, "accepted");
  s.corner_pockets.cut_angle_deg = 150.0;  // corners: parallel at 135, so allowed up to 180 (the range stops at 170)
  EXPECT_EQ(catch_invalid([&] { build_table(s); }).field, "accepted");
}

TEST(TableSpecs, ResizedTableKeepsItsPocketsAtTheCornersAndSides) {
  TableSpec s = pool_table_9ft_spec();
  s.length = 92 * kIn;  // WPA 8-ft: 92 x 46 in
  s.width = 46 * kIn;
  const Table t = build_table(s);
  EXPECT_NEAR(t.pockets[1].centre.x, 46 * kIn, kTol);
  for (const Pocket& p : t.pockets) EXPECT_TRUE(ball_reaches_pocket(t, p, 0.0)) << p.name;
  // Pockets that leave no cushion between them are rejected.
  s.width = 0.15;
  EXPECT_EQ(catch_invalid([&] { build_table(s); }).field, "width");
  s = pool_table_9ft_spec();
  s.corner_pockets.cut_angle_deg = 200;
  EXPECT_EQ(catch_invalid([&] { build_table(s); }).field, "corner_pockets.cut_angle_deg");
  s = pool_table_9ft_spec();
  s.cushion_height = 2.5 * s.ball.radius;
  EXPECT_EQ(catch_invalid([&] { build_table(s); }).field, "cushion_height");
}

// ------------------------------------------------------------------ ball_on_table

TEST(BallOnTable, AcceptsTheOpenTableAndTouchingPositions) {
  for (const Table& t : all_presets()) {
    const double d = contact_distance(t.cushions[0].contact_height, t.ball.radius);
    EXPECT_TRUE(ball_on_table(t, {t.length / 2, t.width / 2})) << t.name;
    EXPECT_TRUE(ball_on_table(t, {t.length / 4, d})) << t.name;          // frozen to the bottom rail
    EXPECT_TRUE(ball_on_table(t, {t.length / 4, d + 1e-9})) << t.name;
    EXPECT_TRUE(ball_on_table(t, {d, t.width / 2})) << t.name;           // frozen to the left end rail
  }
}

TEST(BallOnTable, RejectsPositionsOffTheTableOrInACushion) {
  for (const Table& t : all_presets()) {
    const double d = contact_distance(t.cushions[0].contact_height, t.ball.radius);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(ball_on_table(t, {-0.01, t.width / 2})) << t.name;
    EXPECT_FALSE(ball_on_table(t, {t.length / 4, t.width + 0.001})) << t.name;
    EXPECT_FALSE(ball_on_table(t, {t.length + 1.0, t.width / 2})) << t.name;
    EXPECT_FALSE(ball_on_table(t, {nan, 0.5})) << t.name;
    EXPECT_FALSE(ball_on_table(t, {t.length / 4, 0.5 * d})) << t.name;   // overlaps the bottom cushion
    EXPECT_FALSE(ball_on_table(t, {t.length / 4, d - 1e-6})) << t.name;
    EXPECT_FALSE(ball_on_table(t, {t.length - 0.5 * d, t.width / 2})) << t.name;
  }
  // Next to a jaw, inside the mouth: the ball overlaps the rounded lip.
  const Table t = pool_table_9ft();
  for (const JawArc& j : t.jaws) {
    const Pocket& p = nearest_pocket(t, j.centre);
    const Vec2 site = pocket_site(t, p);
    // Towards the table from the arc's centre, a bit less than contact distance.
    const Vec2 to_site = (site - j.centre) / norm(site - j.centre);
    const Vec2 q = j.centre + (j.radius + 0.5 * contact_distance(j.contact_height, t.ball.radius)) * to_site;
    if (q.x > 0 && q.x < t.length && q.y > 0 && q.y < t.width) {
      EXPECT_FALSE(ball_on_table(t, q)) << p.name;
    }
  }
}

TEST(BallOnTable, ExplicitRadius) {
  // A smaller ball fits closer to the cushion than the table's own ball.
  const Table t = pool_table_9ft();
  const double h = t.cushions[0].contact_height;
  const double small = 0.9 * t.ball.radius;  // h stays below 2 * small
  const Vec2 q{t.length / 4, 0.5 * (contact_distance(h, small) + contact_distance(h, t.ball.radius))};
  EXPECT_TRUE(ball_on_table(t, q, small));
  EXPECT_FALSE(ball_on_table(t, q, t.ball.radius));
  EXPECT_FALSE(ball_on_table(t, q));
}

TEST(BallOnTable, JawsAndPocketsAreObstaclesOnTheirOwn) {
  Table t = carom_table_10ft();
  const Vec2 c{t.length / 2, t.width / 2};
  t.jaws.push_back({c, 0.01, 0.037, {}});
  const double d = contact_distance(0.037, t.ball.radius);
  EXPECT_FALSE(ball_on_table(t, c + Vec2{0.01 + 0.5 * d, 0}));
  EXPECT_TRUE(ball_on_table(t, c + Vec2{0.01 + d, 0}));
  t.jaws.clear();
  t.pockets.push_back({"hole", c, 0.05});
  EXPECT_FALSE(ball_on_table(t, c + Vec2{0.049, 0}));
  EXPECT_TRUE(ball_on_table(t, c + Vec2{0.051, 0}));
  EXPECT_TRUE(in_pocket(t.pockets[0], c + Vec2{0.0499999, 0}));
}

// ------------------------------------------------------------------ validate(Table)

TEST(TableValidate, PresetsAreValid) {
  for (const Table& t : all_presets()) EXPECT_NO_THROW(validate(t)) << t.name;
}

TEST(TableValidate, EachBadFieldIsNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto field = [](auto mutate) {
    Table t = pool_table_9ft();
    mutate(t);
    return catch_invalid([&] { validate(t); });
  };
  EXPECT_EQ(field([&](Table& t) { t.cushions[3].end.x = nan; }).field, "cushions[3].end");
  EXPECT_EQ(field([&](Table& t) { t.cushions[3].end = t.cushions[3].start; }).field, "cushions[3].end");
  EXPECT_EQ(field([&](Table& t) { t.cushions[2].start = {50.0, 0.0}; }).field, "cushions[2].start");
  EXPECT_EQ(field([&](Table& t) { t.cushions[0].contact_height = 2.0 * t.ball.radius; }).field,
            "cushions[0].contact_height");
  EXPECT_EQ(field([&](Table& t) { t.cushions[5].contact_height = inf; }).field, "cushions[5].contact_height");
  EXPECT_EQ(field([&](Table& t) { t.jaws[1].radius = -0.01; }).field, "jaws[1].radius");
  EXPECT_EQ(field([&](Table& t) { t.jaws[1].centre.y = inf; }).field, "jaws[1].centre");
  EXPECT_EQ(field([&](Table& t) { t.pockets[2].radius = 0.5; }).field, "pockets[2].radius");
  EXPECT_EQ(field([&](Table& t) { t.pockets[2].name = t.pockets[0].name; }).field, "pockets[2].name");
  EXPECT_EQ(field([&](Table& t) { t.pockets[4].name.clear(); }).field, "pockets[4].name");
  EXPECT_EQ(field([&](Table& t) { t.length = -2.54; }).field, "length");
  EXPECT_EQ(field([&](Table& t) { t.width = nan; }).field, "width");
  EXPECT_EQ(field([&](Table& t) { t.ball.radius = 0.0; }).field, "ball.radius");
  EXPECT_EQ(field([&](Table& t) { t.ball.mass = -1.0; }).field, "ball.mass");
  EXPECT_EQ(field([&](Table& t) { t.cushions.resize(2); }).field, "cushions");
  EXPECT_EQ(field([&](Table& t) { t.diamonds[0].x = nan; }).field, "diamonds[0]");
  EXPECT_EQ(field([&](Table& t) { t.name.clear(); }).field, "name");
  const Caught c = field([&](Table& t) { t.pockets[2].radius = -1; });
  EXPECT_TRUE(contains(c.message, "pockets[2].radius = -1 is outside (0, 0.2] m")) << c.message;
}

// ------------------------------------------------------------------ closed boundary

// Parametric tables across the spec ranges (whatever validate(TableSpec) accepts).
std::vector<Table> parametric_tables() {
  std::vector<Table> out;
  for (TableSpec base : {pool_table_9ft_spec(), snooker_table_12ft_spec()}) {
    for (double mouth_scale : {0.9, 1.0, 1.3}) {
      for (double cut : {95.0, 135.0, 160.0}) {
        for (double jaw : {0.001, 0.02}) {
          for (double shelf : {0.0, 0.03}) {
            TableSpec s = base;
            s.length *= 0.8;
            s.width *= 0.8;
            s.corner_pockets = {base.corner_pockets.mouth * mouth_scale, std::max(cut, 135.0), jaw, shelf};
            s.side_pockets = {base.side_pockets.mouth * mouth_scale, cut, jaw, shelf};
            try {
              validate(s);
            } catch (const InvalidArgument&) {
              continue;  // outside the spec's ranges: not a table
            }
            out.push_back(build_table(s));
          }
        }
      }
    }
  }
  return out;
}

Table reversed(Table t) {
  std::reverse(t.cushions.begin(), t.cushions.end());
  for (CushionSegment& c : t.cushions) std::swap(c.start, c.end);
  return t;
}

Caught invalid_table(const Table& t) {
  return catch_invalid([&] { validate(t); });
}

TEST(TableBoundary, PresetsAndParametricTablesAreClosed) {
  for (const Table& t : all_presets()) EXPECT_EQ(invalid_table(t).field, "accepted") << invalid_table(t).message;
  const std::vector<Table> tables = parametric_tables();
  EXPECT_GT(tables.size(), 20u);
  for (const Table& t : tables) {
    const Caught c = invalid_table(t);
    EXPECT_EQ(c.field, "accepted") << c.message;
  }
  // Resized presets too (8-ft and 7-ft pool, a half-size snooker table).
  for (auto [spec, scale] : {std::pair{pool_table_9ft_spec(), 92.0 / 100.0}, std::pair{pool_table_9ft_spec(), 0.78},
                             std::pair{snooker_table_12ft_spec(), 0.5}, std::pair{carom_table_10ft_spec(), 0.7}}) {
    spec.length *= scale;
    spec.width *= scale;
    EXPECT_NO_THROW(build_table(spec)) << spec.name << " x " << scale;
  }
}

TEST(TableBoundary, ClockwiseTablesAreRejected) {
  for (const Table& t : all_presets()) {
    const Caught c = invalid_table(reversed(t));
    EXPECT_EQ(c.field, "cushions") << t.name << ": " << c.message;
    EXPECT_TRUE(contains(c.message, "clockwise")) << c.message;
    EXPECT_TRUE(contains(c.message, "allowed > 0")) << c.message;
  }
}

TEST(TableBoundary, OpenTablesNameTheSegmentAfterWhichTheGapIs) {
  Table pool = pool_table_9ft();
  pool.cushions.erase(pool.cushions.begin() + 2);  // the bottom nose between the first two pockets
  Caught c = invalid_table(pool);
  EXPECT_EQ(c.field, "cushions[1].end") << c.message;
  EXPECT_TRUE(contains(c.message, "cushions[1].end = (")) << c.message;
  EXPECT_TRUE(contains(c.message, "the boundary is open")) << c.message;
  Table carom = carom_table_10ft();
  carom.cushions.erase(carom.cushions.begin() + 1);
  EXPECT_EQ(invalid_table(carom).field, "cushions[0].end");
  // A segment given end to start is named as such.
  carom = carom_table_10ft();
  std::swap(carom.cushions[2].start, carom.cushions[2].end);
  c = invalid_table(carom);
  EXPECT_EQ(c.field, "cushions[2]") << c.message;
  EXPECT_TRUE(contains(c.message, "end to start")) << c.message;
  // A nose end moved off its jaw by 1 mm.
  pool = pool_table_9ft();
  pool.cushions[2].end.x -= 1e-3;
  c = invalid_table(pool);
  EXPECT_EQ(c.field, "cushions[2].end") << c.message;
  EXPECT_TRUE(contains(c.message, "the nearest jaw, jaws[2]")) << c.message;
  // Within the tolerance it is still closed.
  pool = pool_table_9ft();
  pool.cushions[2].end.x -= 0.5 * kBoundaryTolerance;
  EXPECT_EQ(invalid_table(pool).field, "accepted");
}

TEST(TableBoundary, TheReproducerOfAnOpenTableIsRejectedByJsonPath) {
  // shared/repro/open_table_internal_error.json: the pool table's facings
  // and jaws without the nose segments between the pockets.
  Table facings_only = pool_table_9ft();
  std::vector<CushionSegment> kept;
  for (std::size_t i = 0; i < facings_only.cushions.size(); ++i)
    if (i % 3 != 2) kept.push_back(facings_only.cushions[i]);
  facings_only.cushions = kept;
  const std::string text = table_to_json(facings_only);
  const Caught c = catch_invalid([&] { table_from_json(text); });
  EXPECT_EQ(c.field, "table.cushions[1].end") << c.message;
  EXPECT_TRUE(contains(c.message, "table.cushions[1].end = (")) << c.message;
  EXPECT_EQ(catch_invalid([&] { table_from_json(text, "scenario.table"); }).field, "scenario.table.cushions[1].end");
}

TEST(TableBoundary, SelfIntersectingTableIsRejected) {
  // A pentagram: every corner turns left, the area is positive, but the
  // segments cross.
  Table t = carom_table_10ft();
  t.length = 2.0;
  t.width = 1.0;
  t.diamonds.clear();
  t.cushions.clear();
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) {
    const double a = std::numbers::pi / 2 + k * 4.0 * std::numbers::pi / 5.0;
    star.push_back({1.0 + 0.45 * std::cos(a), 0.5 + 0.45 * std::sin(a)});
  }
  for (std::size_t k = 0; k < 5; ++k) t.cushions.push_back({star[k], star[(k + 1) % 5], 0.037, {}});
  const Caught c = invalid_table(t);
  EXPECT_EQ(c.field, "cushions[2]") << c.message;
  EXPECT_TRUE(contains(c.message, "crosses cushions[0]")) << c.message;
}

TEST(TableBoundary, ConvexCornerNeedsAJaw) {
  // An L-shaped table: the inner corner at (1, 0.5) juts into the playing area.
  Table t = carom_table_10ft();
  t.length = 2.0;
  t.width = 1.0;
  t.diamonds.clear();
  const std::vector<Vec2> v{{0, 0}, {2, 0}, {2, 0.5}, {1, 0.5}, {1, 1}, {0, 1}};
  t.cushions.clear();
  for (std::size_t k = 0; k < v.size(); ++k) t.cushions.push_back({v[k], v[(k + 1) % v.size()], 0.037, {}});
  EXPECT_EQ(invalid_table(t).field, "cushions[3].start") << invalid_table(t).message;
  // A triangle is fine (all corners turn left).
  t.cushions = {{{0, 0}, {2, 0}, 0.037, {}}, {{2, 0}, {1, 1}, 0.037, {}}, {{1, 1}, {0, 0}, 0.037, {}}};
  EXPECT_EQ(invalid_table(t).field, "accepted") << invalid_table(t).message;
}

TEST(TableBoundary, AJawOnThePlayingSideIsNamed) {
  // jaws[0] joins the last nose (left rail) to the first facing. Mirrored
  // across the chord between them it still passes through both ends but
  // bulges into the playing area instead of rounding the lip.
  Table t = pool_table_9ft();
  const Vec2 p = t.cushions.back().end, q = t.cushions[0].start;
  const Vec2 u = (q - p) / norm(q - p);
  const Vec2 c = t.jaws[0].centre - p;
  t.jaws[0].centre = p + 2.0 * dot(c, u) * u - c;
  ASSERT_NEAR(norm(t.jaws[0].centre - p), t.jaws[0].radius, 1e-12);
  ASSERT_NEAR(norm(t.jaws[0].centre - q), t.jaws[0].radius, 1e-12);
  const Caught caught = invalid_table(t);
  EXPECT_EQ(caught.field, "jaws[0]") << caught.message;
  EXPECT_TRUE(contains(caught.message, "not tangent")) << caught.message;
}

TEST(TableBoundary, EveryPocketMustBeReachable) {
  Table t = carom_table_10ft();
  t.pockets.push_back({"inside", {1.0, 0.7}, 0.05});  // a hole in the bed: reachable
  EXPECT_EQ(invalid_table(t).field, "accepted");
  t.pockets.push_back({"outside", {-0.3, 0.7}, 0.05});
  const Caught c = invalid_table(t);
  EXPECT_EQ(c.field, "pockets[1]") << c.message;
  EXPECT_TRUE(contains(c.message, "cannot be reached")) << c.message;
}

// ------------------------------------------------------------------ inside_playing_area

// The placement rule written out here, without inside_playing_area: on the
// rectangle, clear of every segment and jaw, not over a hole.
bool fits_by_clearance(const Table& t, Vec2 p) {
  if (p.x < 0 || p.x > t.length || p.y < 0 || p.y > t.width) return false;
  for (const Pocket& pocket : t.pockets)
    if (norm(p - pocket.centre) <= pocket.radius) return false;
  return clearance(t, p) >= 0.0;
}

TEST(InsidePlayingArea, EveryPlaceablePositionIsInside) {
  std::vector<Table> tables = all_presets();
  const std::vector<Table> more = parametric_tables();
  tables.insert(tables.end(), more.begin(), more.begin() + 4);
  for (const Table& t : tables) {
    std::size_t placeable = 0;
    for (double x = 0.0; x <= t.length; x += 0.005) {
      for (double y = 0.0; y <= t.width; y += 0.005) {
        if (!fits_by_clearance(t, {x, y})) continue;
        ++placeable;
        ASSERT_TRUE(inside_playing_area(t, {x, y})) << t.name << " (" << x << ", " << y << ")";
        ASSERT_TRUE(ball_on_table(t, {x, y})) << t.name << " (" << x << ", " << y << ")";
      }
    }
    EXPECT_GT(placeable, 50000u) << t.name;
  }
}

TEST(InsidePlayingArea, PositionsBeyondTheCushionsAreOutside) {
  for (const Table& t : all_presets()) {
    for (Vec2 p : {Vec2{t.length / 4, -1e-3}, Vec2{t.length / 4, t.width + 1e-3}, Vec2{-1e-3, t.width / 2},
                   Vec2{t.length + 0.01, 0.3 * t.width}, Vec2{t.length / 3, -0.2}, Vec2{-0.5, -0.5}}) {
      EXPECT_FALSE(inside_playing_area(t, p)) << t.name << " (" << p.x << ", " << p.y << ")";
      EXPECT_FALSE(ball_on_table(t, p)) << t.name;
    }
    // The margin widens the area by that much.
    EXPECT_TRUE(inside_playing_area(t, {t.length / 4, -1e-3}, 2e-3)) << t.name;
    EXPECT_FALSE(inside_playing_area(t, {t.length / 4, -1e-3}, 0.5e-3)) << t.name;
  }
  // Behind the lips: the jaws' centres are in the cushion.
  for (const Table& t : pocketed_presets()) {
    for (const JawArc& j : t.jaws) EXPECT_FALSE(inside_playing_area(t, j.centre)) << t.name;
  }
  // A triangular table inside its rectangle: the rectangle's corner beyond
  // the hypotenuse, far from every segment, is outside and not placeable.
  Table tri = carom_table_10ft();
  tri.length = 2.0;
  tri.width = 1.0;
  tri.diamonds.clear();
  tri.cushions = {{{0, 0}, {2, 0}, 0.037, {}}, {{2, 0}, {1, 1}, 0.037, {}}, {{1, 1}, {0, 0}, 0.037, {}}};
  ASSERT_NO_THROW(validate(tri));
  EXPECT_FALSE(inside_playing_area(tri, {0.1, 0.9}));
  EXPECT_FALSE(ball_on_table(tri, {0.1, 0.9}));
  EXPECT_TRUE(inside_playing_area(tri, {1.0, 0.5}));
  EXPECT_TRUE(ball_on_table(tri, {1.0, 0.5}));
}

TEST(InsidePlayingArea, PocketThroatsAreInside) {
  for (const Table& t : pocketed_presets()) {
    for (const Pocket& p : t.pockets) {
      // From the pocket's site (the corner, or the rail's midpoint) down the
      // axis to the capture circle's centre: between the facings all along.
      // (Starting 0.1 m in front of it, on the playing surface.)
      const Vec2 site = pocket_site(t, p);
      const Vec2 start = site - 0.1 * (p.centre - site) / norm(p.centre - site);
      std::size_t outside_circle = 0;
      for (int i = 0; i <= 200; ++i) {
        const Vec2 q = start + (i / 200.0) * (p.centre - start);
        EXPECT_TRUE(inside_playing_area(t, q)) << t.name << " " << p.name << " (" << q.x << ", " << q.y << ")";
        outside_circle += !in_pocket(p, q);
      }
      EXPECT_GT(outside_circle, 60u) << t.name << " " << p.name << ": the throat, not only the circle, is tested";
      // Beside the axis, half-way to a facing, at the depth of the site.
      const Vec2 axis = (p.centre - site) / norm(p.centre - site);
      const Vec2 q = site + 0.5 * p.radius * perp(axis) + 0.2 * norm(p.centre - site) * axis;
      EXPECT_TRUE(inside_playing_area(t, q)) << t.name << " " << p.name;
    }
  }
}

// ------------------------------------------------------------------ JSON

TEST(TableJson, RoundTripIsExact) {
  for (const Table& t : all_presets()) {
    const std::string text = table_to_json(t);
    const Table back = table_from_json(text);
    EXPECT_EQ(back, t) << t.name;
    EXPECT_EQ(table_to_json(back), text);
  }
  // Awkward numbers survive too.
  Table t = carom_table_10ft();
  t.cushions[0].start.x = 0.1 + 0.2;  // 0.30000000000000004
  t.cushions[3].end.x = 0.1 + 0.2;    // the corner moves with it: still a closed boundary
  t.ball.mass = 1.0 / 3.0;
  EXPECT_EQ(table_from_json(table_to_json(t)), t);
}

TEST(TableJson, PresetForm) {
  EXPECT_EQ(table_from_json(R"({"preset": "pool_9ft"})"), pool_table_9ft());
  EXPECT_EQ(table_from_json(R"({"preset": "snooker_12ft"})"), snooker_table_12ft());
  EXPECT_EQ(table_from_json(R"({"preset": "carom_10ft"})"), carom_table_10ft());
  // Overrides rebuild the geometry.
  const Table eight = table_from_json(R"({"preset": "pool_9ft", "name": "8 ft", "length": 2.3368, "width": 1.1684,
                                          "corner_pockets": {"mouth": 0.12}})");
  EXPECT_EQ(eight.name, "8 ft");
  EXPECT_EQ(eight.length, 2.3368);
  EXPECT_NEAR(eight.pockets[1].centre.x, 2.3368 / 2, kTol);
  TableSpec s = pool_table_9ft_spec();
  s.name = "8 ft";
  s.length = 2.3368;
  s.width = 1.1684;
  s.corner_pockets.mouth = 0.12;
  EXPECT_EQ(eight, build_table(s));
  // A new ball radius carries the cushion height along unless it is given.
  const Table big = table_from_json(R"({"preset": "snooker_12ft", "ball": {"radius": 0.028}})");
  EXPECT_NEAR(big.cushions[0].contact_height, 1.4 * 0.028, kTol);
  EXPECT_EQ(big.ball.mass, snooker_table_12ft().ball.mass);
  const Table high =
      table_from_json(R"({"preset": "snooker_12ft", "ball": {"radius": 0.028}, "cushion_height": 0.04})");
  EXPECT_NEAR(high.cushions[0].contact_height, 0.04, kTol);
}

TEST(TableJson, FullFormDefaults) {
  const Table t = table_from_json(R"({"length": 2, "width": 1, "ball": {"mass": 0.2, "radius": 0.03},
    "cushions": [{"start": [0, 0], "end": [2, 0], "contact_height": 0.04},
                 {"start": [2, 0], "end": [2, 1], "contact_height": 0.04},
                 {"start": [2, 1], "end": [0, 1], "contact_height": 0.04},
                 {"start": [0, 1], "end": [0, 0], "contact_height": 0.04}]})");
  EXPECT_EQ(t.name, "custom");
  EXPECT_EQ(t.cushions.size(), 4u);
  EXPECT_TRUE(t.pockets.empty());
  EXPECT_TRUE(ball_on_table(t, {1, 0.5}));
}

Caught json_error(const std::string& text) {
  return catch_invalid([&] { table_from_json(text); });
}

std::string pool_full_with(const std::string& from, const std::string& to) {
  std::string text = table_to_json(pool_table_9ft());
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(TableJson, MalformedJsonGivesTheBytePosition) {
  const Caught c = json_error(R"({"preset": "pool_9ft",, })");
  EXPECT_EQ(c.field, "table");
  EXPECT_TRUE(contains(c.message, "malformed JSON at byte 23")) << c.message;
  EXPECT_EQ(json_error("").field, "table");
  EXPECT_EQ(json_error("[1, 2]").field, "table");  // not an object
  EXPECT_EQ(catch_invalid([] { table_from_json("{", "scenario.table"); }).field, "scenario.table");
}

TEST(TableJson, UnknownKeysAreRejectedByPath) {
  Caught c = json_error(R"({"preset": "pool_9ft", "colour": "green"})");
  EXPECT_EQ(c.field, "table.colour");
  EXPECT_TRUE(contains(c.message, "allowed")) << c.message;
  EXPECT_EQ(json_error(R"({"preset": "pool_9ft", "corner_pockets": {"mouth": 0.12, "depth": 1}})").field,
            "table.corner_pockets.depth");
  EXPECT_EQ(json_error(R"({"preset": "pool_9ft", "ball": {"colour": 1}})").field, "table.ball.colour");
  // Geometry keys do not mix with a preset.
  EXPECT_EQ(json_error(R"({"preset": "pool_9ft", "cushions": []})").field, "table.cushions");
  EXPECT_EQ(json_error(pool_full_with("\"contact_height\"", "\"colour\": 1, \"contact_height\"")).field,
            "table.cushions[0].colour");
  EXPECT_EQ(json_error(pool_full_with("\"diamonds\"", "\"sights\": [], \"diamonds\"")).field, "table.sights");
  EXPECT_EQ(json_error(R"({"preset": "croquet"})").field, "table.preset");
  EXPECT_EQ(json_error(R"({"preset": "carom_10ft", "side_pockets": {"mouth": 0.1}})").field, "table.side_pockets");
}

TEST(TableJson, BadNumbersAreRejectedByPathWithTheRange) {
  Caught c = json_error(R"({"preset": "pool_9ft", "length": -1})");
  EXPECT_EQ(c.field, "table.length");
  EXPECT_TRUE(contains(c.message, "table.length = -1 is outside (0, 10] m")) << c.message;
  c = json_error(R"({"preset": "pool_9ft", "width": 1e999})");
  EXPECT_EQ(c.field, "table.width");
  EXPECT_TRUE(contains(c.message, "not a finite number")) << c.message;
  c = json_error(R"({"preset": "pool_9ft", "length": "long"})");
  EXPECT_EQ(c.field, "table.length");
  EXPECT_TRUE(contains(c.message, "must be a number")) << c.message;
  EXPECT_EQ(json_error(R"({"preset": "pool_9ft", "length": null})").field, "table.length");
  EXPECT_EQ(json_error(R"({"preset": "pool_9ft", "ball": {"radius": -0.03}})").field, "table.ball.radius");
  EXPECT_EQ(json_error(R"({"preset": "pool_9ft", "side_pockets": {"shelf": -0.01}})").field,
            "table.side_pockets.shelf");
  EXPECT_EQ(json_error(R"({"preset": "pool_9ft", "corner_pockets": {"mouth": 0.03}})").field,
            "table.corner_pockets.mouth");
  // Full form: the pocket's radius, a point, a missing field.
  const std::string pockets = "\"pockets\": [";
  std::string text = table_to_json(pool_table_9ft());
  // Set pockets[2].radius to -1.
  std::size_t at = text.find(pockets);
  for (int i = 0; i < 3; ++i) at = text.find("\"radius\":", at + 1);
  const std::size_t value = at + std::string("\"radius\": ").size();
  const std::size_t stop = text.find_first_of("\n,}", value);
  text.replace(value, stop - value, "-1");
  c = json_error(text);
  EXPECT_EQ(c.field, "table.pockets[2].radius");
  EXPECT_TRUE(contains(c.message, "table.pockets[2].radius = -1 is outside (0, 0.2] m")) << c.message;
  EXPECT_EQ(json_error(pool_full_with("\"start\": [", "\"start\": [1e999, ")).field, "table.cushions[0].start[0]");
  EXPECT_EQ(json_error(pool_full_with("\"start\": [", "\"start\": [1, ")).field, "table.cushions[0].start");
  EXPECT_EQ(json_error(R"({"length": 2, "width": 1, "ball": {"mass": 0.2, "radius": 0.03}})").field,
            "table.cushions");
  EXPECT_EQ(json_error(R"({"length": 2, "width": 1, "ball": {"mass": 0.2}, "cushions": []})").field,
            "table.ball.radius");
}

// ------------------------------------------------------------------ names

namespace names {

const char* kRails[6] = {"bottom rail, left of the side pocket", "bottom rail, right of the side pocket",
                         "right rail", "top rail, right of the side pocket", "top rail, left of the side pocket",
                         "left rail"};

// The documented scheme, checked against the geometry: each name says where
// its part is.
void expect_pocket_table_names(const Table& t) {
  ASSERT_EQ(t.cushions.size(), 18u);
  ASSERT_EQ(t.jaws.size(), 12u);
  const double L = t.length, W = t.width;
  std::vector<std::string> all;
  for (std::size_t i = 0; i < t.cushions.size(); ++i) all.push_back(t.cushions[i].name);
  for (std::size_t i = 0; i < t.jaws.size(); ++i) all.push_back(t.jaws[i].name);
  std::vector<std::string> sorted = all;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "names repeat";
  for (int rail = 0; rail < 6; ++rail) {
    const CushionSegment& s = t.cushions[static_cast<std::size_t>(3 * rail + 2)];
    EXPECT_EQ(s.name, kRails[rail]);
    const Vec2 mid = 0.5 * (s.start + s.end);
    if (contains(s.name, "bottom rail")) { EXPECT_EQ(mid.y, 0.0) << s.name; }
    if (contains(s.name, "top rail")) { EXPECT_EQ(mid.y, W) << s.name; }
    if (contains(s.name, "right rail")) { EXPECT_EQ(mid.x, L) << s.name; }
    if (contains(s.name, "left rail")) { EXPECT_EQ(mid.x, 0.0) << s.name; }
    if (contains(s.name, "left of the side")) { EXPECT_LT(mid.x, L / 2) << s.name; }
    if (contains(s.name, "right of the side")) { EXPECT_GT(mid.x, L / 2) << s.name; }
  }
  for (std::size_t k = 0; k < 6; ++k) {
    const Pocket& p = t.pockets[k];
    const bool side = contains(p.name, "side");
    for (std::size_t m = 0; m < 2; ++m) {
      const JawArc& jaw = t.jaws[2 * k + m];
      const CushionSegment& facing = t.cushions[3 * k + m];
      const std::string prefix = p.name + " pocket, ";
      ASSERT_EQ(jaw.name.rfind(prefix, 0), 0u) << jaw.name;
      const std::string which = jaw.name.substr(prefix.size(), jaw.name.size() - prefix.size() - 4);
      EXPECT_EQ(jaw.name, prefix + which + " jaw");
      EXPECT_EQ(facing.name, prefix + which + " facing");
      // The facing starts or ends on its jaw's circle.
      EXPECT_NEAR(std::min(norm(facing.start - jaw.centre), norm(facing.end - jaw.centre)), jaw.radius, 1e-9)
          << facing.name;
      const Vec2 d = jaw.centre - p.centre;
      if (side) {
        // Left and right of the side pocket, as drawn.
        if (which == "left") { EXPECT_LT(d.x, 0.0) << jaw.name; }
        else if (which == "right") { EXPECT_GT(d.x, 0.0) << jaw.name; }
        else { ADD_FAILURE() << jaw.name; }
      } else {
        // The rail the jaw ends: the bottom rail's jaw lies along x from the corner.
        if (which == "bottom" || which == "top") { EXPECT_GT(std::abs(d.x), std::abs(d.y)) << jaw.name; }
        else if (which == "left" || which == "right") { EXPECT_LT(std::abs(d.x), std::abs(d.y)) << jaw.name; }
        else { ADD_FAILURE() << jaw.name; }
        if (which == "bottom") { EXPECT_LT(jaw.centre.y, W / 2) << jaw.name; }
        if (which == "top") { EXPECT_GT(jaw.centre.y, W / 2) << jaw.name; }
        if (which == "left") { EXPECT_LT(jaw.centre.x, L / 2) << jaw.name; }
        if (which == "right") { EXPECT_GT(jaw.centre.x, L / 2) << jaw.name; }
        EXPECT_TRUE(contains(p.name, which)) << jaw.name << ": a corner pocket's jaw is on one of its two rails";
      }
    }
  }
}

}  // namespace names

TEST(TableNames, PoolAndSnookerPresetsFollowTheScheme) {
  names::expect_pocket_table_names(pool_table_9ft());
  names::expect_pocket_table_names(snooker_table_12ft());
  TableSpec small = pool_table_9ft_spec();
  small.length = 2.0;
  small.width = 1.0;
  names::expect_pocket_table_names(build_table(small));
  // A few names spelled out, as the README lists them.
  const Table t = pool_table_9ft();
  EXPECT_EQ(t.jaws[0].name, "bottom-left pocket, left jaw");
  EXPECT_EQ(t.jaws[1].name, "bottom-left pocket, bottom jaw");
  EXPECT_EQ(t.jaws[2].name, "bottom-side pocket, left jaw");
  EXPECT_EQ(t.jaws[3].name, "bottom-side pocket, right jaw");
  EXPECT_EQ(t.jaws[8].name, "top-side pocket, right jaw");
  EXPECT_EQ(t.cushions[1].name, "bottom-left pocket, bottom facing");
  EXPECT_EQ(t.cushions[2].name, "bottom rail, left of the side pocket");
}

TEST(TableNames, CaromRailsAreNamedByRail) {
  const Table t = carom_table_10ft();
  ASSERT_EQ(t.cushions.size(), 4u);
  EXPECT_EQ(t.cushions[0].name, "bottom rail");
  EXPECT_EQ(t.cushions[1].name, "right rail");
  EXPECT_EQ(t.cushions[2].name, "top rail");
  EXPECT_EQ(t.cushions[3].name, "left rail");
  EXPECT_EQ(t.cushions[0].start.y, 0.0);
  EXPECT_EQ(t.cushions[1].start.x, t.length);
}

TEST(TableNames, JsonNamesAreKeptAndMissingOnesDefaultToTheirPath) {
  const Table t = table_from_json(R"({"length": 2, "width": 1, "ball": {"mass": 0.2, "radius": 0.03},
    "cushions": [{"name": "south", "start": [0, 0], "end": [2, 0], "contact_height": 0.04},
                 {"start": [2, 0], "end": [2, 1], "contact_height": 0.04},
                 {"name": "north \u00e9", "start": [2, 1], "end": [0, 1], "contact_height": 0.04},
                 {"start": [0, 1], "end": [0, 0], "contact_height": 0.04}],
    "jaws": [{"centre": [1, 0.5], "radius": 0.05, "contact_height": 0.04},
             {"name": "post", "centre": [1.5, 0.5], "radius": 0.05, "contact_height": 0.04}]})");
  EXPECT_EQ(t.cushions[0].name, "south");
  EXPECT_EQ(t.cushions[1].name, "cushions[1]");
  EXPECT_EQ(t.cushions[2].name, "north \xc3\xa9");
  EXPECT_EQ(t.cushions[3].name, "cushions[3]");
  EXPECT_EQ(t.jaws[0].name, "jaws[0]");
  EXPECT_EQ(t.jaws[1].name, "post");
  EXPECT_EQ(table_from_json(table_to_json(t)), t);
  EXPECT_TRUE(contains(table_to_json(t), R"("name": "cushions[1]")"));
}

TEST(TableNames, UnnamedPartsInCppUseTheirPath) {
  Table t = carom_table_10ft();
  t.cushions[2].name.clear();
  EXPECT_NO_THROW(validate(t));
  EXPECT_EQ(cushion_name(t, 2), "cushions[2]");
  EXPECT_EQ(cushion_name(t, 1), "right rail");
  const Table back = table_from_json(table_to_json(t));
  EXPECT_EQ(back.cushions[2].name, "cushions[2]");
  name_parts(t);
  EXPECT_EQ(back, t);
  Table pool = pool_table_9ft();
  pool.jaws[4].name.clear();
  EXPECT_EQ(jaw_name(pool, 4), "jaws[4]");
}

TEST(TableNames, BadNamesAreRejectedByPath) {
  const std::string ok64(64, 'x');
  EXPECT_EQ(json_error(pool_full_with(R"("name": "bottom-left pocket, left facing")", "\"name\": \"" + ok64 + "\"")).field,
            "accepted");
  Caught c = json_error(pool_full_with(R"("name": "bottom-left pocket, left facing")", "\"name\": \"" + ok64 + "y\""));
  EXPECT_EQ(c.field, "table.cushions[0].name");
  EXPECT_TRUE(contains(c.message, "1 to 64 bytes")) << c.message;
  c = json_error(pool_full_with(R"("name": "bottom-left pocket, left facing")", R"("name": "")"));
  EXPECT_EQ(c.field, "table.cushions[0].name");
  EXPECT_TRUE(contains(c.message, "must not be empty")) << c.message;
  c = json_error(pool_full_with(R"("name": "bottom-left pocket, left facing")", R"("name": "tab\there")"));
  EXPECT_EQ(c.field, "table.cushions[0].name");
  EXPECT_TRUE(contains(c.message, "control characters")) << c.message;
  c = json_error(pool_full_with(R"("name": "bottom-left pocket, left facing")", R"("name": 7)"));
  EXPECT_EQ(c.field, "table.cushions[0].name");
  // Unique across cushions and jaws: the later one is named.
  c = json_error(pool_full_with(R"("name": "bottom-left pocket, left jaw")", R"("name": "left rail")"));
  EXPECT_EQ(c.field, "table.jaws[0].name");
  EXPECT_TRUE(contains(c.message, "repeats the name of table.cushions[17]")) << c.message;
  // A given name may not take an unnamed part's default.
  Table t = carom_table_10ft();
  t.cushions[3].name.clear();
  t.cushions[0].name = "cushions[3]";
  c = catch_invalid([&] { validate(t); });
  EXPECT_EQ(c.field, "cushions[3].name");
  // In C++ too.
  Table p = pool_table_9ft();
  p.jaws[2].name = std::string("bell\x07");
  EXPECT_EQ(catch_invalid([&] { validate(p); }).field, "jaws[2].name");
}

}  // namespace
}  // namespace cueball
