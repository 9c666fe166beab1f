// A planned shot as JSON (io/plan_json.hpp).
#include "cueball/io/plan_json.hpp"

#include <nlohmann/json.hpp>

#include "cueball/io/scenario_json.hpp"

namespace cueball {

namespace {

using Json = nlohmann::ordered_json;

Json id_or_null(int id) { return id >= 0 ? Json(id) : Json(nullptr); }
Json text_or_null(const std::string& s) { return s.empty() ? Json(nullptr) : Json(s); }

Json leave_json(const Leave& l, int next) {
  Json j;
  j["next"] = id_or_null(next);
  j["cue_ball"] = {l.cue_ball.x, l.cue_ball.y};
  j["next_feasible"] = l.next_feasible;
  j["next_success_probability"] = l.next_success_probability;
  j["next_kind"] = text_or_null(l.next_kind);
  j["next_pocket"] = text_or_null(l.next_pocket);
  j["next_ball"] = id_or_null(l.next_ball);
  j["screened_probability"] = l.screened_probability;
  j["noisy_leaves"] = l.noisy_leaves;
  j["noisy_next_window"] = l.noisy_next_window;
  j["candidate_noisy_leaves"] = l.candidate_noisy_leaves;
  j["candidate_next_window"] = l.candidate_next_window;
  j["score"] = l.score;
  return j;
}

Json shot_json(const Scenario& s, int cue_ball, const PlannedShot& shot, const CueStrikeNoise& noise) {
  const Json scenario = Json::parse(scenario_to_json(scenario_with_shot(s, cue_ball, shot, noise)));
  Json j;
  j["cue"] = scenario["cue"];
  j["target"] = shot.target;
  j["kind"] = to_string(shot.kind);
  j["pocket"] = shot.pocket_name;
  if (!shot.cushion.empty()) j["cushion"] = shot.cushion;
  j["cushions"] = shot.cushions;
  j["intermediate_ball"] = id_or_null(shot.intermediate_ball);
  j["success_probability"] = shot.success_probability;
  j["success_standard_error"] = shot.success_standard_error;
  j["noisy_shots"] = shot.noisy_shots;
  j["window_probability"] = shot.window_probability;
  j["aim_window_deg"] = {shot.aim_window_deg[0], shot.aim_window_deg[1]};
  j["speed_window"] = {shot.speed_window[0], shot.speed_window[1]};
  j["robot"] = {{"tip_height", shot.robot.tip_height}, {"cue_speed", shot.robot.cue_speed}};
  j["ball_speed"] = shot.ball_speed;
  j["geometric_aim_deg"] = shot.geometric_aim_deg;
  j["cut_deg"] = shot.cut_deg;
  if (shot.kind == ShotKind::combination) j["combination_cut_deg"] = shot.combination_cut_deg;
  Json predicted = Json::array();
  for (const PredictedBall& b : shot.predicted) {
    Json p{{"id", b.id}, {"position", {b.position.x, b.position.y}}, {"pocketed", b.pocketed}};
    p["pocket"] = b.pocketed ? Json(s.table.pockets[static_cast<std::size_t>(b.pocket)].name) : Json(nullptr);
    predicted.push_back(p);
  }
  j["predicted"] = predicted;
  j["simulations"] = shot.simulations;
  return j;
}

}  // namespace

std::string plan_to_json(const Scenario& table_state, const ShotPlanResult& plan, const CueStrikeNoise& noise,
                         const PositionPlanResult* position, const BallInHandResult* in_hand, int indent) {
  Json j = shot_json(table_state, plan.cue_ball, plan.shot, noise);
  if (in_hand)
    j["in_hand"] = {{"cue_ball", {in_hand->cue_ball.x, in_hand->cue_ball.y}},
                    {"spots", in_hand->spots},
                    {"spots_played", in_hand->spots_played}};
  if (position) j["position"] = leave_json(position->leave, position->next_target);
  j["simulations"] = plan.simulations;
  j["seconds"] = plan.seconds;
  Json alternatives = Json::array();
  for (std::size_t k = 0; k < plan.alternatives.size(); ++k) {
    alternatives.push_back(shot_json(table_state, plan.cue_ball, plan.alternatives[k], noise));
    if (position) alternatives.back()["position"] = leave_json(position->alternative_leaves[k], position->next_target);
  }
  j["alternatives"] = alternatives;
  j["rejected"] = plan.rejected;
  return j.dump(indent);
}

}  // namespace cueball
