// The cue strike: where and how hard the cue hits the ball, and the ball's
// state just after.
//
// Sources:
//   [LG]  W. Leckie, M. Greenspan, "An event-based pool physics simulator",
//         Advances in Computer Games 11 (2006), LNCS 4250: the
//         cue-ball strike (impulse F along the cue through the contact point
//         (a, c, b), c = sqrt(R^2 - a^2 - b^2), the ball's v and w from it).
//         Their equations are not numbered in the copies we could check; the
//         equations below are numbered (C1)-(C7) here, and the test
//         LeckieGreenspanFormulasAgreeAfterTheChangeOfParameters reproduces
//         [LG]'s printed formulas and compares.
//   [M]   W. C. Marlow, "The Physics of Pocket Billiards" (1995), ch. 6: the
//         same impulse-momentum model, on which [LG] is based.
//   [A30] D. G. Alciatore, "Technical Proofs" (billiards.colostate.edu), TP A.30 "Effects of cue tip
//         offset on cue ball speed and spin": ball speed against tip offset,
//         natural roll at b = 2R/5, and (with TP A.31) the miscue limit of
//         about half the radius. Tip-ball friction 0.6 and restitution
//         0.71-0.87 are Alciatore's (shared/spec/equipment-and-pitfalls.md).
//
// ---------------------------------------------------------------------------
// The model (an instantaneous point impulse along the cue's axis).
//
// Cue frame (C1), in the table frame x, y on the bed, z up:
//     u    = (cos phi, sin phi, 0)          the aim: the cue's direction in the bed's plane
//     s    = u x z = (sin phi, -cos phi, 0) to the right, seen from behind the cue
//     d    = cos(theta) u - sin(theta) z    the cue's direction of travel (butt raised by theta)
//     e_up = sin(theta) u + cos(theta) z    "up" perpendicular to the cue, in its vertical plane
// (s, e_up, -d) is a right-handed orthonormal frame: the tip's view along the cue.
//
// Contact point, relative to the ball's centre (C2):
//     r = a s + b e_up - c d,    c = sqrt(R^2 - a^2 - b^2)
// i.e. a and b are the tip's offsets from the centre as seen sighting along
// the cue. Their length sqrt(a^2 + b^2) = R sin(psi) is the distance of the
// cue's axis from the centre, psi the angle between the axis and the ball's
// normal at the contact.
//
// Unknowns: the impulse J along d, the cue's speed V' after, the ball's v, w.
//     cue:          M_c (V' - V) = -J
//     ball:         m v = J d,   I w = r x (J d),   I = 2/5 m R^2
//     restitution:  (v + w x r) . d - V' = e V      (Newton, along the cue's axis)
// with |r x d|^2 = a^2 + b^2 these give (C3)
//     J = (1 + e) V / (1/m + 1/M_c + (a^2 + b^2)/I)
//       = (1 + e) m V / (1 + m/M_c + 5 (a^2 + b^2) / (2 R^2))
// and, in the table frame,
//     v = (J cos(theta) / m) u                                           (C4)
//     w = (J / I) r x d = (J / I) (a e_up - b s)
//       = (J / I) [a sin(theta) u + b (z x u) + a cos(theta) z]        (C5)
// The ball's speed is (C6)
//     |v| = (1 + e) V cos(theta) / (1 + m/M_c + 5 (a^2 + b^2) / (2 R^2))
// which for a level cue with a = 0 is [A30]'s speed against tip height and the
// relation behind level_cue_speed(); (C5) then gives R w = 5 b |v| / (2R), so
// natural roll (R w = |v|) needs b = 2R/5 (level_cue_tip_height()).
//
// Relation to [LG]'s parameters (their x axis points to the shooter's LEFT,
// the cue along -y; their b is the contact's height above the centre, c its
// horizontal depth):
//     a_LG = -a,   b_LG = b cos(theta) + c sin(theta),   c_LG = c cos(theta) - b sin(theta)   (C7)
// and their denominator a^2 + b_LG^2 cos^2 + c_LG^2 sin^2 - 2 b_LG c_LG cos sin
// is |r x d|^2 = a^2 + b^2. For a level cue the two parametrisations coincide
// (up to the sign of a). Offsets measured across the cue rather than
// vertically make the miscue limit the same at every elevation: with [LG]'s
// vertical offsets a centre-ball hit (a = b = 0) from an elevated cue has its
// axis R sin(theta) from the centre, a miscue beyond about 30 degrees.
//
// Sign conventions (the same as cloth_motion.hpp):
//   - b > 0 (above centre) gives topspin: for aim along +x, w_y > 0, and the
//     slip velocity v + R z x w of cloth_motion.hpp is then v (1 - 5b/(2R)):
//     zero at b = 2R/5 (natural roll), larger than v for draw (b < 0).
//   - a > 0 (RIGHT english) gives w_z > 0, anticlockwise seen from above:
//     the tip pushes the ball's right-hand side forward. (So right english
//     throws an object ball to the left and comes off a rail struck head-on to
//     the right, as players know it.)
//   - With the butt raised, a > 0 also spins the ball about the aim (w . u =
//     J a sin(theta) / I > 0): the swerve/masse component.
//
// Squirt ([A31] D. G. Alciatore, TP A.31 "Cue ball deflection (squirt) due
// to cue tip offset and cue end mass"). With side offset the tip, which holds
// on the ball, is pushed sideways by the spinning ball, and only the shaft's
// end mass m_e moves with it during the contact; the lateral impulse J_s s
// on the ball (s the cue's right, C1) follows from the no-slip condition
// across the cue, (v + w x r) . s = -J_s / m_e, with v and w from both
// impulses (C3)-(C5) and r x s = b d + c e_up:
//     J_s = -(5/2) J a c / (R^2 (1 + m/m_e + (5/2)(1 - a^2/R^2)))       (C8)
// so the ball leaves at the squirt angle alpha from the aim, towards the side
// opposite the offset (right english squirts left):
//     tan(alpha) = -J_s / (J cos(theta))
// which for a level cue and b = 0 is [A31]'s
//     tan(alpha) = (5/2) x sqrt(1 - x^2) / (1 + m/m_e + (5/2)(1 - x^2)),  x = a/R.
// The lateral impulse's torque (J_s / I)(b d + c e_up) takes a little of the
// sidespin back. m_e = 0 turns squirt off (J_s = 0 exactly). The default end
// mass 8 g (about m/m_e = 21 with a pool ball) gives 2.6 degrees at half a
// radius of english, the deflection of a standard (not low-deflection) shaft
// ([A31]'s measured range is about 1 to 3 degrees at that offset). Swerve
// still comes from the elevated cue's spin about the aim (C5).
//
// Approximations (document before you rely on them):
//   1. The vertical part of the impulse, J sin(theta) downward, is absorbed by
//      the bed: the bed's reaction acts through the bottom contact point and so
//      through the centre (no torque), and friction at the bed during the
//      impact is neglected. J itself is that of a free ball, as in [LG]; a
//      rigid bed would stiffen the ball against the vertical part and change J
//      somewhat. So the ball stays on the table (no jump shots), and strongly
//      elevated (masse) shots are approximate: their horizontal speed and the
//      spin about the aim are only indicative.
//   2. M_c is the whole cue's mass along the cue, as in [A30]'s speed
//      relation; across it only the shaft's end mass m_e moves during the
//      contact (squirt, below). No cue flex beyond that.
//   3. The tip holds (no slip) whenever sqrt(a^2 + b^2) <= kMiscueOffsetFraction R
//      and always slips beyond it. With tip friction mu = 0.6 the tip holds
//      while tan(psi) <= mu, i.e. psi <= 31 degrees, offset <= 0.51 R: the
//      same limit, Alciatore's half radius.
#pragma once

