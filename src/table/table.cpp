// Table geometry, presets and validation (see include/cueball/table/table.hpp;
// its JSON: src/io/table_json.cpp).
//
// Sources for the preset numbers:
// - WPA Equipment Specifications ("Playing Surface", "Pocket Openings and
//   Measurements", "Rail and Cushion", "Sights"), as quoted in
//   shared/spec/equipment-and-pitfalls.md and e.g.
//   http://www.billiardsforum.com/pool-tables/official-pool-table-pocket-size
// - BCA Pocket Specifications, shelf depths:
//   https://www.classicbilliards.net/cushions-supplies/bca-pocket-specs.html
// - WPBSA Rules of Snooker, section 1 "The Standard Table" (3569 x 1778 mm;
//   pocket openings "shall conform to the templates authorised by the
//   WPBSA", which are not published).
// - pooltool (ekiefl/pooltool), pooltool/objects/table/specs.py,
//   SnookerTableSpecs: the modelling values used here for the snooker pockets.
// - UMB carom table 2.84 x 1.42 m, cushion height 37 mm, ball 61-61.5 mm,
//   205-220 g (shared/spec/equipment-and-pitfalls.md).
// - Mathavan, Jackson & Parkin 2010: snooker cushion contact height 7R/5.
#include "cueball/table/table.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "table/table_detail.hpp"

#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

constexpr double kInch = 0.0254;                // m, exact
constexpr double kMaxTableSize = 10.0;          // m
constexpr double kMaxRoundRadius = 0.2;         // m, jaw and pocket radii
constexpr double kPointMargin = 0.5;            // m, points within this of the playing surface
constexpr double kMinSegmentLength = 1e-6;      // m
constexpr double kMaxMouth = 0.5;               // m
constexpr double kMaxShelf = 0.2;               // m
constexpr double kMinCutAngle = 90.0;           // deg
constexpr double kMaxCutAngle = 170.0;          // deg
constexpr double kMaxDiamondOffset = 0.5;       // m

// ------------------------------------------------------------------ messages

std::string format_point(Vec2 p) {
  std::ostringstream os;
  os.precision(10);
  os << '(' << p.x << ", " << p.y << ')';
  return os.str();
}

std::string join(const std::string& prefix, const std::string& field) {
  if (prefix.empty()) return field;
  if (!field.empty() && field.front() == '[') return prefix + field;
  return prefix + "." + field;
}

[[noreturn]] void fail(const std::string& field, const std::string& message) { throw InvalidArgument(field, message); }

struct Range {
  double lo;
  double hi;
  bool lo_open;
  bool hi_open;
  const char* unit;

  bool contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    std::string t = std::string(lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) +
                    (hi_open ? ")" : "]");
    if (*unit != '\0') t += std::string(" ") + unit;
    return t;
  }
};

void check(const std::string& field, double value, const Range& range, const std::string& meaning = {}) {
  if (range.contains(value)) return;
  std::string m = field + " = " + format_number(value) +
                  (std::isfinite(value) ? " is outside " : " is not a finite number; allowed ") + range.text();
  if (!meaning.empty()) m += " (" + meaning + ")";
  fail(field, m);
}

Range closed(double lo, double hi, const char* unit) { return {lo, hi, false, false, unit}; }
Range positive_up_to(double hi, const char* unit) { return {0.0, hi, true, false, unit}; }
Range contact_height_range(double radius) { return {radius, 2.0 * radius, true, true, "m"}; }

void check_point(const std::string& field, Vec2 p, double length, double width) {
  if (!is_finite(p)) fail(field, field + " = " + format_point(p) + " is not a finite point");
  const double x_lo = -kPointMargin, x_hi = length + kPointMargin;
  const double y_lo = -kPointMargin, y_hi = width + kPointMargin;
  if (p.x < x_lo || p.x > x_hi || p.y < y_lo || p.y > y_hi) {
    fail(field, field + " = " + format_point(p) + " is outside [" + format_number(x_lo) + ", " + format_number(x_hi) +
                    "] x [" + format_number(y_lo) + ", " + format_number(y_hi) +
                    "] m (within 0.5 m of the playing surface)");
  }
}

