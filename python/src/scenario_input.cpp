// include/cueball/simulation/scenario.hpp: a scenario given from Python (None, Scenario, dict, JSON text, path).
#include "bindings.hpp"

#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <vector>
#include "cueball/io/scenario_json.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball_python {

namespace {

// ------------------------------------------------------------------ whole shots

// A dict key as a scenario path shows it: plain names as they are, others quoted.
std::string path_key(const std::string& key) {
  bool plain = !key.empty() && key.size() <= cueball::kMaxEchoedChars;
  for (char c : key) plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  return plain ? key : cueball::quote_input(key);
}

// A scenario given as Python objects, made ready for Python's json module:
// NumPy scalars and arrays (anything with a dtype and tolist(), e.g.
// np.float32, np.int64, np.array([1.1, 0.7])) become the Python numbers and
// lists tolist() gives, tuples become lists, and the rest is kept. Raises
// InvalidArgument for a NaN or infinite float anywhere (JSON has no spelling
// for it; the message names the field as the library's own checks do), for
// nesting deeper than the JSON reader allows (the same limit, 64), for a
// container that contains itself, and for more values than a scenario's
// largest JSON text could hold. Never recursion without a bound: a recursive
// or 100,000-deep dict raises.
class ScenarioObjects {
 public:
  py::object normalise(const py::handle& value, const std::string& path, std::size_t depth) {
    if (++values_ > kMaxValues)
      throw cueball::InvalidArgument("scenario", "scenario holds more than " + std::to_string(kMaxValues) +
                                                     " values; a scenario's JSON text is at most " +
                                                     std::to_string(cueball::kMaxScenarioBytes) + " bytes");
    if (py::isinstance<py::str>(value)) {
      (void)utf8_argument(value, path);  // a lone surrogate: named here, not as malformed JSON
      return py::reinterpret_borrow<py::object>(value);
    }
    if (py::isinstance<py::float_>(value)) {
      const double v = value.cast<double>();
      if (!std::isfinite(v)) throw cueball::InvalidArgument(path, v, "any finite number");
      return py::reinterpret_borrow<py::object>(value);
    }
    const bool dict = py::isinstance<py::dict>(value);
    const bool list = py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value);
    if (!dict && !list) {
      if (!py::isinstance<py::str>(value) && !py::isinstance<py::int_>(value) && py::hasattr(value, "dtype") &&
          py::hasattr(value, "tolist")) {
        // A NumPy scalar or array: its Python value (a number, or nested lists).
        if (depth >= kMaxDepth)
          throw cueball::InvalidArgument(path, path + " nests deeper than " + std::to_string(kMaxDepth) + " levels");
        const py::object plain = value.attr("tolist")();
        if (py::hasattr(plain, "dtype"))  // tolist() gave no Python value (an object array's element)
          return plain;
        return normalise(plain, path, depth + 1);
      }
      return py::reinterpret_borrow<py::object>(value);
    }
    if (depth >= kMaxDepth)
      throw cueball::InvalidArgument(path, path + " nests deeper than " + std::to_string(kMaxDepth) + " levels");
    PyObject* id = value.ptr();
    for (PyObject* open : open_)
      if (open == id) throw cueball::InvalidArgument(path, path + " contains itself (a circular reference)");
    open_.push_back(id);
    py::object out;
    if (dict) {
      py::dict d;
      for (const auto& item : py::reinterpret_borrow<py::dict>(value)) {
        d[item.first] = normalise(item.second, path + "." + path_key(utf8_argument(py::str(item.first), path + " (a key)")), depth + 1);
      }
      out = std::move(d);
    } else {
      py::list l;
      std::size_t i = 0;
      for (const py::handle& item : value) l.append(normalise(item, path + "[" + std::to_string(i++) + "]", depth + 1));
      out = std::move(l);
    }
    open_.pop_back();
    return out;
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

}  // namespace

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

std::string json_text(const py::handle& dict, const std::string& root) {
  const py::object plain = ScenarioObjects().normalise(dict, root, 0);
  return py::module_::import("json").attr("dumps")(plain).cast<std::string>();
}

ScenarioInput scenario_input(const py::object& scenario) {
  if (scenario.is_none()) return {};
  if (py::isinstance<cueball::Scenario>(scenario)) return {scenario.cast<std::shared_ptr<cueball::Scenario>>(), {}};
  if (py::isinstance<py::str>(scenario)) {
    std::string text = utf8_argument(scenario, "scenario");
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    return {nullptr, first != std::string::npos && text[first] == '{' ? text : read_scenario_file(scenario)};
  }
  if (py::isinstance(scenario, py::module_::import("os").attr("PathLike"))) return {nullptr, read_scenario_file(scenario)};
  if (py::isinstance<py::dict>(scenario)) return {nullptr, json_text(scenario, "scenario")};
  throw ArgumentTypeError("scenario", wrong_type_message(scenario, "scenario",
                                                        "None (the built-in 9-ball break), a cueball.Scenario, a dict, "
                                                        "JSON text, or a path (str or os.PathLike)"));
}

std::shared_ptr<const cueball::Scenario> load_scenario(const ScenarioInput& input) {
  if (input.scenario) return input.scenario;
  if (input.text) return std::make_shared<const cueball::Scenario>(cueball::scenario_from_json(*input.text));
  static const auto built_in = std::make_shared<const cueball::Scenario>(cueball::default_scenario());  // made once
  return built_in;
}

}  // namespace cueball_python
