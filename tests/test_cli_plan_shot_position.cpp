// Tests of `cueball plan-shot --position` and `--in-hand`
// (cli/command_plan_shot.cpp over position_play.hpp and ball_in_hand.hpp):
// the JSON's "position" and "in_hand" objects, the choice by score, the
// text's position lines, the written scenario's cue ball at its spot, and
// --valuation ghost_ball the library's plan, and bad input naming --next,
// --next-simulations, --valuation, --game-ball and --region; --game-ball
// the library's plan with the leave's combination.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/planning/position_play.hpp"
#include "temp_dir.hpp"

namespace cueball {
namespace {

using namespace test;  // the CLI tests' helpers (tests/support/)

// The 1 ball 0.5 m from the top-right pocket, cut about 20 degrees; the 2
// and the 9 elsewhere on the table.
constexpr const char* kThreeBalls = R"({
  "table": "pool_9ft",
  "balls": [
    {"id": 0, "name": "cue", "position": [1.55, 0.70]},
    {"id": 1, "name": "1", "position": [2.214, 0.944]},
    {"id": 2, "name": "2", "position": [0.5, 0.3]},
    {"id": 9, "name": "9", "position": [0.8, 1.0]}
  ]
})";

TEST(CliPlanShotPosition, JsonGivesEveryShotsLeaveAndPlaysTheBestScore) {
  const TempDir dir;
  const std::string scenario = dir.write("three.json", kThreeBalls);
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--position", "--simulations", "1000", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("position"));
  const nlohmann::json& p = j["position"];
  for (const char* key :
       {"next", "cue_ball", "next_feasible", "next_success_probability", "next_kind", "next_pocket", "next_ball",
        "screened_probability", "noisy_leaves", "noisy_next_window", "candidate_noisy_leaves",
        "candidate_next_window", "score"})
    EXPECT_TRUE(p.contains(key)) << key;
  EXPECT_EQ(p["next"], 2);  // the lowest id left
  if (p["next_feasible"].get<bool>()) {
    EXPECT_EQ(p["next_ball"], 2);  // the ball the next plan pots
  } else {
    EXPECT_TRUE(p["next_ball"].is_null());
  }
  // scored on the noisy successes' leaves when there are any
  const double next = p["noisy_leaves"].get<int>() > 0 ? p["noisy_next_window"].get<double>()
                                                       : p["next_success_probability"].get<double>();
  EXPECT_DOUBLE_EQ(p["score"].get<double>(), p["screened_probability"].get<double>() * next);
  // The cue ball's leave is where the noise-free shot's prediction puts it.
  for (const nlohmann::json& b : j["predicted"]) {
    if (b["id"] == 0) {
      EXPECT_EQ(b["position"], p["cue_ball"]);
    }
  }
  for (const nlohmann::json& a : j["alternatives"]) {
    ASSERT_TRUE(a.contains("position"));
    EXPECT_LE(a["position"]["score"].get<double>(), p["score"].get<double>());
  }
}

TEST(CliPlanShotPosition, WithNoBallAfterTheTargetEveryShotHasALeaveOnItsPotAlone) {
  // Only the cue ball and the 1 (a single-pot layout of the planner
  // benchmark): no next ball, plan_shot()'s plan, its alternatives included.
  const TempDir dir;
  const std::string scenario = dir.write("two.json", R"({
  "table": "pool_9ft",
  "balls": [
    {"id": 0, "position": [2.305099864712931, 0.9787961715433114]},
    {"id": 1, "position": [0.49154198107436164, 0.9834269711414346]}
  ]
})");
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--position", "--simulations", "1000", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["position"]["next"].is_null());
  ASSERT_FALSE(j["alternatives"].empty());
  for (const auto& a : j["alternatives"]) {
    EXPECT_TRUE(a["position"]["next"].is_null());
    EXPECT_EQ(a["position"]["score"], a["success_probability"]);
  }
  const CliRun text = run_cli({"plan-shot", scenario, "--ball", "1", "--position", "--simulations", "1000"});
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("no ball left after this one"), std::string::npos) << text.out;
}