std::string indexed(const char* array, std::size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

// ------------------------------------------------------------------ validation

void validate_ball(const BallParameters& ball, const std::string& prefix) {
  check(join(prefix, "ball.mass"), ball.mass, closed(kMassRange.min, kMassRange.max, kMassRange.unit),
        kMassRange.meaning);
  check(join(prefix, "ball.radius"), ball.radius, closed(kRadiusRange.min, kRadiusRange.max, kRadiusRange.unit),
        kRadiusRange.meaning);
}

void validate_size(double length, double width, const std::string& prefix) {
  check(join(prefix, "length"), length, positive_up_to(kMaxTableSize, "m"), "playing surface, cushion nose to nose");
  check(join(prefix, "width"), width, positive_up_to(kMaxTableSize, "m"), "playing surface, cushion nose to nose");
}

// Exactly the rules of validate_table() below, as numbers only: the
// simulator validates its table on every call, and building each element's
// field name there costs more than the checks. The detailed pass runs only
// when this finds something wrong, and it names the field.
bool table_plainly_valid(const Table& t) {
  const auto in_bounds = [&](Vec2 p) {
    return is_finite(p) && p.x >= -kPointMargin && p.x <= t.length + kPointMargin && p.y >= -kPointMargin &&
           p.y <= t.width + kPointMargin;
  };
  const Range size = positive_up_to(kMaxTableSize, "m");
  if (t.name.empty() || !size.contains(t.length) || !size.contains(t.width)) return false;
  if (!closed(kMassRange.min, kMassRange.max, "").contains(t.ball.mass) ||
      !closed(kRadiusRange.min, kRadiusRange.max, "").contains(t.ball.radius))
    return false;
  const Range height = contact_height_range(t.ball.radius);
  const Range round = positive_up_to(kMaxRoundRadius, "m");
  if (t.cushions.size() < 3) return false;
  for (const CushionSegment& c : t.cushions) {
    if (!in_bounds(c.start) || !in_bounds(c.end) || !(norm(c.end - c.start) >= kMinSegmentLength) ||
        !height.contains(c.contact_height))
      return false;
  }
  for (const JawArc& j : t.jaws)
    if (!in_bounds(j.centre) || !round.contains(j.radius) || !height.contains(j.contact_height)) return false;
  for (std::size_t i = 0; i < t.pockets.size(); ++i) {
    const Pocket& p = t.pockets[i];
    if (p.name.empty() || !in_bounds(p.centre) || !round.contains(p.radius)) return false;
    for (std::size_t k = 0; k < i; ++k)
      if (t.pockets[k].name == p.name) return false;
  }
  for (Vec2 d : t.diamonds)
    if (!in_bounds(d)) return false;
  return true;
}

// ------------------------------------------------------------------ closed boundary

void validate_fields(const Table& t, const std::string& prefix);

Vec2 direction(const CushionSegment& s) { return (s.end - s.start) / norm(s.end - s.start); }

bool on_circle(Vec2 p, Vec2 centre, double radius) {
  const Vec2 d = p - centre;
  const double reach = radius + kBoundaryTolerance;
  if (!(dot(d, d) <= reach * reach)) return false;  // cheap rejection of the jaws far away
  return std::abs(norm(d) - radius) <= kBoundaryTolerance;
}

// Signed area of the polygon through every segment's start and end, in order
// (shoelace formula).
double signed_area(const Table& t) {
  double twice = 0.0;
  const std::size_t n = t.cushions.size();
  for (std::size_t i = 0; i < n; ++i) {
    const CushionSegment& s = t.cushions[i];
    const Vec2 next = t.cushions[(i + 1) % n].start;
    twice += cross(s.start, s.end) + cross(s.end, next);
  }
  return 0.5 * twice;
}

// Crossing-number test over the same polygon (edges: each segment, then the
// join from its end to the next start).
bool inside_polygon(const Table& t, Vec2 p) {
  bool inside = false;
  const auto edge = [&](Vec2 a, Vec2 b) {
    if ((a.y > p.y) != (b.y > p.y)) {
      // Where the edge crosses the horizontal through p, compared without a
      // division: p.x < a.x + (p.y - a.y) (b.x - a.x) / (b.y - a.y).
      const double lhs = (p.x - a.x) * (b.y - a.y), rhs = (p.y - a.y) * (b.x - a.x);
      if (b.y > a.y ? lhs < rhs : lhs > rhs) inside = !inside;
    }
  };
  if (t.cushions.empty()) return false;
  Vec2 previous_end = t.cushions.back().end;
  for (const CushionSegment& c : t.cushions) {
    edge(previous_end, c.start);  // the join into this segment
    edge(c.start, c.end);
    previous_end = c.end;
  }
  return inside;
}

// Smallest distance between two segments that do not properly cross, or 0
// when they do.
double segment_gap(const CushionSegment& a, const CushionSegment& b) {
  // Far apart (their boxes, widened by the tolerance, do not meet): the usual case.
  const double slack = 2.0 * kBoundaryTolerance;
  if (std::max(a.start.x, a.end.x) + slack < std::min(b.start.x, b.end.x) ||
      std::max(b.start.x, b.end.x) + slack < std::min(a.start.x, a.end.x) ||
      std::max(a.start.y, a.end.y) + slack < std::min(b.start.y, b.end.y) ||
      std::max(b.start.y, b.end.y) + slack < std::min(a.start.y, a.end.y))
    return std::numeric_limits<double>::infinity();
  const double o1 = cross(a.end - a.start, b.start - a.start), o2 = cross(a.end - a.start, b.end - a.start);
  const double o3 = cross(b.end - b.start, a.start - b.start), o4 = cross(b.end - b.start, a.end - b.start);
  if (((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0)))
    return 0.0;
  return std::min({distance_to_segment(a, b.start), distance_to_segment(a, b.end), distance_to_segment(b, a.start),
                   distance_to_segment(b, a.end)});
}

enum class JoinKind { direct, jaw, pocket, open };

struct Join {
  JoinKind kind = JoinKind::open;
  std::size_t index = 0;  // the jaw or the pocket
};

Join find_join(const Table& t, std::size_t i) {
  const std::size_t n = t.cushions.size();
  const Vec2 p = t.cushions[i].end, q = t.cushions[(i + 1) % n].start;
  // A pocket first: two facings may also meet each other inside the hole.
  for (std::size_t k = 0; k < t.pockets.size(); ++k) {
    const Pocket& pocket = t.pockets[k];
    const double reach = pocket.radius + kBoundaryTolerance;
    const Vec2 dp = p - pocket.centre, dq = q - pocket.centre;
    if (dot(dp, dp) <= reach * reach && dot(dq, dq) <= reach * reach) return {JoinKind::pocket, k};
  }
  if (norm(p - q) <= kBoundaryTolerance) return {JoinKind::direct, 0};
  for (std::size_t j = 0; j < t.jaws.size(); ++j) {
    if (on_circle(p, t.jaws[j].centre, t.jaws[j].radius) && on_circle(q, t.jaws[j].centre, t.jaws[j].radius))
      return {JoinKind::jaw, j};
  }
  return {};
}

// The checks of validate(Table) beyond single fields (table.hpp). Numbers
// only until something fails: the simulator validates its table on every
// call.
void validate_boundary(const Table& t, const std::string& prefix) {
  const std::size_t n = t.cushions.size();
  const auto cushion = [&](std::size_t i) { return join(prefix, indexed("cushions", i)); };
  std::vector<Join> joins(n);
  // 1. Every end meets the next start.
  for (std::size_t i = 0; i < n; ++i) {
    joins[i] = find_join(t, i);
    if (joins[i].kind != JoinKind::open) continue;
    const std::size_t k = (i + 1) % n;
    const Vec2 p = t.cushions[i].end, q = t.cushions[k].start;
    if (norm(t.cushions[k].end - p) <= kBoundaryTolerance) {
      fail(cushion(k), cushion(k) + " runs end to start: its end " + format_point(t.cushions[k].end) + " meets " +
                           cushion(i) + ".end; every segment runs counter-clockwise, from where the previous one "
                           "ends, with the playing surface on its left");
    }
    // The jaw that comes nearest to joining them, if one is meant to.
    std::string hint;
    double best = 0.05;  // m: farther than this, no jaw is meant to join them
    for (std::size_t j = 0; j < t.jaws.size(); ++j) {
      const double off_p = std::abs(norm(p - t.jaws[j].centre) - t.jaws[j].radius);
      const double off_q = std::abs(norm(q - t.jaws[j].centre) - t.jaws[j].radius);
      if (std::max(off_p, off_q) < best) {
        best = std::max(off_p, off_q);
        hint = "; the nearest jaw, " + join(prefix, indexed("jaws", j)) + ", passes " + format_number(off_p) +
               " m from the end and " + format_number(off_q) + " m from the start";
      }
    }
    fail(cushion(i) + ".end",
         cushion(i) + ".end = " + format_point(p) + " is " + format_number(norm(q - p)) + " m from " + cushion(k) +
             ".start = " + format_point(q) + hint + ", allowed " + format_number(kBoundaryTolerance) +
             " m: the boundary is open there. The cushions must form a closed loop: each end meets the next "
             "segment's start directly, on a jaw arc tangent to both, or within a pocket's circle");
  }
  // 2. Counter-clockwise.
  const double area = signed_area(t);
  if (!(area > 0.0)) {
    fail(join(prefix, "cushions"),
         join(prefix, "cushions") + " run clockwise (the polygon through their ends has signed area " +
             format_number(area) + " m^2, allowed > 0): list them counter-clockwise seen from above, each with "
             "the playing surface on the left of start -> end");
  }
  // 3. Corners the ball cannot reach, jaws rounding convex ones.
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = (i + 1) % n;
    const CushionSegment& a = t.cushions[i];
    const CushionSegment& b = t.cushions[k];
    if (joins[i].kind == JoinKind::direct) {
      const double turn = cross(direction(a), direction(b));
      const bool left_or_straight = turn > 1e-9 || (turn >= -1e-9 && dot(direction(a), direction(b)) > 0.0);
      if (!left_or_straight) {
        fail(cushion(k) + ".start",
             cushion(k) + ".start = " + format_point(b.start) + " meets " + cushion(i) +
                 ".end at a corner that juts into the playing surface (the boundary turns right or back there); "
                 "such a corner needs a jaw arc tangent to both segments");
      }
    } else if (joins[i].kind == JoinKind::jaw) {
      const std::size_t j = joins[i].index;
      const JawArc& jaw = t.jaws[j];
      const Vec2 from_a = a.end - jaw.radius * inward_normal(a);
      const Vec2 from_b = b.start - jaw.radius * inward_normal(b);
      const double off = std::max(norm(jaw.centre - from_a), norm(jaw.centre - from_b));
      if (!(off <= kBoundaryTolerance)) {
        const std::string base = join(prefix, indexed("jaws", j));
        fail(base, base + " (centre " + format_point(jaw.centre) + ", radius " + format_number(jaw.radius) +
                       " m) joins " + cushion(i) + ".end and " + cushion(k) +
                       ".start but is not tangent to both with its centre behind them (in the cushion): the "
                       "centre should be at " + format_point(from_a) + " for " + cushion(i) + " and at " +
                       format_point(from_b) + " for " + cushion(k) + ", it is " + format_number(off) +
                       " m off (allowed " + format_number(kBoundaryTolerance) + " m)");
      }
    }
  }
  // 4. No crossings.
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t i = 0; i < k; ++i) {
      if (k == i + 1 || (i == 0 && k == n - 1)) continue;  // neighbours in the loop
      const double gap = segment_gap(t.cushions[i], t.cushions[k]);
      if (gap <= kBoundaryTolerance) {
        fail(cushion(k), cushion(k) + " (" + format_point(t.cushions[k].start) + " -> " +
                             format_point(t.cushions[k].end) + ") " + (gap == 0.0 ? "crosses " : "touches ") +
                             cushion(i) + ": the boundary must not intersect itself");
      }
    }
  }
  // 5. Every pocket reachable.
  for (std::size_t k = 0; k < t.pockets.size(); ++k) {
    bool joins_facings = false;
    for (const Join& j : joins) joins_facings = joins_facings || (j.kind == JoinKind::pocket && j.index == k);
    if (joins_facings || inside_polygon(t, t.pockets[k].centre)) continue;
    const std::string base = join(prefix, indexed("pockets", k));
    fail(base, base + " ('" + t.pockets[k].name + "', centre " + format_point(t.pockets[k].centre) +
                   ") cannot be reached: no two consecutive cushions end within its circle (the facings of a "
                   "pocket end there) and its centre is outside the playing area");
  }
}

