// Scenarios as JSON: the schema, the reader (every error names its JSON
// path, the value and the allowed range) and the writer (its output reads
// back to the same simulation bit for bit). The Scenario itself:
// simulation/scenario.hpp.
//
// Scenario JSON (every key optional; unknown keys are rejected; every error
// names the JSON path, the value and the allowed range):
//   {
//     "table": "pool_9ft" | "snooker_12ft" | "carom_10ft" | { table JSON, see io/table_json.hpp },
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
#pragma once

#include <string>
#include <string_view>

#include "cueball/simulation/scenario.hpp"

namespace cueball {

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

/// A scenario's "noise" object ({"speed": m/s, "aim_deg", "elevation_deg":
/// deg, "side", "height": ball radii}, every key optional, 0 by default) read
/// by the scenario's own reader, with `radius` the ball radius (m) of the
/// offsets. Throws InvalidArgument naming `path`.key, the value and the
/// allowed range ("noise.aim_deg = 50 is outside [0, 30] ...").
CueStrikeNoise noise_from_json(std::string_view json_text, double radius, const std::string& path = "noise");

}  // namespace cueball
