// Ball-cushion impact: the one-impulse model of Han (2005).
//
// Sources:
//   I. Han, "Dynamics in carom and three cushion billiards", Journal of
//     Mechanical Science and Technology 19 (2005) 976-984: a single impulse
//     at the cushion contact I of a free sphere, Newton restitution along
//     the common normal, and Coulomb friction in the tangent plane, either
//     stopping the slip at I (the contact sticks) or, when that needs more
//     than mu times the normal impulse, opposing the incoming slip; the
//     ball's vertical velocity is then dropped (it stays on the bed). The
//     bed contact C takes no part.
//   J. van Balen, "Modelling of a three cushion billiard" (BSc thesis,
//     University of Twente, 2010): e = 0.85 for a cushion; pooltool (E.
//     Kiefl) pairs it with mu = 0.2 for this model (its han_2005 resolver).
//
// Frame of cushion_impact.hpp: X along the cushion, Y horizontal into the
// cushion, Z up; the cushion touches the ball at I, at height h, on the
// common normal n = (0, cos(theta), sin(theta)), sin(theta) = (h - R)/R.
// Equations (numbered here, derived in src/models/cushion/han_2005.cpp):
//   H1 approach speed along n: c = v . n = yG' cos(theta)  (zG' = 0).
//   H2 slip of the ball's surface at I in the tangent plane, along X and
//      t = (0, -sin(theta), cos(theta)):
//        s_x = xG' + R (wy sin(theta) - wz cos(theta)),  s_t = -yG' sin(theta) + R wx.
//   H3 normal impulse (free sphere, Newton): P_n = (1 + e) M c.
//   H4 impulse that stops the slip: P_s = (2/7) M |s| (a tangential impulse
//      changes the slip by 7/(2M) of itself: translation 1/M, rotation
//      R^2/I = 5/(2M)). Stick when P_s <= mu P_n: the tangential impulse is
//      -(2/7) M s; else slip: -mu P_n s/|s|.
//   H5 the impulse J = -P_n n + P_x X + P_t t changes the velocity by J/M in
//      X and Y (Z is dropped: the bed holds the ball) and the spin by
//      R n x J / I = (5/(2 M R)) (P_t, P_x sin(theta), -P_x cos(theta)).
// Closed form: about as cheap as a cushion can be (bench_simulator's
// five-cushion shot under each model). Energy never increases (H3, H4 take
// none in from a free sphere, and dropping the vertical velocity takes some
// out), a head-on ball stays in its plane, and with mu = 0 the spin is
// untouched and yG' becomes (1 - (1 + e) cos^2(theta)) yG': below
// e = 1/cos^2(theta) - 1 (0.19 at h = 7R/5) the ball keeps moving into the
// cushion (the rebound went into the vertical velocity that is dropped), and
// the simulator then takes it as a resting contact with the cushion. With
// the published constants every ball leaves (test_cushion_han_2005).
#pragma once

#include "cueball/models/cushion/rebound.hpp"
#include "cueball/models/cushion/impact.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {

/// The model's constants.
struct Han2005Cushion {
  double mass = 0.0;         ///< M, kg, > 0
  double radius = 0.0;       ///< R, m, > 0
  double restitution = 0.0;  ///< e, Newton's coefficient along the common normal (H3), [0, 1]
  double friction = 0.0;     ///< mu, ball-cushion Coulomb friction (H4), [0, 1]
  double sin_theta = 0.4;    ///< (h - R)/R, [0, 1)
};

/// e = 0.85 (van Balen), mu = 0.2 (pooltool's pairing for this model).
inline constexpr double kHan2005Restitution = 0.85;
inline constexpr double kHan2005Friction = 0.2;

/// The constants for `ball` and a cushion of contact height h (in [R, 2R)).
/// Does not validate: call validate() on the result.
Han2005Cushion han_2005_cushion(const BallParameters& ball, double restitution, double friction, double contact_height);

/// Throws InvalidArgument naming the first constant outside its range (above).
void validate(const Han2005Cushion& c);

/// The ball just after the impact (H1-H5). `ball` must move into the cushion
/// (yG' > 0); the constants must pass validate().
CushionRebound han_2005_rebound(const IncomingBall& ball, const Han2005Cushion& c) noexcept;

}  // namespace cueball