void validate_part_names(const Table& t, const std::string& prefix);

void validate_table(const Table& t, const std::string& prefix) {
  if (!table_plainly_valid(t)) validate_fields(t, prefix);
  validate_part_names(t, prefix);
  validate_boundary(t, prefix);
}

// Cushion and jaw names: each given one printable and at most
// kMaxPartNameBytes; the names in use (given or default) unique across both,
// the later of two alike named. Run by every validate() (each simulate()):
// no allocation for named parts, one sort of hashes, names compared only when
// their hashes are equal (about 2 us for the presets' 30 names on 2 busy
// cores, against some 170 us for simulating the break).
void validate_part_names(const Table& t, const std::string& prefix) {
  const std::size_t nc = t.cushions.size();
  const std::size_t n = nc + t.jaws.size();
  const auto path_of = [&](std::size_t k) {
    return k < nc ? join(prefix, indexed("cushions", k)) : join(prefix, indexed("jaws", k - nc));
  };
  std::vector<std::string> defaults;
  defaults.reserve(n);  // the views below stay valid
  std::vector<std::string_view> names(n);
  std::vector<std::pair<std::size_t, std::size_t>> hashes(n);  // (hash, k)
  for (std::size_t k = 0; k < n; ++k) {
    const std::string& given = k < nc ? t.cushions[k].name : t.jaws[k - nc].name;
    if (given.empty()) {
      defaults.push_back(k < nc ? cushion_name(t, k) : jaw_name(t, k - nc));
      names[k] = defaults.back();
    } else {
      bool printable = given.size() <= kMaxPartNameBytes;
      for (char c : given) printable = printable && static_cast<unsigned char>(c) >= 0x20 && c != 0x7F;
      if (!printable) {
        const std::string f = path_of(k) + ".name";
        fail(f, f + " = " + quote_input(given) + " must be 1 to " + std::to_string(kMaxPartNameBytes) +
                    " bytes without control characters");
      }
      names[k] = given;
    }
    hashes[k] = {std::hash<std::string_view>{}(names[k]), k};
  }
  std::sort(hashes.begin(), hashes.end());
  std::size_t later = n, first = n;
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j < n && hashes[j].first == hashes[i].first) ++j;
    for (std::size_t x = i; x < j; ++x) {
      for (std::size_t y = x + 1; y < j; ++y) {
        const std::size_t kx = hashes[x].second, ky = hashes[y].second;  // kx < ky
        if (names[kx] == names[ky] && ky < later) {
          later = ky;
          first = kx;
        }
      }
    }
    i = j;
  }
  if (later < n) {
    const std::string f = path_of(later) + ".name";
    fail(f, f + " = " + quote_input(names[later]) + " repeats the name of " + path_of(first) +
                "; cushion and jaw names must be unique");
  }
}

