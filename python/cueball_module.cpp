// Python bindings of cueball's public API: the module `cueball` (pybind11).
//
// One block per concept, in the order of include/cueball/: errors,
// parameters, cloth motion, planner, cue strike, cushion impact, whole shots.
// The bindings convert and nothing more: every function calls the library's
// validating entry point (or its validate() first, where the kernel itself
// does not validate), so NaN, infinity and out-of-range input raise
// cueball.InvalidArgument naming the field. Vectors are tuples; enums are
// strings; whole-shot results are the CLI's JSON, as Python objects.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cueball/batch.hpp"
#include "cueball/cloth_motion.hpp"
#include "cueball/cue_strike.hpp"
#include "cueball/cushion_impact.hpp"
#include "cueball/errors.hpp"
#include "cueball/parameters.hpp"
#include "cueball/planner.hpp"
#include "cueball/scenario.hpp"
#include "cueball/simulator.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

constexpr const char* kModuleDoc = R"(cueball: physics of billiard balls (closed forms, no time steps).

Units are SI throughout: m, s, kg, rad (degrees only where a name says so,
as in a scenario's "aim_deg"). Table frame: x, y on the bed, x along the
table, z up. A ball's position is its centre projected on the bed, its
velocity (vx, vy) lies in the bed's plane, its angular velocity is
(wx, wy, wz). Straight shots travel along +x; topspin w0 > 0 turns the ball
the way it rolls (R w0 = v0 is natural roll, 0 a stun, < 0 draw); for motion
along +x topspin is wy. Side spin wz > 0 is anticlockwise seen from above;
right english (tip to the right of centre, seen from behind the cue) gives
wz > 0. mu_r follows paper 001's energy convention: a rolling ball
decelerates at (5/7) mu_r g.

Functions that need the ball and cloth take params=Parameters, default
snooker_parameters() (as the CLI). Bad input raises cueball.InvalidArgument
(a ValueError naming the field), an impossible plan cueball.InfeasibleShot
(ValueError), a simulation that cannot finish cueball.SimulationError
(RuntimeError).)";

// ------------------------------------------------------------------ conversions

using Pair = std::array<double, 2>;
using Triple = std::array<double, 3>;

py::tuple to_tuple(cueball::Vec2 v) { return py::make_tuple(v.x, v.y); }
py::tuple to_tuple(cueball::Vec3 v) { return py::make_tuple(v.x, v.y, v.z); }
cueball::Vec2 to_vec2(const Pair& a) { return {a[0], a[1]}; }
cueball::Vec3 to_vec3(const Triple& a) { return {a[0], a[1], a[2]}; }

// "Type(name=value, ...)" with Python's repr of every value.
std::string repr_of(const char* type, const std::vector<const char*>& names, const py::tuple& values) {
  std::string out = std::string(type) + "(";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += ", ";
    out += std::string(names[i]) + "=" + py::repr(values[i]).cast<std::string>();
  }
  return out + ")";
}

// __repr__ from the fields; `get` returns them as a tuple in `names` order.
template <class T, class Get>
void add_repr(py::class_<T>& cls, const char* type, std::vector<const char*> names, Get get) {
  cls.def("__repr__", [type, names, get](const T& v) { return repr_of(type, names, get(v)); });
}

