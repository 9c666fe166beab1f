// Mathavan, Jackson & Parkin (2010), the ball-cushion impact: the public API
// of cueball/cushion_impact.hpp. The constants (the fits, cushion_impact_model,
// validate), the incoming ball of section 3.1, and solving: validation of the
// inputs, the scaling to the solvers' units and back, and the choice of
// solver, `paper` (mathavan_2010_euler.cpp) or `exact`
// (mathavan_2010_exact.cpp, and for a rolling ball its answers tabulated by
// mathavan_2010_rolling.cpp, built on first use); what they
// share is in mathavan_2010_equations.hpp. mathavan_2010::rebound() is the
// same solve for the simulator, returning the velocities alone.
//
// Sources: S. Mathavan, M. R. Jackson, R. M. Parkin, Proc. IMechE Part C 224
// (2010), sections 3.1 and 3.5 and equations (3d), (7), (16) as numbered
// there; the translator's afterword (S. Tikhonov, 2013) for
// cushion_translator_exact_fit.
#include "cueball/models/cushion/impact.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "cueball/core/errors.hpp"
#include "mathavan_2010_equations.hpp"

namespace cueball {

namespace {

using mathavan_2010::kPi;
using mathavan_2010::Outcome;
using mathavan_2010::Units;

// ------------------------------------------------------------------ validation

[[noreturn]] void reject(const char* field, double value, const std::string& allowed, const char* meaning) {
  throw InvalidArgument(field, value, allowed, meaning);
}

std::string number(double v) {
  std::string text = std::to_string(v);
  while (text.size() > 1 && text.back() == '0') text.pop_back();
  if (!text.empty() && text.back() == '.') text.pop_back();
  return text;
}

void validate_ball(const IncomingBall& ball) {
  if (is_finite(ball.velocity) && is_finite(ball.angular_velocity) && ball.velocity.y > 0.0 && ball.velocity.z == 0.0) {
    return;  // the common case, without the calls that name the fields
  }
  require_finite("velocity.x", ball.velocity.x);
  require_finite("velocity.y", ball.velocity.y);
  require_finite("velocity.z", ball.velocity.z);
  require_finite("angular_velocity.x", ball.angular_velocity.x);
  require_finite("angular_velocity.y", ball.angular_velocity.y);
  require_finite("angular_velocity.z", ball.angular_velocity.z);
  if (!(ball.velocity.y > 0.0)) {
    reject("velocity.y", ball.velocity.y, "(0, inf)", "normal speed yG' into the cushion, m/s");
  }
  if (ball.velocity.z != 0.0) {
    reject("velocity.z", ball.velocity.z, "0", "vertical speed zG' of a ball on the bed (14c), m/s");
  }
}

void validate_options(const CushionImpactOptions& options) {
  if (options.solver != CushionSolver::exact && options.solver != CushionSolver::paper) {
    throw InvalidArgument("solver", "solver is not a CushionSolver value");
  }
  static_assert(CushionImpactOptions{}.exact_tolerance == mathavan_2010::kExactTolerance);
  if (!(options.exact_tolerance >= kMinExactTolerance && options.exact_tolerance <= kMaxExactTolerance)) {
    reject("exact_tolerance", options.exact_tolerance, "[1e-11, 1e-7]",
           "local error per Runge-Kutta step of the exact solver, relative to the largest incoming velocity");
  }
  if (options.paper_steps < 1 || options.paper_steps > 1'000'000'000) {
    reject("paper_steps", options.paper_steps, "[1, 1e9]", "N, Euler steps per (1 + e_e) M yG'(0) (section 3.4)");
  }
}

}  // namespace

// ------------------------------------------------------------------ public

CushionParameters cushion_mathavan2010_paper_fit(const BallParameters& ball) {
  return {0.98, 0.14, default_cushion_height(ball)};  // section 3.5
}

CushionParameters cushion_translator_exact_fit(const BallParameters& ball) {
  return {0.986, 0.2093, default_cushion_height(ball)};  // translator's afterword
}

void validate(const CushionImpactModel& m) {
  if (!(std::isfinite(m.mass) && m.mass > 0.0)) reject("mass", m.mass, "(0, inf)", "ball mass M, kg");
  if (!(std::isfinite(m.radius) && m.radius > 0.0)) reject("radius", m.radius, "(0, inf)", "ball radius R, m");
  require_in_range("mu_s", m.cloth_friction, 0.0, 1.0, "ball-bed friction at C");
  if (!(std::isfinite(m.restitution) && m.restitution > 0.0 && m.restitution <= 1.0)) {
    reject("e_e", m.restitution, "(0, 1]", "ball-cushion coefficient of restitution (16b)");
  }
  if (!(std::isfinite(m.sin_theta) && m.sin_theta > 0.0 && m.sin_theta < 1.0)) {
    reject("sin_theta", m.sin_theta, "(0, 1)", "sin(theta) = (h - R)/R of the contact normal at I");
  }
  const double s = m.sin_theta;
  const double c = std::sqrt((1.0 - s) * (1.0 + s));
  const double tan_theta = s / c;
  if (!(std::isfinite(m.cushion_friction) && m.cushion_friction >= 0.0 && m.cushion_friction <= tan_theta)) {
    reject("mu_w", m.cushion_friction, "[0, tan(theta)] = [0, " + number(tan_theta) + "]",
           "ball-cushion friction; above tan(theta) it could lift the ball off the bed, against (3d)");
  }
  const double wedge = c / (1.0 + s);
  if (m.cushion_friction >= wedge && m.cloth_friction >= wedge) {
    reject("mu_w", m.cushion_friction, "< cos(theta)/(1 + sin(theta)) = " + number(wedge) + " when mu_s is as large",
           "both contacts could stick and wedge the ball");
  }
}

CushionImpactModel cushion_impact_model(const Parameters& table, const CushionParameters& cushion) {
  validate(table);
  const double r = table.ball.radius;
  if (!(std::isfinite(cushion.restitution) && cushion.restitution > 0.0 && cushion.restitution <= 1.0)) {
    reject("e_e", cushion.restitution, "(0, 1]", "ball-cushion coefficient of restitution (16b)");
  }
  if (!(std::isfinite(cushion.friction) && cushion.friction >= 0.0)) {
    reject("mu_w", cushion.friction, "[0, inf)", "ball-cushion sliding friction (7a, 7b)");
  }
  if (!(std::isfinite(cushion.contact_height) && cushion.contact_height > r && cushion.contact_height < 2.0 * r)) {
    reject("h", cushion.contact_height, "(R, 2R) = (" + number(r) + ", " + number(2.0 * r) + ")",
           "height of the cushion contact I above the bed, m");
  }
  CushionImpactModel m;
  m.mass = table.ball.mass;
  m.radius = r;
  m.cloth_friction = table.cloth.sliding_friction;
  m.cushion_friction = cushion.friction;
  m.restitution = cushion.restitution;
  m.sin_theta = cushion_sin_theta(cushion, table.ball);
  validate(m);
  return m;
}

IncomingBall incoming_ball(const PaperIncidence& in) {
  if (!(std::isfinite(in.speed) && in.speed > 0.0)) reject("V0", in.speed, "(0, inf)", "incoming speed, m/s");
  if (!(std::isfinite(in.angle) && in.angle > 0.0 && in.angle <= 0.5 * kPi)) {
    reject("alpha", in.angle, "(0, pi/2] rad", "angle between the velocity and the cushion; pi/2 is head-on");
  }
  require_finite("w_T", in.topspin);
  require_finite("w_S", in.sidespin);
  const double ca = std::cos(in.angle);
  const double sa = std::sin(in.angle);
  IncomingBall b;
  b.velocity = {in.speed * ca, in.speed * sa, 0.0};                         // section 3.1
  b.angular_velocity = {-in.topspin * sa, in.topspin * ca, in.sidespin};  // section 3.1
  return b;
}

CushionImpactResult solve_cushion_impact(const IncomingBall& ball, const CushionImpactModel& model,
                                         const CushionImpactOptions& options) {
  validate(model);
  validate_ball(ball);
  validate_options(options);
  return solve_cushion_impact_unchecked(ball, model, options);
}

namespace mathavan_2010 {

namespace {

// The chosen solver's outcome in scaled units, and the units: what the full
// result and the simulator's rebound are both made from.
struct ScaledSolve {
  Outcome outcome;
  Units units;
};

ScaledSolve solve_scaled(const IncomingBall& ball, const CushionImpactModel& model, const CushionImpactOptions& options,
                         std::vector<CushionImpactSample>* history,
                         RollingOutputs outputs = RollingOutputs::all) {
  const Coefficients k = coefficients(model);
  const double v_normal = ball.velocity.y;
  ScaledSolve r{{}, {v_normal, model.radius, model.mass * v_normal, model.mass * v_normal * v_normal}};
  const State y0 = scaled_state(ball, model.radius, v_normal);
  if (options.solver == CushionSolver::paper) {
    r.outcome = solve_paper(k, y0, options.paper_steps, r.units, history);
  } else if (history != nullptr || !options.rolling_table || !(options.exact_tolerance >= kExactTolerance) ||
             !solve_rolling(k, y0, r.outcome, outputs)) {
    r.outcome = solve_exact(k, y0, r.units, history, options.exact_tolerance);
  }
  return r;
}

// The outgoing velocity and spin in SI units.
CushionRebound outgoing(const ScaledSolve& r) {
  const State& y = r.outcome.final_state;
  const double spin = r.units.speed / r.units.radius;
  return {{y[kVx] * r.units.speed, y[kVy] * r.units.speed, 0.0}, {y[kUx] * spin, y[kUy] * spin, y[kUz] * spin}};
}

}  // namespace

CushionRebound rebound(const IncomingBall& ball, const CushionImpactModel& model, const CushionImpactOptions& options) {
  if (options.record_history) {  // the same solve as solve_cushion_impact_unchecked(): the Runge-Kutta one
    std::vector<CushionImpactSample> history;
    return outgoing(solve_scaled(ball, model, options, &history));
  }
  return outgoing(solve_scaled(ball, model, options, nullptr, RollingOutputs::velocities));
}

}  // namespace mathavan_2010

CushionImpactResult solve_cushion_impact_unchecked(const IncomingBall& ball, const CushionImpactModel& model,
                                                   const CushionImpactOptions& options) {
  CushionImpactResult r;
  const mathavan_2010::ScaledSolve solved =
      mathavan_2010::solve_scaled(ball, model, options, options.record_history ? &r.history : nullptr);
  const Outcome& o = solved.outcome;
  const Units& units = solved.units;
  const CushionRebound out = mathavan_2010::outgoing(solved);
  r.velocity = out.velocity;
  r.angular_velocity = out.angular_velocity;
  r.rebound_speed = norm(r.velocity);
  r.rebound_angle = std::atan2(-r.velocity.y, r.velocity.x);
  r.compression_impulse = o.compression_impulse * units.impulse;
  r.total_impulse = o.total_impulse * units.impulse;
  r.compression_work = o.compression_work * units.work;
  r.beyond_rigid_cushion_limit = units.speed > kRigidCushionSpeedLimit;
  r.solver_steps = o.steps;
  r.solver_events = o.events;
  return r;
}

CushionImpactResult cushion_impact(const IncomingBall& ball, const Parameters& table, const CushionParameters& cushion,
                                   const CushionImpactOptions& options) {
  return solve_cushion_impact(ball, cushion_impact_model(table, cushion), options);
}

}  // namespace cueball
