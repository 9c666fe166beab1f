// Games as JSON (src/io/game_json.cpp): states, actions and rulings round
// trip bit for bit in every phase random 9-ball games reach; the reader
// refuses what breaks the rules, naming the JSON path, and accepts hand
// edits; records replay bit for bit and name their first difference.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <set>
#include <string>

#include "cueball/agents/match.hpp"
#include "cueball/core/random.hpp"
#include "cueball/io/game_json.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "expect_invalid.hpp"
#include "test_scale.hpp"

namespace cueball {
namespace {

using test::expect_invalid;
using Json = nlohmann::json;

void expect_round_trip(const GameState& s) {
  const std::string text = game_state_to_json(s);
  const GameState back = game_state_from_json(text);
  EXPECT_TRUE(back == s) << text.substr(0, 200);
  EXPECT_EQ(game_state_to_json(back), text);
}

TEST(GameJson, StatesActionsAndRulingsRoundTripInEveryPhase) {
  AgentOptions random;
  random.kind = AgentKind::random;
  std::set<std::string> phases, regions;
  int states = 0;
  // Twelve games, and more until a push-out has opened a decision.
  for (std::uint64_t game = 0; game < 12 || (phases.count("decision") == 0 && game < 200); ++game) {
    GameConfig config = default_config(GameKind::nine_ball);
    if (game % 2 == 1) config.noise = tournament_noise();  // angles and offsets in the scenario's units
    if (game % 3 == 2) config.rack.gap_sigma = 0.0005;
    GameState s = new_game(config, game);
    expect_round_trip(s);
    while (!s.over) {
      const Action a = choose_action(random, s, stream_seed(game, static_cast<std::uint64_t>(2 * s.shots)));
      const std::string action = action_to_json(a);
      EXPECT_EQ(action_to_json(action_from_json(action)), action);
      const GameStep step = play(s, a, stream_seed(game, static_cast<std::uint64_t>(2 * s.shots + 1)));
      const std::string ruling = ruling_to_json(step.ruling);
      EXPECT_EQ(ruling_to_json(ruling_from_json(ruling)), ruling);
      s = step.next;
      expect_round_trip(s);
      const Json j = Json::parse(game_state_to_json(s));
      phases.insert(j["game"]["phase"].get<std::string>());
      regions.insert(j["game"]["ball_in_hand"].dump());
      ++states;
    }
  }
  EXPECT_GT(states, 50);
  EXPECT_EQ(phases, (std::set<std::string>{"play", "decision", "over"}));
  EXPECT_TRUE(regions.count("null") && regions.count("\"anywhere\"")) << regions.size();
}

// Every discipline whose rules have landed (the others refuse new_game):
// each state of a few random games round trips, and their records replay.
TEST(GameJson, EveryDisciplineRoundTripsAndReplays) {
  AgentOptions random;
  random.kind = AgentKind::random;
  for (const GameKind kind : {GameKind::eight_ball, GameKind::ten_ball, GameKind::snooker, GameKind::three_cushion}) {
    GameConfig config = default_config(kind);
    config.noise = tournament_noise();
    config.max_shots = 150;  // three-cushion's races are long; truncated games round trip too
    try {
      (void)new_game(config, 0);
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("not available yet"), std::string::npos) << e.what();
      continue;
    }
    SCOPED_TRACE(to_string(kind));
    std::vector<GameRecord> games;
    // Three games a discipline; one under the sanitizers (test_scale.hpp).
    const auto games_played = static_cast<std::uint64_t>(test::scaled(3, 1));
    for (std::uint64_t seed = 0; seed < games_played; ++seed) {
      games.push_back(play_game(config, {random, random}, seed));
      expect_round_trip(games.back().start);
      // Every state of the first game, every 7th of the others (the record's
      // round trip below covers all of them as a whole).
      const std::vector<RecordedStep>& steps = games.back().steps;
      for (std::size_t i = 0; i < steps.size(); i += seed == 0 ? 1 : 7) expect_round_trip(steps[i].state);
    }
    const std::string text = game_records_to_json(games);
    const std::vector<GameRecord> back = game_records_from_json(text);
    EXPECT_EQ(game_records_to_json(back), text);
    for (std::size_t g = 0; g < back.size(); ++g) EXPECT_FALSE(replay_difference(back[g], static_cast<int>(g)));
  }
}

TEST(GameJson, StateFileHasTheScenarioKeysAndTheGameObject) {
  const Json j = Json::parse(game_state_to_json(new_game(default_config(GameKind::nine_ball))));
  for (const char* key : {"table", "parameters", "balls", "game"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_FALSE(j.contains("cue"));
  const Json& g = j["game"];
  for (const char* key : {"kind", "config", "phase", "to_shoot", "ball_in_hand", "scores", "fouls_in_a_row", "on", "groups",
                          "decisions", "push_out_available", "shots", "over", "winner", "truncated", "end_reason"})
    EXPECT_TRUE(g.contains(key)) << key;
  EXPECT_EQ(g["kind"], "nine_ball");
  EXPECT_EQ(g["phase"], "break");
  EXPECT_EQ(g["ball_in_hand"], "behind_head_string");
  EXPECT_EQ(g["on"], Json::array({1}));
  EXPECT_EQ(g["winner"], nullptr);
  EXPECT_EQ(j["balls"].size(), 10u);
}

// The new game's JSON, changed by `edit`, read back.
template <class Edit>
GameState edited(Edit&& edit) {
  Json j = Json::parse(game_state_to_json(new_game(default_config(GameKind::nine_ball))));
  edit(j);
  return game_state_from_json(j.dump());
}

TEST(GameJson, HandEditsAreAccepted) {
  // Balls removed and moved.
  const GameState s = edited([](Json& j) {
    j["balls"].erase(5);
    j["balls"].erase(3);
    j["balls"][1]["position"] = {1.5, 0.3};
  });
  EXPECT_EQ(s.table.balls.size(), 8u);
  EXPECT_EQ(s.table.balls[1].state.position.x, 1.5);
  // A minimal file: the balls and the game's kind; the rest the defaults.
  const GameState minimal = game_state_from_json(R"({
    "balls": [{"id": 0, "position": [0.5, 0.6]}, {"id": 1, "position": [1.8, 0.6]}, {"id": 9, "position": [2.0, 0.9]}],
    "game": {"kind": "nine_ball", "phase": "play", "on": [1]}})");
  EXPECT_EQ(minimal.table.table.name, new_game(default_config(GameKind::nine_ball)).table.table.name);
  Action a;
  a.strike.speed = 2.0;
  a.aim_at = 1;
  const GameStep step = play(minimal, a, 0);
  EXPECT_EQ(step.facts.first_contact, 1);
  // A rectangle in hand.
  const GameState rect = edited([](Json& j) {
    j["game"]["ball_in_hand"] = {{"kind", "rectangle"}, {"x_min", 0.2}, {"x_max", 0.5}, {"y_min", 0.3}, {"y_max", 0.9}};
  });
  ASSERT_TRUE(rect.ball_in_hand);
  EXPECT_EQ(rect.ball_in_hand->kind, PlacementRegion::Kind::rectangle);
  EXPECT_EQ(rect.ball_in_hand->x_max, 0.5);
  expect_round_trip(rect);
}

TEST(GameJson, StatesThatBreakTheRulesNameTheirPath) {
  const auto bad = [](const std::string& field, auto edit) {
    expect_invalid(field, [&] { (void)edited(edit); });
  };
  bad("state.balls[2].position", [](Json& j) { j["balls"][2]["position"] = j["balls"][1]["position"]; });
  bad("state.balls[3].id", [](Json& j) { j["balls"][3]["id"] = 12; });  // not a 9-ball ball
  bad("state.balls[4].id", [](Json& j) { j["balls"][4]["id"] = 2; });   // twice
  bad("state.balls[1].velocity", [](Json& j) { j["balls"][1]["velocity"] = {0.5, 0.0}; });
  bad("state.game.ball_in_hand", [](Json& j) { j["game"]["ball_in_hand"] = "inside_d"; });
  bad("state.game.ball_in_hand", [](Json& j) { j["game"]["ball_in_hand"] = "nowhere"; });
  bad("state.game.ball_in_hand.x_max", [](Json& j) {
    j["game"]["ball_in_hand"] = {{"kind", "rectangle"}, {"x_min", 0.5}, {"x_max", 0.2}, {"y_min", 0.3}, {"y_max", 0.9}};
  });
  bad("state.game.to_shoot", [](Json& j) { j["game"]["to_shoot"] = 2; });
  bad("state.game.breaker", [](Json& j) { j["game"]["breaker"] = -1; });
  bad("state.game.phase", [](Json& j) { j["game"]["phase"] = "halftime"; });
  bad("state.game.phase", [](Json& j) { j["game"]["over"] = true; });
  bad("state.game.decisions", [](Json& j) { j["game"]["phase"] = "decision"; });
  bad("state.game.decisions[0]", [](Json& j) { j["game"]["decisions"] = {"concede"}; });
  bad("state.game.winner", [](Json& j) { j["game"]["winner"] = 1; });
  bad("state.game.groups", [](Json& j) { j["game"]["groups"] = {"solids", "stripes"}; });  // 8-ball only
  bad("state.game.on[0]", [](Json& j) { j["game"]["on"] = {16}; });
  bad("state.game.kind", [](Json& j) { j["game"]["kind"] = "pinball"; });
  bad("state.game.kind", [](Json& j) { j["game"].erase("kind"); });
  bad("state.game.colour", [](Json& j) { j["game"]["colour"] = 1; });  // unknown key
  bad("state.game.config.max_shots", [](Json& j) { j["game"]["config"]["max_shots"] = 0; });
  bad("state.game.config.table", [](Json& j) { j["game"]["config"]["table"] = "bar_7ft"; });
  bad("state.game.config.noise.aim_deg", [](Json& j) { j["game"]["config"]["noise"]["aim_deg"] = 50; });
  bad("state.game", [](Json& j) { j.erase("game"); });
  bad("state.cue", [](Json& j) { j["cue"] = {{"speed", 3.0}}; });
  bad("state.balls", [](Json& j) {  // the cue ball gone while not in hand
    j["game"]["ball_in_hand"] = nullptr;
    j["balls"].erase(0);
  });
  bad("state.spin", [](Json& j) { j["spin"] = 1; });
  bad("state.parameters.mu_s", [](Json& j) { j["parameters"]["mu_s"] = -1.0; });
  // Snooker's region on snooker's table is fine; a 9-ball id in snooker is not.
  Json snooker = Json::parse(game_state_to_json(new_game(default_config(GameKind::nine_ball))));
  snooker["game"]["kind"] = "snooker";
  snooker["game"]["config"] = {{"table", "snooker_12ft"}, {"reds", 6}};
  snooker["game"]["on"] = Json::array();
  snooker.erase("table");
  snooker.erase("parameters");
  snooker["balls"] = {{{"id", 0}, {"position", {0.5, 0.9}}}, {{"id", 7}, {"position", {2.5, 0.9}}}};
  snooker["game"]["ball_in_hand"] = "inside_d";
  expect_invalid("state.balls[1].id", [&] { (void)game_state_from_json(snooker.dump()); });
  snooker["balls"][1]["id"] = 21;
  EXPECT_EQ(game_state_from_json(snooker.dump()).ball_in_hand->kind, PlacementRegion::Kind::inside_d);
}

TEST(GameJson, ActionsAsTheCueObject) {
  const Table table = pool_table_9ft();
  const Action a = action_from_json(
      R"({"speed": 5, "target": 1, "elevation_deg": 2, "side": 0.1, "height": -0.2, "place": [0.5, 0.6],
          "call": {"ball": 9, "pocket": "top-right"}, "push_out": true})",
      &table);
  EXPECT_EQ(a.strike.speed, 5.0);
  EXPECT_EQ(a.aim_at, 1);
  EXPECT_EQ(a.strike.height, -0.2);
  ASSERT_TRUE(a.place);
  EXPECT_EQ(a.place->y, 0.6);
  EXPECT_EQ(a.called_ball, 9);
  ASSERT_TRUE(a.called_pocket);
  EXPECT_EQ(table.pockets[static_cast<std::size_t>(*a.called_pocket)].name, "top-right");
  EXPECT_TRUE(a.push_out);
  EXPECT_EQ(action_from_json(action_to_json(a)).called_pocket, a.called_pocket);
  const Action d = action_from_json(R"({"decision": "pass"})");
  EXPECT_EQ(d.decision, Decision::pass);
  EXPECT_EQ(action_to_json(d), R"({"decision":"pass"})");
  expect_invalid("action.speed", [] { (void)action_from_json(R"({"decision": "pass", "speed": 3})"); });
  expect_invalid("action.decision", [] { (void)action_from_json(R"({"decision": "concede"})"); });
  expect_invalid("action.target", [] { (void)action_from_json(R"({"speed": 3, "target": 1, "aim_deg": 4})"); });
  expect_invalid("action.speed", [] { (void)action_from_json(R"({"speed": 13})"); });
  expect_invalid("action.side", [] { (void)action_from_json(R"({"speed": 3, "side": 0.7})"); });
  expect_invalid("action.call.pocket", [&] { (void)action_from_json(R"({"speed": 3, "call": {"pocket": "left"}})", &table); });
  expect_invalid("cue.ball", [] { (void)action_from_json(R"({"speed": 3, "ball": 0})", nullptr, "cue"); });
}

