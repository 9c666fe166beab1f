// Placing balls (placement.hpp): room, free spots, regions, spotting.
#include "cueball/table/placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cueball/table/rack.hpp"

namespace cueball {

namespace {

// A spotted ball may overlap a ball it is frozen to by this much (round-off
// of the contact distance; the simulator accepts 1e-9 m).
constexpr double kFrozenRoundOff = 1e-12;

// The x-interval of the line y = line_y in which a centre comes closer than
// `reach` to the centre c; empty (lo > hi) when the line passes farther.
struct Blocked {
  double lo = 1.0, hi = 0.0;
};
Blocked blocked_on_line(Vec2 c, double line_y, double reach) {
  const double dy = std::abs(c.y - line_y);
  if (!(dy < reach)) return {};
  const double half = std::sqrt(reach * reach - dy * dy);
  return {c.x - half, c.x + half};
}

}  // namespace

Vec2 foot_spot(const Table& table) { return {0.75 * table.length, 0.5 * table.width}; }

double head_string_x(const Table& table) { return 0.25 * table.length; }

double long_string_y(const Table& table) { return 0.5 * table.width; }

double clearance(const Table& t, Vec2 p, double radius) {
  double c = std::min({p.x, t.length - p.x, p.y, t.width - p.y});
  for (const CushionSegment& s : t.cushions)
    c = std::min(c, distance_to_segment(s, p) - cushion_contact_distance(s.contact_height, radius));
  for (const JawArc& j : t.jaws) c = std::min(c, norm(p - j.centre) - jaw_contact_distance(j, radius));
  for (const Pocket& q : t.pockets) c = std::min(c, norm(p - q.centre) - q.radius);
  return c;
}

double ball_gap(Vec2 p, const std::vector<Vec2>& balls, double radius) {
  double g = std::numeric_limits<double>::infinity();
  for (const Vec2 b : balls) g = std::min(g, norm(p - b) - 2.0 * radius);
  return g;
}

bool is_free_spot(const Table& table, const std::vector<Vec2>& balls, Vec2 p, double radius, double margin) {
  return ball_on_table(table, p, radius) && clearance(table, p, radius) >= margin && ball_gap(p, balls, radius) >= 0.0;
}

const char* to_string(PlacementRegion::Kind kind) {
  switch (kind) {
    case PlacementRegion::Kind::anywhere: return "anywhere";
    case PlacementRegion::Kind::behind_head_string: return "behind_head_string";
    case PlacementRegion::Kind::inside_d: return "inside_d";
    case PlacementRegion::Kind::rectangle: return "rectangle";
  }
  return "?";
}

std::optional<PlacementRegion::Kind> placement_region_from_string(std::string_view name) {
  using Kind = PlacementRegion::Kind;
  for (const Kind k : {Kind::anywhere, Kind::behind_head_string, Kind::inside_d, Kind::rectangle})
    if (name == to_string(k)) return k;
  if (name == "kitchen") return Kind::behind_head_string;
  if (name == "d") return Kind::inside_d;
  return std::nullopt;
}

std::string placement_region_names() { return "anywhere, behind_head_string (kitchen), inside_d (d)"; }

bool in_region(const Table& table, const PlacementRegion& r, Vec2 p) {
  constexpr double tol = kPlacementTolerance;
  switch (r.kind) {
    case PlacementRegion::Kind::anywhere: return true;
    case PlacementRegion::Kind::behind_head_string: return p.x <= head_string_x(table) + tol;
    case PlacementRegion::Kind::inside_d: {
      const SnookerSpots s = snooker_spots(table);
      return p.x <= s.baulk_line_x + tol && norm(p - s.brown) <= s.d_radius + tol;
    }
    case PlacementRegion::Kind::rectangle:
      return p.x >= r.x_min - tol && p.x <= r.x_max + tol && p.y >= r.y_min - tol && p.y <= r.y_max + tol;
  }
  return false;
}

PlacementRegion bounding_rectangle(const Table& table, const PlacementRegion& r) {
  PlacementRegion box{PlacementRegion::Kind::rectangle, 0.0, table.length, 0.0, table.width};
  switch (r.kind) {
    case PlacementRegion::Kind::anywhere: break;
    case PlacementRegion::Kind::behind_head_string: box.x_max = head_string_x(table); break;
    case PlacementRegion::Kind::inside_d: {
      const SnookerSpots s = snooker_spots(table);
      box = {PlacementRegion::Kind::rectangle, s.baulk_line_x - s.d_radius, s.baulk_line_x, s.brown.y - s.d_radius,
             s.brown.y + s.d_radius};
      break;
    }
    case PlacementRegion::Kind::rectangle: box = r; break;
  }
  return box;
}

std::optional<Vec2> random_free_spot(const Table& table, const std::vector<Vec2>& balls, double radius,
                                     RandomStream& rng, int attempts, const PlacementRegion& region, double margin) {
  const PlacementRegion box = bounding_rectangle(table, region);
  for (int k = 0; k < attempts; ++k) {
    const double x = rng.uniform(box.x_min, box.x_max);
    const Vec2 p{x, rng.uniform(box.y_min, box.y_max)};
    if (in_region(table, region, p) && is_free_spot(table, balls, p, radius, margin)) return p;
  }
  return std::nullopt;
}

std::optional<Vec2> spot_on_long_string(const Table& table, const std::vector<Vec2>& object_balls,
                                        std::optional<Vec2> cue_ball, double radius) {
  const double y = long_string_y(table), x0 = foot_spot(table).x;
  std::vector<Blocked> blocked;
  for (const Vec2 b : object_balls) blocked.push_back(blocked_on_line(b, y, 2.0 * radius));
  if (cue_ball) blocked.push_back(blocked_on_line(*cue_ball, y, 2.0 * radius + kSpottingGapToCue));
  // The nearest free place on either side is the foot spot or the end of
  // an interval in the way (frozen to its ball).
  const auto fits = [&](double x) {
    for (const Blocked& b : blocked)
      if (x > b.lo + kFrozenRoundOff && x < b.hi - kFrozenRoundOff) return false;
    const Vec2 p{x, y};
    return ball_on_table(table, p, radius) && clearance(table, p, radius) >= 0.0;
  };
  std::vector<double> behind{x0}, in_front;
  for (const Blocked& b : blocked) {
    if (b.lo > b.hi) continue;
    if (b.hi >= x0) behind.push_back(b.hi);
    if (b.lo <= x0) in_front.push_back(b.lo);
  }
  std::sort(behind.begin(), behind.end());
  std::sort(in_front.begin(), in_front.end(), std::greater<>());
  for (const double x : behind)
    if (fits(x)) return Vec2{x, y};
  for (const double x : in_front)
    if (fits(x)) return Vec2{x, y};
  return std::nullopt;
}

}  // namespace cueball