TEST(CliPlanShotPosition, NextBallIsTheOneGivenAndTheTextSaysTheLeave) {
  const TempDir dir;
  const std::string scenario = dir.write("three.json", kThreeBalls);
  const CliRun r =
      run_cli({"plan-shot", scenario, "--ball", "1", "--position", "--next", "9", "--simulations", "1000"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("  position   leaves the cue ball at ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(": ball 9 next, "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("P(both) = "), std::string::npos) << r.out;
  // Without --position there is no position line.
  const CliRun plain = run_cli({"plan-shot", scenario, "--ball", "1", "--simulations", "1000"});
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(plain.out.find("  position   "), std::string::npos);
}

TEST(CliPlanShotPosition, InHandTakesARegionByName) {
  const TempDir dir;
  const std::string scenario = dir.write("three.json", kThreeBalls);
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--in-hand", "--region", "kitchen", "--simulations",
                            "1000", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_LE(j["in_hand"]["cue_ball"][0].get<double>(), 2.54 / 4 + 1e-9);  // behind the head string
}

TEST(CliPlanShotPosition, InHandPlacesTheCueBallAndTheWrittenScenarioReplaysFromThere) {
  const TempDir dir;
  const std::string scenario = dir.write("three.json", kThreeBalls);
  const std::string out = dir.path("planned.json");
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--in-hand", "--region", "0.3,1.27,0.0,1.27",
                            "--simulations", "1000", "--json", "--scenario-out", out});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("in_hand"));
  ASSERT_TRUE(j.contains("position"));  // --in-hand plays for position
  const nlohmann::json& spot = j["in_hand"]["cue_ball"];
  EXPECT_GE(spot[0].get<double>(), 0.3);
  EXPECT_LE(spot[0].get<double>(), 1.27);
  EXPECT_GE(j["in_hand"]["spots_played"].get<int>(), 1);
  EXPECT_EQ(j["position"]["next"], 2);
  // The written scenario has the cue ball at the spot, the others where they were.
  const nlohmann::json written = nlohmann::json::parse(test::read_text(out));
  for (const nlohmann::json& b : written["balls"]) {
    if (b["id"] == 0) {
      EXPECT_EQ(b["position"], spot);
    } else if (b["id"] == 2) {
      EXPECT_EQ(b["position"], nlohmann::json::array({0.5, 0.3}));
    }
  }
  // The replay pots the 1.
  const CliRun replay = run_cli({"simulate", out, "--json"});
  ASSERT_EQ(replay.status, 0) << replay.err;
  const nlohmann::json played = nlohmann::json::parse(replay.out);
  for (const nlohmann::json& b : played["balls"]) {
    if (b["id"] == 1) {
      EXPECT_TRUE(b["pocketed"].get<bool>());
    }
  }
}

TEST(CliPlanShotPosition, BadRegionIsAUsageErrorNamingTheFlag) {
  const TempDir dir;
  const std::string scenario = dir.write("three.json", kThreeBalls);
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--region", "0,1,0,1"}, "--region");  // needs --in-hand
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--in-hand", "--region", "0,1,0"}, "--region");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--in-hand", "--region", "0,1,0,x"}, "--region");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--in-hand", "--region", "nowhere"}, "--region");  // not a name
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--in-hand", "--region", "1,0,0,1"}, "--region");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--in-hand", "--region", "0,1,0,nan"}, "--region");
  // Issue 24: wholly off the table was exit status 3 ("no spot for the cue ball").
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--in-hand", "--region", "5,6,5,6"},
                     "--region = \"5,6,5,6\": region [5, 6] x [5, 6] m lies wholly off the playing surface; allowed: "
                     "a region overlapping [0, 2.54] x [0, 1.27] m");
}

