// Collision of two balls on the bed: an instantaneous impulse at the contact
// point, Newton restitution along the line of centres and Coulomb friction
// across it, with the spins. Produces cut-induced and spin-induced throw and
// spin transfer.
//
// Sources:
//   D. G. Alciatore, "TP A.14: The effects of cut angle, speed, and spin on
//     object ball throw" (technical proof, 2006): the contact slip velocity
//     v_rel = sqrt((v sin(phi) - R w_z)^2 + (R w_x cos(phi))^2), the
//     speed-dependent ball-ball friction mu(v_rel) = a + b exp(-c v_rel) with
//     a = 9.951e-3, b = 0.108, c = 1.088 s/m (his fit to Marlow's
//     measurements), and the stun-shot throw angle
//     theta = atan(min(mu v cos(phi) / v_rel, 1/7) (v sin(phi) - R w_z) / (v cos(phi))).
//     TP A.5 and A.6 (ball-ball impulse and friction); TP 3.1 (the 90 degree
//     rule) and TP 3.3 (the 30 degree rule).
//   S. Mathavan, M. R. Jackson, R. M. Parkin, "Numerical simulations of the
//     frictional collisions of solid balls on a rough surface", Sports
//     Engineering 17 (2014) 227-237: the same contact, with the normal
//     impulse as the independent variable, friction following the
//     instantaneous slip direction, and the vertical friction component
//     changing only the spins (both balls stay on the bed).
//   W. J. Stronge, "Impact Mechanics" (CUP, 2000), chapters 4-5: Coulomb
//     friction integrated over the normal impulse; slip stops, then sticks.
//
// What is implemented (equations B1-B8 are numbered here, see
// src/ball_collision.cpp for the derivation). Identical balls, mass m,
// radius R, I = 2/5 m R^2; n = (r_b - r_a)/|r_b - r_a| (horizontal),
// t = z^ x n, contact point K = r_a + R n at the centres' height.
//   B1 relative contact velocity of a's surface against b's at K:
//        c = (v_a - v_b) + R (w_a + w_b) x n
//      normal approach speed u_n = c . n = (v_a - v_b) . n (> 0 approaching);
//      tangential slip s = (s_t, s_z) = (c . t, c . z), horizontal and vertical.
//   B2 impulse P = m (p_n n + p_t t + p_z z) on b at K, -P on a at K.
//   B3 velocities: v_a -= p_n n + p_t t, v_b += p_n n + p_t t. The vertical
//      component p_z is taken up by the bed: both balls stay on it (the bed's
//      vertical impulses act through the centres and exert no torque), so p_z
//      changes only the spins. Positions are unchanged.
//   B4 spins: both balls receive the same angular impulse,
//        w_a += 5/(2R) (p_z t - p_t z),  w_b += 5/(2R) (p_z t - p_t z).
//   B5 normal: Newton restitution, u_n' = -e u_n, p_n = (1 + e) u_n / 2. The
//      normal and tangential parts are uncoupled for spheres, so Newton,
//      Poisson and Stronge's energetic coefficients coincide here.
//   B6 slip response: ds_t = -7 dp_t, ds_z = -5 dp_z (horizontal: translation
//      7/2 per ball; vertical: rotation only, 5/2 per ball).
//   B7 Coulomb friction over the normal impulse p in [0, p_n]: while s != 0,
//      (dp_t, dp_z) = mu s^ dp. The slip direction turns during the impact
//      (B6 is anisotropic): s_t = s_t0 exp(-7 L), s_z = s_z0 exp(-5 L), with
//      mu dp = |s| dL. If the slip reaches zero before p_n, the contact grips
//      for the rest of the impact: (p_t, p_z) = (s_t0 / 7, s_z0 / 5), and the
//      balls leave with zero slip at K. The slip never reverses.
//   B8 friction coefficient mu = friction + friction_excess exp(-friction_decay |s0|),
//      evaluated once, at the incoming slip speed |s0| (as TP A.14 does).
// For a slip with one component only (stun shots, or side spin alone) B7 is
// Alciatore's law: friction impulse min(mu p_n, |s0| / k) along the slip,
// k = 7 horizontal, 5 vertical. It is the model of Mathavan et al. (2014)
// without the ball-bed friction during the impact, solved exactly (their
// Euler steps in the normal impulse, in the limit of zero step).
// Not modelled: the hop of the ball that the vertical friction pushes up, the
// bed's friction during the impact, and ball deformation.
//
// Every function here is an allocation-free kernel; the collision does not
// validate (call validate() on the parameters at the API boundary).
#pragma once