TEST(GameJson, StepAndRulingHaveTheDocumentedKeys) {
  const GameState s = new_game(default_config(GameKind::nine_ball));
  Action a;
  a.strike.speed = 8.0;
  a.aim_at = 1;
  const Json j = Json::parse(game_step_to_json(play(s, a, 3)));
  for (const char* key : {"action", "ruling", "facts", "state"}) EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"foul", "points", "turn_over", "game_over", "winner", "respotted", "pocketed", "push_out", "miss",
                          "truncated", "reason"})
    EXPECT_TRUE(j["ruling"].contains(key)) << key;
  EXPECT_EQ(j["facts"]["first_contact"]["ball"], 1);
  EXPECT_EQ(j["state"]["game"]["shots"], 1);
  EXPECT_EQ(j["ruling"]["points"].size(), 2u);
}

TEST(GameJson, RecordsReplayBitForBitAndNameTheFirstDifference) {
  AgentOptions random;
  random.kind = AgentKind::random;
  GameConfig config = default_config(GameKind::nine_ball);
  config.noise = tournament_noise();
  std::vector<GameRecord> games{play_game(config, {random, random}, 5), play_game(config, {random, random}, 6)};
  ASSERT_FALSE(games[0].steps.empty());
  const std::string text = game_records_to_json(games);
  const std::vector<GameRecord> back = game_records_from_json(text);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(game_records_to_json(back), text);
  EXPECT_EQ(back[1].players[0], "random");
  EXPECT_EQ(back[0].steps.size(), games[0].steps.size());
  for (std::size_t g = 0; g < back.size(); ++g)
    EXPECT_FALSE(replay_difference(back[g], static_cast<int>(g))) << replay_difference(back[g])->path;

  // A state nudged by one ulp: found, with its path.
  GameRecord tampered = back[0];
  RecordedStep& step = tampered.steps.front();
  step.state.table.balls.back().state.position.x =
      std::nextafter(step.state.table.balls.back().state.position.x, 10.0);
  const std::optional<ReplayDifference> d = replay_difference(tampered, 0);
  ASSERT_TRUE(d);
  EXPECT_EQ(d->step, 0);
  EXPECT_EQ(d->path, "games[0].steps[0].state.balls[" + std::to_string(step.state.table.balls.size() - 1) + "].position[0]");
  EXPECT_NE(d->recorded, d->replayed);
  // A changed seed: another strike, another table (or ruling).
  GameRecord reseeded = back[0];
  reseeded.steps[1].seed += 1;
  const std::optional<ReplayDifference> r = replay_difference(reseeded, 0);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->step, 1);

  expect_invalid("record.format", [] { (void)game_records_from_json(R"({"games": []})"); });
  expect_invalid("record.games[0].start", [] {
    (void)game_records_from_json(R"({"format": "cueball-game-record", "version": 1, "games": [{"seed": 1}]})");
  });
}

