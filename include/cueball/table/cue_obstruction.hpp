// Cue obstruction: whether the cue, aligned for a strike, passes through a
// ball or below the rail.
//
// Can the cue reach the strike? The cue is a straight cylinder of
// radius kCueTipRadius and length kCueLength along the strike's axis behind
// the contact point, butt raised by the elevation. It is obstructed when it
// passes within R + its radius of another ball's centre (3D), or where it
// first reaches the rail (its axis outside the playing area, inside_playing_area
// of table.hpp, or within its radius in plan of a cushion's nose; sampled
// every 2 mm) its lower edge is below the rail height, taken as the highest cushion nose height h
// of the table (the cushion's top rises behind the nose, so this is a lower
// bound on the real rail). Sources: the same model as pooltool's CueAvoid
// (a cue of tip radius ~7 mm, cushions at their height) and FastFiz's
// cue-stick collision check (isPhysicallyPossible; the engine of the
// computational-pool tournaments, Leckie & Greenspan). Cue dimensions: a
// 58 in (1.47 m) cue with a 13 mm tip, the usual pool cue.
#pragma once

#include <vector>

#include "cueball/core/vec.hpp"
#include "cueball/physics/cue_strike.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

/// Cue length, m (58 in).
inline constexpr double kCueLength = 1.4732;
/// Cue tip radius, m (13 mm tip).
inline constexpr double kCueTipRadius = 0.0065;

/// The rail height cue_obstructed() uses: the highest nose contact height
/// of the table's cushions and jaws, m.
double rail_height(const Table& table);

/// The cue's axis for `strike` on a ball of radius `radius` resting at
/// `cue_ball`: the contact point on the ball (the tip's centre, C2 of
/// cue_strike.hpp) and the unit direction from the tip towards the butt,
/// raised by the elevation (the cue frame C1). A point at length s behind
/// the tip is tip + s * toward_butt.
struct CueAxis {
  Vec3 tip;
  Vec3 toward_butt;
};
CueAxis cue_axis(Vec2 cue_ball, const CueStrike& strike, double radius);

/// True when the cue, aligned for `strike` (radians, metres) on the cue ball
/// at `cue_ball`, passes within its radius of another ball (centres
/// `other_balls`, balls of radius `radius` resting on the bed) or below the
/// rail (header comment). Unvalidated: a kernel.
bool cue_obstructed(const Table& table, Vec2 cue_ball, const std::vector<Vec2>& other_balls, const CueStrike& strike,
                    double radius);

}  // namespace cueball