// A plain value type: __repr__, __eq__ field by field, and pickling (so that
// parameters and states can go to multiprocessing workers); `make` builds
// the value back from the tuple `get` returns.
template <class T, class Get, class Make>
void add_value_semantics(py::class_<T>& cls, const char* type, std::vector<const char*> names, Get get, Make make) {
  add_repr(cls, type, std::move(names), get);
  cls.def("__eq__", [get](const T& a, const py::object& b) -> py::object {
    if (!py::isinstance<T>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
    return py::bool_(get(a).equal(get(b.cast<const T&>())));
  });
  cls.def(py::pickle([get](const T& v) { return get(v); }, [make](const py::tuple& t) { return make(t); }));
}

// ------------------------------------------------------------------ errors

// The exception classes, created once and kept for the life of the process
// (never released: they outlive the module's finalisation).
PyObject* g_invalid_argument = nullptr;
PyObject* g_infeasible_shot = nullptr;
PyObject* g_simulation_error = nullptr;

PyObject* new_exception(py::module_& m, const char* name, const char* doc, PyObject* base) {
  const std::string qualified = std::string("cueball.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.attr(name) = py::handle(type);  // the module holds its own reference
  return type;
}

// Raises `type(message)` with one extra attribute naming what failed.
void raise_with(PyObject* type, const char* message, const char* attribute, const std::string& value) {
  py::object instance = py::reinterpret_borrow<py::object>(type)(message);
  instance.attr(attribute) = value;
  PyErr_SetObject(type, instance.ptr());
}

void bind_errors(py::module_& m) {
  g_invalid_argument = new_exception(
      m, "InvalidArgument",
      "A value outside its allowed range (NaN, infinity, negative mass, malformed scenario, ...).\n"
      "The message names the field, its value and what is allowed; `field` is the field's name\n"
      "in cueball's API (e.g. 'mu_s', 'speed', 'scenario.balls[1].position').",
      PyExc_ValueError);
  g_infeasible_shot = new_exception(
      m, "InfeasibleShot",
      "A well-formed request with no physical answer, e.g. a planned shot violating a validity\n"
      "condition of paper 001's inverse problem; `condition` is the failed condition as an\n"
      "inequality (e.g. 'x1 >= x0').",
      PyExc_ValueError);
  g_simulation_error = new_exception(
      m, "SimulationError", "A simulation could not finish (e.g. it reached the scenario's max_events).",
      PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const cueball::InvalidArgument& e) {
      raise_with(g_invalid_argument, e.what(), "field", e.field());
    } catch (const cueball::InfeasibleShot& e) {
      raise_with(g_infeasible_shot, e.what(), "condition", e.condition());
    } catch (const cueball::SimulationError& e) {
      PyErr_SetString(g_simulation_error, e.what());
    }
  });
}

// ------------------------------------------------------------------ parameters

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

// Default argument of every function that needs the ball and cloth.
py::arg_v params_arg() { return py::arg_v("params", cueball::snooker_parameters(), "snooker_parameters()"); }

// ------------------------------------------------------------------ cloth motion

const char* transition_name(cueball::Transition t) {
  switch (t) {
    case cueball::Transition::sliding_ends: return "sliding_ends";
    case cueball::Transition::rolling_ends: return "rolling_ends";
    case cueball::Transition::vertical_spin_ends: return "vertical_spin_ends";
    case cueball::Transition::none: break;
  }
  return "none";
}

// The kernels of cloth_motion.hpp trust their input: validate it here.
void check_state(const cueball::BallState& s, const cueball::Parameters& p) {
  cueball::validate(p);
  cueball::validate(s);
}

void check_time(const char* field, double t) {
  if (!(std::isfinite(t) && t >= 0.0)) throw cueball::InvalidArgument(field, t, "[0, infinity)", "time, s");
}

void check_straight_shot(double v0, double w0, double side_spin, const cueball::Parameters& p) {
  cueball::validate(p);
  cueball::require_in_range("v0", v0, 0.0, cueball::kMaxSpeed, "initial speed along +x, m/s");
  cueball::require_in_range("w0", w0, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed, "initial topspin, rad/s");
  cueball::require_in_range("side_spin", side_spin, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed,
                            "initial side spin w_z, rad/s");
}