#include <array>

#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/parameters.hpp"
#include "cueball/core/vec.hpp"

namespace cueball {

/// The shaft's end mass of a standard pool cue, kg (squirt, C8).
inline constexpr double kDefaultCueEndMass = 0.008;

struct CueParameters {
  double mass = 0.54;              ///< M_c, kg (19 oz, Alciatore's typical cue)
  double tip_restitution = 0.75;   ///< e, cue tip-ball (Alciatore: 0.71-0.87)
  double end_mass = kDefaultCueEndMass;  ///< m_e, kg: the shaft's end mass of squirt (C8); 0: no squirt
};

/// Largest accepted end mass, kg (a shaft whose end 10 cm weighs 50 g).
inline constexpr double kMaxCueEndMass = 0.05;

/// The squirt angle alpha, radians, of a level cue with side offset a and
/// height offset b (C8): positive (to the left of the aim) for a > 0.
double squirt_angle(double side_offset, double height_offset, const BallParameters& ball, const CueParameters& cue);

/// Largest tip offset from the ball's centre before the tip slips, as a
/// fraction of R (Alciatore: about 0.5).
inline constexpr double kMiscueOffsetFraction = 0.5;

/// Height b of the tip above the ball's centre, m, for a level cue that gives
/// speed v0 > 0 and topspin w0 (positive = forward roll).
double level_cue_tip_height(double v0, double w0, const BallParameters& ball);

/// Cue speed V, m/s, that gives ball speed v0 when striking at height b.
double level_cue_speed(double v0, double tip_height, const BallParameters& ball, const CueParameters& cue);

/// True when |b| is within the miscue limit kMiscueOffsetFraction * R.
bool cue_tip_offset_ok(double tip_height, const BallParameters& ball);

// --------------------------------------------------------------- the strike

/// One stroke of the cue. Angles in radians, lengths in metres.
struct CueStrike {
  double speed = 0.0;          ///< V, m/s: the cue's speed just before impact, (0, kMaxCueSpeed]
  double aim = 0.0;            ///< phi, rad: the cue's direction in the bed's plane, anticlockwise from +x
  double elevation = 0.0;      ///< theta, rad: the butt raised above level, [0, pi/2); 0 = level cue
  double side_offset = 0.0;    ///< a, m: tip to the right of the centre, seen from behind the cue (across the cue)
  double height_offset = 0.0;  ///< b, m: tip above the centre, measured across the cue (in e_up, C1)
};

/// Fastest accepted cue speed, m/s (a power break is about 11 m/s at the ball).
inline constexpr double kMaxCueSpeed = 12.0;
/// Accepted cue masses, kg (the CLI's --cue-mass range).
inline constexpr double kMinCueMass = 0.1;
inline constexpr double kMaxCueMass = 2.0;

/// Throws InvalidArgument naming the first bad field and its allowed range:
/// "mass", "radius" (ball, kMassRange / kRadiusRange), "cue_mass" [0.1, 2] kg,
/// "cue_tip_e" [0, 1], "cue_end_mass" [0, kMaxCueEndMass] kg, "speed" (0, 12] m/s, "aim" (finite), "elevation"
/// [0, pi/2) rad, "side_offset" and "height_offset" (finite), and
/// "tip offset" when sqrt(a^2 + b^2) > kMiscueOffsetFraction R (a miscue).
void validate(const CueStrike& strike, const BallParameters& ball, const CueParameters& cue);

/// True when the strike's tip offset sqrt(a^2 + b^2) is within the miscue
/// limit kMiscueOffsetFraction * R, to 1e-12 relative so that a point computed
/// on the limit is inside (the check validate() makes).
bool cue_tip_offset_ok(const CueStrike& strike, const BallParameters& ball);

/// The ball's state just after the strike (C3)-(C5), at `position`: sliding
/// in general. Validates everything first (validate() above): a miscue is an
/// InvalidArgument naming "tip offset".
BallState strike_ball(const CueStrike& strike, Vec2 position, const BallParameters& ball, const CueParameters& cue);

/// The same kernel without validation, for loops whose inputs have passed
/// validate(): allocation-free, no throw. Outside the validated ranges the
/// result is meaningless (NaN for an offset beyond R).
BallState strike_ball_unchecked(const CueStrike& strike, Vec2 position, const BallParameters& ball,
                                const CueParameters& cue) noexcept;

// --------------------------------------------------------- execution noise

/// Standard deviations of a player's (or robot's) execution error, one per
/// field of CueStrike, in the same units (m/s, rad, rad, m, m). All >= 0.
struct CueStrikeNoise {
  double speed = 0.0;
  double aim = 0.0;
  double elevation = 0.0;
  double side_offset = 0.0;
  double height_offset = 0.0;