void validate_fields(const Table& t, const std::string& prefix) {
  if (t.name.empty()) fail(join(prefix, "name"), join(prefix, "name") + " must not be empty");
  validate_size(t.length, t.width, prefix);
  validate_ball(t.ball, prefix);
  const double radius = t.ball.radius;
  const Range height = contact_height_range(radius);
  const char* height_meaning = "cushion nose height, between the ball's radius and its diameter";
  if (t.cushions.size() < 3) {
    fail(join(prefix, "cushions"),
         join(prefix, "cushions") + " needs at least 3 segments, got " + std::to_string(t.cushions.size()));
  }
  for (std::size_t i = 0; i < t.cushions.size(); ++i) {
    const CushionSegment& s = t.cushions[i];
    const std::string base = join(prefix, indexed("cushions", i));
    check_point(base + ".start", s.start, t.length, t.width);
    check_point(base + ".end", s.end, t.length, t.width);
    const double len = norm(s.end - s.start);
    if (!(len >= kMinSegmentLength)) {
      fail(base + ".end", base + ".end = " + format_point(s.end) + " is " + format_number(len) + " m from " + base +
                              ".start; a segment must be at least " + format_number(kMinSegmentLength) + " m long");
    }
    check(base + ".contact_height", s.contact_height, height, height_meaning);
  }
  for (std::size_t i = 0; i < t.jaws.size(); ++i) {
    const JawArc& j = t.jaws[i];
    const std::string base = join(prefix, indexed("jaws", i));
    check_point(base + ".centre", j.centre, t.length, t.width);
    check(base + ".radius", j.radius, positive_up_to(kMaxRoundRadius, "m"), "radius of the rounded jaw");
    check(base + ".contact_height", j.contact_height, height, height_meaning);
  }
  for (std::size_t i = 0; i < t.pockets.size(); ++i) {
    const Pocket& p = t.pockets[i];
    const std::string base = join(prefix, indexed("pockets", i));
    if (p.name.empty()) fail(base + ".name", base + ".name must not be empty");
    for (std::size_t k = 0; k < i; ++k) {
      if (t.pockets[k].name == p.name) {
        fail(base + ".name", base + ".name = '" + p.name + "' repeats " + join(prefix, indexed("pockets", k)) +
                                 ".name; pocket names must be unique");
      }
    }
    check_point(base + ".centre", p.centre, t.length, t.width);
    check(base + ".radius", p.radius, positive_up_to(kMaxRoundRadius, "m"), "capture radius");
  }
  for (std::size_t i = 0; i < t.diamonds.size(); ++i) {
    check_point(join(prefix, indexed("diamonds", i)), t.diamonds[i], t.length, t.width);
  }
}

// ------------------------------------------------------------------ pocket geometry

// One jaw of a pocket in the pocket's own frame: the mouth line is the x axis
// with its centre at the origin, the pocket lies towards -y (depth = -y), and
// this jaw's pointed lip V is at (mouth/2, 0). beta is the angle between the
// rail and the mouth line: 0 for a side pocket, 45 deg for a corner pocket.
struct JawFrame {
  Vec2 vertex;          // V, the pointed lip (nose line meets facing line)
  Vec2 nose_tangent;    // where the nose segment ends and the arc begins
  Vec2 arc_centre;
  Vec2 facing_tangent;  // where the arc ends and the facing segment begins
  Vec2 facing_end;      // deep end of the facing, at the capture circle's centre depth
  Vec2 nose_dir;        // unit, along the nose away from the pocket
  Vec2 cushion_dir;     // unit, outward normal of the nose (into the cushion)
  Vec2 facing_dir;      // unit, from V along the facing into the pocket
  double capture_radius;
  double capture_depth;  // depth of the capture circle's centre
  double cos_delta;      // depth gained per unit length along the facing
  double lateral_rate;   // lateral change of the facing per unit depth (< 0: the throat narrows)
};