void bind_cloth_motion(py::module_& m) {
  using cueball::BallState;
  using cueball::Parameters;

  py::class_<BallState> state(m, "BallState",
                              "Kinematic state of a ball on the bed. position (x, y), m: the centre projected on\n"
                              "the bed; velocity (vx, vy), m/s; angular_velocity (wx, wy, wz), rad/s, wz > 0\n"
                              "anticlockwise seen from above. Not validated until used.");
  state
      .def(py::init([](const Pair& position, const Pair& velocity, const Triple& angular_velocity) {
             return BallState{to_vec2(position), to_vec2(velocity), to_vec3(angular_velocity)};
           }),
           "position"_a = Pair{0.0, 0.0}, "velocity"_a = Pair{0.0, 0.0}, "angular_velocity"_a = Triple{0.0, 0.0, 0.0})
      .def_property(
          "position", [](const BallState& s) { return to_tuple(s.position); },
          [](BallState& s, const Pair& v) { s.position = to_vec2(v); }, "(x, y), m")
      .def_property(
          "velocity", [](const BallState& s) { return to_tuple(s.velocity); },
          [](BallState& s, const Pair& v) { s.velocity = to_vec2(v); }, "(vx, vy), m/s")
      .def_property(
          "angular_velocity", [](const BallState& s) { return to_tuple(s.angular_velocity); },
          [](BallState& s, const Triple& v) { s.angular_velocity = to_vec3(v); }, "(wx, wy, wz), rad/s");
  add_value_semantics(
      state, "BallState", {"position", "velocity", "angular_velocity"},
      [](const BallState& s) {
        return py::make_tuple(to_tuple(s.position), to_tuple(s.velocity), to_tuple(s.angular_velocity));
      },
      [](const py::tuple& t) {
        return BallState{to_vec2(t[0].cast<Pair>()), to_vec2(t[1].cast<Pair>()), to_vec3(t[2].cast<Triple>())};
      });

  m.def(
      "slip_velocity",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        return to_tuple(cueball::slip_velocity(s, p.ball.radius));
      },
      "state"_a, params_arg(), "Contact-point slip u = v + R z^ x w (paper 001 eq. 1), (ux, uy) m/s.");
  m.def(
      "motion_phase",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        return std::string(cueball::to_string(cueball::motion_phase(s, p)));
      },
      "state"_a, params_arg(), "'sliding', 'rolling', 'spinning' or 'stationary', from the kinematics.");
  m.def(
      "next_transition",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        const cueball::NextTransition next = cueball::next_transition(s, p);
        return py::make_tuple(next.time, transition_name(next.kind));
      },
      "state"_a, params_arg(),
      "(time, kind): seconds until the equations of motion next change, and what changes:\n"
      "'sliding_ends', 'rolling_ends', 'vertical_spin_ends', or 'none' (time = inf, stationary).");
  m.def(
      "phase_end_time",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        return cueball::phase_end_time(s, p);
      },
      "state"_a, params_arg(),
      "Seconds until the path changes (end of sliding or rolling), ignoring vertical spin; inf at rest.");
  m.def(
      "evolve",
      [](const BallState& s, double dt, const Parameters& p) {
        check_state(s, p);
        check_time("dt", dt);
        return cueball::evolve(s, dt, p);
      },
      "state"_a, "dt"_a, params_arg(),
      "The state after dt >= 0 seconds, in closed form across every phase transition.");
  m.def(
      "kinetic_energy",
      [](const BallState& s, const Parameters& p) {
        check_state(s, p);
        return cueball::kinetic_energy(s, p.ball);
      },
      "state"_a, params_arg(), "Translational plus rotational kinetic energy (I = 2/5 m R^2), J.");

  py::class_<cueball::StraightShot> shot(m, "StraightShot",
                                         "A straight shot along +x from x = 0 (paper 001 eqs 19-24).");
  shot.def_readonly("t1", &cueball::StraightShot::t1, "end of sliding, s (eq. 19)")
      .def_readonly("x1", &cueball::StraightShot::x1, "position at the end of sliding, m (eq. 21)")
      .def_readonly("v1", &cueball::StraightShot::v1, "velocity at the end of sliding, m/s, signed along +x (eq. 20)")
      .def_readonly("t2", &cueball::StraightShot::t2, "the ball stops translating, s (eq. 22 with v2 = 0)")
      .def_readonly("x2", &cueball::StraightShot::x2, "rest position, m (eq. 24)")
      .def_readonly("t_spin", &cueball::StraightShot::t_spin, "vertical spin reaches zero, s (0 without side spin)");
  add_repr(shot, "StraightShot", {"t1", "x1", "v1", "t2", "x2", "t_spin"}, [](const cueball::StraightShot& s) {
    return py::make_tuple(s.t1, s.x1, s.v1, s.t2, s.x2, s.t_spin);
  });
  m.def(
      "straight_shot",
      [](double v0, double w0, double side_spin, const Parameters& p) {
        check_straight_shot(v0, w0, side_spin, p);
        return cueball::straight_shot(v0, w0, side_spin, p);
      },
      "v0"_a, "w0"_a = 0.0, "side_spin"_a = 0.0, params_arg(),
      "A ball struck along +x with speed v0 (m/s), topspin w0 (rad/s; R w0 = v0 natural roll, 0 stun,\n"
      "< 0 draw) and side spin w_z (rad/s): when sliding ends and where the ball stops.");
  m.def(
      "straight_shot_state",
      [](double v0, double w0, double side_spin, double t, const Parameters& p) {
        check_straight_shot(v0, w0, side_spin, p);
        check_time("t", t);
        return cueball::straight_shot_state(v0, w0, side_spin, t, p);
      },
      "v0"_a, "w0"_a = 0.0, "side_spin"_a = 0.0, "t"_a = 0.0, params_arg(),
      "The state of straight_shot(v0, w0, side_spin) at time t >= 0, s.");

  m.attr("MAX_SPEED") = cueball::kMaxSpeed;
  m.attr("MAX_ANGULAR_SPEED") = cueball::kMaxAngularSpeed;
}

