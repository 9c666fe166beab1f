// The Python module `cueball`: one source file per concept (as the library's
// headers), each defining one bind_*() that module.cpp calls, and the
// conversions they share.
//
// The bindings convert and nothing more: every function calls the library's
// validating entry point (or its validate() first, where the kernel itself
// does not validate), so NaN, infinity and out-of-range input raise
// cueball.InvalidArgument naming the field. Vectors are tuples; enums are
// strings.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <memory>

#include "cueball/models/cushion/impact.hpp"
#include "cueball/core/parameters.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/core/vec.hpp"

namespace cueball_python {

namespace py = pybind11;
using namespace pybind11::literals;

// ------------------------------------------------------------------ the bind_*() of each file

void bind_errors(py::module_& m);        // errors.cpp: InvalidArgument, InfeasibleShot, SimulationError
void bind_parameters(py::module_& m);    // parameters.cpp
void bind_cloth_motion(py::module_& m);  // cloth_motion.cpp
void bind_planner(py::module_& m);       // planner.cpp
void bind_cue_strike(py::module_& m);    // cue_strike.cpp
void bind_cushion(py::module_& m);       // cushion.cpp
void bind_table(py::module_& m);         // table.cpp: Table, its parts, TableSpec, presets
void bind_rack(py::module_& m);          // rack.cpp: racks, spots
void bind_ball_collision(py::module_& m);  // ball_collision.cpp
void bind_cushion_fit(py::module_& m);   // cushion_fit.cpp: fit_cushion
void bind_calibration(py::module_& m);   // calibration.cpp: calibrate
void bind_scenario(py::module_& m);      // scenario.cpp: Scenario, ShotStrike, SimulationBall, SimulationSettings
void bind_shot_planner(py::module_& m);  // shot_planner.cpp: plan_shot
void bind_simulation(py::module_& m);    // simulation.cpp: simulate
void bind_batch(py::module_& m);         // batch.cpp: simulate_batch
void bind_games(py::module_& m);         // games.cpp: the submodule games (states, actions, play, agents, records)
void bind_rl(py::module_& m);            // rl.cpp: the learning environment's native classes (cueball.rl)
#ifdef CUEBALL_HAVE_SIMULATE_MANY
void bind_simulate_many(py::module_& m);  // simulate_many.cpp (defined there, when it exists)
#endif

// ------------------------------------------------------------------ conversions

/// An argument of the wrong Python type: raised as cueball.InvalidArgumentType
/// (an InvalidArgument and a TypeError) with `field` the argument's name
/// (errors.cpp). pybind11's own refusals of an argument's type are named the
/// same way by cueball/_arguments.py.
struct ArgumentTypeError : std::runtime_error {
  ArgumentTypeError(std::string field_name, const std::string& message)
      : std::runtime_error(message), field(std::move(field_name)) {}
  std::string field;
};

/// `value` as T, or ArgumentTypeError "FIELD = repr(value) is a TYPE; allowed: ALLOWED".
template <class T>
T cast_argument(const py::handle& value, const std::string& field, const char* allowed);

/// A Python str as UTF-8; InvalidArgument naming `field` when it holds a lone
/// UTF-16 surrogate (no UTF-8 for it), ArgumentTypeError when it is no str.
std::string utf8_argument(const py::handle& text, const std::string& field);

/// "FIELD = repr(value) is a TYPE; allowed: ALLOWED" (repr cut at 60 characters).
std::string wrong_type_message(const py::handle& value, const std::string& field, const char* allowed);

template <class T>
T cast_argument(const py::handle& value, const std::string& field, const char* allowed) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw ArgumentTypeError(field, wrong_type_message(value, field, allowed));
  }
}

using Pair = std::array<double, 2>;
using Triple = std::array<double, 3>;

inline py::tuple to_tuple(cueball::Vec2 v) { return py::make_tuple(v.x, v.y); }
inline py::tuple to_tuple(cueball::Vec3 v) { return py::make_tuple(v.x, v.y, v.z); }
inline cueball::Vec2 to_vec2(const Pair& a) { return {a[0], a[1]}; }
inline cueball::Vec3 to_vec3(const Triple& a) { return {a[0], a[1], a[2]}; }

// "Type(name=value, ...)" with Python's repr of every value.
std::string repr_of(const char* type, const std::vector<const char*>& names, const py::tuple& values);

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

// Default argument of every function that needs the ball and cloth: the
// pool preset, as the default table, rack and scenario (python/README.md,
// "Units and defaults").
py::arg_v params_arg();

// The cushion solver named 'exact' or 'paper' (InvalidArgument 'solver'
// otherwise), and its name (cushion.cpp).
/// The solver of that name ("exact", "paper"); InvalidArgument naming `field` otherwise.
cueball::CushionSolver cushion_solver(const std::string& name, const char* field = "solver");

/// Refuses an argument given (`given`) that belongs to another model or
/// solver than the one chosen: InvalidArgument "FIELD applies to the KIND
/// 'OWNER' only, not to 'CHOSEN'", as the scenario reader refuses its key.
void only_for(const char* field, bool given, const char* kind, bool applies, const char* owner, std::string_view chosen);

// ------------------------------------------------------------------ noise of batches (batch.cpp)
/// The scenario with simulate_batch's or simulate_many's noise= applied:
/// True, None or 'scenario' the scenario's own "noise" (`s` itself; a
/// UserWarning when all of it is zero: every shot the nominal strike),
/// False or what noise_argument() reads ('none', 'tournament', a dict of
/// sigmas) in its place. Needs the GIL.
std::shared_ptr<const cueball::Scenario> with_noise_argument(std::shared_ptr<const cueball::Scenario> s,
                                                             const py::object& noise);

// ------------------------------------------------------------------ scenarios (scenario_input.cpp)

// A scenario as Python gave it: a Scenario object (shared, never changed:
// the class is read-only), or the JSON text of one, or neither for the
// built-in 9-ball break.
struct ScenarioInput {
  std::shared_ptr<const cueball::Scenario> scenario;
  std::optional<std::string> text;
};

// Accepts None, a cueball.Scenario, a dict (serialised with Python's json
// module), a str that is JSON text (its first non-blank character is '{') or
// else a file's path, or a path (os.PathLike). Needs the GIL.
ScenarioInput scenario_input(const py::object& scenario);

// The scenario of scenario_input() (the built-in break for neither); runs
// without the GIL.
std::shared_ptr<const cueball::Scenario> load_scenario(const ScenarioInput& input);

// A dict as JSON text for the library's readers: NumPy scalars and arrays
// become numbers and lists, NaN and infinity raise InvalidArgument naming
// the path under `root` ("scenario.cue.speed"). Needs the GIL.
std::string json_text(const py::handle& dict, const std::string& root);

// noise=: None (none given: the caller's default), 'none', 'tournament'
// (tournament_noise()) or a dict of sigmas in the scenario JSON's units
// ("noise" object; tip offsets in radii of `radius`) (convert.cpp).
std::optional<cueball::CueStrikeNoise> noise_argument(const py::object& noise, double radius);

// json.loads(text): the Python objects of one of the library's JSON writers
// (io/), so that a dict is what json.loads makes of the CLI's output. Needs
// the GIL.
py::object json_loads(const std::string& text);

}  // namespace cueball_python
