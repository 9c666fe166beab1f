// Placing balls on a table: the room a spot has, whether a ball may go
// there, the regions where the cue ball may be placed in hand, the strings
// and spots of the rule books, and spotting a ball on the long string.
//
// Frame as in table.hpp. Pool (WPA Rules of Play, "Diagram of the table"):
// the head end is x = 0, the head string is x = L/4, the foot spot (3L/4,
// W/2), the long string y = W/2. Snooker (WPBSA Rules, section 1): the
// baulk line and the D of snooker_spots() (rack.hpp).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/core/random.hpp"
#include "cueball/core/vec.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

/// Foot spot (3L/4, W/2), where pool racks put the apex ball.
Vec2 foot_spot(const Table& table);
/// x of the head string (L/4); the cue ball starts behind it (x < L/4).
double head_string_x(const Table& table);
/// y of the long string (W/2), through the head and foot spots.
double long_string_y(const Table& table);

/// Signed room around a centre p: the smallest of its distances beyond the
/// contact distance of every cushion segment and jaw, beyond every pocket's
/// capture circle, and inside the rectangle [0, L] x [0, W], m. >= 0 where
/// ball_on_table() accepts p and the ball is clear of every pocket's hole.
double clearance(const Table& table, Vec2 p, double radius);

/// Smallest centre distance minus 2 radius from p to `balls` (infinity when
/// there are none), m: >= 0 when a ball at p overlaps none of them.
double ball_gap(Vec2 p, const std::vector<Vec2>& balls, double radius);

/// True when a ball may be placed at p: on the table (ball_on_table), at
/// least `margin` of clearance(), and overlapping none of `balls`
/// (touching allowed).
bool is_free_spot(const Table& table, const std::vector<Vec2>& balls, Vec2 p, double radius, double margin = 0.0);

/// Where the cue ball may be placed when in hand.
struct PlacementRegion {
  enum class Kind : char {
    anywhere,            ///< anywhere on the bed (WPA 1.5, ball in hand after a foul)
    behind_head_string,  ///< the kitchen, x <= L/4 (the break in the WPA games; 8-ball after a scratch on the break)
    inside_d,            ///< the D, its lines included (WPBSA Rules of Snooker, "in-hand")
    rectangle,           ///< [x_min, x_max] x [y_min, y_max], m
  };
  Kind kind = Kind::anywhere;
  double x_min = 0.0, x_max = 0.0, y_min = 0.0, y_max = 0.0;  ///< rectangle only
};

/// The region's name, as the JSON and the CLI write it: "anywhere",
/// "behind_head_string", "inside_d", "rectangle".
const char* to_string(PlacementRegion::Kind kind);

/// The kind named `name` (to_string's names; "kitchen" for
/// behind_head_string and "d" for inside_d too), or none.
std::optional<PlacementRegion::Kind> placement_region_from_string(std::string_view name);
/// The names of the kinds without a rectangle's bounds, for messages:
/// "anywhere, behind_head_string (kitchen), inside_d (d)".
std::string placement_region_names();

/// True when the centre p lies in the region, its lines included (to within
/// kPlacementTolerance, so that a spot computed on a line, such as the D's
/// corners, counts). The region alone: is_free_spot() says whether a ball
/// fits there.
bool in_region(const Table& table, const PlacementRegion& region, Vec2 p);

/// The region's bounding box on the bed [x_min, x_max] x [y_min, y_max] (the
/// whole rectangle of the bed for `anywhere`).
PlacementRegion bounding_rectangle(const Table& table, const PlacementRegion& region);

/// A uniformly random free spot in the region (rejection sampling over its
/// bounding box: two uniforms a try, x then y), or none after `attempts`
/// tries.
std::optional<Vec2> random_free_spot(const Table& table, const std::vector<Vec2>& balls, double radius,
                                     RandomStream& rng, int attempts, const PlacementRegion& region = {},
                                     double margin = 0.0);

/// Least gap left between a spotted ball and the cue ball ("not frozen to
/// the cue ball"), m.
inline constexpr double kSpottingGapToCue = 1e-3;

/// Where a ball is spotted (WPA Rules of Play 1.4, "Spotting balls"): on the
/// long string, on the foot spot or as close to it as possible between the
/// foot spot and the foot rail, frozen to a ball in the way (but
/// kSpottingGapToCue from `cue_ball`, when given); when that part of the line
/// is full, as close to the foot spot as possible in front of it (towards
/// the head). None when no place on the long string is free.
std::optional<Vec2> spot_on_long_string(const Table& table, const std::vector<Vec2>& object_balls,
                                        std::optional<Vec2> cue_ball, double radius);

}  // namespace cueball
