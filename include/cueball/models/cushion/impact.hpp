// Ball-cushion impact: the model of Mathavan, Jackson & Parkin (2010).
//
// Sources:
//   S. Mathavan, M. R. Jackson, R. M. Parkin, "A theoretical analysis of
//     billiard ball dynamics under cushion impacts", Proc. IMechE Part C 224
//     (2010); Russian translation by S. Tikhonov (2013) with the
//     translator's notes and afterword (shared/seeds/000_*.txt); engineering
//     digest in shared/spec/physics.md section 2. Equation numbers below are
//     the paper's.
//   W. J. Stronge, "Impact Mechanics" (Cambridge University Press, 2000):
//     normal impulse as the independent variable, the energetic coefficient of
//     restitution (16b), and slip / stick / slip-reversal at a frictional
//     contact (chapter 5: stick while the friction needed to hold the contact
//     lies inside the friction cone, otherwise slip opposing the slip
//     velocity; slip resumes in the direction that keeps friction continuous).
//
// Frame of the impact (paper Figs 2-4): X along the cushion, Y horizontal and
// pointing into the cushion, Z up. The cushion touches the ball at I, at
// height h above the bed: the common normal makes the angle theta with Y,
// sin(theta) = (h - R) / R (h = 7R/5 gives 2/5). The ball also touches the
// bed at C. The independent variable is the normal impulse P_I at I.
//
// Two solvers of the same equations (14), (3d), (15), (16):
//   paper  the authors' algorithm (section 3.4): explicit Euler in P_I with a
//          fixed step, trapezoid work (16a), stopping at the first step past
//          each condition. Reproduces the published numbers; its constants
//          (e_e = 0.98, mu_w = 0.14) were fitted with it.
//   exact  the same model without discretisation error, i.e. the N -> infinity
//          limit of `paper` (checked against its Richardson extrapolation, to
//          ~2e-7 of the largest incoming velocity or R x spin): event-driven
//          (a slip reaching zero, a stick breaking; the ends of compression
//          and restitution located on the way), each contact slipping or
//          sticking (the friction that holds it, while inside its cone),
//          smooth segments integrated by the Dormand-Prince 5(4) pair with
//          dense output, in the slip velocities (a closed system of four
//          equations; the velocities follow from them and from the angular
//          momentum about the line through both contacts, which no contact
//          force changes); near zero slip, where the equations turn stiff
//          and singular, a slip's direction follows its slow manifold and an
//          approach to zero is finished in logarithmic slip time. A head-on
//          impact stays exactly in its plane and is piecewise linear in P_I.
//          About 3 us per impact at the default tolerance, ~50x faster than `paper` at N = 5000
//          (bench_cushion_impact). A rolling ball's impact depends on one
//          number (its incidence and sidespin combined), and is looked up in
//          a table of this solver's answers built on first use per set of
//          constants (~0.2 us per impact; CushionImpactOptions::rolling_table).
//
// Solving allocates nothing unless the history is requested (or a rolling
// ball with new constants builds their table, once): validate the
// constants once with cushion_impact_model() and call solve_cushion_impact()
// in a simulation loop (cushion_impact() also runs validate(Parameters)), or
// solve_cushion_impact_unchecked() where the caller guarantees the ranges.
#pragma once

#include <vector>

#include "cueball/core/parameters.hpp"
#include "cueball/core/vec.hpp"

