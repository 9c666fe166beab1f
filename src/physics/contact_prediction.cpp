// Collision-time prediction; see contact_prediction.hpp for the method and the policy on
// which root counts.
#include "cueball/physics/contact_prediction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cueball/physics/polynomial_roots.hpp"

namespace cueball {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Which contact counts (contact_prediction.hpp). The contact function f (ascending
// coefficients: f = |d|^2 - D^2 for a pair, the gap itself for a line) and,
// at one instant, the gap g (m, < 0 overlapping) and normal speed g1 (m/s,
// < 0 closing).
struct GapKinematics {
  double g, g1;
};

// A graze shallower than this is no contact: a pair closing so slowly that
// its own relative motion turns it back first never really meets (a ball
// running along a cushion past the point where a jaw is tangent to it closes
// on the jaw at ~1e-8 m/s, 1e-17 m deep); taking it as a contact would only
// set two nearly parallel walls against each other at one instant. A thin
// cut a nanometre deep is still a contact.
constexpr double kGrazeDepth = 1e-12;  // m

// A closing speed at which no graze can be shallower than kGrazeDepth
// (|g1|^2 / 2 |g''| with any |g''| below ~1e4 m/s^2): such a contact needs no
// look ahead, m/s.
constexpr double kSurelyClosing = 1e-4;

// Whether f, from time t0, goes below `deep` before it rises above `clear`,
// within (t0, horizon]: the pair gets into the contact before it gets clear
// of it. Exact to every order of the motion (f is the whole polynomial): a
// pair touching with no normal speed may be driven together by its
// acceleration (a sliding ball curving into a rail), or at third order when
// that cancels against the curvature of its path, and f then has a (near)
// multiple root at t0 that is never crossed decreasing.
template <std::size_t N>
bool deepens(std::array<double, N> c, double t0, double horizon, double clear, double deep) {
  const auto roots = [](const std::array<double, N>& q) {
    if constexpr (N == 3) {
      return solve_quadratic(q);
    } else {
      return solve_quartic(q);
    }
  };
  const double f0 = c[0];
  double until = horizon;
  c[0] = f0 - clear;
  for (double t : roots(c))
    if (t > t0 && t < until) {
      until = t;
      break;
    }
  c[0] = f0 - deep;
  for (double t : roots(c))
    if (t > t0 && t <= until) return true;
  return false;
}

// The earliest t in [0, horizon] at which the contact is entered. Now (t = 0)
// when the pair touches (within kContactTolerance, overlap by round-off
// included) and gets into the contact before it gets clear; a pair closing
// fast only once it touches (gap <= 0), else at its root. Then the earliest
// root of f at which it is closing, unless it only grazes. `at0` is the
// gap kinematics at t = 0, `slope(t)` the normal speed at a root, `f_at(g)`
// the value of f at gap g.
template <std::size_t N, typename Slope, typename FAt>
std::optional<double> earliest_entering_root(const std::array<double, N>& c, double horizon, GapKinematics at0,
                                             Slope slope, FAt f_at) {
  const double clear = f_at(kContactTolerance);
  if (at0.g <= kContactTolerance) {
    if (at0.g1 < -kSurelyClosing ? at0.g <= 0.0
                                 : deepens(c, 0.0, horizon, clear, f_at(std::min(at0.g, 0.0) - kGrazeDepth)))
      return 0.0;
  }
  RealRoots<N - 1> roots;
  if constexpr (N == 3) {
    roots = solve_quadratic(c);
  } else {
    roots = solve_quartic(c);
  }
  for (double t : roots) {
    if (t < 0.0) continue;
    if (t > horizon) break;
    const double g1 = slope(t);
    if (!(g1 < -kMinApproachSpeed)) continue;
    if (g1 < -kSurelyClosing || deepens(c, t, horizon, clear, f_at(-kGrazeDepth))) return t;
  }
  return std::nullopt;
}

// Gap and normal speed of a pair at t = 0, d = dr the relative position and
// dv the relative velocity.
GapKinematics pair_kinematics(Vec2 dr, Vec2 dv, double contact) {
  const double r = norm(dr);
  if (!(r > 0.0)) return {-contact, 0.0};
  return {r - contact, dot(dr, dv) / r};
}

// |d|^2 - D^2 at gap g.
double pair_f_at(double contact, double g) { return g * (2.0 * contact + g); }

// The pair's contact function |dr + dv t + da t^2/2|^2 - D^2, ascending powers.
std::array<double, 5> pair_function(Vec2 dr, Vec2 dv, Vec2 da, double contact) {
  return {dot(dr, dr) - contact * contact, 2.0 * dot(dr, dv), dot(dv, dv) + dot(dr, da), dot(dv, da),
          0.25 * dot(da, da)};
}

// The line's contact function (the gap) n . r(t) - d, ascending powers.
std::array<double, 3> line_function(const QuadraticPath& s, const ContactLine& line) {
  const Vec2 n = line.normal;
  return {dot(n, s.position - line.start) - line.contact_distance, dot(n, s.velocity), 0.5 * dot(n, s.acceleration)};
}

bool within_segment(const QuadraticPath& s, const ContactLine& line, double t) {
  const Vec2 r = s.position - line.start + t * s.velocity + (0.5 * t * t) * s.acceleration;
  const double foot = dot(line.direction, r);
  return foot >= 0.0 && foot <= line.length;  // beyond the segment: a jaw's business
}

// Control points of the relative path d(t) = d0 + v t + a t^2/2 over [0, h]
// as a quadratic Bezier curve: d0, d0 + v h/2, d(h).
struct Hull {
  Vec2 p0, p1, p2;
};

Hull bezier_hull(Vec2 d0, Vec2 v, Vec2 a, double h) {
  return {d0, d0 + (0.5 * h) * v, d0 + h * v + (0.5 * h * h) * a};
}

double squared_distance_to_segment(Vec2 o, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(o - a, ab) / len2, 0.0, 1.0) : 0.0;
  const Vec2 d = a + t * ab - o;
  return dot(d, d);
}

// True when the triangle (hull) comes within `reach` of the origin.
bool hull_reaches_origin(const Hull& h, double reach) {
  const Vec2 o{};
  const double c0 = cross(h.p1 - h.p0, o - h.p0), c1 = cross(h.p2 - h.p1, o - h.p1), c2 = cross(h.p0 - h.p2, o - h.p2);
  if ((c0 >= 0 && c1 >= 0 && c2 >= 0) || (c0 <= 0 && c1 <= 0 && c2 <= 0)) return true;  // inside
  const double r2 = reach * reach;
  return squared_distance_to_segment(o, h.p0, h.p1) <= r2 || squared_distance_to_segment(o, h.p1, h.p2) <= r2 ||
         squared_distance_to_segment(o, h.p2, h.p0) <= r2;
}

}  // namespace

