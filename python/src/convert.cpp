// Conversions and value semantics shared by every binding file.
#include "bindings.hpp"

#include <string>
#include <vector>

#include "cueball/core/errors.hpp"

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

py::arg_v params_arg() { return py::arg_v("params", cueball::pool_parameters(), "pool_parameters()"); }

}  // namespace cueball_python