// ------------------------------------------------------------------ planner

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

// ------------------------------------------------------------------ cue strike

void bind_cue_strike(py::module_& m) {
  using cueball::CueParameters;
  using cueball::CueStrike;
  using cueball::Parameters;

  py::class_<CueParameters> cue(m, "CueParameters", "The cue: mass (kg) and tip-ball restitution.");
  cue.def(py::init([](double mass, double tip_restitution) { return CueParameters{mass, tip_restitution}; }),
          "mass"_a = CueParameters{}.mass, "tip_restitution"_a = CueParameters{}.tip_restitution)
      .def_readwrite("mass", &CueParameters::mass, "M_c, kg, [0.1, 2] (field 'cue_mass' in errors)")
      .def_readwrite("tip_restitution", &CueParameters::tip_restitution, "e, [0, 1] (field 'cue_tip_e' in errors)");
  add_value_semantics(
      cue, "CueParameters", {"mass", "tip_restitution"},
      [](const CueParameters& c) { return py::make_tuple(c.mass, c.tip_restitution); },
      [](const py::tuple& t) { return CueParameters{t[0].cast<double>(), t[1].cast<double>()}; });

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
      .def_readwrite("height_offset", &CueStrike::height_offset, "b, m; > 0 above the centre");
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

// ------------------------------------------------------------------ cushion impact

cueball::CushionSolver cushion_solver(const std::string& name) {
  if (name == "exact") return cueball::CushionSolver::exact;
  if (name == "paper") return cueball::CushionSolver::paper;
  throw cueball::InvalidArgument("solver", "solver = '" + name + "' is not a solver; allowed: 'exact', 'paper'");
}

void bind_cushion_impact(py::module_& m) {
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
         int paper_steps, bool history) {
        cueball::validate(p);
        // The CLI's ranges (cueball cushion): speed, angle, spins, steps.
        cueball::require_in_range("V0", speed, 1e-6, cueball::kMaxSpeed, "incoming speed, m/s");
        if (!(std::isfinite(angle) && angle > 0.0 && angle <= std::numbers::pi / 2))
          throw cueball::InvalidArgument("alpha", angle, "(0, pi/2] rad", "angle between the velocity and the cushion");
        if (topspin)
          cueball::require_in_range("w_T", *topspin, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed,
                                    "topspin w_T, rad/s");
        cueball::require_in_range("w_S", sidespin, -cueball::kMaxAngularSpeed, cueball::kMaxAngularSpeed,
                                  "sidespin w_S, rad/s");
        if (paper_steps < 1 || paper_steps > 100000000)
          throw cueball::InvalidArgument("paper_steps", paper_steps, "[1, 1e8]", "Euler steps of the paper solver");
        const double h = contact_height ? *contact_height : cueball::default_cushion_height(p.ball);
        const cueball::CushionParameters cushion{restitution, friction, h};
        cueball::CushionImpactOptions options;
        options.solver = cushion_solver(solver);
        options.paper_steps = paper_steps;
        options.record_history = history;
        const cueball::PaperIncidence incidence{speed, angle, topspin ? *topspin : speed / p.ball.radius, sidespin};
        return cueball::cushion_impact(cueball::incoming_ball(incidence), p, cushion, options);
      },
      "speed"_a, "angle"_a, "topspin"_a = py::none(), "sidespin"_a = 0.0, py::kw_only(), params_arg(),
      "restitution"_a = fit.restitution, "friction"_a = fit.friction, "contact_height"_a = py::none(),
      "solver"_a = "exact", "paper_steps"_a = 5000, "history"_a = false,
      "A ball hitting a cushion: Mathavan, Jackson & Parkin (2010), solved exactly ('exact') or\n"
      "with the authors' Euler scheme ('paper', paper_steps steps).\n"
      "speed: V0 > 0, m/s. angle: alpha in RADIANS, (0, pi/2], between the velocity and the\n"
      "cushion (pi/2 = head-on). topspin: w_T, rad/s (default None: rolling, V0/R; negative is\n"
      "draw). sidespin: w_S, rad/s about Z, > 0 the 'right' spin of the paper's Fig 2.\n"
      "restitution e_e and friction mu_w default to the authors' fit (0.98, 0.14); contact_height\n"
      "h, m, in (R, 2R), default 7R/5. history=True records the impact along P_I.");
  m.attr("RIGID_CUSHION_SPEED_LIMIT") = cueball::kRigidCushionSpeedLimit;
}