JawFrame jaw_frame(const PocketSpec& p, double beta) {
  JawFrame j{};
  const double phi = p.cut_angle_deg * std::numbers::pi / 180.0;
  j.vertex = {0.5 * p.mouth, 0.0};
  j.nose_dir = {std::cos(beta), std::sin(beta)};
  j.cushion_dir = {std::sin(beta), -std::cos(beta)};
  // The facing leaves V at the cut angle phi from the nose, turning into the cushion.
  j.facing_dir = std::cos(phi) * j.nose_dir + std::sin(phi) * j.cushion_dir;
  const double half = 0.5 * phi;
  const double tangent_length = p.jaw_radius / std::tan(half);
  const Vec2 bisector = (j.nose_dir + j.facing_dir) / norm(j.nose_dir + j.facing_dir);
  j.nose_tangent = j.vertex + tangent_length * j.nose_dir;
  j.facing_tangent = j.vertex + tangent_length * j.facing_dir;
  j.arc_centre = j.vertex + (p.jaw_radius / std::sin(half)) * bisector;
  j.cos_delta = -j.facing_dir.y;
  j.lateral_rate = j.facing_dir.x / j.cos_delta;
  // Capture circle: nearest point `shelf` behind the mouth centre, radius half
  // the throat between the facings at that depth.
  j.capture_radius = 0.5 * p.mouth + j.lateral_rate * p.shelf;
  j.capture_depth = p.shelf + j.capture_radius;
  j.facing_end = j.vertex + (j.capture_depth / j.cos_delta) * j.facing_dir;
  return j;
}

constexpr double kCornerBeta = std::numbers::pi / 4.0;
constexpr double kSideBeta = 0.0;

void validate_pocket_spec(const PocketSpec& p, double beta, double cushion_height, double ball_radius,
                          const std::string& base) {
  check(base + ".mouth", p.mouth, positive_up_to(kMaxMouth, "m"), "lip to lip");
  check(base + ".cut_angle_deg", p.cut_angle_deg, closed(kMinCutAngle, kMaxCutAngle, "deg"),
        "angle between the cushion nose and the jaw facing");
  check(base + ".jaw_radius", p.jaw_radius, positive_up_to(kMaxRoundRadius, "m"), "radius of the rounded lip");
  check(base + ".shelf", p.shelf, closed(0.0, kMaxShelf, "m"), "mouth line to the slate's cut along the pocket axis");
  const JawFrame j = jaw_frame(p, beta);
  if (!(j.capture_radius > 0.0 && j.capture_radius <= kMaxRoundRadius)) {
    fail(base + ".shelf", base + ".shelf = " + format_number(p.shelf) + " m gives a capture radius of " +
                              format_number(j.capture_radius) + " m, outside (0, " + format_number(kMaxRoundRadius) +
                              "] m (the facings close before the shelf)");
  }
  // The facings end at the depth of the capture circle's centre, where they
  // are capture_radius (1 + lateral_rate) from the axis: they must not have
  // met (or crossed) before, i.e. each closes the throat by less than 45 deg.
  if (!(1.0 + j.lateral_rate > 1e-9)) {  // (not at exactly 45 deg either, whatever the rounding)
    const double parallel = 90.0 + beta * 180.0 / std::numbers::pi;  // cut angle of parallel facings
    fail(base + ".cut_angle_deg",
         base + ".cut_angle_deg = " + format_number(p.cut_angle_deg) +
             " deg closes the throat before the capture circle's centre (the facings meet " +
             format_number(0.5 * p.mouth / -j.lateral_rate) + " m behind the mouth, the centre is " +
             format_number(j.capture_depth) + " m); allowed < " + format_number(parallel + 45.0) +
             " deg for this pocket (facings parallel at " + format_number(parallel) + " deg)");
  }
  const double d = cushion_contact_distance(cushion_height, ball_radius);
  // A ball on the pocket's axis must pass between the facings down to the
  // shelf, and between the jaw arcs.
  const double corridor = std::min(0.5 * p.mouth, j.capture_radius) - d / j.cos_delta;
  const double jaw_clearance = std::abs(j.arc_centre.x) - p.jaw_radius - d;
  if (!(corridor > 0.0 && jaw_clearance > 0.0)) {
    fail(base + ".mouth", base + ".mouth = " + format_number(p.mouth) +
                              " m is too narrow for the ball: its centre stays " + format_number(d) +
                              " m from a cushion nose, so the pocket cannot pass it");
  }
  const double facing_length = (j.capture_depth - (-j.facing_tangent.y)) / j.cos_delta;
  if (!(facing_length >= kMinSegmentLength)) {
    fail(base + ".jaw_radius", base + ".jaw_radius = " + format_number(p.jaw_radius) +
                                   " m rounds the jaw past the capture circle's centre; use a smaller radius");
  }
}

Table make_table_shell(const TableSpec& spec) {
  Table t;
  t.name = spec.name;
  t.length = spec.length;
  t.width = spec.width;
  t.ball = spec.ball;
  return t;
}

// Orients [a, b] so that the playing surface is on its left, given a direction
// pointing into the cushion behind it.
CushionSegment oriented(Vec2 a, Vec2 b, Vec2 into_cushion, double h) {
  if (dot(perp(b - a), into_cushion) > 0.0) std::swap(a, b);
  return {a, b, h, {}};
}

