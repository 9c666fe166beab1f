// include/cueball/core/parameters.hpp: ball and cloth parameters, presets, ranges.
#include "bindings.hpp"

#include "cueball/core/errors.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball_python {

void bind_parameters(py::module_& m) {
  using cueball::BallParameters;
  using cueball::ClothParameters;
  using cueball::Parameters;

  py::class_<BallParameters> ball(m, "BallParameters", "The ball: mass (kg) and radius (m).");
  ball.def(py::init([](double mass, double radius) { return BallParameters{mass, radius}; }), "mass"_a, "radius"_a)
      .def_readwrite("mass", &BallParameters::mass, "m, kg")
      .def_readwrite("radius", &BallParameters::radius, "R, m");
  add_value_semantics(
      ball, "BallParameters", {"mass", "radius"},
      [](const BallParameters& b) { return py::make_tuple(b.mass, b.radius); },
      [](const py::tuple& t) { return BallParameters{t[0].cast<double>(), t[1].cast<double>()}; });

  py::class_<ClothParameters> cloth(m, "ClothParameters",
                                    "The cloth: friction coefficients (dimensionless) and gravity (m/s^2).");
  cloth
      .def(py::init([](double sliding_friction, double rolling_resistance, double spin_friction, double gravity) {
             return ClothParameters{sliding_friction, rolling_resistance, spin_friction, gravity};
           }),
           "sliding_friction"_a, "rolling_resistance"_a, "spin_friction"_a, "gravity"_a = 9.81)
      .def_readwrite("sliding_friction", &ClothParameters::sliding_friction,
                     "mu_s, ball-cloth sliding friction; a sliding ball decelerates at mu_s g")
      .def_readwrite("rolling_resistance", &ClothParameters::rolling_resistance,
                     "mu_r, paper 001's energy convention: a rolling ball decelerates at (5/7) mu_r g")
      .def_readwrite("spin_friction", &ClothParameters::spin_friction,
                     "mu_sp, vertical-spin friction: dw_z/dt = -5 mu_sp g / (2R)")
      .def_readwrite("gravity", &ClothParameters::gravity, "g, m/s^2");
  add_value_semantics(
      cloth, "ClothParameters", {"sliding_friction", "rolling_resistance", "spin_friction", "gravity"},
      [](const ClothParameters& c) {
        return py::make_tuple(c.sliding_friction, c.rolling_resistance, c.spin_friction, c.gravity);
      },
      [](const py::tuple& t) {
        return ClothParameters{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(), t[3].cast<double>()};
      });

  py::class_<Parameters> params(m, "Parameters",
                                "Ball and cloth. Fields are read/write; p.ball.mass = 0.17 changes p. Error\n"
                                "messages name the fields mass, radius, mu_s, mu_r, mu_sp, g.");
  params.def(py::init([](const BallParameters& b, const ClothParameters& c) { return Parameters{b, c}; }), "ball"_a,
             "cloth"_a)
      .def_readwrite("ball", &Parameters::ball)
      .def_readwrite("cloth", &Parameters::cloth);
  add_value_semantics(
      params, "Parameters", {"ball", "cloth"}, [](const Parameters& p) { return py::make_tuple(p.ball, p.cloth); },
      [](const py::tuple& t) { return Parameters{t[0].cast<BallParameters>(), t[1].cast<ClothParameters>()}; });

  m.def("snooker_parameters", &cueball::snooker_parameters,
        "Snooker ball on a snooker cloth (Mathavan, Jackson & Parkin 2010 and 2009).");
  m.def("pool_parameters", &cueball::pool_parameters, "WPA pool ball on a typical pool cloth (WPA; Alciatore).");
  m.def("carom_parameters", &cueball::carom_parameters,
        "UMB carom ball on a heated carom cloth (fitted to a recorded three-cushion match; README).");
  m.def("preset_parameters", [](const std::string& name) { return cueball::preset_parameters(name); }, "name"_a,
        "A preset by name: 'snooker' or 'pool'; InvalidArgument otherwise.");
  m.def("validate", py::overload_cast<const Parameters&>(&cueball::validate), "params"_a,
        "Raises InvalidArgument naming the first parameter that is not finite or lies outside its\n"
        "range (see PARAMETER_RANGES), or mu_r >= mu_s.");

  m.def("moment_of_inertia", [](const BallParameters& b) { return cueball::moment_of_inertia(b); }, "ball"_a,
        "I = 2/5 m R^2, kg m^2.");
  m.def("sliding_deceleration", [](const Parameters& p) { return cueball::sliding_deceleration(p); }, "params"_a,
        "mu_s g, m/s^2 (paper 001 eq. 2).");
  m.def("rolling_deceleration", [](const Parameters& p) { return cueball::rolling_deceleration(p); }, "params"_a,
        "(5/7) mu_r g, m/s^2.");
  m.def("spin_deceleration", [](const Parameters& p) { return cueball::spin_deceleration(p); }, "params"_a,
        "5 mu_sp g / (2R), rad/s^2: the decay of the vertical spin.");

  py::dict ranges;
  for (const cueball::ParameterRange* r : cueball::kParameterRanges)
    ranges[r->field] = py::dict("min"_a = r->min, "max"_a = r->max, "unit"_a = r->unit, "meaning"_a = r->meaning);
  m.attr("PARAMETER_RANGES") = ranges;
}

}  // namespace cueball_python
