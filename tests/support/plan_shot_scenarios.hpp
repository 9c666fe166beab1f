// Scenario files the plan-shot CLI tests share.
#pragma once

namespace cueball::test {

// The 1 ball 0.5 m from the top-right pocket, cut about 20 degrees, and the 9
// out of the way. The cue reaches no rail from here, so the planned cue is level.
inline constexpr const char* kCutShot = R"({
  "table": "pool_9ft",
  "balls": [
    {"id": 0, "name": "cue", "position": [1.55, 0.70]},
    {"id": 1, "name": "1", "position": [2.214, 0.944]},
    {"id": 9, "name": "9", "position": [0.8, 1.0]}
  ]
})";

}  // namespace cueball::test
