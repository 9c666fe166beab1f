// include/cueball/physics/cue_strike.hpp: the cue strike.
#include "bindings.hpp"

#include <limits>
#include <numbers>
#include "cueball/physics/cue_strike.hpp"
#include "cueball/core/errors.hpp"

namespace cueball_python {

namespace {

// The scenario's degree (src/simulation/scenario.cpp): the same product converts alike.
constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace

void bind_cue_strike(py::module_& m) {
  using cueball::CueParameters;
  using cueball::CueStrike;
  using cueball::Parameters;

  py::class_<CueParameters> cue(m, "CueParameters",
                                 "The cue: mass (kg), tip-ball restitution and the shaft's end mass of squirt (kg).");
  cue.def(py::init([](double mass, double tip_restitution, double end_mass) {
            return CueParameters{mass, tip_restitution, end_mass};
          }),
          "mass"_a = CueParameters{}.mass, "tip_restitution"_a = CueParameters{}.tip_restitution,
          "end_mass"_a = CueParameters{}.end_mass)
      .def_readwrite("mass", &CueParameters::mass, "M_c, kg, [0.1, 2] (field 'cue_mass' in errors)")
      .def_readwrite("tip_restitution", &CueParameters::tip_restitution, "e, [0, 1] (field 'cue_tip_e' in errors)")
      .def_readwrite("end_mass", &CueParameters::end_mass,
                     "m_e, kg, [0, 0.05]: the shaft's end mass of squirt (Alciatore TP A.31); 0: no squirt "
                     "(field 'cue_end_mass' in errors)");
  add_value_semantics(
      cue, "CueParameters", {"mass", "tip_restitution", "end_mass"},
      [](const CueParameters& c) { return py::make_tuple(c.mass, c.tip_restitution, c.end_mass); },
      [](const py::tuple& t) {
        return CueParameters{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>()};
      });

  py::class_<CueStrike> strike(
      m, "CueStrike",
      "One stroke of the cue (Leckie & Greenspan 2006). speed: the cue's speed before impact, m/s,\n"
      "(0, 12]; aim: its direction in the bed's plane, rad, anticlockwise from +x; elevation: the butt\n"
      "raised, rad, [0, pi/2); side_offset: tip to the RIGHT of centre seen from behind the cue, m\n"
      "(> 0 gives w_z > 0); height_offset: tip above centre across the cue, m (> 0 topspin; 2R/5\n"
      "with a level cue is natural roll). Miscue beyond sqrt(a^2 + b^2) > 0.5 R.");
  strike
      .def(py::init([](double speed, double aim, double elevation, double side_offset, double height_offset) {
             return CueStrike{speed, aim, elevation, side_offset, height_offset};
           }),
           "speed"_a, "aim"_a = 0.0, "elevation"_a = 0.0, "side_offset"_a = 0.0, "height_offset"_a = 0.0)
      .def_readwrite("speed", &CueStrike::speed, "V, m/s")
      .def_readwrite("aim", &CueStrike::aim, "phi, rad, anticlockwise from +x")
      .def_readwrite("elevation", &CueStrike::elevation, "theta, rad; 0 = level cue")
      .def_readwrite("side_offset", &CueStrike::side_offset, "a, m; > 0 right english")
      .def_readwrite("height_offset", &CueStrike::height_offset, "b, m; > 0 above the centre")
      .def_static(
          "from_units",
          [](double speed, double aim_deg, double elevation_deg, double side, double height, double radius) {
            cueball::check_range(cueball::kRadiusRange, radius);
            return CueStrike{speed, aim_deg * kDegree, elevation_deg * kDegree, side * radius, height * radius};
          },
          "speed"_a, "aim_deg"_a = 0.0, "elevation_deg"_a = 0.0, "side"_a = 0.0, "height"_a = 0.0, py::kw_only(),
          py::arg_v("radius", cueball::pool_parameters().ball.radius, "pool_parameters().ball.radius"),
          "The strike given in the scenario's units (its JSON \"cue\", simulate_many's actions): cue speed\n"
          "m/s, aim and elevation in degrees, side and height tip offsets in ball radii of a ball of\n"
          "`radius` m. Converts as the scenario reader does (deg * pi/180, offset * radius), so a\n"
          "scenario with these values strikes with exactly this CueStrike.")
      .def(
          "in_units",
          [](const CueStrike& s, double radius) {
            cueball::check_range(cueball::kRadiusRange, radius);
            return py::dict("speed"_a = s.speed, "aim_deg"_a = s.aim / kDegree, "elevation_deg"_a = s.elevation / kDegree,
                            "side"_a = s.side_offset / radius, "height"_a = s.height_offset / radius);
          },
          py::kw_only(), py::arg_v("radius", cueball::pool_parameters().ball.radius, "pool_parameters().ball.radius"),
          "The strike in the scenario's units, a dict with the JSON \"cue\"'s keys speed (m/s), aim_deg,\n"
          "elevation_deg (degrees), side, height (ball radii of a ball of `radius` m); from_units of it\n"
          "gives this strike back to within an ulp.");
  add_value_semantics(
      strike, "CueStrike", {"speed", "aim", "elevation", "side_offset", "height_offset"},
      [](const CueStrike& s) { return py::make_tuple(s.speed, s.aim, s.elevation, s.side_offset, s.height_offset); },
      [](const py::tuple& t) {
        return CueStrike{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(), t[3].cast<double>(),
                         t[4].cast<double>()};
      });

  m.def(
      "strike_ball",
      [](const CueStrike& s, const Pair& position, const Parameters& p, const CueParameters& c) {
        return cueball::strike_ball(s, to_vec2(position), p.ball, c);
      },
      "strike"_a, "position"_a = Pair{0.0, 0.0}, params_arg(), "cue"_a = CueParameters{},
      "The ball's BallState just after the strike, at `position` (x, y), m; sliding in general.\n"
      "Validates everything; a miscue raises InvalidArgument naming 'tip offset'.");
  m.def(
      "cue_tip_offset_ok",
      [](const CueStrike& s, const Parameters& p) { return cueball::cue_tip_offset_ok(s, p.ball); }, "strike"_a,
      params_arg(), "True when the tip offset sqrt(a^2 + b^2) is within the miscue limit 0.5 R.");
  m.def(
      "level_cue_tip_height",
      [](double v0, double w0, const Parameters& p) {
        cueball::validate(p);
        cueball::require_in_range("v0", v0, std::numeric_limits<double>::min(), cueball::kMaxSpeed, "ball speed, m/s");
        cueball::require_in_range("w0", w0, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed, "topspin, rad/s");
        return cueball::level_cue_tip_height(v0, w0, p.ball);
      },
      "v0"_a, "w0"_a, params_arg(),
      "Tip height b above the centre, m, for a level cue giving ball speed v0 > 0 and topspin w0\n"
      "(b = 2 R^2 w0 / (5 v0); natural roll at b = 2R/5). May lie beyond the miscue limit.");
  m.def(
      "level_cue_speed",
      [](double v0, double tip_height, const Parameters& p, const CueParameters& c) {
        cueball::validate(p);
        cueball::require_in_range("v0", v0, 0.0, cueball::kMaxSpeed, "ball speed, m/s");
        cueball::require_in_range("tip_height", tip_height, -p.ball.radius, p.ball.radius, "tip height, m");
        cueball::require_in_range("cue_mass", c.mass, cueball::kMinCueMass, cueball::kMaxCueMass, "cue mass, kg");
        cueball::require_in_range("cue_tip_e", c.tip_restitution, 0.0, 1.0, "cue tip-ball restitution");
        return cueball::level_cue_speed(v0, tip_height, p.ball, c);
      },
      "v0"_a, "tip_height"_a, params_arg(), "cue"_a = CueParameters{},
      "Cue speed V, m/s, that gives ball speed v0 with a level cue striking at height tip_height (m).");

  m.attr("MAX_CUE_SPEED") = cueball::kMaxCueSpeed;
  m.attr("MISCUE_OFFSET_FRACTION") = cueball::kMiscueOffsetFraction;
}

}  // namespace cueball_python
