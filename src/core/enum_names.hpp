// Names of a closed set of values (shot kinds, cushion and ball-ball models):
// the value of a name and the list of names, through the set's to_string().
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace cueball {

/// The value of `all` whose to_string() is `name`, if there is one.
template <class Value, std::size_t N>
std::optional<Value> value_named(const std::array<Value, N>& all, std::string_view name) {
  for (const Value v : all)
    if (name == to_string(v)) return v;
  return std::nullopt;
}

/// Every name of `all`, comma-separated, each between `quote`s.
template <class Value, std::size_t N>
std::string names_of(const std::array<Value, N>& all, std::string_view quote) {
  std::string names;
  for (const Value v : all) names += (names.empty() ? "" : ", ") + std::string(quote) + to_string(v) + std::string(quote);
  return names;
}

}  // namespace cueball
