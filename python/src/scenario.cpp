// include/cueball/simulation/scenario.hpp: a shot as an object. A Scenario is
// read-only and always valid; every way of making one goes through the
// library's JSON reader (scenario_from_json), so the checks, the defaults and
// the units (degrees and ball radii for the cue) are the JSON's, and its
// JSON (scenario_to_json) reads back to the same simulation bit for bit.
#include "bindings.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>
#include "cueball/io/scenario_json.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/table/rack.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball_python {

namespace {

using cueball::Scenario;
using cueball::SimulationBall;
using cueball::SimulationSettings;
using ScenarioPtr = std::shared_ptr<Scenario>;

// The scenario's "cue" in its units, as the JSON gives it.
struct ShotStrike {
  double speed = 3.0;  // the JSON's default
  double aim_deg = 0.0;
  double elevation_deg = 0.0;
  double side = 0.0;
  double height = 0.0;
  int ball = 0;
  std::optional<int> target;
};

py::tuple shot_fields(const ShotStrike& s) {
  return py::make_tuple(s.speed, s.aim_deg, s.elevation_deg, s.side, s.height, s.ball,
                        s.target ? py::object(py::int_(*s.target)) : py::object(py::none()));
}

py::dict written(const Scenario& s) { return json_loads(cueball::scenario_to_json(s, -1)); }

ScenarioPtr from_json(const std::string& text) {
  py::gil_scoped_release release;
  return std::make_shared<Scenario>(cueball::scenario_from_json(text));
}

ScenarioPtr from_document(const std::string& text) {
  py::gil_scoped_release release;
  return std::make_shared<Scenario>(cueball::scenario_from_document(text));
}

ScenarioPtr built_in() { return std::make_shared<Scenario>(cueball::default_scenario()); }

std::string to_json(const Scenario& s, int indent) {
  if (indent < -1 || indent > 16)
    throw cueball::InvalidArgument("indent", indent, "[-1, 16]", "spaces per level, -1: one line");
  return cueball::scenario_to_json(s, indent);
}

const std::vector<const char*> kShotFields{"speed", "aim_deg", "elevation_deg", "side", "height", "ball", "target"};

// The cue as the scenario's JSON writes it (the values that convert exactly).
std::optional<ShotStrike> cue_of(const Scenario& s) {
  if (!s.cue) return std::nullopt;
  const py::dict c = written(s)["cue"].cast<py::dict>();
  ShotStrike out;
  out.speed = c["speed"].cast<double>();
  out.aim_deg = c.contains("aim_deg") ? c["aim_deg"].cast<double>() : 0.0;
  out.elevation_deg = c["elevation_deg"].cast<double>();
  out.side = c["side"].cast<double>();
  out.height = c["height"].cast<double>();
  out.ball = s.cue->ball;
  out.target = s.cue->target;
  return out;
}

py::list vec(const cueball::Vec2& v) { return py::list(to_tuple(v)); }
py::list vec(const cueball::Vec3& v) { return py::list(to_tuple(v)); }

py::dict ball_json(const SimulationBall& b) {
  py::dict d("id"_a = b.id, "position"_a = vec(b.state.position), "velocity"_a = vec(b.state.velocity),
             "angular_velocity"_a = vec(b.state.angular_velocity));
  if (!b.name.empty()) d["name"] = b.name;
  return d;
}

// The scenario's JSON of the parts given to Scenario(...); the table's own
// JSON text goes in as it is.
std::string scenario_json(const py::object& table, const py::iterable& balls, const std::optional<ShotStrike>& cue,
                          const std::optional<SimulationSettings>& settings,
                          const std::optional<cueball::CueParameters>& cue_parameters, const py::object& noise) {
  std::string table_text;
  if (py::isinstance<py::str>(table)) {
    (void)utf8_argument(table, "table");
    table_text = py::module_::import("json").attr("dumps")(table).cast<std::string>();
  } else if (py::isinstance<cueball::Table>(table)) {
    table_text = cueball::table_to_json(table.cast<const cueball::Table&>());
  } else {
    throw ArgumentTypeError("table", wrong_type_message(table, "table", "a cueball.Table or a preset's name (TABLE_PRESETS)"));
  }
  py::dict d;
  py::list placed;
  for (const py::handle& b : balls) {
    if (py::isinstance<SimulationBall>(b)) {
      placed.append(ball_json(b.cast<const SimulationBall&>()));
    } else if (py::isinstance<cueball::PlacedBall>(b)) {
      const auto& p = b.cast<const cueball::PlacedBall&>();
      placed.append(ball_json(SimulationBall{p.id, p.name, {p.position, {}, {}}}));
    } else {
      throw ArgumentTypeError("balls", wrong_type_message(b, "balls[" + std::to_string(placed.size()) + "]",
                                                          "a SimulationBall or a PlacedBall"));
    }
  }
  d["balls"] = placed;
  if (settings) {
    const cueball::Parameters& p = settings->parameters;
    d["parameters"] = py::dict("mass"_a = p.ball.mass, "radius"_a = p.ball.radius, "mu_s"_a = p.cloth.sliding_friction,
                               "mu_r"_a = p.cloth.rolling_resistance, "mu_sp"_a = p.cloth.spin_friction,
                               "g"_a = p.cloth.gravity);
    const cueball::CushionSettings& k = settings->cushion;
    d["cushion"] = py::dict("model"_a = cueball::to_string(k.model), "restitution"_a = k.restitution,
                            "friction"_a = k.friction);
    // Only the chosen model's and solver's keys: the reader refuses the others.
    if (k.model == cueball::CushionModel::mathavan_2010) {
      d["cushion"]["solver"] = cueball::to_string(k.solver);
      if (k.solver == cueball::CushionSolver::paper) d["cushion"]["paper_steps"] = k.paper_steps;
      if (k.solver == cueball::CushionSolver::exact && k.exact_tolerance != cueball::CushionSettings{}.exact_tolerance)
        d["cushion"]["exact_tolerance"] = k.exact_tolerance;
    }
    if (k.model == cueball::CushionModel::stronge_compliant) d["cushion"]["frequency_ratio"] = k.frequency_ratio;
    const cueball::BallCollisionParameters& c = settings->ball_collision;
    d["ball_collision"] = py::dict("model"_a = cueball::to_string(settings->ball_collision_model),
                                   "restitution"_a = c.restitution, "friction"_a = c.friction);
    if (settings->ball_collision_model == cueball::BallCollisionModel::coulomb_impulse) {
      d["ball_collision"]["friction_excess"] = c.friction_excess;
      d["ball_collision"]["friction_decay"] = c.friction_decay;
    }
    d["max_events"] = settings->max_events;
  }
  if (cue) {
    py::dict c("ball"_a = cue->ball, "speed"_a = cue->speed, "elevation_deg"_a = cue->elevation_deg,
               "side"_a = cue->side, "height"_a = cue->height);
    if (cue->target) c["target"] = *cue->target;
    if (!cue->target || cue->aim_deg != 0.0) c["aim_deg"] = cue->aim_deg;  // both: the reader's error
    if (cue_parameters) {
      c["mass"] = cue_parameters->mass;
      c["tip_restitution"] = cue_parameters->tip_restitution;
      c["end_mass"] = cue_parameters->end_mass;
    }
    d["cue"] = c;
  } else if (cue_parameters) {
    throw cueball::InvalidArgument("cue_parameters", "cue_parameters: the cue's mass and tip belong to a cue strike; "
                                                     "give cue= as well");
  }
  if (!noise.is_none()) d["noise"] = noise;
  const std::string rest = json_text(d, "scenario");  // "{...}", never empty: "balls" is there
  return "{\"table\": " + table_text + ", " + rest.substr(1);
}

cueball::CushionModel cushion_model_named(const std::string& name, const char* field) {
  const std::optional<cueball::CushionModel> model = cueball::cushion_model_from_string(name);
  if (!model)
    throw cueball::InvalidArgument(field, std::string(field) + " = " + cueball::quote_input(name) +
                                              " is not known; allowed: " + cueball::cushion_model_names("'"));
  return *model;
}

cueball::BallCollisionModel ball_collision_model_named(const std::string& name, const char* field) {
  const std::optional<cueball::BallCollisionModel> model = cueball::ball_collision_model_from_string(name);
  if (!model)
    throw cueball::InvalidArgument(field, std::string(field) + " = " + cueball::quote_input(name) +
                                              " is not known; allowed: " + cueball::ball_collision_model_names("'"));
  return *model;
}

// The arguments of one cushion model or solver, given with another (kept
// and never used): refused as the scenario reader refuses their keys.
void check_cushion_owners(const cueball::CushionSettings& k, bool solver, bool paper_steps, bool exact_tolerance,
                          bool frequency_ratio) {
  using cueball::CushionModel;
  using cueball::CushionSolver;
  const char* model = cueball::to_string(k.model);
  only_for("cushion_solver", solver, "model", k.model == CushionModel::mathavan_2010, "mathavan_2010", model);
  only_for("cushion_paper_steps", paper_steps, "model", k.model == CushionModel::mathavan_2010, "mathavan_2010", model);
  only_for("cushion_exact_tolerance", exact_tolerance, "model", k.model == CushionModel::mathavan_2010, "mathavan_2010", model);
  only_for("cushion_frequency_ratio", frequency_ratio, "model", k.model == CushionModel::stronge_compliant,
           "stronge_compliant", model);
  const char* chosen = cueball::to_string(k.solver);
  only_for("cushion_paper_steps", paper_steps, "solver", k.solver == CushionSolver::paper, "paper", chosen);
  only_for("cushion_exact_tolerance", exact_tolerance, "solver", k.solver == CushionSolver::exact, "exact", chosen);
}

// The settings checked as the scenario reader checks its JSON, each error
// naming the argument: the cushion model's constants (at the default contact
// height), the ball-ball model's (a constant of coulomb_impulse's
// speed-dependent friction under mathavan_2014 included), max_events.
void check_settings(const SimulationSettings& s) {
  try {
    (void)cueball::cushion_contact(s.parameters, s.cushion, cueball::default_cushion_height(s.parameters.ball));
  } catch (const cueball::InvalidArgument& e) {
    // Mathavan's own names for the cushion's constants.
    if (e.field() == "e_e" || e.field() == "mu_w") {
      const std::string field = e.field() == "e_e" ? "cushion_restitution" : "cushion_friction";
      throw cueball::InvalidArgument(field, field + ": " + e.what());
    }
    throw;
  }
  try {
    (void)cueball::ball_collision_contact(s.parameters, s.ball_collision_model, s.ball_collision);
  } catch (const cueball::InvalidArgument& e) {
    const std::string field = (e.field() == "mu_s" ? "parameters." : "ball_collision.") + e.field();
    throw cueball::InvalidArgument(field, field + ": " + e.what());
  }
  if (s.max_events < 1 || s.max_events > cueball::kMaxEvents)
    throw cueball::InvalidArgument("max_events", s.max_events, "[1, " + std::to_string(cueball::kMaxEvents) + "]",
                                   "event limit");
}

}  // namespace