void add_diamonds(Table& t, const TableSpec& spec) {
  if (!spec.has_diamonds) return;
  const double L = spec.length, W = spec.width, o = spec.diamond_offset;
  for (int k = 1; k <= 7; ++k) {
    if (spec.has_pockets && k == 4) continue;  // the side pocket
    t.diamonds.push_back({L * k / 8.0, -o});
  }
  for (int k = 1; k <= 3; ++k) t.diamonds.push_back({L + o, W * k / 4.0});
  for (int k = 7; k >= 1; --k) {
    if (spec.has_pockets && k == 4) continue;
    t.diamonds.push_back({L * k / 8.0, W + o});
  }
  for (int k = 3; k >= 1; --k) t.diamonds.push_back({-o, W * k / 4.0});
}

struct PocketSite {
  const char* name;
  bool corner;
  Vec2 mouth_centre;
  Vec2 axis;     // unit, from the mouth centre into the pocket
  Vec2 lateral;  // unit, from the mouth centre towards the jaw met first after leaving the pocket counter-clockwise
};

// World coordinates of a point given in a jaw frame.
Vec2 to_world(const PocketSite& s, Vec2 lateral, Vec2 p) { return s.mouth_centre + p.x * lateral - p.y * s.axis; }
Vec2 dir_to_world(const PocketSite& s, Vec2 lateral, Vec2 d) { return d.x * lateral - d.y * s.axis; }

}  // namespace

std::string cushion_name(const Table& table, std::size_t i) {
  const std::string& given = table.cushions.at(i).name;
  return given.empty() ? "cushions[" + std::to_string(i) + "]" : given;
}

std::string jaw_name(const Table& table, std::size_t i) {
  const std::string& given = table.jaws.at(i).name;
  return given.empty() ? "jaws[" + std::to_string(i) + "]" : given;
}

void name_parts(Table& table) {
  for (std::size_t i = 0; i < table.cushions.size(); ++i) table.cushions[i].name = cushion_name(table, i);
  for (std::size_t i = 0; i < table.jaws.size(); ++i) table.jaws[i].name = jaw_name(table, i);
}

bool operator==(const Table& a, const Table& b) {
  return a.name == b.name && a.length == b.length && a.width == b.width && a.cushions == b.cushions &&
         a.jaws == b.jaws && a.pockets == b.pockets && a.diamonds == b.diamonds && a.ball.mass == b.ball.mass &&
         a.ball.radius == b.ball.radius;
}

double distance_to_segment(const CushionSegment& s, Vec2 p) {
  const Vec2 d = s.end - s.start;
  const double len2 = dot(d, d);
  double u = len2 > 0.0 ? dot(p - s.start, d) / len2 : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  return norm(p - (s.start + u * d));
}

bool ball_on_table(const Table& table, Vec2 p) { return ball_on_table(table, p, table.ball.radius); }

bool inside_playing_area(const Table& table, Vec2 p, double margin) {
  if (inside_polygon(table, p)) return true;  // the common case first
  for (const Pocket& pocket : table.pockets) {
    const Vec2 d = p - pocket.centre;
    const double reach = pocket.radius + margin;
    if (dot(d, d) <= reach * reach) return true;
  }
  if (!(margin > 0.0)) return false;
  const std::size_t n = table.cushions.size();
  for (std::size_t i = 0; i < n; ++i) {
    const CushionSegment& s = table.cushions[i];
    if (distance_to_segment(s, p) <= margin) return true;
    if (distance_to_segment(CushionSegment{s.end, table.cushions[(i + 1) % n].start, 0.0, {}}, p) <= margin) return true;
  }
  return false;
}

bool ball_on_table(const Table& table, Vec2 p, double radius) {
  if (!is_finite(p)) return false;
  if (!inside_playing_area(table, p)) return false;
  for (const CushionSegment& s : table.cushions) {
    if (distance_to_segment(s, p) < cushion_contact_distance(s.contact_height, radius) - kPlacementTolerance) {
      return false;
    }
  }
  for (const JawArc& j : table.jaws) {
    if (norm(p - j.centre) < jaw_contact_distance(j, radius) - kPlacementTolerance) return false;
  }
  for (const Pocket& pocket : table.pockets) {
    if (in_pocket(pocket, p)) return false;
  }
  return true;
}

void validate(const Table& table) { validate_table(table, ""); }

