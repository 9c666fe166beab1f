// Noisy batches (simulation/batch.hpp) as reports and JSON: what `cueball
// batch --json` and `cueball many --json` print, and (parsed) the dict
// Python's simulate_batch returns.
//
// batch: {"shots", "simulated", "miscues", "failures", "speed_reflected",
//   "elevation_reflected" (counts), "seconds", "shots_per_second",
//   "events_per_shot", "pocketed_probability": {"<ball id>": p},
//   "balls": [{"id", "name", "pocketed_probability", "mean_position": [x, y],
//   "position_std": [sx, sy]}] (m, in the scenario's ball order)}
// many: {"shots", "simulated", "miscues", "failures" (counts), "seconds",
//   "shots_per_second", "events_per_shot", "pocketed": {"<ball id>": shots},
//   "outcomes": the CSV file's path (when written)}
#pragma once

#include <string>

#include "cueball/io/report.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball {

/// The batch's counts and throughput (the keys above up to
/// "events_per_shot", with units and meanings for the table).
Report batch_report(const BatchResult& r, const std::string& title = {});

/// The batch JSON above: batch_report() with each ball's outcome; `s` the
/// scenario that was batched (the balls' names). `indent` as in report_to_json.
std::string batch_result_to_json(const Scenario& s, const BatchResult& r, int indent = 2);

/// The shots' counts and throughput of simulate_many (the keys above up to
/// "events_per_shot").
Report many_report(const ManyResult& r, const std::string& title = {});

/// The many JSON above; `outcomes` the path the per-shot CSV was written to
/// ("" : none, no key).
std::string many_result_to_json(const ManyResult& r, const std::string& outcomes = {}, int indent = 2);

}  // namespace cueball
