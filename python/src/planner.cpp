// include/cueball/physics/straight_shot_inverse.hpp: the inverse problem (paper 001 eqs 17-28).
#include "bindings.hpp"

#include <string>
#include "cueball/physics/straight_shot_inverse.hpp"

namespace cueball_python {

void bind_planner(py::module_& m) {
  using cueball::Parameters;
  using cueball::ShotPlan;
  using cueball::ShotTarget;

  py::class_<ShotPlan> plan(m, "ShotPlan",
                            "Initial speed and topspin that bring a ball to x2 with speed v2 (paper 001 eqs 17-28).");
  plan.def_property_readonly(
          "variant", [](const ShotPlan& s) { return std::string(cueball::to_string(s.variant)); },
          "'given_slide_end', 'natural_roll', 'given_spin' or 'given_speed'")
      .def_readonly("v0", &ShotPlan::v0, "initial speed, m/s (eq. 27)")
      .def_readonly("w0", &ShotPlan::w0, "initial topspin, rad/s (eq. 28); R w0 = v0 is natural roll")
      .def_readonly("t1", &ShotPlan::t1, "end of sliding, s (eq. 19)")
      .def_readonly("x1", &ShotPlan::x1, "position at the end of sliding, m (eq. 21)")
      .def_readonly("v1", &ShotPlan::v1, "speed at the end of sliding, m/s (eq. 20)")
      .def_readonly("t2", &ShotPlan::t2, "time at which the ball passes x2 with speed v2, s (eq. 22)");
  add_repr(plan, "ShotPlan", {"variant", "v0", "w0", "t1", "x1", "v1", "t2"}, [](const ShotPlan& s) {
    return py::make_tuple(cueball::to_string(s.variant), s.v0, s.w0, s.t1, s.x1, s.v1, s.t2);
  });

  constexpr const char* kPlanDoc =
      "Positions in m along the line of the shot, increasing in the direction of travel; v2 (m/s)\n"
      "is the speed wanted at x2 (0: stop there). Valid plans satisfy v0 >= R w0 >= -5/2 v0;\n"
      "otherwise InfeasibleShot names the failed condition.";
  // The three variants with one given quantity besides the target.
  using PlanWith = ShotPlan (*)(const ShotTarget&, double, const Parameters&);
  const auto def_plan_with = [&](const char* name, PlanWith solve, const char* given, const char* doc) {
    m.def(
        name,
        [solve](double value, double x2, double v2, double x0, const Parameters& p) {
          return solve(ShotTarget{x0, x2, v2}, value, p);
        },
        py::kw_only(), py::arg(given), "x2"_a, "v2"_a = 0.0, "x0"_a = 0.0, params_arg(),
        (std::string(doc) + kPlanDoc).c_str());
  };
  def_plan_with("plan_shot_with_slide_end", cueball::plan_shot_with_slide_end, "x1",
                "The paper's inverse problem (eqs 25-28): sliding ends at x1.\n");
  def_plan_with("plan_shot_with_spin", cueball::plan_shot_with_spin, "w0",
                "Given topspin w0 (rad/s); v0 and x1 follow.\n");
  def_plan_with("plan_shot_with_speed", cueball::plan_shot_with_speed, "v0",
                "Given speed v0 (m/s); w0 and x1 follow.\n");
  m.def(
      "plan_natural_roll_shot",
      [](double x2, double v2, double x0, const Parameters& p) {
        return cueball::plan_natural_roll_shot(ShotTarget{x0, x2, v2}, p);
      },
      py::kw_only(), "x2"_a, "v2"_a = 0.0, "x0"_a = 0.0, params_arg(),
      (std::string("Natural roll from the start (x1 = x0, R w0 = v0).\n") + kPlanDoc).c_str());
}

}  // namespace cueball_python
