// Tests of `cueball game` (cli/command_game.cpp): new, shoot (text, --json,
// -o, illegal actions), play (score lines, --json, --record) and replay
// (bit for bit; exit 1 at the first difference), and bad input: exit 2 with
// one line naming the flag or the JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "temp_dir.hpp"

namespace cueball {
namespace {

using namespace test;
using Json = nlohmann::json;

TEST(CliGame, NewWritesAStateReadyToBreak) {
  const TempDir dir;
  const CliRun printed = run_cli({"game", "new", "--game", "nine_ball"});
  ASSERT_EQ(printed.status, 0) << printed.err;
  const Json j = Json::parse(printed.out);
  EXPECT_EQ(j["game"]["kind"], "nine_ball");
  EXPECT_EQ(j["game"]["phase"], "break");
  EXPECT_EQ(j["game"]["ball_in_hand"], "behind_head_string");
  const std::string state = dir.path("s.json");
  const CliRun written = run_cli({"game", "new", "--game", "nine_ball", "--seed", "4", "-o", state, "--noise", "tournament"});
  ASSERT_EQ(written.status, 0) << written.err;
  EXPECT_NE(written.out.find("player 0 to break"), std::string::npos) << written.out;
  EXPECT_EQ(count_lines(written.out), 1);
  EXPECT_GT(Json::parse(read_text(state))["game"]["config"]["noise"]["aim_deg"].get<double>(), 0.0);
}

TEST(CliGame, ShootPlaysOneShotAndWritesTheNextState) {
  const TempDir dir;
  const std::string state = dir.path("s.json"), next = dir.path("n.json");
  ASSERT_EQ(run_cli({"game", "new", "--game", "nine_ball", "-o", state}).status, 0);
  // A soft break at the 1: legal or not, judged; the JSON has the documented keys.
  const CliRun r = run_cli({"game", "shoot", state, "--cue", R"({"speed": 1.2, "target": 1})", "--json", "-o", next});
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  for (const char* key : {"action", "ruling", "facts", "state"}) EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["facts"]["first_contact"]["ball"], 1);
  EXPECT_EQ(j["ruling"]["foul"], "illegal_break");  // too soft to drive four balls to a rail
  EXPECT_EQ(j["state"], Json::parse(read_text(next)));
  EXPECT_EQ(j["state"]["game"]["to_shoot"], 1);
  EXPECT_EQ(j["state"]["game"]["ball_in_hand"], "anywhere");
  // The opponent places the cue ball and shoots: one line.
  const CliRun text = run_cli({"game", "shoot", next, "--cue", R"({"speed": 2, "target": 1})", "--place", "1.0,0.3"});
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(count_lines(text.out), 1) << text.out;
  EXPECT_NE(text.out.find("shot 2, player 1: first contact 1"), std::string::npos) << text.out;
  // The same shot with the same seed and noise: the same output.
  const std::vector<std::string> noisy{"game", "shoot", next, "--cue", R"({"speed": 2, "target": 1, "place": [1.0, 0.3]})",
                                       "--noise", "tournament", "--seed", "9", "--json"};
  EXPECT_EQ(run_cli(noisy).out, run_cli(noisy).out);
}

TEST(CliGame, IllegalActionsExitTwoSayingWhy) {
  const TempDir dir;
  const std::string state = dir.path("s.json"), next = dir.path("n.json");
  ASSERT_EQ(run_cli({"game", "new", "--game", "nine_ball", "-o", state}).status, 0);
  // Placing outside the kitchen on the break.
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 8, "target": 1})", "--place", "2.0,0.6"}, "--place");
  // A decision that is not open.
  expect_usage_error({"game", "shoot", state, "--decision", "pass"}, "--decision");
  expect_usage_error({"game", "shoot", state, "--decision", "concede"}, "--decision");
  // A push-out on the break, a call 9-ball does not take.
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 8, "target": 1})", "--push-out"}, "--push-out");
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 8, "target": 1})", "--call", "1,top-right"}, "--call");
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 8, "target": 1})", "--call", "1,left"}, "left");
  // The strike's own JSON.
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 30})"}, "--cue.speed");
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 3, "spin": 1})"}, "--cue.spin");
  expect_usage_error({"game", "shoot", state, "--cue", "{"}, "--cue");
  expect_usage_error({"game", "shoot", state}, "--cue");
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 3})", "--place", "x,1"}, "--place");
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 3})", "--seed", "-1"}, "--seed");
  expect_usage_error({"game", "shoot", state, "--cue", R"({"speed": 3})", "--noise", "loud"}, "--noise");
  // A game that is over.
  ASSERT_EQ(run_cli({"game", "shoot", state, "--cue", R"({"speed": 8, "target": 1})", "-o", next}).status, 0);
  Json over = Json::parse(read_text(next));
  over["game"]["phase"] = "over";
  over["game"]["over"] = true;
  over["game"]["winner"] = 0;
  over["game"]["ball_in_hand"] = nullptr;
  const std::string done = dir.write("over.json", over.dump());
  expect_usage_error({"game", "shoot", done, "--cue", R"({"speed": 3})"}, "the game is over");
}

