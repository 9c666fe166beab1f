// Line of sight (line_of_sight.hpp): the two grazing strokes and the fan of
// every stroke that reaches the target, checked against the other balls.
#include "cueball/table/line_of_sight.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cueball {

namespace {

// The fan of strokes from C that reach the target O: directions within
// alpha of u (the unit vector C -> O), each running until the cue ball's
// centre is 2R from O. Its boundary: the two tangent segments C -> G-, C -> G+
// and the near arc of the circle of radius r = 2R about O between G- and G+.
struct Fan {
  Vec2 c, o, u;
  double d = 0.0;      // |O - C|
  double r = 0.0;      // 2R
  double alpha = 0.0;  // half-angle of the fan, asin(r / d)
  Vec2 left, right;    // the ghost-ball centres of the grazing strokes (G+ to the left of u, G- to the right)
};

Vec2 rotate(Vec2 v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

Fan make_fan(Vec2 cue, Vec2 target, double radius) {
  Fan f;
  f.c = cue;
  f.o = target;
  f.d = norm(target - cue);
  f.u = (target - cue) / f.d;
  f.r = 2.0 * radius;
  f.alpha = std::asin(f.r / f.d);
  const double tangent = std::sqrt(f.d * f.d - f.r * f.r);
  f.left = cue + tangent * rotate(f.u, f.alpha);
  f.right = cue + tangent * rotate(f.u, -f.alpha);
  return f;
}

// Distance from p to the near arc (directions from O within pi/2 - alpha of
// the direction O -> C).
double distance_to_near_arc(const Fan& f, Vec2 p) {
  const Vec2 v = p - f.o;
  const double len = norm(v);
  const double half = 0.5 * std::numbers::pi - f.alpha;
  if (len > 0.0) {
    const double cos_angle = std::clamp(dot(v / len, -f.u), -1.0, 1.0);
    if (std::acos(cos_angle) <= half) return std::abs(len - f.r);
  }
  return std::min(norm(p - f.left), norm(p - f.right));
}

// True when p lies inside the fan: within alpha of u seen from C and no
// farther from C than the contact along its own direction.
bool inside_fan(const Fan& f, Vec2 p) {
  const Vec2 v = p - f.c;
  const double t = norm(v);
  if (t == 0.0) return true;
  const double cos_delta = std::clamp(dot(v / t, f.u), -1.0, 1.0);
  const double delta = std::acos(cos_delta);
  if (delta > f.alpha) return false;
  const double s = f.d * std::sin(delta);
  const double t_hit = f.d * std::cos(delta) - std::sqrt(std::max(0.0, f.r * f.r - s * s));
  return t <= t_hit;
}

double distance_to_fan(const Fan& f, Vec2 p) {
  if (inside_fan(f, p)) return 0.0;
  return std::min({distance_to_segment(p, f.c, f.left), distance_to_segment(p, f.c, f.right),
                   distance_to_near_arc(f, p)});
}

}  // namespace

BallView view_of_ball(Vec2 cue, Vec2 target, const std::vector<Vec2>& obstacles, double radius) {
  BallView view;
  if (norm(target - cue) <= 2.0 * radius) {
    view.left_edge = view.right_edge = view.full = true;
    return view;
  }
  const Fan f = make_fan(cue, target, radius);
  const double clear = f.r - kSightTolerance;
  view.left_edge = view.right_edge = view.full = true;
  for (const Vec2 p : obstacles) {
    if (distance_to_segment(p, f.c, f.left) < clear) view.left_edge = false;
    if (distance_to_segment(p, f.c, f.right) < clear) view.right_edge = false;
    if (distance_to_fan(f, p) < clear) view.full = false;
  }
  return view;
}

}  // namespace cueball