namespace cueball {

// ------------------------------------------------------------------ constants

/// Constants of the cushion in the impact model.
struct CushionParameters {
  double restitution = 0.0;     ///< e_e, energetic coefficient of restitution (16b), (0, 1]
  double friction = 0.0;        ///< mu_w, ball-cushion sliding friction (7a, 7b), >= 0
  double contact_height = 0.0;  ///< h, height of the contact point I above the bed, m, in (R, 2R)
};

/// h = 7R/5, the usual snooker and pool cushion (paper section 2).
constexpr double default_cushion_height(const BallParameters& ball) { return 1.4 * ball.radius; }

/// sin(theta) = (h - R) / R: the angle of the common normal at I to Y (Fig 3).
constexpr double cushion_sin_theta(const CushionParameters& cushion, const BallParameters& ball) {
  return (cushion.contact_height - ball.radius) / ball.radius;
}

/// e_e = 0.98, mu_w = 0.14, h = 7R/5: fitted by the authors (section 3.5) with
/// the `paper` (Euler, N = 5000) solver. Use with CushionSolver::paper.
CushionParameters cushion_mathavan2010_paper_fit(const BallParameters& ball);

/// e_e = 0.986, mu_w = 0.2093, h = 7R/5: the translator's fit of the same
/// data with a high-order solver (afterword), meant for CushionSolver::exact.
/// Note: in this implementation `paper` at N = 5000 is already within ~5e-4
/// m/s of `exact`, so the two pairs are not interchangeable fits of one
/// curve: a rolling head-on ball rebounds at 0.911 V0 with the paper's pair
/// and 0.863 V0 with this one (either solver).
CushionParameters cushion_translator_exact_fit(const BallParameters& ball);

/// The rigid-cushion assumption holds up to this incoming normal speed, m/s
/// (section 3.5, Fig 7).
inline constexpr double kRigidCushionSpeedLimit = 2.5;

/// The model's constants in raw form: everything eqs (14), (3d) and (16b)
/// need. Build it with cushion_impact_model() from the table parameters, or
/// directly where the table ranges of validate(Parameters) do not apply (the
/// frictionless limit mu_s = mu_w = 0, a cushion fit scanning mu_w).
struct CushionImpactModel {
  double mass = 0.0;              ///< M, kg
  double radius = 0.0;            ///< R, m
  double cloth_friction = 0.0;    ///< mu_s, ball-bed friction at C, [0, 1]
  double cushion_friction = 0.0;  ///< mu_w, ball-cushion friction at I, [0, tan(theta)]
  double restitution = 0.0;       ///< e_e, (0, 1]
  double sin_theta = 0.4;         ///< sin(theta) = (h - R)/R, (0, 1)
};

/// Validates `table` (validate(Parameters)) and `cushion`, and combines them.
CushionImpactModel cushion_impact_model(const Parameters& table, const CushionParameters& cushion);

/// Throws InvalidArgument naming the first constant outside the range where
/// the model is defined: M, R > 0; mu_s in [0, 1]; e_e in (0, 1];
/// sin(theta) in (0, 1); mu_w in [0, tan(theta)] (a larger mu_w could lift the
/// ball off the bed, which the model excludes by (3d) with dz_G = 0); and not
/// both frictions at or above cos(theta)/(1 + sin(theta)), where both contacts
/// can stick and the ball wedges (the normal impulse grows without bound).
void validate(const CushionImpactModel& model);

// ------------------------------------------------------------------ the ball

/// The incoming ball in the cushion frame, just before contact.
struct IncomingBall {
  Vec3 velocity;          ///< (xG', yG', zG'), m/s; yG' > 0 (moving into the cushion), zG' = 0
  Vec3 angular_velocity;  ///< (theta_x', theta_y', theta_z'), rad/s
};

/// The paper's description of the incoming ball (section 3.1, Fig 2).
struct PaperIncidence {
  double speed = 0.0;     ///< V0 > 0, m/s
  double angle = 0.0;     ///< alpha in (0, pi/2] rad, between the velocity and the cushion; pi/2 is head-on
  double topspin = 0.0;   ///< w_T, rad/s; V0/R is natural roll, negative is draw
  double sidespin = 0.0;  ///< w_S, rad/s about Z; positive is the "right" spin of Fig 2
};

/// Initial conditions of section 3.1: xG' = V0 cos(a), yG' = V0 sin(a), zG' = 0,
/// wx = -w_T sin(a), wy = w_T cos(a), wz = w_S. Throws InvalidArgument
/// ("V0", "alpha", "w_T", "w_S") outside the ranges above.
IncomingBall incoming_ball(const PaperIncidence& incidence);

// ------------------------------------------------------------------ solving

enum class CushionSolver {
  exact,  ///< event-driven, no discretisation error (the N -> infinity limit of `paper`)
  paper,  ///< the authors' explicit Euler in P_I (section 3.4)
};

/// The range of CushionImpactOptions::exact_tolerance (and of the
/// simulation's CushionSettings::exact_tolerance).
inline constexpr double kMinExactTolerance = 1e-11;
inline constexpr double kMaxExactTolerance = 1e-7;

struct CushionImpactOptions {
  CushionSolver solver = CushionSolver::exact;
  /// N of the paper's step dP_I = (1 + e_e) M yG'(0) / N (section 3.4), >= 1.
  int paper_steps = 5000;
  /// Fill CushionImpactResult::history (allocates; off in simulation loops).
  bool record_history = false;
  /// `exact`: the local error tolerance of a Runge-Kutta step, relative to the
  /// largest incoming velocity (R x spin included), in [1e-11, 1e-7]. The
  /// default 1e-8 keeps the accuracy goal (1e-6 of that velocity from the
  /// N -> infinity limit of `paper`) on random impacts where 1e-7 did not (a
  /// slip passing close to zero); smaller values are for reference solutions
  /// and cost more steps, 1e-7 trades that accuracy for ~20% fewer steps
  /// (random sliding impacts; ~30% on a planner's, README "Cushion models").
  double exact_tolerance = 1e-8;
  /// `exact` on a rolling ball (no slip at C, a simulator's usual cushion hit)
  /// at exact_tolerance >= 1e-8: look the answer up in a table of the solver's
  /// answers for these constants (piecewise Chebyshev interpolants in the one
  /// variable such an impact depends on, fitted to 2e-8 of the largest
  /// incoming velocity; ~0.2 us instead of ~2-3 us). The table is built on
  /// the first rolling ball that needs it (15-45 ms for usual constants, at
  /// most ~0.15 s; deterministic, thread-safe) and kept in a cache of the 16
  /// most recently used sets of constants (an evicted one is rebuilt
  /// identically), so the answer depends on the inputs and options alone.
  /// Turn it off where the constants change from call to call (fitting
  /// them). The Runge-Kutta solve also when the history is recorded, at
  /// tighter tolerances, and where the table has no fitted piece (near a
  /// change in the sequence of slip and stick phases;
  /// |xG' - cos(theta) R w_z / (1 + sin(theta))| > 50 yG').
  /// solver_steps is 0 for a looked-up answer.
  bool rolling_table = true;
};

/// The state of the impact at one value of the normal impulse P_I.
struct CushionImpactSample {
  double normal_impulse = 0.0;     ///< P_I, N s
  double cushion_slip_speed = 0.0; ///< s, slip speed at I (12), m/s
  double cushion_slip_angle = 0.0; ///< Phi, slip direction at I from X in the X-Y' plane (5), rad; 0 when s = 0
  double bed_slip_speed = 0.0;     ///< s', slip speed at C (13), m/s
  double bed_slip_angle = 0.0;     ///< Phi', slip direction at C from X (9), rad; 0 when s' = 0
  Vec3 velocity;                   ///< (xG', yG', zG'), m/s
  Vec3 angular_velocity;           ///< rad/s
  double work = 0.0;               ///< W_{Z'_I}, work of the normal force at I (16a), J (negative in compression)
};

struct CushionImpactResult {
  Vec3 velocity;            ///< outgoing (xG', yG', zG'), m/s; yG' < 0 away from the cushion
  Vec3 angular_velocity;    ///< outgoing spin, rad/s
  double rebound_speed = 0.0;  ///< |velocity|, m/s
  /// beta = atan2(-yG', xG'), rad: from the cushion line (+X); above pi/2 when
  /// the ball comes back on the side it arrived from (Fig 11).
  double rebound_angle = 0.0;
  double compression_impulse = 0.0;  ///< P_I^c, normal impulse at the end of compression (16c), N s
  double total_impulse = 0.0;        ///< P_I^f, at the end of restitution (16b), N s
  /// W_{Z'_I}(P_I^c), the work of the normal force during compression (16a),
  /// J; negative (the paper's sign: dW = z_I' dP_I with z_I' = -yG' cos(theta)).
  double compression_work = 0.0;
  /// The incoming normal speed yG' exceeds kRigidCushionSpeedLimit: outside
  /// the range where the rigid-cushion model was validated (Fig 7).
  bool beyond_rigid_cushion_limit = false;
  int solver_steps = 0;   ///< Euler steps (paper) or accepted Runge-Kutta steps (exact)
  int solver_events = 0;  ///< events: end of compression and of restitution, slips reaching zero, sticks breaking
  /// Filled only with CushionImpactOptions::record_history: the paper solver
  /// records every Euler step, the exact solver every step and event.
  std::vector<CushionImpactSample> history;
};

/// Solves the impact with the table's ball and cloth and the cushion's
/// constants. Validates everything (InvalidArgument names the field).
CushionImpactResult cushion_impact(const IncomingBall& ball, const Parameters& table,
                                   const CushionParameters& cushion, const CushionImpactOptions& options = {});

/// The same with the model's raw constants (validate(CushionImpactModel)),
/// e.g. the frictionless limit. Validates `ball` and `options` too.
CushionImpactResult solve_cushion_impact(const IncomingBall& ball, const CushionImpactModel& model,
                                         const CushionImpactOptions& options = {});

/// solve_cushion_impact() without the validation, for a simulation's inner
/// loop: the caller guarantees that validate(model) passes (e.g. `model` came
/// from cushion_impact_model()), that `ball` is finite with yG' > 0 and
/// zG' = 0, and that `options` are in range; the result is then identical.
/// Outside those ranges the result is unspecified (it may throw).
CushionImpactResult solve_cushion_impact_unchecked(const IncomingBall& ball, const CushionImpactModel& model,
                                                   const CushionImpactOptions& options = {});

}  // namespace cueball
