// The viewer's game document (src/io/game_viewer_json.cpp): a 9-ball break,
// a push-out and the pass that answers it, then a few more shots; the
// document parses, has one entry per step with its caption, scores, foul or
// decision, and every shot's result replays to the same shot.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cueball/agents/agent.hpp"
#include "cueball/agents/match.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/games/break_shot.hpp"
#include "cueball/games/game.hpp"
#include "cueball/io/game_viewer_json.hpp"
#include "cueball/io/scenario_json.hpp"

namespace cueball {
namespace {

struct Played {
  GameState start;
  std::vector<GameStep> steps;
};

// The break, then (when the rules offer it) a push-out and a pass, then
// ghost-ball shots until `shots` steps or the end of the game.
AgentOptions agent(AgentKind kind) {
  AgentOptions o;
  o.kind = kind;
  return o;
}

Played play_some(std::uint64_t seed, std::size_t shots) {
  Played out{new_game(default_config(GameKind::nine_ball), seed), {}};
  GameState s = out.start;
  const auto step = [&](const Action& a) {
    out.steps.push_back(play(s, a, seed + out.steps.size()));
    s = out.steps.back().next;
  };
  step(recommended_break(s));
  if (!s.over && legal_actions(s).push_out) {
    Action push = choose_action(agent(AgentKind::random), s, seed);
    push.push_out = true;
    push.strike.speed = 0.8;  // a soft push-out: the cue ball stays on the table
    push.called_ball.reset();
    push.called_pocket.reset();
    step(push);
    if (!s.over && s.phase == GamePhase::decision) {
      Action pass;
      pass.decision = Decision::pass;
      step(pass);
    }
  }
  while (!s.over && out.steps.size() < shots) step(choose_action(agent(AgentKind::ghost_ball), s, seed));
  return out;
}

TEST(GameViewerJson, OneEntryPerStepWithCaptionsScoresAndResults) {
  const Played g = play_some(3, 6);
  ASSERT_GE(g.steps.size(), 3u);
  const auto doc = nlohmann::json::parse(game_viewer_json(g.start, g.steps, {"planner", "ghost_ball"}));
  const auto& game = doc.at("game");
  EXPECT_EQ(game.at("kind"), "nine_ball");
  EXPECT_EQ(game.at("players"), nlohmann::json::array({"planner", "ghost_ball"}));
  const auto& shots = game.at("shots");
  ASSERT_EQ(shots.size(), g.steps.size());
  bool saw_decision = false;
  GameState before = g.start;
  for (std::size_t i = 0; i < g.steps.size(); ++i) {
    const GameStep& step = g.steps[i];
    const auto& e = shots[i];
    SCOPED_TRACE("step " + std::to_string(i) + ": " + e.at("caption").get<std::string>());
    EXPECT_EQ(e.at("player"), before.to_shoot);
    EXPECT_EQ(e.at("scores"), nlohmann::json::array({step.next.scores[0], step.next.scores[1]}));
    EXPECT_EQ(e.at("caption"), game_step_caption(before, step));
    EXPECT_EQ(e.at("caption").get<std::string>().rfind("shot " + std::to_string(i + 1) + ", player ", 0), 0u);
    ASSERT_TRUE(e.contains("result"));
    if (step.action.decision) {
      saw_decision = true;
      EXPECT_EQ(e.at("decision"), to_string(*step.action.decision));
      // the table as it stands: every ball of the state at rest, no time
      EXPECT_EQ(e.at("result").at("end_time"), 0.0);
      EXPECT_EQ(e.at("result").at("balls").size(), before.table.balls.size());
      for (const auto& b : e.at("result").at("balls")) EXPECT_FALSE(b.at("segments").empty()) << "the page needs a segment per ball";
      EXPECT_TRUE(e.at("result").at("cue_strike").is_null());
    } else {
      EXPECT_EQ(e.at("foul"), step.ruling.foul ? nlohmann::json(to_string(*step.ruling.foul)) : nlohmann::json(nullptr));
      // the result replays: its scenario gives the same shot
      const Scenario replay = scenario_from_json(e.at("result").at("scenario").dump());
      const SimulationResult r = run_scenario(replay);
      EXPECT_EQ(r.end_time, step.result.end_time);
      EXPECT_EQ(r.events.size(), step.result.events.size());
      EXPECT_EQ(e.at("result").at("end_time"), step.result.end_time);
      EXPECT_EQ(e.at("result").at("balls").size(), step.result.balls.size());
    }
    before = step.next;
  }
  EXPECT_TRUE(saw_decision) << "the seed gives no push-out and pass: pick another";
  EXPECT_EQ(game.at("winner"), before.winner ? nlohmann::json(*before.winner) : nlohmann::json(nullptr));
  EXPECT_EQ(game.at("end_reason"), before.end_reason);
}

TEST(GameViewerJson, CaptionsNamePottedBallsAndFouls) {
  GameState s = new_game(default_config(GameKind::nine_ball));
  GameStep step;
  step.shot = s.table;
  step.ruling.pocketed = {0, 9};
  step.ruling.foul = Foul::scratch;
  step.ruling.reason = "cue ball pocketed (WPA 6.1)";
  EXPECT_EQ(game_step_caption(s, step), "shot 1, player 0: cue, 9 potted; foul: scratch (cue ball pocketed (WPA 6.1))");
  GameStep decision;
  decision.action.decision = Decision::pass;
  decision.ruling.reason = "WPA 2.4";
  s.to_shoot = 1;
  s.shots = 3;
  EXPECT_EQ(game_step_caption(s, decision), "shot 4, player 1: pass (WPA 2.4)");
  // three-cushion: no pockets, a point
  const GameState carom = new_game(default_config(GameKind::three_cushion));
  GameStep point;
  point.shot = carom.table;
  point.ruling.points = {1, 0};
  point.ruling.reason = "UMB Art. 83";
  EXPECT_EQ(game_step_caption(carom, point), "shot 1, player 0: played; +1 to player 0 (UMB Art. 83)");
}

TEST(GameViewerJson, ARecordReplaysToTheSameDocument) {
  // a whole game between agents (play_game), its record re-played
  GameConfig config = default_config(GameKind::nine_ball);
  config.max_shots = 8;
  const GameRecord record = play_game(config, {agent(AgentKind::ghost_ball), agent(AgentKind::random)}, 5);
  std::vector<GameStep> steps;
  GameState s = record.start;
  for (const RecordedStep& r : record.steps) {
    steps.push_back(play(s, r.action, r.seed));
    ASSERT_EQ(steps.back().next, r.state);
    s = steps.back().next;
  }
  const std::string doc = game_viewer_json(record);
  EXPECT_EQ(doc, game_viewer_json(record.start, steps, record.players));
  const auto game = nlohmann::json::parse(doc).at("game");
  EXPECT_EQ(game.at("shots").size(), record.steps.size());
  EXPECT_EQ(game.at("players"), nlohmann::json::array({"ghost_ball", "random"}));
  const GameState& end = record.steps.back().state;
  EXPECT_EQ(game.at("end_reason"), end.end_reason);
}

TEST(GameViewerJson, AnAgentsReasoningIsInItsEntry) {
  // the planner agent's reasoning recorded by play_game reaches the document;
  // the ghost-ball agent weighs nothing and its entries have none
  GameConfig config = default_config(GameKind::nine_ball);
  config.max_shots = 4;
  AgentOptions planner = agent(AgentKind::planner);
  planner.simulations = kMinPlanSimulations;
  const GameRecord record = play_game(config, {planner, agent(AgentKind::ghost_ball)}, 3);
  const auto shots = nlohmann::json::parse(game_viewer_json(record)).at("game").at("shots");
  ASSERT_EQ(shots.size(), record.steps.size());
  int with = 0;
  for (std::size_t k = 0; k < record.steps.size(); ++k) {
    const Reasoning& r = record.steps[k].reasoning;
    const GameState& before = k == 0 ? record.start : record.steps[k - 1].state;
    EXPECT_EQ(shots[k].contains("reasoning"), before.to_shoot == 0) << k;
    if (!shots[k].contains("reasoning")) continue;
    ++with;
    EXPECT_EQ(shots[k].at("reasoning").at("summary"), r.summary);
    ASSERT_EQ(shots[k].at("reasoning").at("considered").size(), r.considered.size());
    for (std::size_t j = 0; j < r.considered.size(); ++j) {
      EXPECT_EQ(shots[k].at("reasoning").at("considered")[j].at("what"), r.considered[j].what);
      if (r.considered[j].estimate >= 0.0) {
        EXPECT_DOUBLE_EQ(shots[k].at("reasoning").at("considered")[j].at("estimate").get<double>(), r.considered[j].estimate);
      }
    }
  }
  EXPECT_GT(with, 0);
  // a reasoning list of the wrong length is refused
  std::vector<GameStep> steps;
  GameState s = record.start;
  for (const RecordedStep& r : record.steps) {
    steps.push_back(play(s, r.action, r.seed));
    s = steps.back().next;
  }
  EXPECT_THROW((void)game_viewer_json(record.start, steps, record.players, -1, std::vector<Reasoning>(1)),
               InvalidArgument);
}

TEST(GameViewerJson, AnEmptyGameHasNoShots) {
  const GameState s = new_game(default_config(GameKind::eight_ball));
  const auto doc = nlohmann::json::parse(game_viewer_json(s, {}, {"a", "b"}));
  EXPECT_EQ(doc.at("game").at("kind"), "eight_ball");
  EXPECT_TRUE(doc.at("game").at("shots").empty());
  EXPECT_TRUE(doc.at("game").at("winner").is_null());
}

}  // namespace
}  // namespace cueball
