// Conversions and value semantics shared by every binding file.
#include "bindings.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "cueball/core/errors.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/planning/shot_planner.hpp"

namespace cueball_python {

// "Type(name=value, ...)" with Python's repr of every value.
std::string repr_of(const char* type, const std::vector<const char*>& names, const py::tuple& values) {
  std::string out = std::string(type) + "(";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += ", ";
    out += std::string(names[i]) + "=" + py::repr(values[i]).cast<std::string>();
  }
  return out + ")";
}

void only_for(const char* field, bool given, const char* kind, bool applies, const char* owner, std::string_view chosen) {
  if (!given || applies) return;
  throw cueball::InvalidArgument(field, std::string(field) + " applies to the " + kind + " '" + owner + "' only, not to " +
                                            cueball::quote_input(chosen));
}

std::string wrong_type_message(const py::handle& value, const std::string& field, const char* allowed) {
  std::string shown = py::repr(value).cast<std::string>();  // ASCII-safe enough: repr escapes what it must
  const std::string type = py::type::of(value).attr("__name__").cast<std::string>();
  const bool vowel = !type.empty() && std::string("aeiou").find(type[0]) != std::string::npos;
  return field + " = " + cueball::one_line(shown.size() > 60 ? shown.substr(0, 60) + "\u2026" : shown) + " is " +
         (vowel ? "an " : "a ") + type + "; allowed: " + allowed;
}

std::string utf8_argument(const py::handle& text, const std::string& field) {
  if (!py::isinstance<py::str>(text)) throw ArgumentTypeError(field, wrong_type_message(text, field, "str"));
  Py_ssize_t size = 0;
  const char* data = PyUnicode_AsUTF8AndSize(text.ptr(), &size);
  if (data != nullptr) return std::string(data, static_cast<std::size_t>(size));
  PyErr_Clear();  // a UnicodeEncodeError: a lone surrogate
  const Py_ssize_t length = PyUnicode_GetLength(text.ptr());
  for (Py_ssize_t i = 0; i < length; ++i) {
    const Py_UCS4 c = PyUnicode_ReadChar(text.ptr(), i);
    if (c >= 0xD800 && c <= 0xDFFF) {
      char where[64];
      std::snprintf(where, sizeof where, "U+%04X at index %zd", static_cast<unsigned>(c), i);
      throw cueball::InvalidArgument(field, field + " has a lone UTF-16 surrogate (" + where +
                                                "), which no UTF-8 text can hold; allowed: valid Unicode text");
    }
  }
  throw cueball::InvalidArgument(field, field + " is not valid Unicode text");
}

py::arg_v params_arg() { return py::arg_v("params", cueball::pool_parameters(), "pool_parameters()"); }

// noise=: None (the config's), 'none', 'tournament' or a dict of sigmas in the scenario's units.
std::optional<cueball::CueStrikeNoise> noise_argument(const py::object& noise, double radius) {
  if (noise.is_none()) return std::nullopt;
  if (py::isinstance<py::dict>(noise)) return cueball::noise_from_json(json_text(noise, "noise"), radius, "noise");
  if (py::isinstance<py::str>(noise)) {
    const std::string name = utf8_argument(noise, "noise");
    if (name == "none") return cueball::CueStrikeNoise{};
    if (name == "tournament") return cueball::tournament_noise();
    throw cueball::InvalidArgument("noise", "noise = '" + name + "' is not known; allowed: 'none', 'tournament' or a dict of sigmas");
  }
  throw ArgumentTypeError("noise", wrong_type_message(noise, "noise", "None, 'none', 'tournament' or a dict of sigmas"));
}

}  // namespace cueball_python
