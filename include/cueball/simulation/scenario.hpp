// A shot as a user describes it: table, balls, cue strike, parameters; run
// through the simulator.
//
// Its JSON (the schema, reading, writing): io/scenario_json.hpp; the result
// JSON: io/result_json.hpp.
//
// Limits, checked before any work, each error naming what to change:
//   kMaxScenarioBytes  the scenario's JSON text (a file, a Python str or dict)
//   kMaxBalls          balls on the table (rack and "balls" together)
//   kMaxEvents         "max_events"
//   kMaxSamples        result_to_json's samples: sample times x balls
// Tip offsets "side" (to the right, seen from behind the cue) and "height"
// (above the centre) are in ball radii; the miscue limit is 0.5. Without
// "cue" the balls start with the velocities given.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/physics/cue_strike.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

/// Longest scenario JSON text, bytes (16 MiB).
inline constexpr std::size_t kMaxScenarioBytes = 16u << 20;
/// Most balls a scenario may place (a snooker frame has 22).
inline constexpr std::size_t kMaxBalls = 64;
/// Largest "max_events" (the default is 100000).
inline constexpr int kMaxEvents = 1'000'000;
/// Most sampled ball states in a result: (floor(end_time x rate) + 1) x balls.
inline constexpr double kMaxSamples = 200000;

/// A cue strike in the scenario's units: degrees and ball radii.
struct CueStrikeInUnits {
  double aim_deg = 0.0;
  double elevation_deg = 0.0;
  double side = 0.0;    ///< a / R
  double height = 0.0;  ///< b / R
};

struct ShotStrike {
  int ball = 0;              ///< id of the struck ball
  std::optional<int> target; ///< aim at this ball's centre (instead of strike.aim)
  CueStrike strike;          ///< offsets in metres here
  /// The values as the scenario's "cue" gave them (scenario_from_json sets
  /// it); scenario_to_json writes them back when they convert to `strike`
  /// exactly, else the double nearest strike / unit that does.
  std::optional<CueStrikeInUnits> given;
};

struct Scenario {
  Table table;
  SimulationSettings settings;        ///< parameters, cushion and ball-collision constants, event limit
  std::vector<SimulationBall> balls;  ///< as placed, before the strike
  std::optional<ShotStrike> cue;
  CueParameters cue_parameters;
  CueStrikeNoise noise;               ///< standard deviations for batch runs (metres, radians)
};



/// The strike's aim resolved (target ball) and checked.
CueStrike resolved_strike(const Scenario& s, const CueStrike& strike);

/// The balls at t = 0 after the cue strike `strike` (the scenario's own when
/// not given). Throws InvalidArgument on a miscue or a bad strike.
std::vector<SimulationBall> balls_after_strike(const Scenario& s, const std::optional<CueStrike>& strike = {});

/// Runs the scenario's shot. The result's first event is the cue strike.
SimulationResult run_scenario(const Scenario& s);

/// Where a ball ended a shot.
struct BallAfterShot {
  int id = 0;
  Vec2 position;      ///< where it came to rest (a pocketed ball: where it was captured), m
  bool pocketed = false;
  int pocket = -1;    ///< index into table.pockets when pocketed
};

/// Every ball's end of the shot `r`, in its order.
std::vector<BallAfterShot> balls_after_shot(const SimulationResult& r);

/// The table a shot leaves, to plan or play the next shot on: `before`'s
/// table and settings, its balls that `after` names and not pocketed, at
/// rest where `after` puts them, in `before`'s order, the "cue" cleared (a
/// ball `after` does not name is left off).
Scenario table_after(const Scenario& before, const std::vector<BallAfterShot>& after);
/// table_after(before, balls_after_shot(r)): the table the simulated shot left.
Scenario table_after(const Scenario& before, const SimulationResult& r);

/// True when the scenario's cue strike (its aim resolved) is obstructed: the
/// cue, aligned for it, passes through another ball or below the rail
/// (cue_obstructed(), table/cue_obstruction.hpp). False without a cue. A flag only:
/// run_scenario() plays an obstructed strike all the same.
bool cue_strike_obstructed(const Scenario& s);


}  // namespace cueball
