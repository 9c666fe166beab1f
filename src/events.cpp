// Collision-time prediction; see events.hpp for the method and the policy on
// which root counts.
#include "cueball/events.hpp"

#include <algorithm>
#include <cmath>

#include "cueball/polynomial_roots.hpp"

namespace cueball {

namespace {

// Which contact counts (events.hpp). A contact at one instant is described
// by its gap g (m, < 0 overlapping), normal speed g1 (m/s, < 0 closing) and
// normal acceleration g2 (m/s^2, < 0 driving it together).
struct GapKinematics {
  double g, g1, g2;
};

// Closing into contact, and not a graze: a pair closing so slowly that its
// own relative motion (g2 > 0: the curvature of a path past a ball or jaw)
// turns it back before it is kGrazeDepth deep never really meets (a ball
// running along a cushion past the point where a jaw is tangent to it closes
// on the jaw at ~1e-8 m/s, 1e-17 m deep); taking it as a contact would only
// set two nearly parallel walls against each other at one instant. A thin
// cut a nanometre deep is still a contact. Approach speeds below
// kMinApproachSpeed are none.
constexpr double kGrazeDepth = 1e-12;  // m

bool closing(const GapKinematics& k) {
  if (!(k.g1 < -kMinApproachSpeed)) return false;
  return !(k.g2 > 0.0) || k.g - k.g1 * k.g1 / (2.0 * k.g2) < -kGrazeDepth;
}

// A pair touching (gap within kContactTolerance, overlap by round-off
// included) that is not closing (g1 >= -1e-12) but whose relative normal
// acceleration drives it together, parting (if at all) too slowly to get
// farther than kContactTolerance apart before it turns back: it would enter
// the contact at once, yet f has a (near) double root at 0 with no
// decreasing crossing, so the root rule alone cannot see it. Accelerations
// below kMinPressAcceleration are round-off (|a| ~ 2 m/s^2 carries ~1e-16 of
// it); sustained over a 1 s slide, 1e-9 m/s^2 moves a ball 5e-10 m.
constexpr double kMinPressAcceleration = 1e-9;  // m/s^2

bool pressed(const GapKinematics& k) {
  if (!(k.g <= kContactTolerance && k.g1 >= -kMinApproachSpeed && k.g2 < -kMinPressAcceleration)) return false;
  const double parting = std::max(k.g1, 0.0);
  return k.g + parting * parting / (2.0 * -k.g2) <= kContactTolerance;
}

// A contact now (t = 0): touching or overlapping and closing, or pressed.
// Closing from a gap of up to `closing_gap` counts.
bool entering_now(const GapKinematics& k, double closing_gap = 0.0) {
  return (k.g <= closing_gap && closing(k)) || pressed(k);
}

// A closing speed at which no graze can be shallower than kGrazeDepth
// (|g1|^2 / 2 g2 with any g2 below ~1e4 m/s^2), so that the normal
// acceleration need not be formed, m/s.
constexpr double kSurelyClosing = 1e-4;

// The earliest t in [0, horizon] at which the contact is entered: now, or a
// root of the contact function f (ascending coefficients) at which it is
// closing. `at(t)` gives the gap kinematics at time t, `slope(t)` its
// normal speed alone (cheaper: at a root the gap is the contact distance).
template <std::size_t N, typename At, typename Slope>
std::optional<double> earliest_entering_root(const std::array<double, N>& c, double horizon, At at, Slope slope,
                                             bool may_touch_now) {
  if (may_touch_now && entering_now(at(0.0))) return 0.0;
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
    if (g1 < -kSurelyClosing || closing(at(t))) return t;
  }
  return std::nullopt;
}

// Gap kinematics of |d(t)| against the contact distance, d(t) = dr + dv t +
// da t^2/2 the relative path: the normal acceleration carries the curvature
// term |w_t|^2 / |d| of the relative velocity w's tangential part.
GapKinematics pair_kinematics(Vec2 dr, Vec2 dv, Vec2 da, double contact, double t) {
  const Vec2 d = dr + t * dv + (0.5 * t * t) * da;
  const Vec2 w = dv + t * da;
  const double r = norm(d);
  if (!(r > 0.0)) return {-contact, 0.0, 0.0};
  const double g1 = dot(d, w) / r;
  return {r - contact, g1, (dot(w, w) - g1 * g1 + dot(d, da)) / r};
}

GapKinematics line_kinematics(const QuadraticPath& s, const ContactLine& line, double t) {
  const Vec2 r = s.position - line.start + t * s.velocity + (0.5 * t * t) * s.acceleration;
  return {dot(line.normal, r) - line.contact_distance, dot(line.normal, s.velocity + t * s.acceleration),
          dot(line.normal, s.acceleration)};
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
  // |dr + dv t + da t^2/2|^2 - contact^2, ascending powers.
  const std::array<double, 5> c{dot(dr, dr) - contact * contact, 2.0 * dot(dr, dv), dot(dv, dv) + dot(dr, da),
                                dot(dv, da), 0.25 * dot(da, da)};
  // c[0] ~ 2 contact gap: only a pair within the tolerance can touch now.
  return earliest_entering_root(
      c, horizon, [&](double t) { return pair_kinematics(dr, dv, da, contact, t); },
      [&](double t) {
        const Vec2 d = dr + t * dv + (0.5 * t * t) * da;
        return dot(d, dv + t * da) / contact;  // normal relative velocity at contact, m/s
      },
      c[0] <= 3.0 * contact * kContactTolerance);
}

bool contact_now(const QuadraticPath& a, const QuadraticPath& b, double contact) {
  return entering_now(pair_kinematics(b.position - a.position, b.velocity - a.velocity,
                                      b.acceleration - a.acceleration, contact, 0.0),
                      kContactTolerance);
}

ContactLine contact_line(Vec2 start, Vec2 end, double contact_distance) {
  const double length = norm(end - start);
  const Vec2 e = (end - start) / length;
  return {start, e, perp(e), length, contact_distance};  // the playing surface is on the left
}

std::optional<double> predict_line_contact(const QuadraticPath& s, const ContactLine& line, double horizon) {
  const Vec2 n = line.normal;
  const Vec2 a = s.acceleration;
  const Vec2 r0 = s.position - line.start;
  const double d = line.contact_distance;
  const std::array<double, 3> c{dot(n, r0) - d, dot(n, s.velocity), 0.5 * dot(n, a)};
  if (c[1] == 0.0 && c[2] == 0.0) return std::nullopt;  // not moving across the line
  if (std::isfinite(horizon)) {
    // The hull's points all stay on the table side of the contact line.
    const Hull h = bezier_hull(r0, s.velocity, a, horizon);
    if (dot(n, h.p0) > d && dot(n, h.p1) > d && dot(n, h.p2) > d) return std::nullopt;
  }
  const auto t = earliest_entering_root(
      c, horizon, [&](double tt) { return line_kinematics(s, line, tt); },
      [&](double tt) { return dot(line.normal, s.velocity + tt * s.acceleration); }, c[0] <= kContactTolerance);
  if (!t || !within_segment(s, line, *t)) return std::nullopt;
  return t;
}

bool line_contact_now(const QuadraticPath& s, const ContactLine& line) {
  return within_segment(s, line, 0.0) && entering_now(line_kinematics(s, line, 0.0), kContactTolerance);
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