// ------------------------------------------------------------------ whole shots

// A dict key as a scenario path shows it: plain names as they are, others quoted.
std::string path_key(const std::string& key) {
  bool plain = !key.empty() && key.size() <= cueball::kMaxEchoedChars;
  for (char c : key) plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  return plain ? key : cueball::quote_input(key);
}

// Raises InvalidArgument for a NaN or infinite float anywhere in a scenario
// given as Python objects (JSON has no spelling for it; the message names the
// field as the library's own checks do), for nesting deeper than the JSON
// reader allows (the same limit, 64), for a container that contains itself,
// and for more values than a scenario's largest JSON text could hold. Never
// recursion without a bound: a recursive or 100,000-deep dict raises.
class ScenarioObjectCheck {
 public:
  void check(const py::handle& value, const std::string& path, std::size_t depth) {
    if (++values_ > kMaxValues)
      throw cueball::InvalidArgument("scenario", "scenario holds more than " + std::to_string(kMaxValues) +
                                                     " values; a scenario's JSON text is at most " +
                                                     std::to_string(cueball::kMaxScenarioBytes) + " bytes");
    if (py::isinstance<py::float_>(value)) {
      const double v = value.cast<double>();
      if (!std::isfinite(v)) throw cueball::InvalidArgument(path, v, "any finite number");
      return;
    }
    const bool dict = py::isinstance<py::dict>(value);
    const bool list = py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value);
    if (!dict && !list) return;
    if (depth >= kMaxDepth)
      throw cueball::InvalidArgument(path, path + " nests deeper than " + std::to_string(kMaxDepth) + " levels");
    PyObject* id = value.ptr();
    for (PyObject* open : open_)
      if (open == id) throw cueball::InvalidArgument(path, path + " contains itself (a circular reference)");
    open_.push_back(id);
    if (dict) {
      for (const auto& item : py::reinterpret_borrow<py::dict>(value)) {
        check(item.second, path + "." + path_key(py::str(item.first).cast<std::string>()), depth + 1);
      }
    } else {
      std::size_t i = 0;
      for (const py::handle& item : value) check(item, path + "[" + std::to_string(i++) + "]", depth + 1);
    }
    open_.pop_back();
  }

 private:
  static constexpr std::size_t kMaxDepth = 64;  // detail::kMaxJsonDepth, the JSON reader's
  // Every JSON value takes at least two bytes of text (itself and a separator).
  static constexpr std::size_t kMaxValues = cueball::kMaxScenarioBytes / 2;
  std::vector<PyObject*> open_;  // the containers on the path from the root
  std::size_t values_ = 0;
};

