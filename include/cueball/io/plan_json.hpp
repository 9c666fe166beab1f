// A planned shot as JSON: what `cueball plan-shot --json` prints.
//
//   {"cue": {the scenario's "cue" that plays the shot}, "target": id, "kind",
//    "pocket": name, "cushion" (a one-cushion bank's), "cushions": [names],
//    "intermediate_ball": id | null, "success_probability",
//    "success_standard_error", "noisy_shots", "window_probability",
//    "aim_window_deg": [lo, hi], "speed_window": [lo, hi] (m/s),
//    "robot": {"tip_height" (m), "cue_speed" (m/s)}, "ball_speed",
//    "geometric_aim_deg", "cut_deg", "combination_cut_deg" (combinations),
//    "predicted": [{"id", "position", "pocketed", "pocket": name | null}],
//    "simulations",
//    "in_hand": {"cue_ball": [x, y], "spots", "spots_played"} (ball in hand),
//    "position": {leave} (position play: "next", "cue_ball", "next_feasible",
//      "next_success_probability", "next_kind", "next_pocket", "next_ball",
//      "screened_probability", "score"),
//    "seconds", "alternatives": [shots as above], "rejected": [reasons]}
// (the top level's "simulations" is the whole plan's engine runs).
#pragma once

#include <string>

#include "cueball/planning/ball_in_hand.hpp"
#include "cueball/planning/position_play.hpp"
#include "cueball/planning/shot_planner.hpp"

namespace cueball {

/// The plan made on `table_state` (with ball in hand, the table the cue ball
/// was placed on: BallInHandResult::table) under `noise`, as the JSON above;
/// `position` and `in_hand` when the plan played for position or placed the
/// cue ball. `indent` as in result_to_json.
std::string plan_to_json(const Scenario& table_state, const ShotPlanResult& plan, const CueStrikeNoise& noise,
                         const PositionPlanResult* position = nullptr, const BallInHandResult* in_hand = nullptr,
                         int indent = 2);

}  // namespace cueball
