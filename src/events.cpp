// Collision-time prediction; see events.hpp for the method and the policy on
// which root counts.
#include "cueball/events.hpp"

#include <cmath>

#include "cueball/polynomial_roots.hpp"

namespace cueball {

namespace {

// The earliest root of f in [0, horizon] at which f is decreasing (entering
// contact), f given by ascending coefficients and f' by `slope`, which is
// scaled so that it is a normal approach speed in m/s when negative. A
// contact function already <= 0 and decreasing at t = 0 means contact now.
// Approach speeds below kMinApproachSpeed count as none: they are round-off
// (e.g. of a contact just resolved), and even sustained for a whole shot they
// would move a ball by less than 1e-10 m.
constexpr double kMinApproachSpeed = 1e-12;  // m/s

template <std::size_t N, typename Slope>
std::optional<double> earliest_entering_root(const std::array<double, N>& c, double horizon, Slope slope) {
  if (c[0] <= 0.0 && slope(0.0) < -kMinApproachSpeed) return 0.0;
  RealRoots<N - 1> roots;
  if constexpr (N == 3) {
    roots = solve_quadratic(c);
  } else {
    roots = solve_quartic(c);
  }
  for (double t : roots) {
    if (t < 0.0) continue;
    if (t > horizon) break;
    if (slope(t) < -kMinApproachSpeed) return t;
  }
  return std::nullopt;
}

}  // namespace

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
  const Vec2 dr = b.position - a.position;
  const Vec2 dv = b.velocity - a.velocity;
  const Vec2 da = phase_acceleration(b, p) - phase_acceleration(a, p);
  if (dv == Vec2{} && da == Vec2{}) return std::nullopt;  // no relative motion
  const double contact = 2.0 * p.ball.radius;
  // Cheap rejection: the gap cannot close within the horizon.
  if (std::isfinite(horizon)) {
    const double reach = norm(dv) * horizon + 0.5 * norm(da) * horizon * horizon;
    if (norm(dr) - contact > reach) return std::nullopt;
  }
  // |dr + dv t + da t^2/2|^2 - (2R)^2, ascending powers.
  const std::array<double, 5> c{dot(dr, dr) - contact * contact, 2.0 * dot(dr, dv), dot(dv, dv) + dot(dr, da),
                                dot(dv, da), 0.25 * dot(da, da)};
  return earliest_entering_root(c, horizon, [&](double t) {
    const Vec2 d = dr + t * dv + (0.5 * t * t) * da;
    return dot(d, dv + t * da) / contact;  // normal relative velocity at contact, m/s
  });
}

std::optional<double> predict_ball_line_contact(const BallState& s, const Parameters& p, Vec2 start, Vec2 end,
                                                double contact_distance, double horizon) {
  const Vec2 along = end - start;
  const double length = norm(along);
  const Vec2 e = along / length;
  const Vec2 n = perp(e);  // inward normal: the playing surface is on the left
  const Vec2 a = phase_acceleration(s, p);
  const std::array<double, 3> c{dot(n, s.position - start) - contact_distance, dot(n, s.velocity), 0.5 * dot(n, a)};
  if (c[1] == 0.0 && c[2] == 0.0) return std::nullopt;  // not moving across the line
  const auto t = earliest_entering_root(c, horizon, [&](double tt) { return dot(n, s.velocity + tt * a); });
  if (!t) return std::nullopt;
  const Vec2 r = s.position + *t * s.velocity + (0.5 * *t * *t) * a;
  const double foot = dot(e, r - start);
  if (foot < 0.0 || foot > length) return std::nullopt;  // beyond the segment: a jaw's business
  return t;
}

std::optional<double> predict_ball_circle_contact(const BallState& s, const Parameters& p, Vec2 centre,
                                                  double distance, double horizon) {
  const Vec2 a = phase_acceleration(s, p);
  if (s.velocity == Vec2{} && a == Vec2{}) return std::nullopt;
  const Vec2 dr = s.position - centre;
  if (std::isfinite(horizon)) {
    const double reach = norm(s.velocity) * horizon + 0.5 * norm(a) * horizon * horizon;
    if (norm(dr) - distance > reach) return std::nullopt;
  }
  const std::array<double, 5> c{dot(dr, dr) - distance * distance, 2.0 * dot(dr, s.velocity),
                                dot(s.velocity, s.velocity) + dot(dr, a), dot(s.velocity, a), 0.25 * dot(a, a)};
  return earliest_entering_root(c, horizon, [&](double t) {
    const Vec2 d = dr + t * s.velocity + (0.5 * t * t) * a;
    return dot(d, s.velocity + t * a) / distance;  // radial velocity at contact, m/s
  });
}

}  // namespace cueball