bool predict_contact_possible(const QuadraticPath& a, const QuadraticPath& b, double contact, double horizon) {
  if (!std::isfinite(horizon)) return true;
  return hull_reaches_origin(bezier_hull(b.position - a.position, b.velocity - a.velocity,
                                         b.acceleration - a.acceleration, horizon),
                             contact);
}

QuadraticPath quadratic_path(const BallState& s, const Parameters& p) {
  return {s.position, s.velocity, phase_acceleration(s, p)};
}

std::optional<double> predict_contact(const QuadraticPath& a, const QuadraticPath& b, double contact,
                                      double horizon) {
  const Vec2 dr = b.position - a.position;
  const Vec2 dv = b.velocity - a.velocity;
  const Vec2 da = b.acceleration - a.acceleration;
  if (dv == Vec2{} && da == Vec2{}) return std::nullopt;  // no relative motion
  // Cheap rejection: the relative path's hull never comes within contact.
  if (std::isfinite(horizon) && !hull_reaches_origin(bezier_hull(dr, dv, da, horizon), contact)) return std::nullopt;
  const std::array<double, 5> c = pair_function(dr, dv, da, contact);
  // c[0] ~ 2 contact gap: only a pair within the tolerance can touch now.
  const GapKinematics at0 = c[0] <= 3.0 * contact * kContactTolerance ? pair_kinematics(dr, dv, contact)
                                                                      : GapKinematics{kInfinity, 0.0};
  return earliest_entering_root(
      c, horizon, at0,
      [&](double t) {
        const Vec2 d = dr + t * dv + (0.5 * t * t) * da;
        return dot(d, dv + t * da) / contact;  // normal relative velocity at contact, m/s
      },
      [&](double g) { return pair_f_at(contact, g); });
}

