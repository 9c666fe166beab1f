// Tracked shots, calibration reports and fitted constants as JSON
// (README "Tracked shots" and "Calibrating from tracked shots").
//
// Tracked shots (every error names the JSON path, the value and what is allowed):
//   { "table": "carom_10ft" | "pool_9ft" | "snooker_12ft" | { table JSON, io/table_json.hpp },
//     "shots": [ { "cue_ball": "yellow",                       (required: the struck ball's name)
//                  "shot_id": n | "text", "id": .., "index": n, (optional; the report's id is
//                                                                shot_id, else id, else index, else
//                                                                the position in "shots")
//                  "balls": { "yellow": { "t": [s, ...], "x": [m, ...], "y": [m, ...] },
//                             "red": {...}, ... } }, ... ],
//     any other top-level key whose value is a string: a description, ignored
//     ("what", "units", "sampling", "provenance", ...) }
#pragma once

#include <string>
#include <string_view>

#include "cueball/calibration/calibrate.hpp"
#include "cueball/calibration/tracked_shot.hpp"

namespace cueball {

/// Longest tracked-shots text, bytes (256 MiB).
inline constexpr std::size_t kMaxTrackedShotsBytes = std::size_t{256} << 20;

/// Parses and validates (validate_tracked_shot) a tracked-shots document;
/// throws InvalidArgument whose field() is the JSON path
/// ("shots[3].balls.red.t[5]").
TrackedShots tracked_shots_from_json(std::string_view json_text);

/// The fitted constants as a scenario fragment that scenario_from_json
/// accepts as it is and that a scenario may copy in:
///   { "table": name or table object, "parameters": { mass, radius, mu_s, mu_r, mu_sp, g },
///     "cushion": { "model", "restitution", "friction" (+ "frequency_ratio") },
///     "ball_collision": { "model", "restitution", "friction" (+ coulomb_impulse's
///       "friction_excess", "friction_decay") } }: the ball-ball model the strikes
/// were fitted under, not fitted itself, as a scenario writes it.
std::string constants_to_json(const FitModel& model, const std::string& table_name, int indent = 1);

/// The constants of a scenario (or of such a fragment) over the tracked
/// shots' table: its "parameters" and "cushion" (and "ball_collision")
/// settings; throws InvalidArgument naming the path ("scenario.parameters.mu_r").
FitModel fit_model_from_json(std::string_view json_text, const TrackedShots& shots);

/// The report:
///   { "table": .., "constants": constants_to_json(model), "start_constants": ..,
///     "summary": { "training": S, "held_out": S }, with S = { "shots", "cue_rmse_median",
///       "cue_rmse_p90", "cue_rmse_mean", "all_rmse_median", "all_rmse_p90", "all_rmse_mean",
///       "object_rmse_median", "object_rmse_p90", "contact_mismatches", "seconds_per_shot" } (m, s),
///     "constant_evaluations": n, "constant_iterations": n, "constant_restarts": n,
///     "uncertainty": { "method": "none" | "bootstrap over the training shots", "replicates": n,
///       "constants": { "mu_s": { "value", "std_dev", "p05", "p95" }, "mu_r": .., "mu_sp": ..,
///                      "cushion_restitution": .., "cushion_friction": .. } (empty without) },
///     "seconds": s,
///     "shots": [ { "id", "held_out", "strike": { "speed", "aim_deg", "elevation_deg", "side",
///                  "height", "strike_time" }, "cue_rmse", "all_rmse",
///                  "balls": { name: { "rmse", "moved", "moved_simulated" } },
///                  "first_contact": the simulated cue ball's first object ball (null: none),
///                  "contact_mismatch", "simulations", "seconds", "notes": [..] } ] }
/// An RMSE without samples is null.
std::string calibration_report_to_json(const CalibrationReport& report, int indent = 1);

}  // namespace cueball