// A scenario file, read with the library's size limit (never a never-ending
// file read until memory runs out).
std::string read_scenario_file(const py::object& path) {
  const py::object file = py::module_::import("builtins").attr("open")(path, "rb");
  py::object data;
  try {
    data = file.attr("read")(cueball::kMaxScenarioBytes + 1);
  } catch (...) {
    file.attr("close")();
    throw;
  }
  file.attr("close")();
  std::string text = data.cast<std::string>();
  if (text.size() > cueball::kMaxScenarioBytes) {
    const std::string name = py::str(path).cast<std::string>();
    throw cueball::InvalidArgument("scenario", cueball::quote_input(name, cueball::kMaxEchoedPathChars) + ": the scenario file is larger than the " +
                                                   std::to_string(cueball::kMaxScenarioBytes) + " bytes allowed (16 MiB)");
  }
  return text;
}

// The scenario's JSON text, or nothing for the built-in 9-ball break.
// Accepts None, a dict (serialised with Python's json module), a str that is
// JSON text (a scenario is an object: its first non-blank character is '{')
// or else a file's path, or a path (os.PathLike).
std::optional<std::string> scenario_text(const py::object& scenario) {
  if (scenario.is_none()) return std::nullopt;
  if (py::isinstance<py::str>(scenario)) {
    std::string text = scenario.cast<std::string>();
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    return first != std::string::npos && text[first] == '{' ? text : read_scenario_file(scenario);
  }
  if (py::isinstance(scenario, py::module_::import("os").attr("PathLike"))) return read_scenario_file(scenario);
  if (py::isinstance<py::dict>(scenario)) {
    ScenarioObjectCheck().check(scenario, "scenario", 0);
    return py::module_::import("json").attr("dumps")(scenario).cast<std::string>();
  }
  throw py::type_error("scenario must be None (the built-in 9-ball break), a dict, JSON text, or a path (str or os.PathLike)");
}

cueball::Scenario load_scenario(const std::optional<std::string>& text) {
  return text ? cueball::scenario_from_json(*text) : cueball::default_scenario();
}

// [x, y] as a list: the object json.loads makes of the CLI's output.
py::list to_list(cueball::Vec2 v) {
  py::list l;
  l.append(v.x);
  l.append(v.y);
  return l;
}

py::dict batch_dict(const cueball::Scenario& s, const cueball::BatchResult& r) {
  py::dict probability;
  py::list balls;
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const cueball::BallOutcome& b = r.balls[i];
    probability[py::int_(b.id)] = b.pocketed_probability;
    balls.append(py::dict("id"_a = b.id, "name"_a = s.balls[i].name, "pocketed_probability"_a = b.pocketed_probability,
                          "mean_position"_a = to_list(b.mean_position), "position_std"_a = to_list(b.position_std)));
  }
  const double events_per_shot = r.simulated > 0 ? static_cast<double>(r.events) / r.simulated : 0.0;
  return py::dict("shots"_a = r.shots, "simulated"_a = r.simulated, "miscues"_a = r.miscues, "failures"_a = r.failures,
                  "speed_reflected"_a = r.speed_reflected, "elevation_reflected"_a = r.elevation_reflected,
                  "seconds"_a = r.seconds, "shots_per_second"_a = r.shots_per_second,
                  "events_per_shot"_a = events_per_shot, "pocketed_probability"_a = probability, "balls"_a = balls);
}

