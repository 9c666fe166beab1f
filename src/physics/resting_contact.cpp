// Resting contacts: see resting_contact.hpp for the model and its argument.
#include "cueball/physics/resting_contact.hpp"

#include <array>
#include <cmath>

#include "cueball/physics/contact_prediction.hpp"

namespace cueball {

namespace {

// The spin change that alters the slip u = v + R z^ x w by du without
// touching v: w -> w - (1/R) z^ x du (the torque of a friction impulse at
// the bed, (2/5) m du, whose push on the centre is cancelled by a reaction).
void change_slip_by_spin(BallState& s, Vec2 du, double radius) {
  s.angular_velocity.x += du.y / radius;
  s.angular_velocity.y -= du.x / radius;
}

}  // namespace

BallState rolling_with(const BallState& s, Vec2 velocity, double radius) {
  const Vec2 w = perp(velocity) / radius;
  return {s.position, velocity, {w.x, w.y, s.angular_velocity.z}};
}

BallState end_slip(const BallState& s, double radius) {
  return rolling_with(s, s.velocity - (2.0 / 7.0) * slip_velocity(s, radius), radius);
}

Vec2 nearest_clear_of_walls(Vec2 v, std::span<const Vec2> normals) {
  const double slack = 1e-14 * norm(v);  // a projection's own round-off
  const auto clear = [&](Vec2 w) {
    for (Vec2 n : normals)
      if (dot(w, n) < -slack) return false;
    return true;
  };
  if (clear(v)) return v;
  // The allowed set is a cone in the plane: the nearest point of it is the
  // projection onto one of its edges, or its apex.
  Vec2 best{};
  double best_distance = dot(v, v);
  for (Vec2 n : normals) {
    const double into = dot(v, n);
    if (!(into < 0.0)) continue;
    const Vec2 w = v - into * n;
    if (clear(w) && into * into < best_distance) {
      best = w;
      best_distance = into * into;
    }
  }
  return best;
}

BallState rest_against_walls(const BallState& s, std::span<const Vec2> normals, double radius) {
  BallState out = s;
  // a. plastic: the velocity into the walls the ball is not leaving (normal
  // speed below kMinApproachSpeed) goes.
  std::array<Vec2, kMaxWalls> held{};
  std::size_t count = 0;
  for (Vec2 n : normals)
    if (dot(s.velocity, n) < kMinApproachSpeed && count < held.size()) held[count++] = n;
  out.velocity = nearest_clear_of_walls(s.velocity, std::span<const Vec2>(held.data(), count));
  // b. the pressing slip, against the walls the ball still rests on (a wall
  // cannot push a ball that moves away from it): the nearest slip that
  // presses into none of them, reached through the spin.
  std::size_t resting = 0;
  for (std::size_t k = 0; k < count; ++k)
    if (dot(out.velocity, held[k]) < kMinApproachSpeed) held[resting++] = held[k];
  // A slip below kSlipTolerance is rolling (cloth_motion.hpp): it presses nothing.
  const Vec2 u = slip_velocity(out, radius);
  const Vec2 clear = -nearest_clear_of_walls(-u, std::span<const Vec2>(held.data(), resting));
  if (norm(clear - u) > kSlipTolerance) change_slip_by_spin(out, clear - u, radius);
  return out;
}

BallState rest_against_wall(const BallState& s, Vec2 n, double radius) {
  return rest_against_walls(s, std::span<const Vec2>(&n, 1), radius);
}

bool press_apart(BallState& a, BallState& b, double radius) {
  const BallState a0 = a, b0 = b;
  const Vec2 n = (b.position - a.position) / norm(b.position - a.position);  // a -> b
  // A normal relative speed (a closing below the impact models' range, or a
  // parting too slow to clear the contact) is absorbed first (plastic,
  // momentum kept); one of round-off size is none.
  const double closing = -dot(b.velocity - a.velocity, n);
  if (std::abs(closing) >= kMinApproachSpeed) {
    a.velocity = a.velocity - (0.5 * closing) * n;
    b.velocity = b.velocity + (0.5 * closing) * n;
  }
  // a's friction, -mu_s g u^, points at b when u_a . n < 0; b's at a when u_b . n > 0.
  // A slip below kSlipTolerance is rolling (cloth_motion.hpp): it presses nothing.
  const double a_presses = -dot(slip_velocity(a, radius), n);
  const double b_presses = dot(slip_velocity(b, radius), n);
  const double push_b = a_presses > kSlipTolerance ? (2.0 / 5.0) * a_presses : 0.0;  // J / m on b, along n
  const double push_a = b_presses > kSlipTolerance ? (2.0 / 5.0) * b_presses : 0.0;  // J / m on a, along -n
  if (a_presses > kSlipTolerance) change_slip_by_spin(a, a_presses * n, radius);
  if (b_presses > kSlipTolerance) change_slip_by_spin(b, -b_presses * n, radius);
  a.velocity = a.velocity - push_a * n;
  b.velocity = b.velocity + push_b * n;
  // Changes below the resolution of the numbers are no change.
  return !(a.velocity == a0.velocity && b.velocity == b0.velocity && a.angular_velocity == a0.angular_velocity &&
           b.angular_velocity == b0.angular_velocity);
}

}  // namespace cueball
