// include/cueball/models/cushion/impact.hpp: the Mathavan 2010 cushion impact.
#include "bindings.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include "cueball/models/cushion/impact.hpp"
#include "cueball/models/cushion/model.hpp"
#include "cueball/core/errors.hpp"

namespace cueball_python {

cueball::CushionSolver cushion_solver(const std::string& name, const char* field) {
  if (const std::optional<cueball::CushionSolver> s = cueball::cushion_solver_from_string(name)) return *s;
  throw cueball::InvalidArgument(field, std::string(field) + " = '" + name + "' is not a solver; allowed: 'exact', 'paper'");
}

namespace {

// The paper's incidence from cushion_impact()'s and cushion_rebound()'s
// arguments, checked in the CLI's ranges (cueball cushion); topspin None is
// a rolling ball.
cueball::PaperIncidence checked_incidence(double speed, double angle, std::optional<double> topspin, double sidespin,
                                          const cueball::Parameters& p) {
  cueball::validate(p);
  cueball::require_in_range("V0", speed, 1e-6, cueball::kMaxSpeed, "incoming speed, m/s");
  if (!(std::isfinite(angle) && angle > 0.0 && angle <= std::numbers::pi / 2))
    throw cueball::InvalidArgument("alpha", angle, "(0, pi/2] rad", "angle between the velocity and the cushion");
  if (topspin)
    cueball::require_in_range("w_T", *topspin, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed,
                              "topspin w_T, rad/s");
  cueball::require_in_range("w_S", sidespin, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed,
                            "sidespin w_S, rad/s");
  return {speed, angle, topspin ? *topspin : speed / p.ball.radius, sidespin};
}

}  // namespace

void bind_cushion(py::module_& m) {
  using cueball::CushionImpactResult;
  using cueball::CushionImpactSample;
  using cueball::Parameters;

  py::class_<CushionImpactSample> sample(m, "CushionImpactSample",
                                         "The impact at one value of the normal impulse P_I (cushion frame).");
  sample.def_readonly("normal_impulse", &CushionImpactSample::normal_impulse, "P_I, N s")
      .def_readonly("cushion_slip_speed", &CushionImpactSample::cushion_slip_speed, "s, slip speed at I, m/s")
      .def_readonly("cushion_slip_angle", &CushionImpactSample::cushion_slip_angle, "Phi, rad from X")
      .def_readonly("bed_slip_speed", &CushionImpactSample::bed_slip_speed, "s', slip speed at C, m/s")
      .def_readonly("bed_slip_angle", &CushionImpactSample::bed_slip_angle, "Phi', rad from X")
      .def_property_readonly("velocity", [](const CushionImpactSample& s) { return to_tuple(s.velocity); }, "m/s")
      .def_property_readonly(
          "angular_velocity", [](const CushionImpactSample& s) { return to_tuple(s.angular_velocity); }, "rad/s")
      .def_readonly("work", &CushionImpactSample::work, "work of the normal force at I, J (negative in compression)");
  add_repr(sample, "CushionImpactSample", {"normal_impulse", "velocity", "angular_velocity", "work"},
           [](const CushionImpactSample& s) {
             return py::make_tuple(s.normal_impulse, to_tuple(s.velocity), to_tuple(s.angular_velocity), s.work);
           });

  py::class_<CushionImpactResult> result(
      m, "CushionImpactResult",
      "The ball after a cushion impact, in the cushion frame: X along the cushion, Y into it, Z up.");
  result
      .def_property_readonly(
          "velocity", [](const CushionImpactResult& r) { return to_tuple(r.velocity); },
          "outgoing (vX, vY, vZ), m/s; vY < 0 away from the cushion")
      .def_property_readonly(
          "angular_velocity", [](const CushionImpactResult& r) { return to_tuple(r.angular_velocity); },
          "outgoing spin (wX, wY, wZ), rad/s")
      .def_readonly("rebound_speed", &CushionImpactResult::rebound_speed, "|velocity|, m/s")
      .def_readonly("rebound_angle", &CushionImpactResult::rebound_angle,
                    "beta = atan2(-vY, vX), rad from the cushion line; > pi/2 back on the arrival side")
      .def_readonly("compression_impulse", &CushionImpactResult::compression_impulse,
                    "P_I at the end of compression (16c), N s")
      .def_readonly("total_impulse", &CushionImpactResult::total_impulse, "P_I at the end of restitution (16b), N s")
      .def_readonly("compression_work", &CushionImpactResult::compression_work,
                    "work of the normal force in compression (16a), J, negative")
      .def_readonly("beyond_rigid_cushion_limit", &CushionImpactResult::beyond_rigid_cushion_limit,
                    "the normal speed exceeds 2.5 m/s, where the rigid-cushion model was validated")
      .def_readonly("solver_steps", &CushionImpactResult::solver_steps, "Euler or Runge-Kutta steps")
      .def_readonly("solver_events", &CushionImpactResult::solver_events, "events met by the solver")
      .def_readonly("history", &CushionImpactResult::history, "list of CushionImpactSample (history=True only)");
  add_repr(result, "CushionImpactResult",
           {"velocity", "angular_velocity", "rebound_speed", "rebound_angle", "compression_impulse", "total_impulse",
            "compression_work"},
           [](const CushionImpactResult& r) {
             return py::make_tuple(to_tuple(r.velocity), to_tuple(r.angular_velocity), r.rebound_speed,
                                   r.rebound_angle, r.compression_impulse, r.total_impulse, r.compression_work);
           });

  const cueball::CushionParameters fit = cueball::cushion_mathavan2010_paper_fit(cueball::snooker_parameters().ball);
  m.def(
      "cushion_impact",
      [](double speed, double angle, std::optional<double> topspin, double sidespin, const Parameters& p,
         double restitution, double friction, std::optional<double> contact_height, const std::string& solver,
         int paper_steps, bool history, double exact_tolerance, bool rolling_table) {
        const cueball::PaperIncidence incidence = checked_incidence(speed, angle, topspin, sidespin, p);
        if (paper_steps < 1 || paper_steps > 100000000)
          throw cueball::InvalidArgument("paper_steps", paper_steps, "[1, 1e8]", "Euler steps of the paper solver");
        const double h = contact_height ? *contact_height : cueball::default_cushion_height(p.ball);
        const cueball::CushionParameters cushion{restitution, friction, h};
        cueball::CushionImpactOptions options;
        options.solver = cushion_solver(solver);
        options.paper_steps = paper_steps;
        options.record_history = history;
        options.exact_tolerance = exact_tolerance;
        options.rolling_table = rolling_table;
        return cueball::cushion_impact(cueball::incoming_ball(incidence), p, cushion, options);
      },
      "speed"_a, "angle"_a, "topspin"_a = py::none(), "sidespin"_a = 0.0, py::kw_only(), params_arg(),
      "restitution"_a = fit.restitution, "friction"_a = fit.friction, "contact_height"_a = py::none(),
      "solver"_a = "exact", "paper_steps"_a = 5000, "history"_a = false,
      "exact_tolerance"_a = cueball::CushionImpactOptions{}.exact_tolerance,
      "rolling_table"_a = cueball::CushionImpactOptions{}.rolling_table,
      "A ball hitting a cushion: Mathavan, Jackson & Parkin (2010), solved exactly ('exact') or\n"
      "with the authors' Euler scheme ('paper', paper_steps steps).\n"
      "speed: V0 > 0, m/s. angle: alpha in RADIANS, (0, pi/2], between the velocity and the\n"
      "cushion (pi/2 = head-on). topspin: w_T, rad/s (default None: rolling, V0/R; negative is\n"
      "draw). sidespin: w_S, rad/s about Z, > 0 the 'right' spin of the paper's Fig 2.\n"
      "restitution e_e and friction mu_w default to the authors' fit (0.98, 0.14); contact_height\n"
      "h, m, in (R, 2R), default 7R/5. history=True records the impact along P_I.\n"
      "exact_tolerance: the exact solver's local error per Runge-Kutta step relative to the\n"
      "largest incoming velocity, [1e-11, 1e-7], default 1e-8. rolling_table: a rolling ball\n"
      "(at exact_tolerance >= 1e-8) is looked up in a table built once per set of constants\n"
      "(15-150 ms, cached); pass False when sweeping the constants.");
  m.attr("RIGID_CUSHION_SPEED_LIMIT") = cueball::kRigidCushionSpeedLimit;

  py::class_<cueball::CushionRebound> rebound(
      m, "CushionRebound", "The ball after a cushion impact by any model, in the cushion frame: X along it, Y into it, Z up.");
  rebound
      .def_property_readonly(
          "velocity", [](const cueball::CushionRebound& r) { return to_tuple(r.velocity); },
          "outgoing (vX, vY, vZ), m/s; vY < 0 away from the cushion")
      .def_property_readonly(
          "angular_velocity", [](const cueball::CushionRebound& r) { return to_tuple(r.angular_velocity); },
          "outgoing spin (wX, wY, wZ), rad/s")
      .def_property_readonly(
          "rebound_speed", [](const cueball::CushionRebound& r) { return std::hypot(r.velocity.x, r.velocity.y); }, "m/s")
      .def_property_readonly(
          "rebound_angle", [](const cueball::CushionRebound& r) { return std::atan2(-r.velocity.y, r.velocity.x); },
          "beta, rad from the cushion line");
  add_repr(rebound, "CushionRebound", {"velocity", "angular_velocity"}, [](const cueball::CushionRebound& r) {
    return py::make_tuple(to_tuple(r.velocity), to_tuple(r.angular_velocity));
  });
  m.def(
      "cushion_rebound",
      [](double speed, double angle, std::optional<double> topspin, double sidespin, const std::string& model,
         const Parameters& p, std::optional<double> restitution, std::optional<double> friction,
         std::optional<double> contact_height, std::optional<double> frequency_ratio) {
        const cueball::PaperIncidence incidence = checked_incidence(speed, angle, topspin, sidespin, p);
        const std::optional<cueball::CushionModel> chosen = cueball::cushion_model_from_string(model);
        if (!chosen)
          throw cueball::InvalidArgument("model", "model = " + cueball::quote_input(model) +
                                                      " is not known; allowed: " + cueball::cushion_model_names("'"));
        cueball::CushionSettings settings = cueball::default_cushion_settings(*chosen);
        if (restitution) settings.restitution = *restitution;
        if (friction) settings.friction = *friction;
        only_for("frequency_ratio", frequency_ratio.has_value(), "model", *chosen == cueball::CushionModel::stronge_compliant,
                 "stronge_compliant", model);
        if (frequency_ratio) settings.frequency_ratio = *frequency_ratio;
        const double h = contact_height ? *contact_height : cueball::default_cushion_height(p.ball);
        cueball::require_in_range("contact_height", h, p.ball.radius * (1 + 1e-9), 2 * p.ball.radius * (1 - 1e-9),
                                  "cushion contact height h, m, between R and 2R");
        return cueball::cushion_rebound(cueball::incoming_ball(incidence), cueball::cushion_contact(p, settings, h));
      },
      "speed"_a, "angle"_a, "topspin"_a = py::none(), "sidespin"_a = 0.0, py::kw_only(), "model"_a = "mathavan_2010",
      params_arg(), "restitution"_a = py::none(), "friction"_a = py::none(), "contact_height"_a = py::none(),
      "frequency_ratio"_a = py::none(),
      "A ball hitting a cushion by the model named (main README \"Models\"): 'mathavan_2010' (exact),\n"
      "'han_2005' or 'stronge_compliant', with the model's own constants unless given (restitution,\n"
      "friction; frequency_ratio: stronge_compliant's Omega). Arguments as cushion_impact's: speed V0\n"
      "m/s, angle alpha in RADIANS (pi/2 head-on), topspin w_T (None: rolling), sidespin w_S, rad/s.");
}

}  // namespace cueball_python