TEST(CliGame, StatesThatBreakTheRulesExitTwoNamingTheKey) {
  const TempDir dir;
  const std::string state = dir.path("s.json");
  ASSERT_EQ(run_cli({"game", "new", "--game", "nine_ball", "-o", state}).status, 0);
  const Json good = Json::parse(read_text(state));
  const auto with = [&](const char* name, auto edit) {
    Json j = good;
    edit(j);
    return dir.write(name, j.dump());
  };
  const std::vector<std::string> cue{"--cue", R"({"speed": 8, "target": 1})"};
  const auto shoot = [&](const std::string& file) {
    std::vector<std::string> args{"game", "shoot", file};
    args.insert(args.end(), cue.begin(), cue.end());
    return args;
  };
  expect_usage_error(shoot(with("overlap.json", [](Json& j) { j["balls"][2]["position"] = j["balls"][3]["position"]; })),
                     "state.balls[");
  expect_usage_error(shoot(with("id.json", [](Json& j) { j["balls"][2]["id"] = 14; })), "state.balls[2].id");
  expect_usage_error(shoot(with("d.json", [](Json& j) { j["game"]["ball_in_hand"] = "inside_d"; })), "state.game.ball_in_hand");
  expect_usage_error(shoot(with("turn.json", [](Json& j) { j["game"]["to_shoot"] = 3; })), "state.game.to_shoot");
  expect_usage_error(shoot(dir.path("missing.json")), "cannot open");
  // A hand edit: balls removed and the cue ball moved in the kitchen.
  const std::string edited = with("edited.json", [](Json& j) {
    j["balls"].erase(8);
    j["balls"].erase(4);
    j["balls"][0]["position"] = {0.4, 0.5};
  });
  const CliRun r = run_cli(shoot(edited));
  EXPECT_EQ(r.status, 0) << r.err;
  expect_usage_error({"game", "new", "--game", "pinball"}, "--game");
  expect_usage_error({"game", "new", "--game", "nine_ball", "--noise", R"({"aim_deg": 90})"}, "--noise.aim_deg");
  expect_usage_error({"game"}, "");
}

TEST(CliGame, PlayWritesTheFirstGameAsAViewerPage) {
  const TempDir dir;
  const std::string page = dir.path("game.html"), record = dir.path("r.json");
  const CliRun r = run_cli({"game", "play", "--game", "nine_ball", "--players", "ghost_ball,random", "--games", "2", "--seed", "2",
                            "--record", record, "--html", page});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("viewer of game 1 written to"), std::string::npos) << r.out;
  const std::string html = read_text(page);
  const std::string open = R"(<script type="application/json" id="cueball-result">)";
  const std::size_t at = html.find(open);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(html.find("__CUEBALL_RESULT__"), std::string::npos);
  const std::size_t from = at + open.size();
  const std::string doc_text = html.substr(from, html.find("</script>", from) - from);
  EXPECT_EQ(doc_text.find('<'), std::string::npos) << "every < escaped";
  const Json doc = Json::parse(doc_text);
  const Json games = Json::parse(read_text(record))["games"];
  ASSERT_EQ(games.size(), 2u);
  // the first game: one entry per recorded step, the players and the end as recorded
  EXPECT_EQ(doc["game"]["shots"].size(), games[0]["steps"].size());
  EXPECT_EQ(doc["game"]["players"], Json::array({"ghost_ball", "random"}));
  EXPECT_EQ(doc["game"]["kind"], "nine_ball");
  for (const Json& shot : doc["game"]["shots"]) EXPECT_TRUE(shot.contains("result") && shot.contains("caption"));
}

