// A game as the viewer's game document (io/game_viewer_json.hpp).
#include "cueball/io/game_viewer_json.hpp"

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "cueball/core/errors.hpp"
#include "cueball/io/result_json.hpp"
#include "io/json_output.hpp"
#include "cueball/simulation/simulator.hpp"

namespace cueball {

namespace {

using Json = nlohmann::json;

// The name of ball `id` in `balls` ("9", "red3", "yellow"), or its id.
std::string ball_label(const std::vector<SimulationBall>& balls, int id) {
  const SimulationBall* b = find_ball(balls, id);
  return b && !b->name.empty() ? b->name : std::to_string(id);
}

std::string join_balls(const std::vector<SimulationBall>& balls, const std::vector<int>& ids) {
  std::string out;
  for (const int id : ids) {
    if (!out.empty()) out += ", ";
    out += ball_label(balls, id);
  }
  return out;
}

// The table of `state` with its balls at rest, as a result (no cue, no
// events, end_time 0): what the viewer shows for a decision.
std::string table_as_it_stands(const GameState& state) {
  Scenario s = state.table;
  s.cue.reset();
  const SimulationResult r = simulate(s.table, s.balls, s.settings);
  return result_to_json(s, r, 0.0, -1);
}

}  // namespace

std::string game_step_caption(const GameState& before, const GameStep& step) {
  const int player = before.to_shoot;  // 0 or 1, as game.hpp and the CLI number them
  const Ruling& ruling = step.ruling;
  const std::vector<SimulationBall>& balls = step.shot.balls.empty() ? before.table.balls : step.shot.balls;
  std::string out = "shot " + std::to_string(before.shots + 1) + ", player " + std::to_string(player) + ": ";
  if (step.action.decision) {
    out += to_string(*step.action.decision);
  } else {
    const bool pockets = !step.shot.table.pockets.empty();  // three-cushion has none
    if (!ruling.pocketed.empty())
      out += join_balls(balls, ruling.pocketed) + " potted";
    else
      out += pockets ? "nothing potted" : "played";
    if (ruling.push_out) out += "; push-out";
    if (ruling.foul) out += std::string("; foul: ") + to_string(*ruling.foul);
    if (ruling.miss) out += " (a miss)";
  }
  for (std::size_t p = 0; p < ruling.points.size(); ++p) {
    const int pts = ruling.points[p];
    if (pts != 0) out += "; " + std::string(pts > 0 ? "+" : "") + std::to_string(pts) + " to player " + std::to_string(p);
  }
  if (!ruling.respotted.empty()) out += "; respotted " + join_balls(balls, ruling.respotted);
  if (!ruling.reason.empty()) out += " (" + ruling.reason + ")";
  return out;
}

std::string game_viewer_json(const GameState& start, const std::vector<GameStep>& steps,
                             const std::array<std::string, 2>& players, int indent,
                             const std::vector<Reasoning>& reasoning) {
  if (!reasoning.empty() && reasoning.size() != steps.size())
    throw InvalidArgument("reasoning", static_cast<double>(reasoning.size()), std::to_string(steps.size()),
                          "one reasoning per step, or none");
  Json shots = Json::array();
  const GameState* before = &start;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const GameStep& step = steps[k];
    Json entry;
    entry["player"] = before->to_shoot;
    entry["caption"] = game_step_caption(*before, step);
    entry["scores"] = Json::array({step.next.scores[0], step.next.scores[1]});
    if (step.action.decision) {
      entry["decision"] = to_string(*step.action.decision);
      entry["result"] = Json::parse(table_as_it_stands(*before));
    } else {
      entry["foul"] = step.ruling.foul ? Json(to_string(*step.ruling.foul)) : Json(nullptr);
      entry["result"] = Json::parse(result_to_json(step.shot, step.result, 0.0, -1));
    }
    if (!reasoning.empty() && io::has_reasoning(reasoning[k])) entry["reasoning"] = io::reasoning_json(reasoning[k]);
    shots.push_back(std::move(entry));
    before = &step.next;
  }
  const GameState& last = *before;
  Json game;
  game["kind"] = to_string(last.config.kind);
  game["players"] = Json::array({players[0], players[1]});
  game["winner"] = last.winner ? Json(*last.winner) : Json(nullptr);
  game["end_reason"] = last.end_reason;
  game["shots"] = std::move(shots);
  return Json{{"game", std::move(game)}}.dump(indent);
}

std::string game_viewer_json(const GameRecord& record, int indent) {
  std::vector<GameStep> steps;
  std::vector<Reasoning> reasoning;
  steps.reserve(record.steps.size());
  GameState state = record.start;
  for (const RecordedStep& recorded : record.steps) {
    steps.push_back(play(state, recorded.action, recorded.seed));
    reasoning.push_back(recorded.reasoning);
    state = steps.back().next;
  }
  return game_viewer_json(record.start, steps, record.players, indent, reasoning);
}

}  // namespace cueball
