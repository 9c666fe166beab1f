// Ball-ball collision of Mathavan, Jackson & Parkin (2014): the impulse at
// the ball-ball contact integrated over the normal impulse, with Coulomb
// friction at the ball-ball contact AND at both balls' contacts with the
// cloth during the impact, solved exactly (event-driven, no fixed step).
//
// Source: S. Mathavan, M. R. Jackson, R. M. Parkin, "Numerical simulations of
// the frictional collisions of solid balls on a rough surface", Sports
// Engineering 17 (2014) 227-237; constants e_b = 0.89, mu_b = 0.05,
// mu_s = 0.21; their Tables 1 and 2 (cut shots of a rolling cue ball) are
// reproduced in tests/test_ball_collision_mathavan_2014.cpp. The paper's own
// equation numbers are not quoted here: its text was not at hand, only its
// tables and secondary descriptions of its scheme (explicit Euler steps in
// the normal impulse, the cloth's normal reaction from the vertical component
// of the ball-ball friction only, energetic restitution). Stronge, "Impact
// Mechanics" (CUP, 2000), chapters 4-5: friction over the normal impulse,
// slip, stick, and the energetic coefficient of restitution.
//
// Model (M1-M11 are derived in src/models/ball_collision/mathavan_2014.cpp).
// Identical balls, mass m, radius R, I = 2/5 m R^2. n = (r_b - r_a)/|r_b - r_a|
// (horizontal), t = z^ x n, z^ up. Ball-ball contact K at the centres'
// height; cloth contacts C_a = r_a - R z^, C_b = r_b - R z^.
//   M1 slips. At K (a's surface against b's): c = (v_a - v_b) + R (w_a + w_b) x n,
//      approach speed u_n = c . n, slip s = (s_t, s_z) = (c . t, c . z).
//      At the cloth: sigma_X = v_X - R w_X x z^ (horizontal), X = a, b.
//   M2 impulses per unit mass, functions of the normal impulse p (on b along n):
//      on b at K: p n + P_t t + P_z z^, on a the opposite; on X at C_X: the
//      cloth's friction F_X (horizontal) and normal reaction N_X z^.
//   M3 the balls stay on the cloth and gravity's impulse over the impact is
//      neglected (as the paper does): the cloth's reaction is the vertical
//      friction at K pressing a ball down, dN_b = max(-dP_z, 0),
//      dN_a = max(dP_z, 0). The ball pushed up gets no reaction and no cloth
//      friction (its hop is not modelled).
//   M4 velocities and spins: dv_a = -(dp n + dP_t t) + dF_a,
//      dv_b = dp n + dP_t t + dF_b, dw_X = 5/(2R) (dP_z t - dP_t z^ - z^ x dF_X).
//   M5 the slips are linear in the impulses:
//        du_n = -2 dp + (dF_a - dF_b) . n
//        ds_t = -7 dP_t + (dF_a - dF_b) . t
//        ds_z = -5 dP_z + 5/2 (dF_a + dF_b) . n
//        dsigma_a = -(1 + 5/2 dP_z/dp) n dp - dP_t t + 7/2 dF_a
//        dsigma_b =  (1 - 5/2 dP_z/dp) n dp + dP_t t + 7/2 dF_b
//   M6 Coulomb at K: (dP_t, dP_z) = mu_b s^ dp while s != 0. When s reaches
//      zero the contact grips with zero friction for the rest of the impact
//      (the only sticking friction consistent with M3-M5 is zero).
//   M7 Coulomb at the cloth: dF_X = -mu_s sigma_X^ dN_X; a cloth slip at zero
//      (a rolling ball, a ball at rest) slips at once along the part of its
//      rate that friction cannot cancel: it cannot stick for the allowed
//      constants (3.5 mu_s mu_b < 1).
//   M8 s_z never changes sign (s_z = 0 is invariant): the same ball is pressed
//      into the cloth for the whole impact (b when s_z < 0, as behind a
//      rolling cue ball; a when s_z > 0; none when s_z = 0).
//   M9 restitution (energetic, Stronge): compression ends at u_n = 0 with the
//      work W_c = Int u_n dp; the impact ends when Int u_n dp = (1 - e^2) W_c.
//      Without cloth friction u_n = u_n0 - 2p and this is Newton's
//      p_n = (1 + e) u_n0 / 2 of ball_collision.hpp (B5).
//   M10 solved in a blended slip age tau, dp/dtau = |s| / (|s| + mu_b): tau ~ p
//      while the slip is large, and tau ~ L (mu_b dp = |s| dL) near a grip,
//      where the slip dies out exponentially in tau instead of like a
//      non-integer power of the normal impulse left. Every rate is then
//      smooth: Dormand-Prince 5(4) steps with error control (1e-10 of the
//      velocity scale per step; the results agree with the closed forms to
//      ~1e-12), the ends of compression and of the impact located on the step
//      (Hermite start, Newton). Closed forms when there is no ball-ball
//      friction or slip, and for the normal impulse after a grip.
//   M11 with cloth_friction = 0 this is the model of resolve_ball_collision()
//      in ball_collision.hpp with a constant friction (friction_excess = 0);
//      the two agree to ~1e-12 of the velocities.
// Not modelled: the hop of the ball pushed up, vertical velocities, gravity's
// impulse during the impact, ball deformation, speed-dependent friction.
//
// Allocation-free; the collision does not validate (call validate() on the
// constants at the API boundary).
#pragma once

#include "cueball/models/ball_collision/coulomb_impulse.hpp"
#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {

/// Constants of the Mathavan et al. (2014) ball-ball impact.
struct Mathavan2014Contact {
  double restitution = 0.0;     ///< e_b, energetic coefficient of restitution (M9), [0, 1]
  double ball_friction = 0.0;   ///< mu_b, ball-ball sliding friction (M6), [0, 0.5]
  double cloth_friction = 0.0;  ///< mu_s, ball-cloth sliding friction during the impact (M7), [0, 0.5]
};

inline constexpr ParameterRange kMathavan2014RestitutionRange{
    "restitution", "ball-ball coefficient of restitution (energetic)", "", 0.0, 1.0};
inline constexpr ParameterRange kMathavan2014BallFrictionRange{
    "ball_friction", "ball-ball sliding friction", "", 0.0, 0.5};
inline constexpr ParameterRange kMathavan2014ClothFrictionRange{
    "cloth_friction", "ball-cloth sliding friction during the impact", "", 0.0, 0.5};

/// The paper's constants: e_b = 0.89, mu_b = 0.05, mu_s = 0.21.
Mathavan2014Contact mathavan_2014_contact();

/// Throws InvalidArgument naming the first field that is not finite or lies
/// outside its range (above). The ranges keep the model's premises: the
/// cloth contacts cannot stick during the impact (3.5 mu_s mu_b < 1).
void validate(const Mathavan2014Contact& c);

/// Collision of two identical balls touching and approaching (M1-M11): the
/// states just after the impact, with the ball-ball impulses (normal,
/// tangential along t, vertical) in N s. Conventions as resolve_ball_collision():
/// only the direction r_b - r_a is used, and a pair that is not approaching
/// (or with coincident centres) is returned unchanged with zero impulses.
/// `friction` is mu_b, `slip_speed` the incoming |s| (m/s), `gripped` whether
/// the ball-ball slip stopped during the impact. The cloth's friction
/// impulses are not reported: they are what the balls' total horizontal
/// momentum changes by.
BallCollisionResult mathavan_2014_collision(const BallState& a, const BallState& b, const BallParameters& ball,
                                            const Mathavan2014Contact& c) noexcept;

}  // namespace cueball