// Touching now (within kContactTolerance) and getting into the contact: the
// rule of earliest_entering_root at t = 0, a pair closing fast from a gap
// within the tolerance included.
template <std::size_t N, typename FAt>
bool touching_and_entering(const std::array<double, N>& c, GapKinematics k, double horizon, FAt f_at) {
  if (k.g > kContactTolerance) return false;
  if (k.g1 < -kSurelyClosing) return true;
  return deepens(c, 0.0, horizon, f_at(kContactTolerance), f_at(std::min(k.g, 0.0) - kGrazeDepth));
}

bool contact_now(const QuadraticPath& a, const QuadraticPath& b, double contact, double horizon) {
  const Vec2 dr = b.position - a.position;
  const Vec2 dv = b.velocity - a.velocity;
  const Vec2 da = b.acceleration - a.acceleration;
  if (dv == Vec2{} && da == Vec2{}) return false;
  return touching_and_entering(pair_function(dr, dv, da, contact), pair_kinematics(dr, dv, contact), horizon,
                               [&](double g) { return pair_f_at(contact, g); });
}

ContactLine contact_line(Vec2 start, Vec2 end, double contact_distance) {
  const double length = norm(end - start);
  const Vec2 e = (end - start) / length;
  return {start, e, perp(e), length, contact_distance};  // the playing surface is on the left
}

std::optional<double> predict_line_contact(const QuadraticPath& s, const ContactLine& line, double horizon) {
  const std::array<double, 3> c = line_function(s, line);
  if (c[1] == 0.0 && c[2] == 0.0) return std::nullopt;  // not moving across the line
  if (std::isfinite(horizon)) {
    // The hull's points all stay on the table side of the contact line.
    const Vec2 n = line.normal;
    const double d = line.contact_distance;
    const Hull h = bezier_hull(s.position - line.start, s.velocity, s.acceleration, horizon);
    if (dot(n, h.p0) > d && dot(n, h.p1) > d && dot(n, h.p2) > d) return std::nullopt;
  }
  const auto t = earliest_entering_root(
      c, horizon, GapKinematics{c[0], c[1]},
      [&](double tt) { return dot(line.normal, s.velocity + tt * s.acceleration); }, [](double g) { return g; });
  if (!t || !within_segment(s, line, *t)) return std::nullopt;
  return t;
}

bool line_contact_now(const QuadraticPath& s, const ContactLine& line, double horizon) {
  const std::array<double, 3> c = line_function(s, line);
  if (c[1] == 0.0 && c[2] == 0.0) return false;
  return within_segment(s, line, 0.0) &&
         touching_and_entering(c, GapKinematics{c[0], c[1]}, horizon, [](double g) { return g; });
}

std::optional<double> predict_line_contact(const QuadraticPath& s, Vec2 start, Vec2 end, double contact_distance,
                                           double horizon) {
  return predict_line_contact(s, contact_line(start, end, contact_distance), horizon);
}

std::optional<double> predict_circle_contact(const QuadraticPath& s, Vec2 centre, double distance, double horizon) {
  return predict_contact({centre, {}, {}}, s, distance, horizon);
}

Vec2 phase_acceleration(const BallState& s, const Parameters& p) {
  switch (motion_phase(s, p)) {
    case MotionPhase::sliding: {
      const Vec2 u = slip_velocity(s, p.ball.radius);
      return -(sliding_deceleration(p) / norm(u)) * u;  // paper 001 eq. 2
    }
    case MotionPhase::rolling:
      return -(rolling_deceleration(p) / norm(s.velocity)) * s.velocity;  // eq. 13
    case MotionPhase::spinning:
    case MotionPhase::stationary:
      break;
  }
  return {};
}

std::optional<double> predict_ball_ball_contact(const BallState& a, const BallState& b, const Parameters& p,
                                                double horizon) {
  return predict_contact(quadratic_path(a, p), quadratic_path(b, p), 2.0 * p.ball.radius, horizon);
}

std::optional<double> predict_ball_line_contact(const BallState& s, const Parameters& p, Vec2 start, Vec2 end,
                                                double contact_distance, double horizon) {
  return predict_line_contact(quadratic_path(s, p), start, end, contact_distance, horizon);
}

std::optional<double> predict_ball_circle_contact(const BallState& s, const Parameters& p, Vec2 centre,
                                                  double distance, double horizon) {
  return predict_circle_contact(quadratic_path(s, p), centre, distance, horizon);
}

}  // namespace cueball