#include <utility>

#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/parameters.hpp"
#include "cueball/core/vec.hpp"

namespace cueball {

/// Constants of the ball-ball contact. Friction as a function of the
/// incoming contact slip speed u (B8):
///   mu(u) = friction + friction_excess * exp(-friction_decay * u);
/// friction_excess = 0 gives a constant coefficient.
struct BallCollisionParameters {
  double restitution = 0.0;      ///< e, Newton's coefficient along the line of centres (B5), [0, 1]
  double friction = 0.0;         ///< mu at high slip speed (the constant mu when friction_excess = 0), [0, 1]
  double friction_excess = 0.0;  ///< extra mu at zero slip speed, [0, 1]; friction + friction_excess <= 1
  double friction_decay = 0.0;   ///< c, s/m: how fast the excess fades with slip speed, [0, 100]
  friend bool operator==(const BallCollisionParameters&, const BallCollisionParameters&) = default;
};

inline constexpr ParameterRange kBallRestitutionRange{
    "restitution", "ball-ball coefficient of restitution (Newton)", "", 0.0, 1.0};
inline constexpr ParameterRange kBallFrictionRange{
    "friction", "ball-ball friction at high slip speed", "", 0.0, 1.0};
inline constexpr ParameterRange kBallFrictionExcessRange{
    "friction_excess", "extra ball-ball friction at zero slip speed", "", 0.0, 1.0};
inline constexpr ParameterRange kBallFrictionDecayRange{
    "friction_decay", "decay rate of the extra ball-ball friction with slip speed", "s/m", 0.0, 100.0};

/// Throws InvalidArgument naming the first field that is not finite or lies
/// outside its range (above), or "friction_excess" when friction +
/// friction_excess > 1.
void validate(const BallCollisionParameters& p);

/// e = 0.95 (Alciatore: 0.92-0.98) with Alciatore's speed-dependent friction
/// fit mu(u) = 9.951e-3 + 0.108 exp(-1.088 u) (TP A.14).
BallCollisionParameters ball_collision_alciatore();

/// No friction at all: the impulse acts along the line of centres only and
/// the spins pass through unchanged.
BallCollisionParameters ball_collision_frictionless(double restitution);

/// mu at contact slip speed `slip_speed` >= 0 (m/s), B8.
double ball_friction(const BallCollisionParameters& p, double slip_speed);

/// True if the centres are closing: (r_b - r_a) . (v_b - v_a) < 0. A touching
/// pair that is separating (or at rest relative to each other) must not collide.
constexpr bool balls_approaching(const BallState& a, const BallState& b) {
  return dot(b.position - a.position, b.velocity - a.velocity) < 0.0;
}

/// The outcome of one collision.
struct BallCollisionResult {
  BallState a;  ///< ball a just after the impact (position unchanged)
  BallState b;  ///< ball b just after the impact (position unchanged)
  /// m p_n >= 0, N s: the normal impulse on b along n = (r_b - r_a)/|r_b - r_a| (on a along -n).
  double normal_impulse = 0.0;
  /// m p_t, N s: the horizontal friction impulse on b along t = z^ x n (on a the opposite).
  double tangential_impulse = 0.0;
  /// m p_z, N s: the vertical friction impulse on b (on a the opposite); the bed
  /// takes it up, so it changes only the spins (B3).
  double vertical_impulse = 0.0;
  double friction = 0.0;    ///< mu used (B8)
  double slip_speed = 0.0;  ///< |s0|, the incoming contact slip speed (B1), m/s
  /// The slip stopped during the impact: the balls leave the contact gripping
  /// (zero slip at K). False when there was no slip to begin with.
  bool gripped = false;
};

/// Collision of two identical balls touching (|r_b - r_a| = 2R) and
/// approaching (B1-B8): the states of a and b just after the impact, with the
/// impulses. Only the direction r_b - r_a is used, so a pair that overlaps or
/// gaps by round-off is treated as touching. A pair that is not approaching
/// (or with coincident centres) is returned unchanged with zero impulses.
/// Uses ball.radius, and ball.mass only to scale the reported impulses.
BallCollisionResult resolve_ball_collision(const BallState& a, const BallState& b, const BallParameters& ball,
                                           const BallCollisionParameters& contact) noexcept;

/// The same, returning only the two states {a, b} after the impact.
std::pair<BallState, BallState> collide_balls(const BallState& a, const BallState& b, const BallParameters& ball,
                                              const BallCollisionParameters& contact) noexcept;

}  // namespace cueball
