// Opening positions: 9-ball, 8-ball, 10-ball and snooker racks on any Table.
//
// Frame as in table.hpp. Pool: the head end is x = 0, the head string is at
// a quarter of the length and the foot spot at three quarters on the long
// string y = width/2 (WPA Rules: the diamonds mark an eighth of the length;
// the head and foot strings pass through the second diamonds from the ends).
// Snooker: the baulk (bottom) cushion is x = 0 and the top cushion x = length;
// spots per the WPBSA Rules of Snooker, section 1 (see SnookerSpots).
//
// Ball id 0 is always the cue ball; ids are unique. Frozen racks (gap_sigma =
// 0) put neighbouring balls exactly touching: centres 2R apart along the
// triangular lattice (up to rounding, far below 1e-12 m).
//
// Random gaps (gap_sigma > 0): the lattice spacing is widened from 2R to
// 2R + 4 sigma about the apex ball, and every other ball of the triangle is
// moved from its widened site by a random vector whose components are
// independent N(0, sigma^2), shortened to length 2 sigma when longer. Two
// balls' centres are then at least (2R + 4 sigma) - 2 sigma - 2 sigma = 2R
// apart (triangle inequality), so no pair overlaps; neighbouring gaps lie in
// [0, 8 sigma] with mean about 4 sigma. The apex ball stays on its spot. The
// random numbers come from std::mt19937_64 seeded with `seed`, turned into
// uniforms (53 high bits) and normals (Box-Muller) by cueball itself, so a
// seed gives the same rack with every standard library.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cueball/table/placement.hpp"
#include "cueball/table/table.hpp"
#include "cueball/core/vec.hpp"

namespace cueball {

struct PlacedBall {
  int id = 0;        ///< 0 = cue ball
  std::string name;  ///< "cue", "1".."15"; snooker "red1".."red15", "yellow", ...
  Vec2 position;     ///< centre, m
};

struct RackOptions {
  double gap_sigma = 0.0;  ///< m, scale of random gaps, [0, kMaxGapSigma]; 0 = frozen rack
  std::uint64_t seed = 0;  ///< seeds std::mt19937_64
};

inline constexpr double kMaxGapSigma = 0.005;  ///< m

/// Throws InvalidArgument("gap_sigma", ...) unless 0 <= gap_sigma <= kMaxGapSigma.
void validate(const RackOptions& options);

// foot_spot(), head_string_x(): placement.hpp.

/// Snooker markings (WPBSA Rules, section 1(d)-(f)), for a table of any size:
/// distances given for the standard 3569 x 1778 mm table scale with the
/// table's length (baulk line, black spot) and width (D radius).
struct SnookerSpots {
  double baulk_line_x = 0.0;  ///< 737 mm from the bottom cushion face
  double d_radius = 0.0;      ///< 292 mm, the D's semicircle about the brown spot, in baulk
  Vec2 black;                 ///< 324 mm from the top cushion face
  Vec2 pink;                  ///< midway between the centre spot and the top cushion face
  Vec2 blue;                  ///< centre spot
  Vec2 brown;                 ///< middle of the baulk line
  Vec2 yellow;                ///< right corner of the D seen from baulk (y = W/2 - d_radius)
  Vec2 green;                 ///< left corner of the D seen from baulk (y = W/2 + d_radius)
};
SnookerSpots snooker_spots(const Table& table);

/// Gap between the pink and the apex red: "as near to the Pink as possible
/// without touching it" (WPBSA Rules, section 2), m.
inline constexpr double kPinkApexGap = 1e-3;

/// Every rack function validates the table and the options first
/// (InvalidArgument naming the table's field or "gap_sigma"), then checks that
/// every ball can be placed (ball_on_table()) and no two overlap; otherwise it
/// throws InvalidArgument with field "rack" (the scenario's "rack" object)
/// whose message names the ball, gives its position and the range its centre
/// must lie in, and the length and width a rectangular table needs for this
/// rack (or, for two overlapping balls, their distance and the 2R needed).

/// 10 balls: cue (id 0) on the long string one ball diameter behind the head
/// string; 1-9 in a diamond (rows 1-2-3-2-1) pointing at the head, the 1 on
/// the foot spot, the 9 in the centre (WPA Rules of 9-Ball, "Racking").
std::vector<PlacedBall> rack_nine_ball(const Table& table, const RackOptions& options = {});

/// 16 balls: cue as in 9-ball; 1-15 in a triangle (rows 1..5), apex (the 1)
/// on the foot spot, the 8 in the centre of the third row, a solid (5) and a
/// stripe (12) in the back corners (WPA Rules of 8-Ball, "Racking").
std::vector<PlacedBall> rack_eight_ball(const Table& table, const RackOptions& options = {});

/// 11 balls: cue as in 9-ball; 1-10 in a triangle (rows 1..4), the 1 at the
/// apex on the foot spot, the 10 in the middle of the third row (WPA Rules
/// of Play 9.2, "Ten Ball Rack").
std::vector<PlacedBall> rack_ten_ball(const Table& table, const RackOptions& options = {});

/// 22 balls: cue (id 0) inside the D between the brown and yellow spots;
/// reds (ids 1-15) in a triangle whose apex red is kPinkApexGap behind the
/// pink (towards the top cushion) with its base parallel to the top cushion;
/// yellow 16, green 17, brown 18, blue 19, pink 20, black 21 on their spots
/// (WPBSA Rules, section 2 "Positioning of balls").
std::vector<PlacedBall> rack_snooker(const Table& table, const RackOptions& options = {});

/// rack_snooker() with `reds` reds: 15 as above; 6 or 10 (the short games)
/// a triangle of 3 or 4 rows, ids 1..reds, the apex where the 15's is.
/// InvalidArgument("reds", ...) for any other count.
std::vector<PlacedBall> rack_snooker_with_reds(const Table& table, int reds, const RackOptions& options = {});

}  // namespace cueball