void bind_scenario(py::module_& m) {
  py::class_<SimulationBall> ball_cls(m, "SimulationBall",
                                  "A ball placed for a shot: id (0-1000000, unique), name (default the id), state\n"
                                  "(BallState: position m, velocity m/s, angular_velocity rad/s) before the strike.");
  ball_cls.def(py::init([](int id, const Pair& position, const Pair& velocity, const Triple& angular_velocity,
                       const std::string& name) {
             return SimulationBall{id, name, {to_vec2(position), to_vec2(velocity), to_vec3(angular_velocity)}};
           }),
           "id"_a, "position"_a, "velocity"_a = Pair{0.0, 0.0}, "angular_velocity"_a = Triple{0.0, 0.0, 0.0},
           "name"_a = "")
      .def_readwrite("id", &SimulationBall::id)
      .def_readwrite("name", &SimulationBall::name, "'' in a new ball: the scenario names it by its id")
      .def_readwrite("state", &SimulationBall::state, "BallState (a copy; assign a new one to change it)");
  add_value_semantics(
      ball_cls, "SimulationBall", {"id", "name", "state"},
      [](const SimulationBall& b) { return py::make_tuple(b.id, b.name, b.state); },
      [](const py::tuple& t) {
        return SimulationBall{t[0].cast<int>(), t[1].cast<std::string>(), t[2].cast<cueball::BallState>()};
      });

  const SimulationSettings defaults;
  py::class_<SimulationSettings> settings_cls(
      m, "SimulationSettings",
      "The physics of a shot: parameters (ball and cloth); the cushion model by name (cushion_model:\n"
      "'mathavan_2010', the default, 'han_2005' or 'stronge_compliant') with its restitution and\n"
      "friction (each model's own defaults when not given); for mathavan_2010, cushion_solver 'exact'\n"
      "or 'paper' (the Euler scheme, cushion_paper_steps steps) and cushion_exact_tolerance (the exact\n"
      "solver's local error per step, [1e-11, 1e-7]; 1e-8 keeps the accuracy goal, 1e-7 is 14-29% cheaper\n"
      "a sliding impact for planners' inner loops, its error in the README); for stronge_compliant,\n"
      "cushion_frequency_ratio (Omega, (1, 1000]); the ball-ball model by name\n"
      "(ball_collision_model: 'coulomb_impulse', the default, or 'mathavan_2014') with its constants\n"
      "ball_collision (the model's own when not given); and max_events (SimulationError beyond it,\n"
      "[1, 1e6]). Checked when made, as a scenario's JSON: an argument of another model or solver\n"
      "than the one chosen (cushion_frequency_ratio with 'mathavan_2010', cushion_paper_steps with the\n"
      "exact solver, ...) raises InvalidArgument naming it.");
  settings_cls
      .def(py::init([](const cueball::Parameters& p, const py::object& e, const py::object& mu,
                       const py::object& c, int max_events, const std::string& model, const std::string& solver,
                       int paper_steps, const py::object& omega, const std::string& ball_model,
                       double exact_tolerance) {
             SimulationSettings s;
             s.parameters = p;
             s.cushion = cueball::default_cushion_settings(cushion_model_named(model, "cushion_model"));
             if (!e.is_none()) s.cushion.restitution = cast_argument<double>(e, "cushion_restitution", "float or None");
             if (!mu.is_none()) s.cushion.friction = cast_argument<double>(mu, "cushion_friction", "float or None");
             s.cushion.solver = cushion_solver(solver, "cushion_solver");
             s.cushion.paper_steps = paper_steps;
             s.cushion.exact_tolerance = exact_tolerance;
             if (!omega.is_none()) s.cushion.frequency_ratio = cast_argument<double>(omega, "cushion_frequency_ratio", "float or None");
             s.ball_collision_model = ball_collision_model_named(ball_model, "ball_collision_model");
             s.ball_collision = c.is_none() ? cueball::default_ball_collision(s.ball_collision_model)
                                            : cast_argument<cueball::BallCollisionParameters>(
                                                  c, "ball_collision", "BallCollisionParameters or None");
             s.max_events = max_events;
             const SimulationSettings d;
             check_cushion_owners(s.cushion, solver != cueball::to_string(d.cushion.solver),
                                  paper_steps != d.cushion.paper_steps, exact_tolerance != d.cushion.exact_tolerance,
                                  !omega.is_none());
             check_settings(s);
             return s;
           }),
           py::arg_v("parameters", defaults.parameters, "pool_parameters()"),
           py::arg_v("cushion_restitution", py::none(), "the model's own (0.98 for mathavan_2010)"),
           py::arg_v("cushion_friction", py::none(), "the model's own (0.14 for mathavan_2010)"),
           py::arg_v("ball_collision", py::none(), "the model's own (ball_collision_alciatore() for coulomb_impulse)"),
           "max_events"_a = defaults.max_events, "cushion_model"_a = cueball::to_string(defaults.cushion.model),
           "cushion_solver"_a = cueball::to_string(defaults.cushion.solver),
           "cushion_paper_steps"_a = defaults.cushion.paper_steps,
           py::arg_v("cushion_frequency_ratio", py::none(), "the model's own (1.8 for stronge_compliant)"),
           "ball_collision_model"_a = cueball::to_string(defaults.ball_collision_model),
           "cushion_exact_tolerance"_a = defaults.cushion.exact_tolerance)
      .def_readwrite("parameters", &SimulationSettings::parameters)
      .def_property(
          "cushion_model", [](const SimulationSettings& s) { return std::string(cueball::to_string(s.cushion.model)); },
          [](SimulationSettings& s, const std::string& name) { s.cushion.model = cushion_model_named(name, "cushion_model"); },
          "the cushion model by name (its constants stay as they are: set them too)")
      .def_property(
          "cushion_restitution", [](const SimulationSettings& s) { return s.cushion.restitution; },
          [](SimulationSettings& s, double v) { s.cushion.restitution = v; }, "e_e (mathavan_2010, (0, 1]) or e (han_2005, [0, 1])")
      .def_property(
          "cushion_friction", [](const SimulationSettings& s) { return s.cushion.friction; },
          [](SimulationSettings& s, double v) { s.cushion.friction = v; }, "mu_w (mathavan_2010) or mu (han_2005), >= 0")
      .def_property(
          "cushion_solver", [](const SimulationSettings& s) { return std::string(cueball::to_string(s.cushion.solver)); },
          [](SimulationSettings& s, const std::string& name) {
            check_cushion_owners(s.cushion, true, false, false, false);
            s.cushion.solver = cushion_solver(name, "cushion_solver");
          },
          "mathavan_2010's solver: 'exact' or 'paper'")
      .def_property(
          "cushion_paper_steps", [](const SimulationSettings& s) { return s.cushion.paper_steps; },
          [](SimulationSettings& s, int n) {
            check_cushion_owners(s.cushion, false, true, false, false);
            s.cushion.paper_steps = n;
          },
          "the paper solver's Euler steps, [1, 1e5]")
      .def_property(
          "cushion_exact_tolerance", [](const SimulationSettings& s) { return s.cushion.exact_tolerance; },
          [](SimulationSettings& s, double v) {
            check_cushion_owners(s.cushion, false, false, true, false);
            s.cushion.exact_tolerance = v;
          },
          "the exact solver's local error per step, [1e-11, 1e-7] (1e-8 keeps the accuracy goal)")
      .def_property(
          "cushion_frequency_ratio", [](const SimulationSettings& s) { return s.cushion.frequency_ratio; },
          [](SimulationSettings& s, double v) {
            check_cushion_owners(s.cushion, false, false, false, true);
            s.cushion.frequency_ratio = v;
          },
          "stronge_compliant's Omega, tangential over normal natural frequency, (1, 1000]")
      .def_property(
          "ball_collision_model",
          [](const SimulationSettings& s) { return std::string(cueball::to_string(s.ball_collision_model)); },
          [](SimulationSettings& s, const std::string& name) {
            s.ball_collision_model = ball_collision_model_named(name, "ball_collision_model");
          },
          "the ball-ball model by name (its constants stay as they are: set them too)")
      .def_readwrite("ball_collision", &SimulationSettings::ball_collision)
      .def_readwrite("max_events", &SimulationSettings::max_events);
  add_value_semantics(
      settings_cls, "SimulationSettings",
      {"parameters", "cushion_model", "cushion_restitution", "cushion_friction", "cushion_solver", "cushion_paper_steps",
       "cushion_frequency_ratio", "ball_collision_model", "ball_collision", "max_events", "cushion_exact_tolerance"},
      [](const SimulationSettings& s) {
        return py::make_tuple(s.parameters, std::string(cueball::to_string(s.cushion.model)), s.cushion.restitution,
                              s.cushion.friction, std::string(cueball::to_string(s.cushion.solver)), s.cushion.paper_steps,
                              s.cushion.frequency_ratio, std::string(cueball::to_string(s.ball_collision_model)),
                              s.ball_collision, s.max_events, s.cushion.exact_tolerance);
      },
      [](const py::tuple& t) {
        SimulationSettings s;
        s.parameters = t[0].cast<cueball::Parameters>();
        s.cushion.model = cushion_model_named(t[1].cast<std::string>(), "cushion_model");
        s.cushion.restitution = t[2].cast<double>();
        s.cushion.friction = t[3].cast<double>();
        s.cushion.solver = cushion_solver(t[4].cast<std::string>(), "cushion_solver");
        s.cushion.paper_steps = t[5].cast<int>();
        s.cushion.frequency_ratio = t[6].cast<double>();
        s.ball_collision_model = ball_collision_model_named(t[7].cast<std::string>(), "ball_collision_model");
        s.ball_collision = t[8].cast<cueball::BallCollisionParameters>();
        s.max_events = t[9].cast<int>();
        s.cushion.exact_tolerance = t[10].cast<double>();
        return s;
      });

  py::class_<ShotStrike> shot(
      m, "ShotStrike",
      "A scenario's cue strike in the scenario's units (its JSON \"cue\"): speed of the cue, m/s, (0, 12];\n"
      "aim_deg, degrees anticlockwise from +x (or target, a ball id to aim at); elevation_deg, degrees,\n"
      "[0, 89]; side (to the right seen from behind the cue) and height (above the centre) tip offsets\n"
      "in ball radii, miscue beyond 0.5; ball, the id of the ball struck. Checked when a Scenario is made.");
  shot.def(py::init([](double speed, double aim_deg, double elevation_deg, double side, double height, int ball,
                       std::optional<int> target) {
             return ShotStrike{speed, aim_deg, elevation_deg, side, height, ball, target};
           }),
           "speed"_a, "aim_deg"_a = 0.0, "elevation_deg"_a = 0.0, "side"_a = 0.0, "height"_a = 0.0, "ball"_a = 0,
           "target"_a = py::none())
      .def_readwrite("speed", &ShotStrike::speed, "cue speed, m/s")
      .def_readwrite("aim_deg", &ShotStrike::aim_deg, "degrees from +x")
      .def_readwrite("elevation_deg", &ShotStrike::elevation_deg, "degrees")
      .def_readwrite("side", &ShotStrike::side, "a / R, ball radii")
      .def_readwrite("height", &ShotStrike::height, "b / R, ball radii")
      .def_readwrite("ball", &ShotStrike::ball, "id of the struck ball")
      .def_readwrite("target", &ShotStrike::target, "id of the ball aimed at, or None (aim_deg)");
  add_value_semantics(
      shot, "ShotStrike", kShotFields, shot_fields,
      [](const py::tuple& t) {
        return ShotStrike{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(), t[3].cast<double>(),
                          t[4].cast<double>(), t[5].cast<int>(),    t[6].cast<std::optional<int>>()};
      });

  py::class_<Scenario, ScenarioPtr> scenario(
      m, "Scenario",
      "A shot: table, balls, cue strike, physics. Read-only and always valid (made through the\n"
      "library's scenario reader: the JSON's checks, defaults and units). simulate(), simulate_batch()\n"
      "and simulate_many() take it wherever they take a scenario dict; == compares the full JSON;\n"
      "pickled as its JSON, which reads back to the same simulation bit for bit.");
  scenario
      .def(py::init([](const py::object& table, const py::iterable& balls, std::optional<ShotStrike> cue,
                       std::optional<SimulationSettings> settings, std::optional<cueball::CueParameters> cue_parameters,
                       const py::object& noise) {
             return from_json(scenario_json(table, balls, cue, settings, cue_parameters, noise));
           }),
           "table"_a, "balls"_a, "cue"_a = py::none(), py::kw_only(), "settings"_a = py::none(),
           "cue_parameters"_a = py::none(), "noise"_a = py::none(),
           "A scenario from its parts: table (a Table or a preset's name), balls (SimulationBall or\n"
           "PlacedBall, e.g. a rack), cue (ShotStrike, or None: the balls start as given), settings\n"
           "(SimulationSettings; None: the table's ball with the cloth preset that goes with the table),\n"
           "cue_parameters (CueParameters; None: the default cue), noise (a dict of the JSON's \"noise\":\n"
           "speed m/s, aim_deg, elevation_deg degrees, side, height ball radii). Errors name the JSON path\n"
           "('scenario.balls[1].position').")
      .def_static("default", &built_in, "The built-in 9-ball break (simulate(None)'s).")
      .def_static("from_json", &from_json, "text"_a, "A scenario from its JSON text (README 'Scenario format').")
      .def_static("from_document", &from_document, "text"_a,
                  "A scenario JSON, or a result JSON (Result.to_json()) whose \"scenario\" is read: a replay.")
      .def("to_json", &to_json, "indent"_a = 1, "The scenario in full, every value explicit; from_json of it simulates bit for bit alike.")
      .def("to_dict", &written, "json.loads(to_json()).")
      .def_property_readonly("table", [](const Scenario& s) { return s.table; }, "the Table (a copy)")
      .def_property_readonly(
          "balls", [](const Scenario& s) { return s.balls; }, "list of SimulationBall as placed, before the strike (copies)")
      .def_property_readonly(
          "cue", &cue_of,
          "the cue strike in the scenario's units (ShotStrike: degrees, ball radii), or None")
      .def_property_readonly("cue_parameters", [](const Scenario& s) { return s.cue_parameters; }, "CueParameters (a copy)")
      .def_property_readonly(
          "noise", [](const Scenario& s) -> py::object { return written(s)["noise"]; },
          "the execution noise of simulate_batch, a dict in the scenario's units (speed m/s, aim_deg,\n"
          "elevation_deg degrees, side, height ball radii)")
      .def_property_readonly("settings", [](const Scenario& s) { return s.settings; }, "SimulationSettings (a copy)")
      .def_property_readonly(
          "parameters", [](const Scenario& s) { return s.settings.parameters; }, "settings.parameters")
      .def("__eq__",
           [](const Scenario& a, const py::object& b) -> py::object {
             if (!py::isinstance<Scenario>(b)) return py::reinterpret_borrow<py::object>(Py_NotImplemented);
             return py::bool_(cueball::scenario_to_json(a, -1) == cueball::scenario_to_json(b.cast<const Scenario&>(), -1));
           })
      .def("__repr__",
           [](const Scenario& s) {
             const std::optional<ShotStrike> c = cue_of(s);
             const std::string cue = c ? repr_of("ShotStrike", kShotFields, shot_fields(*c)) : "None";
             return "Scenario(table=" + py::repr(py::str(s.table.name)).cast<std::string>() +
                    ", balls=" + std::to_string(s.balls.size()) + ", cue=" + cue + ")";
           })
      .def(py::pickle([](const Scenario& s) { return cueball::scenario_to_json(s, -1); }, &from_json));
  // Scenarios are compared by value but never changed: hashable by their JSON.
  scenario.def("__hash__", [](const Scenario& s) { return py::hash(py::str(cueball::scenario_to_json(s, -1))); });

  m.def("default_scenario", &built_in, "Scenario.default(): the built-in 9-ball break.");
  m.def("scenario_from_json", &from_json, "text"_a, "Scenario.from_json(text).");
  m.def("scenario_from_document", &from_document, "text"_a,
        "Scenario.from_document(text): a scenario or a result JSON's \"scenario\".");
  m.def("scenario_to_json", &to_json, "scenario"_a, "indent"_a = 1, "scenario.to_json(indent).");
}

}  // namespace cueball_python
