// A cluster of touching balls struck at one instant (a frozen rack at the
// break, a frozen combination, a Newton's cradle): every contact of the
// cluster is resolved together, not pair by pair.
//
// Why. Resolving the touching pairs one after another, in any fixed order,
// passes the impulse along like an ideal Newton's cradle, and the order
// decides the outcome: mirror images of one break differ by twenty standard
// errors and reversing the balls' indices changes the share of breaks that
// make a ball (docs/break.md). Rigid simultaneous impulses (a linear
// complementarity problem with Newton's restitution) remove the order but
// are not unique for a rack and do not pass the impulse through it; which
// solution is right is decided by the contacts' compliance (Liu, Zhao &
// Brogliato 2008 [1]; Ceanga & Hurmuzlu 2001 [2]).
//
// The model: the geometry is frozen for the sub-millisecond impact (the
// balls move ~1e-3 R meanwhile [3]) and each contact k, along the line of
// centres n_k from its ball a to its ball b, is a Hertz spring on the
// normal approach delta_k [4, eq. 4.23; 1, eq. 2.4]:
//
//   d(delta_k)/dt = (v_a - v_b) . n_k                                   (C1)
//   F_k = K delta_k^(3/2)                 loading (delta_k = its maximum)
//   F_k = (K / e^3) (delta_k - (1 - e^2) delta_max)^(3/2)    unloading  (C2)
//   m dv_a/dt = -sum F_k n_k,  m dv_b/dt = +sum F_k n_k                 (C3)
//
// (C2) is Walton & Braun's loading-unloading hysteresis [5] for the Hertz
// law: the unloading branch returns e^2 of the work stored, so a single pair
// leaves with Newton's restitution e exactly, whatever its speed, and the
// cluster only loses energy. K is Hertz's for two phenolic resin balls
// (hertz_stiffness_per_mass: 0.48 mm of compression and 0.28 ms of contact
// at 5 m/s). Between touching balls the equations are homogeneous: scaling
// every velocity scales the outcome, and K only sets the time scale [1, 3].
// K matters for balls apart by a gap smaller than the compression (a rack
// of balls made to +-0.127 mm: docs/break.md): the approach of such a
// contact starts at -gap, so the wave crosses the gap inside the impact, as
// it does in a real rack, instead of a pairwise collision after it.
// (C1)-(C3) are integrated by velocity Verlet with a step of 1/64 of a
// pair's contact time at the cluster's largest possible relative speed
// (t_c = 2.94 delta_max / v [4, eq. 11.24]) until no contact carries a
// force or closes (or only slower than the simulator's resting contacts
// take over, or, across a gap, too slowly to close it within a contact
// time: a later collision). Momentum is kept to rounding (every impulse
// acts on two balls, equal and opposite); should the integration leave more
// energy than there was, the velocities relative to the centre of mass are
// scaled back, so energy never rises.
//
// Order: the balls are ranked by position (x, then y) and the contacts by
// their balls' ranks before anything is summed, so the result is the same to
// the last bit whatever order the balls are given in. Spin takes no part
// (frictionless contacts through the centres: no torque); a pair of balls
// touching nothing else keeps the ball-ball model's impact (friction,
// throw) in the simulator.
//
// Checks (tests/test_contact_cluster.cpp): one pair gives e; a Newton's
// cradle sends the last ball off; a perfectly racked 15-ball break with
// e = 1 against the Hertz integration of [3]; momentum, energy, index order,
// mirror images, step convergence.
//
// Sources:
// [1] C. Liu, Z. Zhao, B. Brogliato, "Frictionless multiple impacts in
//     multibody systems. I. Theoretical framework", Proc. R. Soc. A 464
//     (2008) 3193-3211, doi:10.1098/rspa.2008.0078.
// [2] V. Ceanga, Y. Hurmuzlu, "A new look at an old problem: Newton's
//     cradle", J. Appl. Mech. 68 (2001) 575-583, doi:10.1115/1.1344902.
// [3] "Perfectly centered break of a perfectly aligned pool ball rack"
//     (Physics / Mathematics Stack Exchange; Hertz 3/2 springs, e = 1,
//     15 balls: the balls' speeds and directions after the break).
// [4] K. L. Johnson, Contact Mechanics, Cambridge 1985, ch. 4 and 11.
// [5] O. R. Walton, R. L. Braun, "Viscosity, granular-temperature, and stress
//     calculations for shearing assemblies of inelastic, frictional disks",
//     J. Rheology 30 (1986) 949-980.
// E. J. Hinch, S. Saint-Jean, "The fragmentation of a line of balls by an
// impact", Proc. R. Soc. A 455 (1999) 3201-3220, show the same compliant
// chain reproducing a real cradle's small departures from the ideal one.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "cueball/core/parameters.hpp"
#include "cueball/core/vec.hpp"

