// Internal: JSON parsing that reports a non-finite number by its field path.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "cueball/errors.hpp"

namespace cueball::detail {

/// Deeper nesting is rejected: valid documents nest at most 5 levels, and
/// recursion over a deeper value (nlohmann's dump) could overflow the stack.
inline constexpr std::size_t kMaxJsonDepth = 64;

/// Parses `text`; too deep nesting, malformed JSON and numbers too large for a double (1e999:
/// nlohmann's out_of_range 406, the only way JSON text can carry a non-finite
/// number) throw InvalidArgument, the latter naming the field by its path
/// below `path`, tracked by a parser callback.
inline nlohmann::json parse_json(std::string_view text, const std::string& path) {
  using json = nlohmann::json;
  struct Frame {
    bool array;
    std::size_t index;
    std::string key;
  };
  std::vector<Frame> stack;
  const auto after_value = [&stack] {
    if (!stack.empty() && stack.back().array) ++stack.back().index;
  };
  const json::parser_callback_t track = [&](int, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (stack.size() >= kMaxJsonDepth)
          throw InvalidArgument(path, path + " nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        stack.push_back({event == json::parse_event_t::array_start, 0, {}});
        break;
      case json::parse_event_t::key: stack.back().key = parsed.get<std::string>(); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack.pop_back();
        after_value();
        break;
      case json::parse_event_t::value: after_value(); break;
    }
    return true;
  };
  try {
    return json::parse(text.begin(), text.end(), track);
  } catch (const json::parse_error& e) {
    throw InvalidArgument(path, path + ": malformed JSON at byte " + std::to_string(e.byte) + ": " + e.what());
  } catch (const json::exception& e) {
    std::string field = path;
    for (const Frame& f : stack) {
      if (f.array) {
        field.append(1, '[').append(std::to_string(f.index)).append(1, ']');
      } else {
        field.append(1, '.').append(f.key);
      }
    }
    throw InvalidArgument(field, field + " is not a finite number (" + e.what() + ")");
  }
}

}  // namespace cueball::detail