namespace {

void validate_spec(const TableSpec& spec, const std::string& prefix) {
  if (spec.name.empty()) fail(join(prefix, "name"), join(prefix, "name") + " must not be empty");
  validate_size(spec.length, spec.width, prefix);
  validate_ball(spec.ball, prefix);
  check(join(prefix, "cushion_height"), spec.cushion_height, contact_height_range(spec.ball.radius),
        "cushion nose height, between the ball's radius and its diameter");
  if (spec.has_diamonds) {
    check(join(prefix, "diamond_offset"), spec.diamond_offset, closed(0.0, kMaxDiamondOffset, "m"),
          "sight centre behind the cushion nose");
  }
  if (!spec.has_pockets) return;
  validate_pocket_spec(spec.corner_pockets, kCornerBeta, spec.cushion_height, spec.ball.radius,
                       join(prefix, "corner_pockets"));
  validate_pocket_spec(spec.side_pockets, kSideBeta, spec.cushion_height, spec.ball.radius,
                       join(prefix, "side_pockets"));
  // Room for a nose segment between neighbouring pockets.
  const JawFrame c = jaw_frame(spec.corner_pockets, kCornerBeta);
  const JawFrame s = jaw_frame(spec.side_pockets, kSideBeta);
  const double corner_reach = std::sqrt(0.5) * spec.corner_pockets.mouth + norm(c.nose_tangent - c.vertex);
  const double side_reach = 0.5 * spec.side_pockets.mouth + norm(s.nose_tangent - s.vertex);
  if (!(spec.width - 2.0 * corner_reach >= kMinSegmentLength)) {
    fail(join(prefix, "width"), join(prefix, "width") + " = " + format_number(spec.width) +
                                    " m leaves no cushion between the corner pockets (their jaws reach " +
                                    format_number(corner_reach) + " m along each rail)");
  }
  if (!(0.5 * spec.length - corner_reach - side_reach >= kMinSegmentLength)) {
    fail(join(prefix, "length"), join(prefix, "length") + " = " + format_number(spec.length) +
                                     " m leaves no cushion between the corner and side pockets");
  }
}

Table build_unchecked(const TableSpec& spec) {
  Table t = make_table_shell(spec);
  const double L = spec.length, W = spec.width, h = spec.cushion_height;
  if (!spec.has_pockets) {
    // Carom: four noses meeting at the corners, which a ball cannot reach
    // (they are concave seen from the playing surface), so no jaws.
    t.cushions = {{{0.0, 0.0}, {L, 0.0}, h, "bottom rail"},
                  {{L, 0.0}, {L, W}, h, "right rail"},
                  {{L, W}, {0.0, W}, h, "top rail"},
                  {{0.0, W}, {0.0, 0.0}, h, "left rail"}};
    add_diamonds(t, spec);
    return t;
  }
  const double half_corner = 0.5 * std::sqrt(0.5) * spec.corner_pockets.mouth;  // mouth centre's offset from the corner
  const double r2 = std::sqrt(0.5);
  // Counter-clockwise from (0, 0). `lateral` points towards the jaw whose nose
  // continues counter-clockwise (the "out" jaw).
  // in / out: the jaw (and its facing) reached first going counter-clockwise,
  // and the other one, named after their rail (corner pockets) or their side
  // of the pocket (side pockets); see "Names" in table.hpp.
  const char* const in_names[6] = {"left", "left", "bottom", "right", "right", "top"};
  const char* const out_names[6] = {"bottom", "right", "right", "top", "left", "left"};
  const char* const rail_names[6] = {"bottom rail, left of the side pocket", "bottom rail, right of the side pocket",
                                     "right rail", "top rail, right of the side pocket",
                                     "top rail, left of the side pocket", "left rail"};
  const PocketSite sites[6] = {
      {"bottom-left", true, {half_corner, half_corner}, {-r2, -r2}, {r2, -r2}},
      {"bottom-side", false, {0.5 * L, 0.0}, {0.0, -1.0}, {1.0, 0.0}},
      {"bottom-right", true, {L - half_corner, half_corner}, {r2, -r2}, {r2, r2}},
      {"top-right", true, {L - half_corner, W - half_corner}, {r2, r2}, {-r2, r2}},
      {"top-side", false, {0.5 * L, W}, {0.0, 1.0}, {-1.0, 0.0}},
      {"top-left", true, {half_corner, W - half_corner}, {-r2, r2}, {-r2, -r2}},
  };
  struct WorldJaw {
    Vec2 nose_tangent;
  };
  WorldJaw in_jaw[6];
  WorldJaw out_jaw[6];
  for (int i = 0; i < 6; ++i) {
    const PocketSite& site = sites[i];
    const PocketSpec& p = site.corner ? spec.corner_pockets : spec.side_pockets;
    const JawFrame f = jaw_frame(p, site.corner ? kCornerBeta : kSideBeta);
    // The "in" jaw (reached first going counter-clockwise) mirrors the "out" jaw.
    for (int side = 0; side < 2; ++side) {
      const Vec2 lateral = side == 0 ? -1.0 * site.lateral : site.lateral;
      const Vec2 tangent = to_world(site, lateral, f.facing_tangent);
      const Vec2 end = to_world(site, lateral, f.facing_end);
      const Vec2 nose_dir = dir_to_world(site, lateral, f.nose_dir);
      const Vec2 facing_dir = dir_to_world(site, lateral, f.facing_dir);
      // The cushion lies behind the facing on the side the nose turns to.
      const Vec2 into_cushion = nose_dir - dot(nose_dir, facing_dir) * facing_dir;
      const std::string which = std::string(site.name) + " pocket, " + (side == 0 ? in_names[i] : out_names[i]);
      t.cushions.push_back(oriented(tangent, end, into_cushion, h));
      t.cushions.back().name = which + " facing";
      t.jaws.push_back({to_world(site, lateral, f.arc_centre), p.jaw_radius, h, which + " jaw"});
      (side == 0 ? in_jaw[i] : out_jaw[i]).nose_tangent = to_world(site, lateral, f.nose_tangent);
    }
    // The boundary runs in -> out: the in-jaw's facing (pushed first) leads
    // into the pocket, the out-jaw's facing leads out of it.
    t.pockets.push_back({site.name, site.mouth_centre + f.capture_depth * site.axis, f.capture_radius});
  }
  // Nose segments: from each pocket's out jaw to the next pocket's in jaw,
  // snapped exactly onto their rail (bottom, bottom, right, top, top, left)
  // to remove the rounding of the frame change.
  const auto snap = [&](int rail, Vec2 p) -> Vec2 {
    switch (rail) {
      case 0: case 1: return {p.x, 0.0};
      case 2: return {L, p.y};
      case 3: case 4: return {p.x, W};
      default: return {0.0, p.y};
    }
  };
  std::vector<CushionSegment> ordered;
  ordered.reserve(18);
  for (int i = 0; i < 6; ++i) {
    ordered.push_back(t.cushions[static_cast<std::size_t>(2 * i)]);
    ordered.push_back(t.cushions[static_cast<std::size_t>(2 * i + 1)]);
    const int next = (i + 1) % 6;
    ordered.push_back({snap(i, out_jaw[i].nose_tangent), snap(i, in_jaw[next].nose_tangent), h, rail_names[i]});
  }
  t.cushions = std::move(ordered);
  add_diamonds(t, spec);
  return t;
}

}  // namespace

