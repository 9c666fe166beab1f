// Scenarios of balls at rest at given places on the 9-ft pool table, for the
// planner's tests (through the scenario reader, so that they are what a user's
// file gives).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "cueball/io/scenario_json.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball::test {

struct Placed {
  int id;
  Vec2 p;
};

/// The shortest form of v that reads back to the same double.
inline std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// The balls at rest at their places on "pool_9ft", no cue strike.
inline Scenario layout(const std::vector<Placed>& balls) {
  std::string json = R"({"table": "pool_9ft", "balls": [)";
  for (std::size_t i = 0; i < balls.size(); ++i)
    json += (i ? ", " : "") + std::string(R"({"id": )") + std::to_string(balls[i].id) + R"(, "position": [)" +
            exact(balls[i].p.x) + ", " + exact(balls[i].p.y) + "]}";
  return scenario_from_json(json + "]}");
}

}  // namespace cueball::test
