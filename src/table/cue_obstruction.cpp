// Cue obstruction (cue_obstruction.hpp): the cue as a cylinder behind the
// contact point, checked against the other balls and the rail.
#include "cueball/table/cue_obstruction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cueball {

double rail_height(const Table& table) {
  double h = 0.0;
  for (const CushionSegment& c : table.cushions) h = std::max(h, c.contact_height);
  for (const JawArc& j : table.jaws) h = std::max(h, j.contact_height);
  return h;
}

namespace {

// The rail test of one point p of the cue's axis in plan: `over` as
// cue_obstructed() samples it (outside the playing area, or within the
// cue's radius of a cushion's nose line), and, when not, how far p can move
// in plan with that still false: its distance to the nearest nose line less
// the cue's radius, and to the playing area's boundary (inside_playing_area:
// the polygon of the nose lines and their joins, and the pockets' circles),
// whichever is smaller. Both are 1-Lipschitz in p.
struct RailSample {
  bool over = false;
  double clear = 0.0;
};
RailSample rail_sample(const Table& table, Vec2 p) {
  RailSample r;
  r.over = !inside_playing_area(table, p);
  double clear = std::numeric_limits<double>::infinity();
  Vec2 previous_end = table.cushions.empty() ? Vec2{} : table.cushions.back().end;
  for (const CushionSegment& c : table.cushions) {
    const double d = distance_to_segment(c, p);
    if (d < kCueTipRadius) r.over = true;
    clear = std::min({clear, d - kCueTipRadius, distance_to_segment(p, previous_end, c.start)});
    previous_end = c.end;
  }
  for (const Pocket& k : table.pockets) clear = std::min(clear, std::abs(norm(p - k.centre) - k.radius));
  r.clear = r.over ? 0.0 : clear;
  return r;
}

// Rounding in the distances and the samples' positions, m: far below the 2 mm steps.
constexpr double kClearSlack = 1e-9;
// The samples along the cue, m.
constexpr double kStep = 0.002;

}  // namespace

CueAxis cue_axis(Vec2 cue_ball, const CueStrike& strike, double radius) {
  const double R = radius;
  // The cue frame (C1) of cue_strike.hpp and the contact point (C2).
  const Vec3 u{std::cos(strike.aim), std::sin(strike.aim), 0.0};
  const Vec3 side{u.y, -u.x, 0.0};
  const double ce = std::cos(strike.elevation), se = std::sin(strike.elevation);
  const Vec3 d{ce * u.x, ce * u.y, -se};
  const Vec3 up{se * u.x, se * u.y, ce};
  const double a = strike.side_offset, b = strike.height_offset;
  const double c = std::sqrt(std::max(0.0, R * R - a * a - b * b));
  return {Vec3{cue_ball.x, cue_ball.y, R} + a * side + b * up - c * d, -d};
}

bool cue_obstructed(const Table& table, Vec2 cue_ball, const std::vector<Vec2>& other_balls, const CueStrike& strike,
                    double radius) {
  const double R = radius;
  const CueAxis axis = cue_axis(cue_ball, strike, radius);
  const Vec3 tip = axis.tip;
  const Vec3 d = -axis.toward_butt;  // along the strike, butt to tip
  const double ce = std::cos(strike.elevation);
  const Vec3 butt = tip - kCueLength * d;
  for (const Vec2 p : other_balls)
    if (distance_to_segment(Vec3{p.x, p.y, R}, tip, butt) < R + kCueTipRadius) return true;
  // The rail: the first point (2 mm steps) where the cue is over it, within
  // its radius in plan of a cushion's nose or outside the playing area; the
  // cue only rises behind it. The samples nearer in plan to one that is
  // clear than its clearance (rail_sample) cannot be over the rail and are
  // passed over, not tested: the same samples (s summed step by step), the
  // same answer, without testing the ~700 points of a cue over the bed.
  const double rail = rail_height(table);
  const double drop = kCueTipRadius / ce;  // the lower edge below the axis
  const double plan_step = ce * kStep;     // the axis moves ce per unit length in plan
  double s = 0.0;
  while (s <= kCueLength) {
    const Vec3 x = tip - s * d;
    const RailSample r = rail_sample(table, {x.x, x.y});
    if (r.over) return x.z - drop < rail;
    const double passable = (r.clear - kClearSlack) / plan_step;  // samples ahead that stay clear
    s += kStep;
    for (int j = 1; j < passable && s <= kCueLength; ++j) s += kStep;
  }
  return false;
}

}  // namespace cueball
