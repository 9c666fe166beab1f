// Cue obstruction (cue_obstruction.hpp): the cue as a cylinder behind the
// contact point, checked against the other balls and the rail.
#include "cueball/table/cue_obstruction.hpp"

#include <algorithm>
#include <cmath>

namespace cueball {

double rail_height(const Table& table) {
  double h = 0.0;
  for (const CushionSegment& c : table.cushions) h = std::max(h, c.contact_height);
  for (const JawArc& j : table.jaws) h = std::max(h, j.contact_height);
  return h;
}

bool cue_obstructed(const Table& table, Vec2 cue_ball, const std::vector<Vec2>& other_balls, const CueStrike& strike,
                    double radius) {
  const double R = radius;
  // The cue frame (C1) of cue_strike.hpp and the contact point (C2).
  const Vec3 u{std::cos(strike.aim), std::sin(strike.aim), 0.0};
  const Vec3 side{u.y, -u.x, 0.0};
  const double ce = std::cos(strike.elevation), se = std::sin(strike.elevation);
  const Vec3 d{ce * u.x, ce * u.y, -se};
  const Vec3 up{se * u.x, se * u.y, ce};
  const double a = strike.side_offset, b = strike.height_offset;
  const double c = std::sqrt(std::max(0.0, R * R - a * a - b * b));
  const Vec3 tip = Vec3{cue_ball.x, cue_ball.y, R} + a * side + b * up - c * d;
  const Vec3 butt = tip - kCueLength * d;
  for (const Vec2 p : other_balls)
    if (distance_to_segment(Vec3{p.x, p.y, R}, tip, butt) < R + kCueTipRadius) return true;
  // The rail: the first point (2 mm steps) where the cue is over it, within
  // its radius in plan of a cushion's nose or outside the playing area; the
  // cue only rises behind it.
  const double rail = rail_height(table);
  const double drop = kCueTipRadius / ce;  // the lower edge below the axis
  constexpr double kStep = 0.002;
  for (double s = 0.0; s <= kCueLength; s += kStep) {
    const Vec3 x = tip - s * d;
    const Vec2 p{x.x, x.y};
    bool over_rail = !inside_playing_area(table, p);
    for (std::size_t k = 0; k < table.cushions.size() && !over_rail; ++k)
      over_rail = distance_to_segment(table.cushions[k], p) < kCueTipRadius;
    if (over_rail) return x.z - drop < rail;
  }
  return false;
}

}  // namespace cueball