void bind_whole_shots(py::module_& m) {
  m.def(
      "simulate",
      [](const py::object& scenario, double sample_rate) {
        const std::optional<std::string> text = scenario_text(scenario);
        std::string json;
        {
          py::gil_scoped_release release;
          cueball::require_in_range("sample_rate", sample_rate, 0.0, 1e4, "sampling rate, Hz (0: none)");
          const cueball::Scenario s = load_scenario(text);
          json = cueball::result_to_json(s, cueball::run_scenario(s), sample_rate, -1);
        }
        return py::module_::import("json").attr("loads")(json);
      },
      "scenario"_a = py::none(), "sample_rate"_a = 0.0,
      "Simulates a whole shot, event by event, until every ball is at rest or pocketed, and returns\n"
      "the result as `cueball simulate --json` prints it (json.loads of it): table, parameters,\n"
      "end_time, events, balls (final states, pocketing, trajectory segments) and, with\n"
      "sample_rate > 0 (Hz), samples. scenario: None (the built-in 9-ball break), the scenario's\n"
      "JSON text (a str starting with '{'), a dict of the same, or a path (any other str, or a\n"
      "pathlib.Path) to a scenario file; see the README's\n"
      "'Scenario format'. Releases the GIL while simulating.");
  m.def(
      "simulate_batch",
      [](const py::object& scenario, long long shots, long long threads, std::uint64_t seed) {
        // Taken as long long so that a huge count gets the range error naming it.
        if (shots < 1 || shots > cueball::kMaxBatchShots)
          throw cueball::InvalidArgument("shots", static_cast<double>(shots),
                                         "[1, " + cueball::format_number(cueball::kMaxBatchShots) + "]",
                                         "number of shots");
        if (threads < 1 || threads > cueball::kMaxBatchThreads)
          throw cueball::InvalidArgument("threads", static_cast<double>(threads),
                                         "[1, " + std::to_string(cueball::kMaxBatchThreads) + "]", "worker threads");
        const std::optional<std::string> text = scenario_text(scenario);
        cueball::Scenario s;
        cueball::BatchResult r;
        {
          py::gil_scoped_release release;
          s = load_scenario(text);
          // A worker's error (e.g. InvalidArgument) is rethrown here, in this thread.
          r = cueball::simulate_batch(
              s, cueball::BatchOptions{static_cast<int>(shots), static_cast<int>(threads), seed});
        }
        return batch_dict(s, r);
      },
      "scenario"_a = py::none(), "shots"_a = 1000, "threads"_a = 1, "seed"_a = 0,
      "Simulates `shots` copies of the scenario's shot with Gaussian execution noise on the cue\n"
      "strike (the scenario's \"noise\"), on `threads` threads; deterministic for a seed whatever\n"
      "the number of threads; memory does not grow with `shots` (at most 1e8). A noisy cue speed\n"
      "above 12 m/s or elevation below 0 is reflected at the limit (2 cap - v, -e) and counted; a\n"
      "noisy tip offset beyond the miscue limit (0.5 R) is a miscue, counted and not simulated. An\n"
      "error in any shot raises the same exception a single run of it would (the lowest-numbered\n"
      "shot's, whatever `threads`). Returns the keys of `cueball batch --json`: shots, simulated,\n"
      "miscues, failures, speed_reflected, elevation_reflected, seconds, shots_per_second,\n"
      "events_per_shot, pocketed_probability {ball id (int): probability} and balls [{id, name, pocketed_probability, mean_position, position_std}].\n"
      "Releases the GIL while simulating.");
}

}  // namespace

PYBIND11_MODULE(cueball, m) {
  m.doc() = kModuleDoc;
  m.attr("__version__") = CUEBALL_VERSION;
  bind_errors(m);
  bind_parameters(m);
  bind_cloth_motion(m);
  bind_planner(m);
  bind_cue_strike(m);
  bind_cushion_impact(m);
  bind_whole_shots(m);
}
