// The library's JSON writers as nlohmann values, for writers that nest them
// (the result JSON nests the scenario and the facts). Private: nlohmann stays out of the
// public headers.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "cueball/games/record.hpp"
#include "cueball/io/report.hpp"
#include "cueball/models/ball_collision/model.hpp"
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
/// A value u in the scenario's units (degrees, ball radii) whose u * unit is
/// x exactly when there is one near x / unit (`given` first): what the
/// scenario writer writes for angles and tip offsets (scenario_json.cpp).
double in_units(double x, double unit, std::optional<double> given);
/// The scenario's "ball_collision": the model's name and its constants (the
/// speed-dependent friction's two only for coulomb_impulse); J is
/// nlohmann::json or nlohmann::ordered_json. Also what a calibration's
/// constants carry (tracked_shots_json.cpp).
template <class J>
J ball_collision_json(const SimulationSettings& s) {
  J j = {{"model", to_string(s.ball_collision_model)},
         {"restitution", s.ball_collision.restitution},
         {"friction", s.ball_collision.friction}};
  if (s.ball_collision_model == BallCollisionModel::coulomb_impulse) {
    j["friction_excess"] = s.ball_collision.friction_excess;
    j["friction_decay"] = s.ball_collision.friction_decay;
  }
  return j;
}
/// scenario_to_json() as a value.
nlohmann::json scenario_json(const Scenario& s);
/// An agent's reasoning (games/record.hpp) as a record's and the viewer's
/// game document write it: {"summary", "considered": [{"what", "estimate",
/// "next_estimate"}]}, each estimate only when known (>= 0) (game_json.cpp).
nlohmann::json reasoning_json(const Reasoning& r);
/// False for an empty reasoning (a user's action): nothing written.
bool has_reasoning(const Reasoning& r);
/// report_to_json() as a value, for the writers that add to a report
/// (batch_json.cpp, cushion_json.cpp).
nlohmann::ordered_json report_json(const Report& report);

}  // namespace cueball::io
