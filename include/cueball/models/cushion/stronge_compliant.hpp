// Ball-cushion impact with tangential compliance: the `stronge_compliant`
// model, one plain kernel.
//
// Sources:
//   W. J. Stronge, "Impact Mechanics" (Cambridge University Press; 1st ed.
//     2000, section 5.2 "Tangential compliance in planar impact of rough
//     bodies"; 2nd ed. 2018, the same lumped-parameter model): at the contact
//     a massless particle is tied to one body by a normal spring and a
//     tangential spring and touches the other body with Coulomb friction; the
//     normal spring is stiffer in restitution than in compression (stiffness
//     k during compression, k / e^2 during restitution), which gives the
//     energetic coefficient of restitution e; the tangential spring keeps its
//     stiffness k_t throughout. The tangential motion then goes through slip,
//     stick and slip reversal, each phase a harmonic motion in closed form.
//     The ratio of the stiffnesses, eta^2 = k / k_t, fixes the ratio of the
//     tangential to the normal natural frequency (S3); an elastic contact has
//     Mindlin's eta^2 = (2 - nu) / (2 (1 - nu)) with Poisson's ratio nu (the
//     value Stronge uses for elastic bodies, and pooltool's
//     normal_tangent_stiffness_ratio), i.e. eta^2 in [1, 1.5], Omega in
//     [1.53, 1.87] for a solid sphere.
//   pooltool (E. Kiefl, D. McBlane; github.com/ekiefl/pooltool), ball-cushion
//     model `stronge_compliant` (pooltool/physics/resolve/ball_cushion/
//     stronge_compliant/ and pooltool/physics/resolve/stronge_compliant.py;
//     pull requests #240, which introduced it, and #256, which made it the
//     default with omega_ratio = 1.8). pooltool applies the model at the
//     ball's equator (a vertical cushion face) and drops the vertical
//     velocity afterwards; the defaults below are pooltool's.
//
// Frame of the impact: that of cushion_impact.hpp. X along the cushion, Y
// horizontal into the cushion, Z up; the cushion touches the ball at I, at
// height h: the common normal n = (0, cos theta, sin theta) from the centre
// to I makes the angle theta with Y, sin(theta) = (h - R)/R. pooltool's model
// is sin(theta) = 0 (the default); h = 7R/5 gives 0.4.
//
// What is modelled:
//   * The ball is a free rigid sphere (I = 2/5 M R^2) while the cushion pushes
//     it at I. For a sphere the inverse mass of the contact point is
//     diagonal in the contact frame, 1/M along n and 7/(2M) in every
//     tangential direction (S1): the normal motion does not depend on
//     friction, and the tangential slip keeps its direction (Stronge's
//     collinear case), so the whole impact is one scalar problem along the
//     initial slip direction t at I.
//   * Stronge's compliant contact at I (S2-S8): harmonic normal compression
//     and restitution, tangential stick and slip in closed form; a slip
//     ends (stick) at a closed-form instant, a stick ends (slip) at the first
//     zero of a difference of two sinusoids, found by steps that provably
//     cannot pass it. Any number of phases; pooltool's closed form allows
//     three (slip, stick, reversed slip) and agrees with this where those
//     suffice.
//   * The bed afterwards: the vertical velocity the cushion's impulse leaves
//     (-(1 + e) cos(theta) sin(theta) yG'(0) from the normal impulse, and the
//     vertical part of the friction impulse) is removed, as by a perfectly
//     plastic, frictionless bed (S9; pooltool: "rvw[1][2] = 0").
// What is not: the bed's friction and the bed's normal force during the
// impact (Mathavan 2010 has both; with them the problem is no longer
// collinear and needs the numerical solver of cushion_impact.hpp), cushion
// mass, rolling and spinning resistance at I, and any rate dependence (the
// result is homogeneous of degree one in the incoming velocities and does not
// depend on M or on the stiffness scale k, only on the ratio Omega).
// Consequence of S9 for theta > 0: a frictionless cushion returns
// yG' = -((1 + e) cos^2(theta) - 1) yG'(0), not -e yG'(0), because the bed
// absorbs the vertical part of the rebound; with sin(theta) = 0.4 and e = 1
// that is 0.68 yG'(0). Use sin(theta) = 0 (pooltool) unless that loss is
// wanted.
//
// Equations (derived in src/models/cushion/stronge_compliant.cpp). In units of the
// incoming normal contact speed V = yG'(0) cos(theta) and of time 1/omega_n:
//   S1  contact-point velocity change per unit impulse / M: 1 along n, beta = 7/2 along t
//   S2  normal: compression 0 <= t <= pi/2, phase phi = t; restitution up to
//       t_f = (1 + e) pi/2, phi = pi/2 + (t - pi/2)/e; normal force / (M V omega_n) = sin(phi),
//       normal impulse / (M V) p(t) = 1 - cos(phi) in compression, 1 - e cos(phi) in restitution,
//       p(t_f) = 1 + e; the normal contact velocity leaves at -e V
//   S3  Omega = omega_t / omega_n = sqrt(beta / eta^2), eta^2 = k / k_t
//   S4  friction limit on the spring deflection: |u| <= L(t) = mu eta^2 sin(phi)
//   S5  slip in direction sigma = +-1: u = -sigma L, v(t) = v(t0) - sigma mu beta (p(t) - p(t0)),
//       particle slip velocity s = v + du/dt = A + sigma mu (beta kappa - eta^2 / kappa) cos(phi)
//       (kappa = 1 in compression, e in restitution): affine in cos(phi)
//   S6  stick: du/dt = -v, u(t) = u_s cos(Omega tau) - (v_s / Omega) sin(Omega tau),
//       v(t) = Omega u_s sin(Omega tau) + v_s cos(Omega tau), tau = t - t_s
//   S7  slip -> stick where s = 0 (closed form from S5); stick -> slip where |u| = L (search)
//   S8  the first phase: stick if v0 <= mu eta^2, else slip; gross slip throughout if s
//       keeps its sign at the ends of both normal phases, v0 >= mu max(beta, (1 + e) beta - eta^2 / e);
//       then v_f = v0 - mu beta (1 + e)
//   S9  impulses / M: normal (1 + e) V along -n at I, tangential (v_f - v0) V / beta along t;
//       velocity and spin of a free sphere, then zG' := 0
// Limits: mu = 0 gives no tangential impulse; Omega -> infinity (a rigid
// tangential spring) gives the rigid-body Coulomb impulse of a rough sphere
// in Stronge's rigid-body theory (slip until the slip stops, then stick, the
// normal impulse fixed by the energetic coefficient):
// v_f = max(0, v0 - mu beta (1 + e)).
//
// The kernel allocates nothing, does not throw and is deterministic: validate
// the constants once (validate(), or build them with
// stronge_compliant_cushion()), then call stronge_compliant_rebound() in the
// simulation loop. Cost with the defaults (Release, a shared 2-core
// machine, best of repeated runs): 0.09-0.14 us per call for large random
// spins (mostly slip throughout), 0.16-0.25 us for rolling balls with side
// spin up to V/R (a stick phase; its end takes some 5 evaluations of two
// sine-cosine pairs on average, at most about 70 over a wide random scan of
// Omega in (1, 5]). Stiffer springs make more stick-slip cycles, some
// 0.7 Omega phases: about 500 evaluations on average for Omega in the
// hundreds.
#pragma once