void validate(const TableSpec& spec) { validate_spec(spec, ""); }

Table build_table(const TableSpec& spec) {
  validate_spec(spec, "");
  Table t = build_unchecked(spec);
  validate_table(t, "");
  return t;
}

// ------------------------------------------------------------------ presets

TableSpec pool_table_9ft_spec() {
  TableSpec s;
  s.name = "pool 9 ft (WPA)";
  // WPA "Playing Surface": 9-foot table 100 x 50 in (+/- 1/8 in), cushion nose to nose.
  s.length = 100.0 * kInch;
  s.width = 50.0 * kInch;
  // WPA ball: 2.25 in, 5.5-6 oz (pool_parameters(): 2.25 in, 6 oz).
  s.ball = pool_parameters().ball;
  // Cushion nose 1 7/16 in above the bed for 2.25 in balls (63.9 % of the
  // diameter; WPA "Rail and Cushion": 62.5-64.5 %).
  s.cushion_height = 1.4375 * kInch;
  s.has_pockets = true;
  // WPA "Pocket Openings": corner mouth 4.5-4.625 in, side mouth 5-5.125 in
  // (middle of each range), cut angles 142 and 104 deg (+/- 1). Shelf: BCA
  // corner 1 5/8 - 1 7/8 in, side 0 - 3/8 in (middle of each range). The
  // lips' rounding is not specified; 1/4 in is the WPA maximum facing
  // thickness, used here as the radius of the rounded lip.
  s.corner_pockets = {4.5625 * kInch, 142.0, 0.25 * kInch, 1.75 * kInch};
  s.side_pockets = {5.0625 * kInch, 104.0, 0.25 * kInch, 0.1875 * kInch};
  // WPA "Sights": centre 3 11/16 in from the nose of the cushion.
  s.has_diamonds = true;
  s.diamond_offset = (3.0 + 11.0 / 16.0) * kInch;
  return s;
}

TableSpec snooker_table_12ft_spec() {
  TableSpec s;
  s.name = "snooker 12 ft (WPBSA)";
  // WPBSA Rules 1(a): 11 ft 8.5 in x 5 ft 10 in (3569 x 1778 mm) within the cushion faces.
  s.length = 3.569;
  s.width = 1.778;
  // 52.5 mm balls (WPBSA Rules 2); mass 0.1406 kg (Mathavan et al. 2010).
  s.ball = snooker_parameters().ball;
  // Contact height 7R/5 (Mathavan, Jackson & Parkin 2010, sin(theta) = 2/5).
  s.cushion_height = 1.4 * s.ball.radius;
  s.has_pockets = true;
  // WPBSA Rules 1(c)(ii): openings per the WPBSA templates, which are not
  // published. Modelling values of pooltool's SnookerTableSpecs: corner
  // mouth 83 mm, jaw radius 4 in, shelf ("depth") 36 mm; middle mouth 87 mm,
  // jaw radius 2.5 in, shelf 0.95 in; facings parallel to the pocket's axis
  // (pooltool's pocket angle 0 = cut angles 135 and 90 deg here).
  s.corner_pockets = {0.083, 135.0, 4.0 * kInch, 0.036};
  s.side_pockets = {0.087, 90.0, 2.5 * kInch, 0.95 * kInch};
  s.has_diamonds = false;  // snooker tables have no sights
  s.diamond_offset = 0.0;
  return s;
}

TableSpec carom_table_10ft_spec() {
  TableSpec s;
  s.name = "carom 10 ft (UMB)";
  // UMB match table: playing surface 2.84 x 1.42 m, cushion height 37 mm.
  s.length = 2.84;
  s.width = 1.42;
  // UMB balls 61-61.5 mm, 205-220 g.
  s.ball = {0.210, 0.0615 / 2.0};
  s.cushion_height = 0.037;
  s.has_pockets = false;
  s.corner_pockets = {};
  s.side_pockets = {};
  // Sights at eighths and quarters; no UMB figure for their offset was found,
  // so the WPA 3 11/16 in is used (drawing only).
  s.has_diamonds = true;
  s.diamond_offset = (3.0 + 11.0 / 16.0) * kInch;
  return s;
}

Table pool_table_9ft() { return build_table(pool_table_9ft_spec()); }
Table snooker_table_12ft() { return build_table(snooker_table_12ft_spec()); }
Table carom_table_10ft() { return build_table(carom_table_10ft_spec()); }

TableSpec preset_table_spec(std::string_view name) {
  if (name == "pool_9ft") return pool_table_9ft_spec();
  if (name == "snooker_12ft") return snooker_table_12ft_spec();
  if (name == "carom_10ft") return carom_table_10ft_spec();
  std::string allowed;
  for (std::string_view n : kTablePresetNames) allowed += (allowed.empty() ? "" : ", ") + std::string(n);
  fail("preset", "preset = '" + std::string(name) + "' is not known; allowed: " + allowed);
}

Table preset_table(std::string_view name) { return build_table(preset_table_spec(name)); }

const char* cloth_preset_for(const Table& table) {
  if (table.name.find("snooker") != std::string::npos) return "snooker";
  return table.name.find("carom") != std::string::npos ? "carom" : "pool";
}

Parameters default_parameters(const Table& table) {
  Parameters p = preset_parameters(cloth_preset_for(table));
  p.ball = table.ball;
  return p;
}

// ------------------------------------------------------------------ for the JSON reader (io/table_json.cpp)

namespace detail {

void validate_table_at(const Table& table, const std::string& prefix) { validate_table(table, prefix); }
void validate_spec_at(const TableSpec& spec, const std::string& prefix) { validate_spec(spec, prefix); }
Table build_table_unchecked(const TableSpec& spec) { return build_unchecked(spec); }
std::string join_path(const std::string& prefix, const std::string& field) { return join(prefix, field); }

}  // namespace detail

}  // namespace cueball
