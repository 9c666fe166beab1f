// Resting contacts: balls that touch a cushion, a jaw or each other without
// an impact worth the name, and what the simulator does with them.
//
// The impact models (cushion_impact.hpp, ball_collision.hpp) take a contact
// that closes at a finite normal speed and return the rebound. Two kinds of
// contact have no such speed, and instantaneous impulses alone cannot end
// them:
//
//   slow   the pair closes at under kPushSpeed (a slow roll tapping a resting
//          ball, a ball pushed along by the one it just hit). Rebounds would
//          come ever smaller and ever sooner without end (inelastic collapse,
//          a Zeno sequence; equipment-and-pitfalls.md, items 5-6).
//   pressed  the pair touches with no normal speed, but the friction of a
//          sliding ball's slip on the cloth (paper 001 eq. 2: a = -mu_s g u^)
//          drives it into the contact: a swerve or masse shot along a frozen
//          rail, a ball spinning against a rail or another ball. Left alone,
//          it would move into the body it touches.
//
// Both are resolved here by impulses that provably leave the contact neither
// closing nor pressed, and that only remove energy:
//
// 1. Against a wall (cushion nose or jaw, inward normal n), rest_against_wall:
//    a. the normal velocity into the wall is absorbed (a plastic normal
//       impulse from the wall: v.n -> 0, energy falls);
//    b. the part of the slip that presses the ball into the wall, u.n > 0, is
//       removed by the cloth's own friction, the wall's normal reaction
//       holding the centre: a friction impulse F at the contact with the bed
//       changes the slip by (5/2) F / m through the spin and the centre's
//       velocity by F / m, which the wall's reaction -F cancels. So
//       F = -(2/5) m (u.n) n, the spin changes by -(1/R) z^ x du, and v does
//       not. This is the impulse the constrained motion along the wall would
//       apply (the wall's reaction balancing the normal part of the cloth's
//       friction) until u.n vanished, taken at once. The friction does
//       negative work -(1/5) m (u.n)^2; the wall's does none (v.n = 0).
//    Afterwards v.n >= 0 and u.n <= 0: the ball's acceleration, -mu_s g u^ or
//    along -v^ when rolling, never points into the wall. The tangential part
//    of the slip, and so the swerve along the rail, is kept.
// 2. Two balls pressed together with no normal speed, press_apart: the same
//    for each ball whose slip presses it into the other, the reaction now
//    acting on the other ball (normal impulse J = (2/5) m |u.n| through the
//    centres, at the equator: no torque). The pressed ball keeps its velocity;
//    the other one leaves at J / m. Energy: the pressing ball's slip loses
//    (1/5) m (u.n)^2, the other gains at most J^2 / 2m = (2/25) m (u.n)^2.
// 3. Slow contacts between balls, and pressed pairs that press_apart cannot
//    part (their pressing comes from rolling, not slip), become a group: the
//    simulator gathers every ball touching the group that the group closes on
//    slowly, ends each member's slip with the impulse sliding would apply
//    anyway (-(2/7) m u, paper 001 eq. 9 reached at once), and gives them all
//    the group's mean velocity, rolling; walls the group touches take away the
//    part of that velocity into them (a projection onto the allowed cone).
//    Momentum is kept up to the walls' impulses; 7/10 m v^2 is convex and a
//    projection onto a cone through 0 shortens v, so energy does not rise.
//    Identical velocities mean identical accelerations: nothing within the
//    group approaches or presses again, so the cascade ends in one event.
//    At these speeds the group moves less than v^2 / (2 (5/7) mu_r g), under
//    a millimetre, before it stops.
//
// Sources: the impulses are derived here from paper 001's friction law
// (eqs 2 and 9: -mu_s m g u^, the slip's end at v - (2/7) u) and the
// cushion's normal reaction; resolving resting contact by impulses follows
// B. Mirtich and J. Canny, "Impulse-based simulation of rigid bodies" (1995);
// the inelastic collapse a pairwise impulse rule would run into is S.
// McNamara and W. R. Young, Phys. Rev. E 50, R28 (1994).
//
// What this leaves out: the contact is resolved at once instead of over the
// finite time that friction (at most mu_s m g) would take; the tangential
// slip does not feel the cushion's own friction (mu_w) nor the vertical part
// of the cushion's normal force during the pressed phase; a slow group moves
// as one body (no rolling of one ball over another). Fast contacts keep their
// impact models: a pair touching nothing else by the ball-ball model, a
// cluster of touching balls (a frozen rack, a Newton's cradle) all at once
// (simulation/contact_cluster.hpp).
#pragma once

#include <cstddef>
#include <span>

#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/vec.hpp"

namespace cueball {

/// Normal closing speeds below this are slow contacts (resolved here, not by
/// the impact models), m/s.
inline constexpr double kPushSpeed = 0.01;

/// The ball rolling (zero slip) with velocity v; the vertical spin is kept.
BallState rolling_with(const BallState& s, Vec2 velocity, double radius);

/// The ball after the friction impulse that ends its slip, -(2/7) m u (paper
/// 001 eq. 9): it rolls at v - (2/7) u.
BallState end_slip(const BallState& s, double radius);

/// The nearest velocity to v with no part into any wall of inward normals
/// `normals` (v'.n >= 0 for each): v itself, its projection onto one wall, or
/// zero (a corner). Exact: the allowed set is a cone in the plane.
Vec2 nearest_clear_of_walls(Vec2 v, std::span<const Vec2> normals);

/// The most walls one ball can touch at once that rest_against_walls takes
/// into account (a cushion and a jaw at their tangent point, a corner).
inline constexpr std::size_t kMaxWalls = 8;

/// rest_against_wall against every wall the ball touches at once (1. above
/// with the projections onto the cone of the walls: the walls' reactions are
/// then pushes, and the friction's work is -(1/5) m |du|^2). Walls beyond
/// kMaxWalls are ignored.
BallState rest_against_walls(const BallState& s, std::span<const Vec2> normals, double radius);

/// A ball touching a wall whose inward normal at the contact is `n` (unit),
/// slow or pressed (1. above): the state with no velocity into the wall and,
/// unless it is leaving the wall (v.n > 0, when the wall can exert no force),
/// no slip pressing into it.
BallState rest_against_wall(const BallState& s, Vec2 n, double radius);

/// Two touching balls, a and b, held in contact (closing by round-off, or
/// parting too slowly to clear it): absorbs their normal relative speed
/// (plastic), then removes the slip that presses each into the other (2.
/// above). Returns false when nothing changed (bit for bit).
bool press_apart(BallState& a, BallState& b, double radius);

}  // namespace cueball
