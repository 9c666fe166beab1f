// Closed-form motion on the cloth. Equation numbers refer to paper 001
// (A. Jaroukh, "Analysis of a billiard ball movement", Politechnical student
// journal 12(41), Bauman MSTU, 2019); vertical spin follows spec §1.
#include "cueball/physics/cloth_motion.hpp"

#include <cmath>
#include <limits>

#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Time for the vertical spin to decay to zero; +inf when there is none.
double vertical_spin_stop_time(double wz, const Parameters& p) {
  return std::abs(wz) > kSpinTolerance ? std::abs(wz) / spin_deceleration(p) : kInfinity;
}

// w_z after dt: linear decay towards zero, clamped (it never reverses).
double decay_vertical_spin(double wz, double dt, const Parameters& p) {
  if (dt >= vertical_spin_stop_time(wz, p) || std::abs(wz) <= kSpinTolerance) return 0.0;
  return wz - std::copysign(spin_deceleration(p) * dt, wz);
}

// Duration of sliding, t1 = 2|u0| / (7 mu_s g) (eq. 8).
double sliding_time(double slip_speed, const Parameters& p) {
  return 2.0 * slip_speed / (7.0 * sliding_deceleration(p));
}

// Duration of rolling until rest, 7|v1| / (5 mu_r g) (eq. 22 with v2 = 0).
double rolling_time(double speed, const Parameters& p) { return speed / rolling_deceleration(p); }

// Horizontal angular velocity of a ball rolling without slip: u = 0 in eq. 1
// gives w_h = z^ x v / R.
Vec2 rolling_spin(Vec2 v, double radius) { return perp(v) / radius; }

BallState slide(const BallState& s, double dt, const Parameters& p) {
  const double radius = p.ball.radius;
  const Vec2 u0 = slip_velocity(s, radius);
  const double slip_speed = norm(u0);
  const Vec2 u_hat = u0 / slip_speed;  // constant while sliding (eq. 4)
  const double a = sliding_deceleration(p);
  const double t1 = sliding_time(slip_speed, p);
  const double t = dt < t1 ? dt : t1;

  BallState out;
  out.position = s.position + t * s.velocity - (0.5 * a * t * t) * u_hat;  // eq. 7
  out.velocity = s.velocity - (a * t) * u_hat;                              // eq. 6
  out.angular_velocity.z = decay_vertical_spin(s.angular_velocity.z, dt, p);
  if (t < t1) {
    // w = w0 + (5 mu_s g / 2R) t (z^ x u^)  (eq. 3 integrated)
    const Vec2 dw = (2.5 * a * t / radius) * perp(u_hat);
    out.angular_velocity.x = s.angular_velocity.x + dw.x;
    out.angular_velocity.y = s.angular_velocity.y + dw.y;
  } else {
    // End of sliding: v1 = v0 - 2/7 u0 (eq. 9). Snap exactly onto rolling.
    out.velocity = s.velocity - (2.0 / 7.0) * u0;
    if (norm(out.velocity) <= kSpeedTolerance) out.velocity = {};  // a perfect stop shot
    const Vec2 w = rolling_spin(out.velocity, radius);
    out.angular_velocity.x = w.x;
    out.angular_velocity.y = w.y;
  }
  return out;
}

BallState roll(const BallState& s, double dt, const Parameters& p) {
  const double speed = norm(s.velocity);
  const Vec2 v_hat = s.velocity / speed;
  const double a = rolling_deceleration(p);
  BallState out;
  out.angular_velocity.z = decay_vertical_spin(s.angular_velocity.z, dt, p);
  if (dt < rolling_time(speed, p)) {
    out.position = s.position + dt * s.velocity - (0.5 * a * dt * dt) * v_hat;  // eq. 14
    out.velocity = s.velocity - (a * dt) * v_hat;                                // eq. 13
    const Vec2 w = rolling_spin(out.velocity, p.ball.radius);
    out.angular_velocity.x = w.x;
    out.angular_velocity.y = w.y;
  } else {
    out.position = s.position + (0.5 * speed / a) * s.velocity;  // eq. 14 at the stop: |v|^2 / 2a along v^
  }
  return out;
}

}  // namespace

const char* to_string(MotionPhase phase) {
  switch (phase) {
    case MotionPhase::sliding: return "sliding";
    case MotionPhase::rolling: return "rolling";
    case MotionPhase::spinning: return "spinning";
    case MotionPhase::stationary: return "stationary";
  }
  return "unknown";
}

MotionPhase motion_phase(const BallState& s, const Parameters& p) {
  const Vec2 u = slip_velocity(s, p.ball.radius);
  if (dot(u, u) > kSlipTolerance * kSlipTolerance) return MotionPhase::sliding;
  if (dot(s.velocity, s.velocity) > kSpeedTolerance * kSpeedTolerance) return MotionPhase::rolling;
  if (std::abs(s.angular_velocity.z) > kSpinTolerance) return MotionPhase::spinning;
  return MotionPhase::stationary;
}

