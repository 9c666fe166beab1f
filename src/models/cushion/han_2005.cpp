// The one-impulse cushion model of Han (2005): equations H1-H5 of
// include/cueball/models/cushion/han_2005.hpp.
//
// Derivation. The cushion acts on the ball at I = G + R n only, by one
// impulse J, as on a free sphere. The velocity of the ball's surface at I is
// v + w x (R n), with
//   w x (R n) = R (wy sin(theta) - wz cos(theta), -wx sin(theta), wx cos(theta)).
// Its component along n is c = v . n (H1); along X and t = X x n =
// (0, -sin(theta), cos(theta)) it is s (H2). An impulse
// J = -P_n n + P_x X + P_t t gives
//   dv = J / M,   dw = R n x J / I,   n x X = (0, sin(theta), -cos(theta)),   n x t = X,
// so the surface velocity at I changes by -P_n/M along n and by
// (1/M + R^2/I) = 7/(2M) times (P_x, P_t) in the tangent plane: the normal
// and tangential problems separate. Newton's law c' = -e c gives H3; the
// tangential impulse that brings s to zero is -(2/7) M s, admissible while
// its size is at most mu P_n (Coulomb's cone), otherwise friction slides at
// mu P_n against the slip (H4; for a single impulse the slip keeps its
// direction while it shrinks, so "against the incoming slip" is exact).
// Han then keeps the ball on the bed: the vertical component of J/M is
// dropped, the bed supplying the opposite vertical impulse through the centre
// (no torque), H5.

#include "cueball/models/cushion/han_2005.hpp"

#include <cmath>

#include "cueball/core/errors.hpp"

namespace cueball {

Han2005Cushion han_2005_cushion(const BallParameters& ball, double restitution, double friction,
                                double contact_height) {
  return {ball.mass, ball.radius, restitution, friction, (contact_height - ball.radius) / ball.radius};
}

void validate(const Han2005Cushion& c) {
  require_in_range("mass", c.mass, 1e-12, 1e12, "M");
  require_in_range("radius", c.radius, 1e-12, 1e12, "R");
  require_in_range("restitution", c.restitution, 0.0, 1.0, "Han 2005 e");
  require_in_range("friction", c.friction, 0.0, 1.0, "Han 2005 mu");
  require_in_range("sin_theta", c.sin_theta, 0.0, 1.0 - 1e-9, "(h - R)/R");
}

CushionRebound han_2005_rebound(const IncomingBall& ball, const Han2005Cushion& c) noexcept {
  const double sn = c.sin_theta;
  const double cs = std::sqrt(1.0 - sn * sn);
  const double R = c.radius;
  const Vec3 v = ball.velocity;
  const Vec3 w = ball.angular_velocity;

  const double approach = v.y * cs + v.z * sn;                         // H1
  const double slip_x = v.x + R * (w.y * sn - w.z * cs);               // H2
  const double slip_t = -v.y * sn + v.z * cs + R * w.x;
  const double normal = (1.0 + c.restitution) * c.mass * approach;     // H3
  const double slip = std::hypot(slip_x, slip_t);
  const double stop = (2.0 / 7.0) * c.mass * slip;                     // H4
  const double scale = stop <= c.friction * normal ? (2.0 / 7.0) * c.mass : (slip > 0.0 ? c.friction * normal / slip : 0.0);
  const double p_x = -scale * slip_x;
  const double p_t = -scale * slip_t;

  CushionRebound out;                                                  // H5
  out.velocity = {v.x + p_x / c.mass, v.y + (-normal * cs - p_t * sn) / c.mass, 0.0};
  const double k = 2.5 / (c.mass * R);
  out.angular_velocity = {w.x + k * p_t, w.y + k * p_x * sn, w.z - k * p_x * cs};
  return out;
}

}  // namespace cueball
