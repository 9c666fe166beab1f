// The cue-obstruction rail test by the model's definition (header comment of
// cueball/table/cue_obstruction.hpp): every 2 mm sample of the cue's axis from
// the tip, the first one outside the playing area or within the cue's radius
// of a nose line decides (no balls: the rail alone). The reference that
// tests/test_cue_obstruction.cpp checks the library's rail test against and
// bench/bench_cue_obstruction.cpp times it against.
#pragma once

#include <cmath>

#include "cueball/table/cue_obstruction.hpp"
#include "cueball/table/table.hpp"

namespace cueball::test {

inline bool over_rail_low_by_every_sample(const Table& table, Vec2 cue_ball, const CueStrike& strike, double R) {
  const CueAxis axis = cue_axis(cue_ball, strike, R);
  const double rail = rail_height(table);
  const double drop = kCueTipRadius / std::cos(strike.elevation);
  for (double s = 0.0; s <= kCueLength; s += 0.002) {
    const Vec3 x = axis.tip + s * axis.toward_butt;
    const Vec2 p{x.x, x.y};
    bool over = !inside_playing_area(table, p);
    for (const CushionSegment& k : table.cushions) over = over || distance_to_segment(k, p) < kCueTipRadius;
    if (over) return x.z - drop < rail;
  }
  return false;
}

}  // namespace cueball::test