double phase_end_time(const BallState& s, const Parameters& p) {
  switch (motion_phase(s, p)) {
    case MotionPhase::sliding: return sliding_time(norm(slip_velocity(s, p.ball.radius)), p);
    case MotionPhase::rolling: return rolling_time(norm(s.velocity), p);
    case MotionPhase::spinning:
    case MotionPhase::stationary: break;
  }
  return kInfinity;
}

NextTransition next_transition(const BallState& s, const Parameters& p) {
  const double t_spin = vertical_spin_stop_time(s.angular_velocity.z, p);
  double t_phase = kInfinity;
  Transition phase_end = Transition::none;
  switch (motion_phase(s, p)) {
    case MotionPhase::sliding:
      t_phase = sliding_time(norm(slip_velocity(s, p.ball.radius)), p);
      phase_end = Transition::sliding_ends;
      break;
    case MotionPhase::rolling:
      t_phase = rolling_time(norm(s.velocity), p);
      phase_end = Transition::rolling_ends;
      break;
    case MotionPhase::spinning:
    case MotionPhase::stationary:
      break;
  }
  if (t_spin < t_phase) return {t_spin, Transition::vertical_spin_ends};
  return {t_phase, phase_end};
}

BallState evolve_in_phase(const BallState& s, MotionPhase phase, double dt, const Parameters& p) {
  switch (phase) {
    case MotionPhase::sliding:
      return slide(s, dt, p);
    case MotionPhase::rolling:
      return roll(s, dt, p);
    case MotionPhase::spinning:
      return {s.position, {}, {0.0, 0.0, decay_vertical_spin(s.angular_velocity.z, dt, p)}};
    case MotionPhase::stationary:
      break;
  }
  return {s.position, {}, {}};
}

BallState evolve(const BallState& s, double dt, const Parameters& p) {
  BallState state = s;
  // Each pass either finishes or crosses one transition; there are at most
  // four (sliding ends, rolling ends, vertical spin ends, and nothing moves).
  for (int pass = 0; pass < 5; ++pass) {
    const MotionPhase phase = motion_phase(state, p);
    const NextTransition next = next_transition(state, p);
    if (dt < next.time || next.kind == Transition::none) return evolve_in_phase(state, phase, dt, p);
    state = evolve_in_phase(state, phase, next.time, p);
    dt -= next.time;
  }
  return state;
}

double kinetic_energy(const BallState& s, const BallParameters& b) {
  const Vec3& w = s.angular_velocity;
  return 0.5 * b.mass * dot(s.velocity, s.velocity) + 0.5 * moment_of_inertia(b) * dot(w, w);
}

void validate(const BallState& s) {
  if (!is_finite(s.position)) throw InvalidArgument("position", "position must be finite (got a NaN or infinity)");
  if (!is_finite(s.velocity)) throw InvalidArgument("velocity", "velocity must be finite (got a NaN or infinity)");
  if (!is_finite(s.angular_velocity))
    throw InvalidArgument("angular_velocity", "angular_velocity must be finite (got a NaN or infinity)");
  require_in_range("speed", norm(s.velocity), 0.0, kMaxSpeed, "|velocity|, m/s");
  require_in_range("angular speed", norm(s.angular_velocity), 0.0, kMaxAngularSpeed, "|angular_velocity|, rad/s");
}

StraightShot straight_shot(double v0, double w0, double side_spin, const Parameters& p) {
  BallState state{{0.0, 0.0}, {v0, 0.0}, {0.0, w0, side_spin}};
  StraightShot shot{0.0, 0.0, v0, 0.0, 0.0, 0.0};
  const auto translating = [](MotionPhase ph) { return ph == MotionPhase::sliding || ph == MotionPhase::rolling; };
  MotionPhase phase = motion_phase(state, p);
  double t = 0.0;
  for (int pass = 0; pass < 5; ++pass) {
    const NextTransition next = next_transition(state, p);
    if (next.kind == Transition::none) break;
    state = evolve_in_phase(state, phase, next.time, p);
    t += next.time;
    if (next.kind == Transition::sliding_ends) {
      shot.t1 = t;
      shot.x1 = state.position.x;
      shot.v1 = state.velocity.x;
    }
    // The vertical spin may end on its own or at the same instant as a phase.
    if (side_spin != 0.0 && shot.t_spin == 0.0 && state.angular_velocity.z == 0.0) shot.t_spin = t;
    const MotionPhase after = motion_phase(state, p);
    if (translating(phase) && !translating(after)) {
      shot.t2 = t;
      shot.x2 = state.position.x;
    }
    phase = after;
  }
  return shot;
}

BallState straight_shot_state(double v0, double w0, double side_spin, double t, const Parameters& p) {
  return evolve(BallState{{0.0, 0.0}, {v0, 0.0}, {0.0, w0, side_spin}}, t, p);
}

}  // namespace cueball