TEST(GameJson, AnAgentsReasoningRoundTripsInARecord) {
  AgentOptions planner;
  planner.kind = AgentKind::planner;
  planner.simulations = kMinPlanSimulations;
  AgentOptions random;
  random.kind = AgentKind::random;
  GameConfig config = default_config(GameKind::nine_ball);
  config.max_shots = 3;
  const GameRecord game = play_game(config, {planner, random}, 4);
  // the planner breaks: its reasoning says so; the random agent's steps have none
  ASSERT_GE(game.steps.size(), 2u);
  EXPECT_EQ(game.steps[0].reasoning.summary, "break");
  const std::string text = game_records_to_json({game});
  const std::vector<GameRecord> back = game_records_from_json(text);
  ASSERT_EQ(back.front().steps.size(), game.steps.size());
  for (std::size_t k = 0; k < game.steps.size(); ++k) {
    const Reasoning& a = game.steps[k].reasoning;
    const Reasoning& b = back.front().steps[k].reasoning;
    EXPECT_EQ(a.summary, b.summary);
    ASSERT_EQ(a.considered.size(), b.considered.size());
    for (std::size_t j = 0; j < a.considered.size(); ++j) {
      EXPECT_EQ(a.considered[j].what, b.considered[j].what);
      EXPECT_DOUBLE_EQ(a.considered[j].estimate, b.considered[j].estimate);
      EXPECT_DOUBLE_EQ(a.considered[j].next_estimate, b.considered[j].next_estimate);
    }
  }
  EXPECT_EQ(game_records_to_json(back), text);
  // a bad estimate is named by its path
  GameRecord bad = game;
  bad.steps[0].reasoning.considered = {{"a shot", 0.5, -1.0}};
  std::string bad_text = game_records_to_json({bad});
  const std::size_t at = bad_text.find("\"estimate\":0.5");
  ASSERT_NE(at, std::string::npos);
  bad_text.replace(at, 14, "\"estimate\":1.5");
  expect_invalid("record.games[0].steps[0].reasoning.considered[0].estimate",
                 [&] { (void)game_records_from_json(bad_text); });
}

TEST(GameJson, ConfigsRoundTripWithTheirVariants) {
  GameConfig c = default_config(GameKind::eight_ball);
  c.break_scratch_region = PlacementRegion::Kind::anywhere;
  c.noise = tournament_noise();
  c.fouls_to_lose = 0;
  const std::string text = game_config_to_json(c);
  const GameConfig back = game_config_from_json(text);
  EXPECT_EQ(game_config_to_json(back), text);
  EXPECT_EQ(back.noise.aim, c.noise.aim);
  EXPECT_EQ(back.noise.side_offset, c.noise.side_offset);
  EXPECT_EQ(back.break_scratch_region, PlacementRegion::Kind::anywhere);
  expect_invalid("config.reds", [] { (void)game_config_from_json(R"({"kind": "snooker", "reds": 7})"); });
  expect_invalid("config.kind", [] { (void)game_config_from_json(R"({"reds": 6})"); });
  expect_invalid("config.break_scratch_region",
                 [] { (void)game_config_from_json(R"({"kind": "eight_ball", "break_scratch_region": "inside_d"})"); });
}

}  // namespace
}  // namespace cueball