  /// == CueStrikeNoise{}: no noise at all, every "noisy" strike the nominal one.
  friend bool operator==(const CueStrikeNoise&, const CueStrikeNoise&) = default;
};

/// Throws InvalidArgument naming the first standard deviation that is
/// negative or not finite ("sigma speed", "sigma aim", ...).
void validate(const CueStrikeNoise& sigma);

/// The strike actually played: each field shifted by its sigma times one
/// standard-normal draw, in the order speed, aim, elevation, side_offset,
/// height_offset:
///     speed' = speed + sigma.speed * z[0],  aim' = aim + sigma.aim * z[1], ...
/// Independent Gaussian errors, additive and absolute. The caller owns the
/// random generator (reproducible batches, any engine, antithetic or
/// quasi-random draws); with zero sigma the strike is returned unchanged.
/// Pure: nothing is clamped, so the result may be a miscue (check with
/// cue_tip_offset_ok()) or out of range (negative elevation, speed <= 0),
/// which strike_ball() then reports; the batch simulator decides whether that
/// counts as a miscue or is redrawn. Throws InvalidArgument if sigma fails
/// validate() or a draw is not finite ("standard_normals[i]").
CueStrike with_noise(const CueStrike& strike, const CueStrikeNoise& sigma,
                     const std::array<double, 5>& standard_normals);

}  // namespace cueball
