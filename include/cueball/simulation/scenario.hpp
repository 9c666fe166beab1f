// A shot as a user describes it: table, balls, cue strike, parameters. Read
// from and written to JSON; run through the simulator.
//
// Scenario JSON (every key optional; unknown keys are rejected; every error
// names the JSON path, the value and the allowed range):
//   {
//     "table": "pool_9ft" | "snooker_12ft" | "carom_10ft" | { table JSON, see table.hpp },
//     "parameters": { "preset": "pool" | "snooker", "mass": kg, "radius": m,
//                     "mu_s": .., "mu_r": .., "mu_sp": .., "g": m/s^2 },
//         (default: the cloth preset that goes with the table, and the table's ball)
//     "cushion": { "restitution": e_e, "friction": mu_w },      (Mathavan model; default 0.98, 0.14)
//     "ball_collision": { "restitution": e, "friction": mu, "friction_excess": .., "friction_decay": s/m },
//         (a key of another model or solver than the one chosen, e.g. "friction_decay" under
//          "mathavan_2014" or "paper_steps" with the exact solver, is refused naming the owner)
//     "rack": { "type": "nine_ball" | "eight_ball" | "snooker", "gap_sigma": m, "seed": n },
//     "balls": [ { "id": n, "name": "..", "position": [x, y],
//                  "velocity": [vx, vy], "angular_velocity": [wx, wy, wz] } ],
//         ("rack" and "balls" together: the rack, then each listed ball replaces
//          the rack's ball with the same id or is added)
//     "cue": { "ball": id (0), "speed": m/s (cue speed), "aim_deg": deg | "target": id,
//              "elevation_deg": deg, "side": a/R, "height": b/R,
//              "mass": kg, "tip_restitution": e, "end_mass": kg (squirt; 0: none) },
//     "noise": { "speed": m/s, "aim_deg": deg, "elevation_deg": deg, "side": a/R, "height": b/R },
//     "max_events": n
//   }
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

/// Parses and validates a scenario; throws InvalidArgument with the JSON path.
Scenario scenario_from_json(std::string_view json_text);

/// The scenario written out in full, every value explicit: the table's whole
/// geometry (names included), "parameters" (mass, radius, mu_s, mu_r, mu_sp,
/// g), "cushion", "ball_collision", "max_events", every ball as placed
/// ("balls": id, name, position, velocity, angular_velocity; no "rack"), the
/// "cue" (target or aim_deg, elevation_deg, side, height, speed, mass,
/// tip_restitution, end_mass) and the "noise". scenario_from_json() of it gives the
/// same simulation bit for bit: numbers are written as the shortest decimal
/// that reads back to the same double, and angles and tip offsets as a value
/// whose conversion to radians and metres gives the scenario's own (the value
/// the JSON gave when there was one). Only a strike set in C++ whose radians
/// or metres no value in degrees or ball radii converts to exactly (about 9
/// per cent of angles and 4 per cent of offsets) comes back rounded to the
/// nearest convertible one, within an ulp.
/// `indent` as in result_to_json.
std::string scenario_to_json(const Scenario& s, int indent = 1);

/// A scenario JSON, or a result JSON of result_to_json() (an object with
/// "events" and "scenario"), whose "scenario" is read: the way to replay a
/// result. Errors name the path inside the scenario ("scenario.cue.speed").
Scenario scenario_from_document(std::string_view json_text);

/// The built-in default: a 9-ball break on a 9-ft pool table, cue ball on
/// the head string, struck at 7 m/s at the centre of the 1 ball.
Scenario default_scenario();

/// The strike's aim resolved (target ball) and checked.
CueStrike resolved_strike(const Scenario& s, const CueStrike& strike);

/// The balls at t = 0 after the cue strike `strike` (the scenario's own when
/// not given). Throws InvalidArgument on a miscue or a bad strike.
std::vector<SimulationBall> balls_after_strike(const Scenario& s, const std::optional<CueStrike>& strike = {});

/// Runs the scenario's shot. The result's first event is the cue strike.
SimulationResult run_scenario(const Scenario& s);

/// True when the scenario's cue strike (its aim resolved) is obstructed: the
/// cue, aligned for it, passes through another ball or below the rail
/// (cue_obstructed(), shot_planner.hpp). False without a cue. A flag only:
/// run_scenario() plays an obstructed strike all the same.
bool cue_strike_obstructed(const Scenario& s);

/// A scenario's "noise" object ({"speed": m/s, "aim_deg", "elevation_deg":
/// deg, "side", "height": ball radii}, every key optional, 0 by default) read
/// by the scenario's own reader, with `radius` the ball radius (m) of the
/// offsets. Throws InvalidArgument naming `path`.key, the value and the
/// allowed range ("noise.aim_deg = 50 is outside [0, 30] ...").
CueStrikeNoise noise_from_json(std::string_view json_text, double radius, const std::string& path = "noise");

/// The documented result JSON (README "Result format"): table, parameters,
/// events (ball_cushion and ball_jaw events with the part's index and
/// "cushion_name" / "jaw_name"), balls (final states, pocketing, trajectory
/// segments), "cue_strike" ({"given": the scenario's cue, "resolved": ball,
/// target, speed, aim_deg, elevation_deg, side, height and the same in
/// radians and metres, cue mass and tip restitution}, or null without a cue),
/// "cue_obstructed" (cue_strike_obstructed(), false without a cue),
/// "scenario" (scenario_to_json: replaying it reproduces the result bit for
/// bit) and, when sample_rate > 0, the states sampled at that rate (Hz). `indent`: spaces per nesting level, or
/// -1 for everything on one line. More than kMaxSamples sampled states throw
/// InvalidArgument naming "sample_rate" (before anything is allocated).
std::string result_to_json(const Scenario& s, const SimulationResult& r, double sample_rate = 0.0, int indent = 1);

}  // namespace cueball
