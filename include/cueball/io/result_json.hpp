// The simulation result as JSON (README "Result format"): the table, the
// parameters, the events, what the shot did ("facts", io/shot_facts_json.hpp),
// the balls' trajectories and, on request, sampled states.
#pragma once

#include <string>

#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/simulator.hpp"

namespace cueball {

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