#include "cueball/models/cushion/rebound.hpp"
#include "cueball/models/cushion/impact.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {

/// The model's constants in raw form.
struct StrongeCompliantCushion {
  double radius = 0.0;           ///< R, m, > 0
  double restitution = 0.0;      ///< e, Stronge's energetic coefficient of restitution (S2), (0, 1]
  double friction = 0.0;         ///< mu, ball-cushion Coulomb friction at I (S4, S5), [0, 1]
  double sin_theta = 0.0;        ///< sin(theta) = (h - R)/R of the normal at I, [0, 1); 0 = pooltool
  double frequency_ratio = 0.0;  ///< Omega = omega_t / omega_n (S3), (1, 1000]
};

/// The cushion's constants, with pooltool's defaults.
struct StrongeCompliantConstants {
  double restitution = 0.85;     ///< pooltool BallParams.e_c
  double friction = 0.2;         ///< pooltool BallParams.f_c
  double sin_theta = 0.0;        ///< pooltool applies the model at the equator
  double frequency_ratio = 1.8;  ///< pooltool PR #256 ("omega_ratio", raised from 1.7 to 1.8)
};

/// Combines the ball with the cushion's constants and validates the result.
StrongeCompliantCushion stronge_compliant_cushion(const BallParameters& ball,
                                                  const StrongeCompliantConstants& constants = {});

/// Omega of an elastic contact with Poisson's ratio nu in [0, 0.5) (S3 with
/// Stronge's eta^2 = (2 - nu) / (2 (1 - nu))): 1.698 for nu = 0.3 (pooltool's
/// first default, 1.7). Throws InvalidArgument ("nu") outside [0, 0.5).
double stronge_frequency_ratio(double poisson_ratio);

/// Throws InvalidArgument naming the first constant outside its range: R > 0;
/// e in (0, 1]; mu in [0, 1]; sin_theta in [0, 1); Omega in (1, 1000] (below
/// 1 the tangential spring is softer than k / beta, outside the elastic range
/// above and outside what the phase logic was checked for; far above, the
/// stick phases split into many short ones); and (1 + e) cos(theta)
/// (cos(theta) - mu sin(theta)) > 1 ("sin_theta"), which guarantees yG' < 0
/// after S9 whatever the friction does (at sin_theta = 0 it always holds).
void validate(const StrongeCompliantCushion& cushion);

/// The rebound. The caller guarantees validate(c) passes and that `ball` is
/// finite with yG' > 0 and zG' = 0 (IncomingBall's contract); the result is
/// then finite, never has more kinetic energy than `ball`, and has zG' = 0.
CushionRebound stronge_compliant_rebound(const IncomingBall& ball, const StrongeCompliantCushion& c) noexcept;

}  // namespace cueball
