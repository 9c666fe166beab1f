// The library's JSON writers as nlohmann values, for writers that nest them
// (the result JSON nests the scenario and the facts). Private: nlohmann stays out of the
// public headers.
#pragma once

#include <nlohmann/json.hpp>

#include "cueball/io/report.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/shot_facts.hpp"
#include "cueball/table/table.hpp"

namespace cueball::io {

/// shot_facts_to_json() as a value.
nlohmann::json shot_facts_json(const Table& table, const ShotFacts& facts);

/// [x, y] and [x, y, z].
nlohmann::json vec(Vec2 v);
nlohmann::json vec(Vec3 v);
/// A ball state: position, velocity, angular_velocity.
nlohmann::json state_json(const BallState& s);
/// The ball and cloth as a scenario's (and a result's) "parameters".
nlohmann::json parameters_json(const Parameters& p);
/// The scenario's "cue", in the units it was given in.
nlohmann::json cue_json(const Scenario& s);
/// scenario_to_json() as a value.
nlohmann::json scenario_json(const Scenario& s);
/// report_to_json() as a value, for the writers that add to a report
/// (batch_json.cpp, cushion_json.cpp).
nlohmann::ordered_json report_json(const Report& report);

}  // namespace cueball::io
