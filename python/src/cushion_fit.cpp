// include/cueball/models/cushion/fit.hpp: fitting e_e and mu_w to measured rebounds.
#include "bindings.hpp"

#include "cueball/models/cushion/model.hpp"

#include <string>
#include <vector>
#include "cueball/models/cushion/fit.hpp"

namespace cueball_python {

void bind_cushion_fit(py::module_& m) {
  using cueball::CushionFit;
  using cueball::CushionFitData;
  using cueball::CushionFitOptions;
  using cueball::HeadOnRebound;
  using cueball::ObliqueRebound;
  using cueball::PaperIncidence;

  py::class_<PaperIncidence> incidence(
      m, "PaperIncidence",
      "A ball arriving at a cushion (Mathavan 2010, section 3.1): speed V0 > 0, m/s; angle alpha,\n"
      "rad, (0, pi/2] between the velocity and the cushion (pi/2 head-on); topspin w_T, rad/s (V0/R\n"
      "rolling); sidespin w_S, rad/s about Z (> 0 the paper's 'right' spin). As cushion_impact's arguments.");
  incidence
      .def(py::init([](double speed, double angle, double topspin, double sidespin) {
             return PaperIncidence{speed, angle, topspin, sidespin};
           }),
           "speed"_a, "angle"_a, "topspin"_a, "sidespin"_a = 0.0)
      .def_readwrite("speed", &PaperIncidence::speed, "V0, m/s")
      .def_readwrite("angle", &PaperIncidence::angle, "alpha, rad")
      .def_readwrite("topspin", &PaperIncidence::topspin, "w_T, rad/s")
      .def_readwrite("sidespin", &PaperIncidence::sidespin, "w_S, rad/s");
  add_value_semantics(
      incidence, "PaperIncidence", {"speed", "angle", "topspin", "sidespin"},
      [](const PaperIncidence& i) { return py::make_tuple(i.speed, i.angle, i.topspin, i.sidespin); },
      [](const py::tuple& t) {
        return PaperIncidence{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(), t[3].cast<double>()};
      });

  py::class_<HeadOnRebound> head_on(m, "HeadOnRebound",
                                    "A head-on impact of a rolling ball without side spin (the paper's Fig 7):\n"
                                    "incoming_speed V0 and the measured rebound_speed, m/s.");
  head_on
      .def(py::init([](double incoming_speed, double rebound_speed) { return HeadOnRebound{incoming_speed, rebound_speed}; }),
           "incoming_speed"_a, "rebound_speed"_a)
      .def_readwrite("incoming_speed", &HeadOnRebound::incoming_speed, "V0, m/s")
      .def_readwrite("rebound_speed", &HeadOnRebound::rebound_speed, "m/s");
  add_value_semantics(
      head_on, "HeadOnRebound", {"incoming_speed", "rebound_speed"},
      [](const HeadOnRebound& h) { return py::make_tuple(h.incoming_speed, h.rebound_speed); },
      [](const py::tuple& t) { return HeadOnRebound{t[0].cast<double>(), t[1].cast<double>()}; });

  py::class_<ObliqueRebound> oblique(
      m, "ObliqueRebound",
      "Any impact: its incidence (PaperIncidence) and the measured rebound_speed (m/s) and\n"
      "rebound_angle beta (rad from the cushion line, as CushionImpactResult.rebound_angle).");
  oblique
      .def(py::init([](const PaperIncidence& in, double rebound_speed, double rebound_angle) {
             return ObliqueRebound{in, rebound_speed, rebound_angle};
           }),
           "incidence"_a, "rebound_speed"_a, "rebound_angle"_a)
      .def_readwrite("incidence", &ObliqueRebound::incidence)
      .def_readwrite("rebound_speed", &ObliqueRebound::rebound_speed, "m/s")
      .def_readwrite("rebound_angle", &ObliqueRebound::rebound_angle, "beta, rad");
  add_value_semantics(
      oblique, "ObliqueRebound", {"incidence", "rebound_speed", "rebound_angle"},
      [](const ObliqueRebound& o) { return py::make_tuple(o.incidence, o.rebound_speed, o.rebound_angle); },
      [](const py::tuple& t) {
        return ObliqueRebound{t[0].cast<PaperIncidence>(), t[1].cast<double>(), t[2].cast<double>()};
      });

  py::class_<CushionFitData> data(m, "CushionFitData",
                                  "Measured rebounds: head_on (list of HeadOnRebound) and oblique (list of\n"
                                  "ObliqueRebound); at least 3 head-on, 2 oblique or 1 of each.");
  data.def(py::init([](const std::vector<HeadOnRebound>& h, const std::vector<ObliqueRebound>& o) {
             return CushionFitData{h, o};
           }),
           "head_on"_a = std::vector<HeadOnRebound>{}, "oblique"_a = std::vector<ObliqueRebound>{})
      .def_readwrite("head_on", &CushionFitData::head_on, "list of HeadOnRebound (assign a new list to change it)")
      .def_readwrite("oblique", &CushionFitData::oblique, "list of ObliqueRebound (assign a new list to change it)");
  add_value_semantics(
      data, "CushionFitData", {"head_on", "oblique"},
      [](const CushionFitData& d) { return py::make_tuple(d.head_on, d.oblique); },
      [](const py::tuple& t) {
        return CushionFitData{t[0].cast<std::vector<HeadOnRebound>>(), t[1].cast<std::vector<ObliqueRebound>>()};
      });

  py::class_<CushionFitOptions> options(
      m, "CushionFitOptions",
      "solver 'exact' or 'paper' (the constants belong to the solver they were fitted with);\n"
      "paper_steps N of the paper solver; grid_step of the (e_e, mu_w) grid over (0, 1]^2, (0, 0.5];\n"
      "contact_height h, m (0: 7R/5).");
  options
      .def(py::init([](const std::string& solver, int paper_steps, double grid_step, double contact_height) {
             return CushionFitOptions{cushion_solver(solver), paper_steps, grid_step, contact_height};
           }),
           "solver"_a = "exact", "paper_steps"_a = 5000, "grid_step"_a = 0.01, "contact_height"_a = 0.0)
      .def_property(
          "solver", [](const CushionFitOptions& o) { return std::string(cueball::to_string(o.solver)); },
          [](CushionFitOptions& o, const std::string& s) { o.solver = cushion_solver(s); }, "'exact' or 'paper'")
      .def_readwrite("paper_steps", &CushionFitOptions::paper_steps, "N, for solver 'paper'")
      .def_readwrite("grid_step", &CushionFitOptions::grid_step, "(0, 0.5]")
      .def_readwrite("contact_height", &CushionFitOptions::contact_height, "h, m; 0 means 7R/5");
  add_value_semantics(
      options, "CushionFitOptions", {"solver", "paper_steps", "grid_step", "contact_height"},
      [](const CushionFitOptions& o) {
        return py::make_tuple(std::string(cueball::to_string(o.solver)), o.paper_steps, o.grid_step, o.contact_height);
      },
      [](const py::tuple& t) {
        return CushionFitOptions{cushion_solver(t[0].cast<std::string>()), t[1].cast<int>(), t[2].cast<double>(),
                                 t[3].cast<double>()};
      });

  py::class_<CushionFit> fit(m, "CushionFit",
                             "The fitted cushion constants (Mathavan 2010, section 3.5) and how well the data\n"
                             "determine them.");
  fit.def_readonly("restitution", &CushionFit::restitution, "e_e at the minimum")
      .def_readonly("friction", &CushionFit::friction, "mu_w at the minimum")
      .def_readonly("residual", &CushionFit::residual, "sum of squared errors at the minimum, m^2/s^2")
      .def_readonly("grid_restitution", &CushionFit::grid_restitution, "the grid's best e_e, before refinement")
      .def_readonly("grid_friction", &CushionFit::grid_friction, "the grid's best mu_w")
      .def_readonly("grid_residual", &CushionFit::grid_residual, "m^2/s^2")
      .def_readonly("restitution_sigma", &CushionFit::restitution_sigma, "standard error of e_e (inf: undetermined)")
      .def_readonly("friction_sigma", &CushionFit::friction_sigma, "standard error of mu_w (inf: undetermined)")
      .def_readonly("correlation", &CushionFit::correlation, "of the two estimates, [-1, 1]")
      .def_readonly("condition_number", &CushionFit::condition_number, "of the scaled J^T J")
      .def_readonly("poorly_separated", &CushionFit::poorly_separated,
                    "the data fix nearly one combination of e_e and mu_w only (e.g. head-on data alone)")
      .def_readonly("friction_upper_bound", &CushionFit::friction_upper_bound, "tan(theta), the model's limit of mu_w")
      .def_readonly("residuals", &CushionFit::residuals, "number of residual components")
      .def_readonly("impacts_solved", &CushionFit::impacts_solved)
      .def_readonly("beyond_rigid_cushion_limit", &CushionFit::beyond_rigid_cushion_limit,
                    "data points with a normal speed above 2.5 m/s");
  add_repr(fit, "CushionFit",
           {"restitution", "friction", "residual", "restitution_sigma", "friction_sigma", "correlation",
            "poorly_separated"},
           [](const CushionFit& f) {
             return py::make_tuple(f.restitution, f.friction, f.residual, f.restitution_sigma, f.friction_sigma,
                                   f.correlation, f.poorly_separated);
           });

  m.def(
      "fit_cushion",
      [](const CushionFitData& d, const cueball::Parameters& p, const CushionFitOptions& o) {
        py::gil_scoped_release release;
        return cueball::fit_cushion(d, p, o);
      },
      "data"_a, params_arg(), "options"_a = CushionFitOptions{},
      "Fits the cushion's e_e and mu_w to measured rebounds with the ball and cloth of params\n"
      "(Mathavan 2010, section 3.5: the 0.01 grid, then Levenberg-Marquardt). InvalidArgument names\n"
      "e.g. 'head_on[2].rebound_speed', or 'data' when there is none. Releases the GIL.");
}

}  // namespace cueball_python
