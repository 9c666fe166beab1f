// The exception classes and the translation of the library's exceptions.
#include "bindings.hpp"

#include <exception>
#include <string>
#include "cueball/core/errors.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "cueball/simulation/simulator.hpp"

namespace cueball_python {

namespace {

// ------------------------------------------------------------------ errors

// The exception classes, created once and kept for the life of the process
// (never released: they outlive the module's finalisation).
PyObject* g_invalid_argument = nullptr;
PyObject* g_invalid_argument_type = nullptr;
PyObject* g_infeasible_shot = nullptr;
PyObject* g_simulation_error = nullptr;
PyObject* g_no_feasible_shot = nullptr;

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

}  // namespace

void bind_errors(py::module_& m) {
  g_invalid_argument = new_exception(
      m, "InvalidArgument",
      "A value outside its allowed range (NaN, infinity, negative mass, malformed scenario, ...).\n"
      "The message names the field, its value and what is allowed; `field` is the field's name\n"
      "in cueball's API (e.g. 'mu_s', 'speed', 'scenario.balls[1].position').",
      PyExc_ValueError);
  {
    // An argument of the wrong Python type: an InvalidArgument naming it, and a
    // TypeError as Python's own (pybind11's four-line TypeError before).
    const py::tuple bases = py::make_tuple(py::handle(g_invalid_argument), py::handle(PyExc_TypeError));
    g_invalid_argument_type = new_exception(
        m, "InvalidArgumentType",
        "An argument of the wrong Python type (a str where a float is expected, a 2-vector for a\n"
        "3-vector, ...): an InvalidArgument whose `field` names the argument, and a TypeError.",
        bases.ptr());
  }
  g_infeasible_shot = new_exception(
      m, "InfeasibleShot",
      "A well-formed request with no physical answer, e.g. a planned shot violating a validity\n"
      "condition of paper 001's inverse problem; `condition` is the failed condition as an\n"
      "inequality (e.g. 'x1 >= x0').",
      PyExc_ValueError);
  g_simulation_error = new_exception(
      m, "SimulationError", "A simulation could not finish (e.g. it reached the scenario's max_events).",
      PyExc_RuntimeError);
  g_no_feasible_shot = new_exception(
      m, "NoFeasibleShot",
      "plan_shot found no strike of the requested kinds that pots the ball; the message says why for\n"
      "each candidate (every pocket blocked, the cue obstructed, no aim pots on the exact simulation, ...).",
      PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ArgumentTypeError& e) {
      raise_with(g_invalid_argument_type, e.what(), "field", e.field);
    } catch (const cueball::InvalidArgument& e) {
      raise_with(g_invalid_argument, e.what(), "field", e.field());
    } catch (const cueball::InfeasibleShot& e) {
      raise_with(g_infeasible_shot, e.what(), "condition", e.condition());
    } catch (const cueball::SimulationError& e) {
      PyErr_SetString(g_simulation_error, e.what());
    } catch (const cueball::NoFeasibleShot& e) {
      PyErr_SetString(g_no_feasible_shot, e.what());
    }
  });
}

}  // namespace cueball_python
