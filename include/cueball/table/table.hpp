// Table geometry: cushions, pocket jaws, pockets, with presets (JSON:
// io/table_json.hpp).
//
// Frame (shared/spec/physics.md): x, y in the bed of the table, z up, metres.
// The origin is one corner of the playing surface measured cushion nose to
// cushion nose; x runs along the length (0..length), y across the width
// (0..width). Pocket and plot names below read the table drawn with x to the
// right and y up: "bottom" is the rail y = 0, "left" the end x = 0.
//
// The simulator predicts collisions from three primitives, kept deliberately
// simple:
//
// * CushionSegment: a straight cushion nose line from `start` to `end`. The
//   playing surface is on the LEFT of start -> end, so the inward normal
//   (pointing onto the playing surface) is perp(end - start) / |end - start|;
//   the boundary of a table runs counter-clockwise seen from above. The nose
//   is a horizontal edge at height h = contact_height above the bed. A ball of
//   radius R (centre at height R) touches it when the 3-D distance from the
//   ball's centre to that edge is R, i.e. when the centre's distance d in the
//   plan from the nose line satisfies d^2 + (h - R)^2 = R^2:
//       d = R cos(theta) = sqrt(h (2R - h)),   sin(theta) = (h - R) / R
//   (Mathavan, Jackson & Parkin 2010, Fig. 3; spec/physics.md section 2).
//   Only contacts whose foot of the perpendicular falls inside [start, end]
//   belong to the segment: the ends are rounded off by jaw arcs (pockets) or
//   meet another segment at a corner the ball cannot reach (carom table).
//
// * JawArc: the rounded tip where a cushion nose turns into a pocket facing.
//   Its nose is a horizontal circle of radius `radius` about `centre` at the
//   same height h, tangent to the nose segment and to the facing segment it
//   joins. The same 3-D argument gives the contact rule: a ball touches the
//   jaw when its centre is at plan distance  radius + sqrt(h (2R - h))  from
//   `centre`, approaching from outside. The simulator may treat the jaw as a
//   full circle: it is inscribed in the cushion's corner, so a ball can reach
//   its hidden part only by crossing one of the two tangent segments or the
//   pocket's capture circle first (checked by a flood fill of reachable ball
//   centres in tests/test_table.cpp).
//
// * Pocket: the plan outline of the hole cut in the slate, a circle. A ball is
//   pocketed when its centre comes within `radius` of `centre` (distance <=
//   radius): from then its contact point with the bed (directly below its
//   centre) is over the hole and it falls. The WPA/BCA "shelf" is the distance
//   from the centre of the mouth line (lip to lip) to the slate's cut along
//   the pocket's axis (BCA pocket specifications; WPA Equipment
//   Specifications, "Shelf"), so the circle's nearest point to the table lies
//   `shelf` behind the middle of the mouth. Its radius is half the throat
//   width between the two facings at that depth, so that the circle spans the
//   throat: a ball that has passed the jaws and the shelf and is still between
//   the facings is inside the circle before the facings end (the facings stop
//   at the depth of the circle's centre). See build_table().
//
// Names. Every cushion segment and jaw has a name, which the result JSON's
// events carry ("cushion_name", "jaw_name"). The presets and every table of
// build_table() use this stable scheme (pockets: "bottom-left",
// "bottom-side", "bottom-right", "top-right", "top-side", "top-left"):
//   * nose segments, by rail: "bottom rail", "right rail", "top rail",
//     "left rail"; on a rail with a side pocket, "bottom rail, left of the
//     side pocket", "bottom rail, right of the side pocket", "top rail, left
//     of the side pocket", "top rail, right of the side pocket";
//   * jaws: "<pocket> pocket, <which> jaw" and the facing behind it
//     "<pocket> pocket, <which> facing", where <which> is the rail the jaw
//     ends for a corner pocket ("bottom-left pocket, bottom jaw" is on the
//     bottom rail, "bottom-left pocket, left jaw" on the left one) and the
//     side of the pocket for a side pocket ("bottom-side pocket, left jaw",
//     "top-side pocket, right jaw"), left and right as drawn (x to the right).
// A custom table (JSON or C++) may name its parts: a name is at most
// kMaxPartNameBytes bytes without control characters, and the names in use
// are unique across cushions and jaws. A part without a name (an empty name
// in C++, no "name" in JSON) is called by its JSON path, "cushions[3]" or
// "jaws[0]" (cushion_name(), jaw_name()); table_from_json() fills these
// defaults in and table_to_json() writes them.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/core/parameters.hpp"
#include "cueball/core/vec.hpp"