TEST(CliGame, PlayPrintsEveryGameAndRecordsWhatReplayReproduces) {
  const TempDir dir;
  const std::string record = dir.path("r.json");
  const CliRun r = run_cli({"game", "play", "--game", "nine_ball", "--players", "random,random", "--games", "3", "--seed", "11",
                            "--noise", "tournament", "--record", record});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("game 3 (seed 13)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total: 3 games, wins "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fouls "), std::string::npos);
  const CliRun json = run_cli({"game", "play", "--game", "nine_ball", "--players", "random,random", "--games", "3", "--seed",
                               "11", "--noise", "tournament", "--json"});
  ASSERT_EQ(json.status, 0) << json.err;
  const Json summary = Json::parse(json.out);
  ASSERT_EQ(summary["games"].size(), 3u);
  for (const char* key : {"seed", "players", "scores", "winner", "truncated", "end_reason", "steps", "fouls", "pots"})
    EXPECT_TRUE(summary["games"][0].contains(key)) << key;
  EXPECT_EQ(summary["totals"]["games"], 3);
  const Json rec = Json::parse(read_text(record));
  EXPECT_EQ(rec["format"], "cueball-game-record");
  ASSERT_EQ(rec["games"].size(), 3u);
  EXPECT_EQ(rec["games"][0]["steps"].size(), summary["games"][0]["steps"]);

  const CliRun replay = run_cli({"game", "replay", record});
  ASSERT_EQ(replay.status, 0) << replay.err;
  EXPECT_NE(replay.out.find("3 games"), std::string::npos) << replay.out;
  EXPECT_NE(replay.out.find("bit for bit"), std::string::npos) << replay.out;

  // One recorded position changed in its last digit: exit 1 naming where.
  Json changed = rec;
  Json& x = changed["games"][1]["steps"][0]["state"]["balls"][1]["position"][0];
  x = std::nextafter(x.get<double>(), 10.0);
  const CliRun diff = run_cli({"game", "replay", dir.write("changed.json", changed.dump())});
  EXPECT_EQ(diff.status, 1) << diff.err;
  EXPECT_EQ(count_lines(diff.err), 1) << diff.err;
  EXPECT_NE(diff.err.find("games[1].steps[0].state.balls[1].position[0]"), std::string::npos) << diff.err;

  expect_usage_error({"game", "play", "--game", "nine_ball", "--players", "random"}, "--players");
  expect_usage_error({"game", "play", "--game", "nine_ball", "--players", "random,shark"}, "--players");
  expect_usage_error({"game", "play", "--game", "nine_ball", "--players", "random,random", "--games", "0"}, "--games");
  expect_usage_error({"game", "play", "--game", "nine_ball", "--players", "random,random", "--simulations", "2.5"},
                     "--simulations");
  expect_usage_error({"game", "play", "--game", "nine_ball", "--players", "random,random", "--noise", "{}"}, "--noise");
  expect_usage_error({"game", "play", "--game", "nine_ball", "--players", "random,random", "--seconds", "-1"},
                     "--seconds");
  expect_usage_error({"game", "play", "--game", "nine_ball", "--players", "random,random", "--seconds", "1h"},
                     "--seconds");
  expect_usage_error({"game", "replay", dir.write("bad.json", R"({"games": []})")}, "record.format");
}

}  // namespace
}  // namespace cueball
