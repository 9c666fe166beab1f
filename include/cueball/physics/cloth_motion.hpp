// Motion of one ball on the cloth, in closed form (paper 001 and spec §1).
//
// A ball on the bed is in one of four motion phases:
//   sliding   the contact point slips, u = v + R z^ x w != 0 (eq. 1). Friction
//             -mu_s m g u^ acts with u^ constant (eq. 4), so v, w are linear in
//             t and the path is a parabola (eqs 5-7). Lasts t1 = 2|u0|/(7 mu_s g)
//             (eq. 8) and ends with v1 = v0 - 2/7 u0 (eq. 9).
//   rolling   u = 0, w_horizontal = z^ x v / R. Rolling resistance decelerates
//             it at (5/7) mu_r g along v^ (eqs 11-14) until it stops after
//             7|v1| / (5 mu_r g) (eq. 22 with v2 = 0).
//   spinning  at rest on the cloth but turning about the vertical.
//   stationary nothing moves.
// Spin about the vertical, w_z, is independent of the others in every phase
// and decays linearly to zero: dw_z/dt = -(5 mu_sp g / 2R) sign(w_z) (spec §1,
// the torque of a finite contact patch), never reversing.
//
// Every function here is a pure, allocation-free kernel: no validation (call
// validate() on inputs at the API boundary), no time stepping.
#pragma once

#include "cueball/core/parameters.hpp"
#include "cueball/core/vec.hpp"

namespace cueball {

/// Kinematic state of a ball on the bed of the table.
struct BallState {
  Vec2 position;          ///< centre of the ball projected on the bed, m
  Vec2 velocity;          ///< velocity of the centre, m/s (in the bed's plane)
  Vec3 angular_velocity;  ///< rad/s; x, y horizontal, z about the vertical (positive: anticlockwise seen from above)
};

enum class MotionPhase { sliding, rolling, spinning, stationary };

/// "sliding", "rolling", "spinning" or "stationary".
const char* to_string(MotionPhase phase);

/// What changes at the end of the current piece of closed-form motion.
enum class Transition {
  none,            ///< nothing will change: the ball is stationary
  sliding_ends,    ///< slip reaches zero: sliding -> rolling (or -> at rest for a stop shot)
  rolling_ends,    ///< the ball stops translating: rolling -> spinning or stationary
  vertical_spin_ends,  ///< w_z reaches zero (the phase may stay the same)
};

struct NextTransition {
  double time;  ///< s from now; +infinity for Transition::none
  Transition kind;
};

/// Slip speeds below this (m/s) count as zero: the ball is rolling. At
/// mu_s g ~ 2 m/s^2 such a slip would vanish in under 1e-12 s.
inline constexpr double kSlipTolerance = 1e-12;
/// Speeds below this (m/s) count as zero: the ball is not translating.
inline constexpr double kSpeedTolerance = 1e-12;
/// Vertical spins below this (rad/s) count as zero.
inline constexpr double kSpinTolerance = 1e-10;

/// Contact-point slip velocity u = v + R z^ x w (paper 001 eq. 1).
constexpr Vec2 slip_velocity(const BallState& s, double radius) {
  return {s.velocity.x - radius * s.angular_velocity.y, s.velocity.y + radius * s.angular_velocity.x};
}

/// The motion phase, derived from the kinematics (never from a stored label).
MotionPhase motion_phase(const BallState& s, const Parameters& p);

/// Time until the equations of motion next change, and what changes.
NextTransition next_transition(const BallState& s, const Parameters& p);

/// Time until the ball's path changes: the end of sliding or of rolling,
/// ignoring the vertical spin (which never affects the path); +infinity for a
/// ball that is not translating. Event predictors use it as their horizon.
double phase_end_time(const BallState& s, const Parameters& p);

/// The state after `dt` seconds, assuming the ball stays in `phase` for the
/// whole interval (0 <= dt <= the next transition's time). At dt equal to the
/// transition time the result is snapped exactly onto the new phase (zero
/// slip, zero speed or zero vertical spin).
BallState evolve_in_phase(const BallState& s, MotionPhase phase, double dt, const Parameters& p);

/// The state after `dt` >= 0 seconds, crossing as many phase transitions as
/// needed (at most four). Equivalent to chaining evolve_in_phase().
BallState evolve(const BallState& s, double dt, const Parameters& p);

/// Kinetic energy, translational plus rotational (I = 2/5 m R^2), J.
double kinetic_energy(const BallState& s, const BallParameters& b);

/// Throws InvalidArgument naming the field if any component is not finite or
/// is implausibly large (|v| <= 30 m/s, |w| <= 3000 rad/s).
void validate(const BallState& s);

inline constexpr double kMaxSpeed = 30.0;            ///< m/s, far above a power break (~11 m/s)
inline constexpr double kMaxAngularSpeed = 3000.0;   ///< rad/s

/// Summary of a straight shot along +x from x = 0 (paper 001 §2, eqs 19-24):
/// a ball struck with speed v0, topspin w0 (positive turns it the way it rolls,
/// R w0 = v0 is natural roll) and side spin (w_z).
struct StraightShot {
  double t1;  ///< end of sliding, s (eq. 19)
  double x1;  ///< position at end of sliding, m (eq. 21)
  double v1;  ///< velocity at end of sliding, m/s, signed along +x (eq. 20)
  double t2;  ///< the ball stops translating, s (eq. 22 with v2 = 0)
  double x2;  ///< rest position, m (eq. 24)
  double t_spin;  ///< vertical spin reaches zero, s (0 without side spin)
};

/// Computed from the general closed forms above (so it also covers draw that
/// reverses the ball and overspin, which eqs 19-24 exclude).
StraightShot straight_shot(double v0, double w0, double side_spin, const Parameters& p);

/// The state of that straight shot at time t >= 0.
BallState straight_shot_state(double v0, double w0, double side_spin, double t, const Parameters& p);

}  // namespace cueball