namespace cueball {

/// A straight cushion nose. Playing surface on the left of start -> end.
struct CushionSegment {
  Vec2 start;
  Vec2 end;
  double contact_height = 0.0;  ///< h, height of the nose above the bed, m, in (R, 2R)
  std::string name;             ///< "Names" above; empty: the default "cushions[i]"

  friend bool operator==(const CushionSegment&, const CushionSegment&) = default;
};

/// The rounded cushion tip at a pocket jaw; contact at plan distance
/// radius + sqrt(h (2R - h)) from centre.
struct JawArc {
  Vec2 centre;
  double radius = 0.0;          ///< m, > 0
  double contact_height = 0.0;  ///< h, m, in (R, 2R)
  std::string name;             ///< "Names" above; empty: the default "jaws[j]"

  friend bool operator==(const JawArc&, const JawArc&) = default;
};

/// Capture circle: a ball whose centre is within `radius` of `centre` drops.
struct Pocket {
  std::string name;
  Vec2 centre;
  double radius = 0.0;  ///< m, in (0, 0.2]

  friend bool operator==(const Pocket&, const Pocket&) = default;
};

struct Table {
  std::string name;
  double length = 0.0;  ///< playing surface along x, cushion nose to nose, m
  double width = 0.0;   ///< playing surface along y, cushion nose to nose, m
  std::vector<CushionSegment> cushions;
  std::vector<JawArc> jaws;
  std::vector<Pocket> pockets;
  std::vector<Vec2> diamonds;  ///< sights on the rail, for drawing only
  BallParameters ball;         ///< the balls played on this table
};

bool operator==(const Table& a, const Table& b);

/// Longest cushion or jaw name, bytes.
inline constexpr std::size_t kMaxPartNameBytes = 64;
/// The name of table.cushions[i] in use: its own, or "cushions[i]" when empty.
std::string cushion_name(const Table& table, std::size_t i);
/// The name of table.jaws[j] in use: its own, or "jaws[j]" when empty.
std::string jaw_name(const Table& table, std::size_t j);
/// Gives every unnamed cushion and jaw its default name (cushion_name()).
void name_parts(Table& table);

// ------------------------------------------------------------------ contact rules

/// Plan distance from a ball's centre to a cushion nose line (or a jaw's
/// circle) at first contact: R cos(theta) = sqrt(h (2R - h)) with
/// sin(theta) = (h - R)/R. Precondition 0 < h < 2R (not checked: hot path).
inline double cushion_contact_distance(double contact_height, double radius) {
  return std::sqrt(contact_height * (2.0 * radius - contact_height));
}

/// Distance between a ball's centre and the jaw's centre at contact.
inline double jaw_contact_distance(const JawArc& jaw, double radius) {
  return jaw.radius + cushion_contact_distance(jaw.contact_height, radius);
}

/// Unit normal of the nose line pointing onto the playing surface.
inline Vec2 inward_normal(const CushionSegment& s) {
  const Vec2 d = s.end - s.start;
  return perp(d) / norm(d);
}

/// Distance from p to the closest point of the finite segment [start, end].
double distance_to_segment(const CushionSegment& s, Vec2 p);

/// True when a ball centred at p is captured by the pocket (|p - c| <= radius).
inline bool in_pocket(const Pocket& pocket, Vec2 p) {
  const Vec2 d = p - pocket.centre;
  return dot(d, d) <= pocket.radius * pocket.radius;
}

/// Slack allowed when a ball is placed touching a cushion or a jaw, m: the
/// simulator's contact tolerance (contact_prediction.hpp kContactTolerance), so that
/// wherever a shot leaves a ball at rest, the next shot can start.
inline constexpr double kPlacementTolerance = 1e-9;

/// True when a ball of radius `radius` can be placed with its centre at p:
/// the centre is finite and inside the closed boundary
/// (inside_playing_area(table, p): the bed, the pockets' throats included,
/// where a ball can come to rest hanging in the jaws); the ball does not overlap any cushion segment
/// (distance to the segment >= contact distance - kPlacementTolerance) or jaw;
/// and its centre is not over a pocket's hole. Touching is allowed.
/// Precondition: a validated table, 0 < radius with every contact height in
/// (0, 2 radius) (not checked).
bool ball_on_table(const Table& table, Vec2 p, double radius);
/// The same for the table's own ball, table.ball.radius.
bool ball_on_table(const Table& table, Vec2 p);

/// Ends that are this close count as meeting, m (a micrometre: far below any
/// cushion's manufacturing tolerance, far above the rounding of a table built
/// from a spec or read back from its JSON).
inline constexpr double kBoundaryTolerance = 1e-6;

/// Throws InvalidArgument naming the first bad field, e.g. "cushions[3].end":
/// name, length and width in (0, 10] m; ball mass and radius in their
/// parameter ranges; at least 3 cushions; every point finite and within
/// 0.5 m of the playing surface; segments at least 1e-6 m long; contact
/// heights in (R, 2R); jaw radii and pocket radii in (0, 0.2] m; pocket
/// names non-empty and unique; cushion and jaw names as in "Names" (header
/// comment), e.g. "jaws[2].name".
///
/// Then the table must be a closed playing area, the boundary the simulator
/// relies on (header comment). In list order, cushions[i].end joins
/// cushions[i+1].start (and the last joins the first) in one of three ways,
/// each within kBoundaryTolerance:
///   * directly: the two points meet (a carom corner). The boundary must turn
///     left or run straight there (a corner the ball cannot reach); a convex
///     corner needs a jaw arc, else "cushions[i+1].start" is named;
///   * by a jaw arc: both points lie on some jaws[j]'s circle. The jaw must be
///     tangent to both segments with its centre behind them, in the cushion
///     (centre = point - radius * inward normal for each), else "jaws[j]";
///   * across a pocket: both points lie within some pockets[k]'s circle (the
///     deep ends of the two facings of a pocket).
/// An end that meets none of them leaves the boundary open: "cushions[i].end"
/// (or "cushions[i+1]" when that segment is simply given end to start). The
/// polygon through every segment's start and end, in order, must run
/// counter-clockwise (positive signed area, playing surface on the left of
/// every segment), else "cushions"; no two segments that are not neighbours
/// in the loop may cross or touch, else the later one, "cushions[k]", is
/// named; and every pocket must be reachable: it joins two facings as above
/// or its centre lies inside the polygon, else "pockets[k]". Jaws that join
/// nothing are allowed (free-standing round obstacles).
void validate(const Table& table);

/// True when a ball's centre at p is inside the closed playing area of a
/// validated table, or within `margin` (m, >= 0) of it. The area is the
/// polygon through every cushion segment's start and end in list order (the
/// nose lines, closed by straight chords across jaw arcs and pocket gaps)
/// together with every pocket's capture circle, so a pocket's throat, between
/// its facings down to the circle, is inside. A ball touching a cushion has
/// its centre R cos(theta) inside the nose line, so with margin 0 a centre
/// outside means the ball has passed through a cushion by more than that.
/// Points on the boundary may go either way unless margin > 0. Across a jaw
/// the chord cuts the arc's corner: the area there is larger than the
/// cushion's nose by at most radius (1 - cos(turn / 2)) (0.3 mm for the pool
/// preset's corner jaws). Cost: one crossing-number test over 2 N edges (N
/// cushions; no division, no allocation), then one distance per pocket only
/// when p is outside the polygon, and one per edge only when it is outside
/// everything and margin > 0: about 40 ns for the pool and snooker presets,
/// 17 ns for carom (2 busy cores, -O3). Precondition: validate(table) passed
/// (not checked: hot path).
bool inside_playing_area(const Table& table, Vec2 p, double margin = 0.0);

// ------------------------------------------------------------------ parametric tables

/// One kind of pocket (both jaws alike). WPA measures the mouth "between
/// opposing cushion noses where the direction changes into the pocket (from
/// pointed lip to pointed lip)"; here that is the distance between the two
/// points where a nose line meets its facing line (the sharp corners before
/// rounding). The cut angle is the angle inside the cushion between its nose
/// and its facing (WPA "horizontal pocket cut angle"): 135 deg (corner) or
/// 90 deg (side) makes the facings parallel to the pocket's axis, larger
/// angles narrow the throat.
struct PocketSpec {
  double mouth = 0.0;          ///< m, lip to lip, (0, 0.5]
  double cut_angle_deg = 0.0;  ///< degrees, [90, 170]
  double jaw_radius = 0.0;     ///< m, radius of the rounded lip, (0, 0.2]
  double shelf = 0.0;          ///< m, mouth line to the slate's cut along the axis, [0, 0.2]
};

/// A rectangular table with four corner pockets and two side pockets at
/// mid-length (has_pockets), or a pocketless carom table.
struct TableSpec {
  std::string name;
  double length = 0.0;          ///< m, (0, 10]
  double width = 0.0;           ///< m, (0, 10]
  double cushion_height = 0.0;  ///< h of every nose, m, (R, 2R)
  BallParameters ball;
  bool has_pockets = true;
  PocketSpec corner_pockets;    ///< ignored without pockets
  PocketSpec side_pockets;      ///< ignored without pockets
  bool has_diamonds = true;     ///< 18 (pocketed) or 20 (carom) sights at 1/8 and 1/4 spacing
  double diamond_offset = 0.0;  ///< m, sight centre behind the nose line, [0, 0.5]
};

/// Throws InvalidArgument naming the field, e.g. "corner_pockets.mouth",
/// including when a pocket cannot pass a ball (the corridor between the jaws
/// and facings is narrower than a ball), when the facings close the throat
/// before the capture circle's centre ("cut_angle_deg": each facing may turn
/// in by less than 45 deg from parallel, so side pockets need a cut angle
/// below 135 deg) or pockets leave no cushion between them.
void validate(const TableSpec& spec);

/// The geometry of a spec (validated first). Layout, counter-clockwise from
/// the corner (0, 0): for each pocket, its two jaws: the nose segment ends at
/// the jaw arc's tangent point, the arc turns through 180 deg - cut angle and
/// meets the facing segment, which runs into the pocket to the depth of the
/// capture circle's centre. Pockets in order bottom-left (0,0), bottom-side
/// (L/2,0), bottom-right (L,0), top-right (L,W), top-side (L/2,W), top-left
/// (0,W); capture circle: see the header comment. Diamonds at every eighth of
/// the length and quarter of the width (WPA: "the diamonds mark a quarter of
/// the width and an eighth of the length"), except where a side pocket is.
Table build_table(const TableSpec& spec);

/// 9-ft pool table (WPA Equipment Specifications; BCA shelf).
TableSpec pool_table_9ft_spec();
/// Full-size snooker table (WPBSA Rules of Snooker, section 1).
TableSpec snooker_table_12ft_spec();
/// UMB match carom table, no pockets.
TableSpec carom_table_10ft_spec();

Table pool_table_9ft();
Table snooker_table_12ft();
Table carom_table_10ft();

/// Preset names for preset_table() and the JSON "preset" key.
inline constexpr std::array<std::string_view, 3> kTablePresetNames{"pool_9ft", "snooker_12ft", "carom_10ft"};
/// The spec of a preset by name; throws InvalidArgument("preset", ...) otherwise.
TableSpec preset_table_spec(std::string_view name);
Table preset_table(std::string_view name);

/// The cloth preset that goes with a table: "snooker" for a table whose name
/// says snooker, "carom" for one whose name says carom, else "pool" (what a
/// scenario uses unless it names one).
const char* cloth_preset_for(const Table& table);
/// preset_parameters(cloth_preset_for(table)) with the table's own ball.
Parameters default_parameters(const Table& table);

// JSON: table_from_json(), table_to_json() in io/table_json.hpp.

}  // namespace cueball