namespace cueball {

/// Two balls of a cluster, by their index in its lists, touching or apart
/// by a gap smaller than the impact's compression.
struct ClusterContact {
  std::size_t a = 0;
  std::size_t b = 0;
  double gap = 0.0;  ///< m between the surfaces at the impact, >= 0: the approach starts at -gap
};

struct ClusterImpact {
  std::vector<Vec2> velocities;  ///< after the impact, in the input order
  std::vector<double> impulses;  ///< each contact's normal impulse per unit mass, m/s, in the input order
  int steps = 0;                 ///< integration steps taken
};

/// Verlet steps per contact time of a pair at the cluster's largest relative
/// speed: the outcome is within 1e-3 m/s per 10 m/s of the converged one
/// (test_contact_cluster, StepsConverge).
inline constexpr double kClusterStepsPerContactTime = 64.0;

/// Phenolic resin pool balls: Young's modulus and Poisson's ratio (S. Crown,
/// "Modeling the effects of velocity, spin, frictional coefficient, and
/// impact angle on deflection angle in near-elastic collisions of phenolic
/// resin spheres", as quoted in "Collision of billiard balls",
/// dbkcues.ru). Two pool balls closing at 5 m/s: 0.48 mm of compression,
/// 0.28 ms of contact.
inline constexpr double kPhenolicYoungsModulus = 5.84e9;  ///< Pa
inline constexpr double kPhenolicPoissonRatio = 0.34;

struct ClusterSettings {
  double restitution = 1.0;  ///< Newton's e, [0, 1] (taken as 0.01 below that: a perfectly plastic cluster can creep on without end)
  /// K / m of (C2), m^-1/2 s^-2: Hertz's K = (4/3) E* sqrt(R / 2) for two
  /// equal spheres [4, eq. 4.23], over a ball's mass. Without gaps the
  /// outcome does not depend on it.
  double stiffness = 1.0;
  /// m/s: the impact ends once no contact closes, or could be pushed by the
  /// work stored in it, faster than this (the simulator's resting contacts,
  /// resting_contact.hpp, take such slow contacts; 0: never).
  double slow_speed = 0.0;
  double steps_per_contact_time = kClusterStepsPerContactTime;
};

/// Resolves every contact of a cluster of equal balls at once, (C1)-(C3).
/// `positions` and `velocities` (horizontal, m and m/s) at the impact.
/// A contact apart across a gap that no closing speed brings shut within a
/// pair's contact time is left to close later. Throws SimulationError if
/// the cluster has not parted after 200000 steps.
ClusterImpact resolve_cluster_impact(std::span<const Vec2> positions, std::span<const Vec2> velocities,
                                     std::span<const ClusterContact> contacts, const ClusterSettings& settings);

/// K / m for two balls of the given radius and mass made of phenolic resin.
double hertz_stiffness_per_mass(const BallParameters& ball);
/// The greatest compression, m, and the duration, s, of a Hertz impact of
/// two equal balls closing at `speed` with K / m = `stiffness` (no
/// restitution loss) [4, eqs. 11.23-11.24].
double hertz_compression(double speed, double stiffness);
double hertz_contact_time(double speed, double stiffness);

}  // namespace cueball