// plan-shot --ball 1 --position --valuation ghost_ball --simulations 1000
// --json (with --game-ball when given) on the scenario `json`, and the
// library's plan of the same request.
struct GhostBallPlans {
  nlohmann::json cli;
  PositionPlanResult lib;
};
GhostBallPlans ghost_ball_plans(const std::string& json, std::optional<int> game_ball) {
  const TempDir dir;
  std::vector<std::string> args{"plan-shot",   dir.write("table.json", json), "--ball",         "1",   "--position",
                                "--valuation", "ghost_ball",                  "--simulations", "1000", "--json"};
  if (game_ball) args.insert(args.end(), {"--game-ball", std::to_string(*game_ball)});
  const CliRun r = run_cli(args);
  EXPECT_EQ(r.status, 0) << r.err;
  PositionRequest q;
  q.shot.target = 1;
  q.shot.simulations = 1000;
  q.valuation = LeaveValuation::ghost_ball;
  q.game_ball = game_ball;
  return {nlohmann::json::parse(r.out), plan_shot_for_position(scenario_from_json(json), q)};
}

// --valuation ghost_ball: the library's plan (PositionRequest::valuation) to
// the bit, each leave's next shot the best straight pot by its ghost-ball chance.
TEST(CliPlanShotPosition, ValuationGhostBallIsTheLibrarysPlan) {
  const auto [j, lib] = ghost_ball_plans(kThreeBalls, std::nullopt);
  EXPECT_EQ(j["cue"]["aim_deg"].get<double>(), lib.plan.shot.strike.aim_deg);
  EXPECT_EQ(j["simulations"].get<int>(), lib.plan.simulations);
  const nlohmann::json& p = j["position"];
  EXPECT_EQ(p["score"].get<double>(), lib.leave.score);
  EXPECT_EQ(p["next_success_probability"].get<double>(), lib.leave.next_success_probability);
  if (p["next_feasible"].get<bool>()) {
    EXPECT_EQ(p["next_kind"], "direct");
  }
}

// --game-ball: the library's plan with PositionRequest::game_ball to the
// bit; the 2 behind the 9 at a corner, so that the leave's next shot is the
// 9 by a combination through the 2.
TEST(CliPlanShotPosition, GameBallIsTheLibrarysPlan) {
  const std::string json = R"({"table": "pool_9ft", "balls": [{"id": 0, "position": [1.35, 0.75]},
    {"id": 1, "position": [1.85, 0.45]}, {"id": 2, "position": [0.5, 0.5]}, {"id": 9, "position": [0.4, 0.4]}]})";
  const auto [j, lib] = ghost_ball_plans(json, 9);
  EXPECT_EQ(j["cue"]["aim_deg"].get<double>(), lib.plan.shot.strike.aim_deg);
  EXPECT_EQ(j["simulations"].get<int>(), lib.plan.simulations);
  const nlohmann::json& p = j["position"];
  EXPECT_EQ(p["score"].get<double>(), lib.leave.score);
  EXPECT_EQ(p["next_kind"], "combination");
  EXPECT_EQ(p["next_ball"], 9);
}

TEST(CliPlanShotPosition, BadNextIsAUsageErrorNamingTheFlag) {
  const TempDir dir;
  const std::string scenario = dir.write("three.json", kThreeBalls);
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--position", "--next", "7"}, "--next");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--position", "--next", "1"}, "--next");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--position", "--next", "0"}, "--next");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--next", "2"}, "--next");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--position", "--next-simulations", "10"},
                     "--next-simulations");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--position", "--next-simulations", "600.5"},
                     "--next-simulations");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--position", "--valuation", "geometry"},
                     "--valuation = \"geometry\" is not a valuation; allowed: windows, ghost_ball");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--valuation", "ghost_ball"}, "--valuation");  // needs --position
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--game-ball", "2"}, "--game-ball = 2 needs --position");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--position", "--game-ball", "2"},
                     "--game-ball = 2 needs valuation ghost_ball");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--position", "--valuation", "ghost_ball", "--game-ball", "7"},
                     "--game-ball = 7 is not the id of a ball on the table; allowed: an object ball on the table");
}

}  // namespace
}  // namespace cueball
