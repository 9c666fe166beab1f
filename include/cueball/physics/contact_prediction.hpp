// When will the next event happen? Collision-time prediction from the
// closed-form trajectories of cloth_motion.hpp.
//
// Between two transitions a ball moves with constant acceleration (paper 001
// eqs 6-7 and 13-14), so its centre is a quadratic in time:
//     r(t) = r0 + v0 t + a t^2 / 2,
// with a = -mu_s g u^ while sliding, -(5/7) mu_r g v^ while rolling, 0 at rest.
// A contact condition that is a distance between two such curves, or between
// one and a fixed line or point, is then a polynomial in t:
//   ball - straight cushion   n . r(t) - c = d           quadratic
//   ball - ball               |r_b(t) - r_a(t)|^2 = (2R)^2   quartic
//   ball - circle (jaw, pocket) |r(t) - c|^2 = d^2        quartic
// solved by polynomial_roots.hpp, which dispatches on the true degree (equal
// accelerations make the leading coefficients exactly zero).
//
// Which root (equipment-and-pitfalls.md, items 2-4): the earliest root in
// [0, horizon] at which the pair is approaching (the contact function is
// decreasing), unless it is a graze so slow that the pair's own relative
// motion turns it back within 1e-12 m (it never really meets). A pair already touching or overlapping by round-off that is
// approaching collides now (t = 0); one that is touching and separating does
// not collide again. A tangent (grazing) root, where the pair neither
// approaches nor separates, is no collision: no impulse would be exchanged;
// neither is an approach slower than 1e-12 m/s (round-off of a contact just
// resolved, which even sustained for a whole shot moves a ball < 1e-10 m).
// A pair touching now (gap within kContactTolerance, either side) with no
// normal speed whose relative acceleration drives it together (a sliding
// ball curving into a rail, spin pressing a resting ball into a contact) is a
// contact now (t = 0): f has a double root at 0 and never crosses it
// decreasing, so the root rule alone would miss it for the whole segment.
//
// `horizon` is how long the current pieces of trajectory stay valid (the
// earliest next transition of the balls involved); roots beyond it are not
// reported, because the trajectories change there.
#pragma once

#include <optional>

#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {

/// Gap within which two bodies count as touching, m, either side of contact
/// (the simulator accepts balls overlapping by up to this much).
inline constexpr double kContactTolerance = 1e-9;
/// Normal approach speeds below this count as none, m/s: round-off (e.g. of a
/// contact just resolved), which even sustained for a whole shot would move a
/// ball by less than 1e-10 m.
inline constexpr double kMinApproachSpeed = 1e-12;

/// Constant acceleration of the ball's centre in its current motion phase.
Vec2 phase_acceleration(const BallState& s, const Parameters& p);

/// The centre's path within one motion phase: r(t) = position + velocity t +
/// acceleration t^2 / 2.
struct QuadraticPath {
  Vec2 position;
  Vec2 velocity;
  Vec2 acceleration;
};

QuadraticPath quadratic_path(const BallState& s, const Parameters& p);

/// The same path seen from dt later.
constexpr QuadraticPath advance(const QuadraticPath& q, double dt) {
  return {q.position + dt * q.velocity + (0.5 * dt * dt) * q.acceleration, q.velocity + dt * q.acceleration,
          q.acceleration};
}

/// The kernels on precomputed paths (what the simulator calls). Over a finite
/// horizon they first reject cheaply: a quadratic path over [0, h] is a
/// Bezier curve inside the triangle of its control points, so a triangle that
/// stays farther away than the contact distance means no contact, and no
/// polynomial is solved.
std::optional<double> predict_contact(const QuadraticPath& a, const QuadraticPath& b, double contact_distance,
                                      double horizon);
/// The cheap test alone: false when the relative path's hull over [0, horizon]
/// stays farther than contact_distance (no contact possible).
bool predict_contact_possible(const QuadraticPath& a, const QuadraticPath& b, double contact_distance,
                              double horizon);
std::optional<double> predict_line_contact(const QuadraticPath& s, Vec2 start, Vec2 end, double contact_distance,
                                           double horizon);

/// A straight cushion nose prepared once: unit direction, inward normal,
/// length and the contact distance.
struct ContactLine {
  Vec2 start;
  Vec2 direction;  ///< unit, start -> end
  Vec2 normal;     ///< unit, inward: perp(direction)
  double length = 0.0;
  double contact_distance = 0.0;
};
ContactLine contact_line(Vec2 start, Vec2 end, double contact_distance);
std::optional<double> predict_line_contact(const QuadraticPath& s, const ContactLine& line, double horizon);
std::optional<double> predict_circle_contact(const QuadraticPath& s, Vec2 centre, double distance, double horizon);

/// Whether the pair is entering contact at this instant by the rules above:
/// touching within kContactTolerance and closing, not a graze, or pressed.
/// (predict_contact reports a closing pair at t = 0 only once it touches: its
/// root lies a gap of up to 1e-9 m ahead.) A circle (jaw) is a path with no
/// motion.
/// `horizon` as for predict_contact (a pair parting now is pressed only if
/// its acceleration turns it back within the horizon).
bool contact_now(const QuadraticPath& a, const QuadraticPath& b, double contact_distance, double horizon);
/// The same for a straight cushion nose (foot of the perpendicular within it).
bool line_contact_now(const QuadraticPath& s, const ContactLine& line, double horizon);

/// Earliest time in [0, horizon] at which balls a and b (same radius) touch
/// while approaching.
std::optional<double> predict_ball_ball_contact(const BallState& a, const BallState& b, const Parameters& p,
                                                double horizon);

/// A straight cushion nose from `start` to `end`, with the playing surface on
/// the left (inward normal perp(end - start)). The ball touches it when its
/// centre is `contact_distance` from the nose line, with the foot of the
/// perpendicular between start and end.
std::optional<double> predict_ball_line_contact(const BallState& s, const Parameters& p, Vec2 start, Vec2 end,
                                                double contact_distance, double horizon);

/// Earliest time in [0, horizon] at which the ball's centre comes within
/// `distance` of `centre` while approaching it (a jaw arc's contact circle, a
/// pocket's capture circle).
std::optional<double> predict_ball_circle_contact(const BallState& s, const Parameters& p, Vec2 centre,
                                                  double distance, double horizon);

}  // namespace cueball
