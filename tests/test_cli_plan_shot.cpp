// Tests of `cueball plan-shot` (cli/command_plan_shot.cpp): the JSON's keys,
// the replay of --scenario-out by `simulate`, the kinds kick and combination,
// --targets (the only pottable legal target chosen), bad input (exit 2, one
// line naming the flag) and an infeasible layout (exit 3).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/planning/shot_planner.hpp"
#include "plan_shot_scenarios.hpp"
#include "temp_dir.hpp"

namespace cueball {
namespace {

using namespace test;  // the CLI tests' helpers (tests/support/)

using test::kCutShot;

// A wall of three balls between the cue ball and the 1: only a kick reaches it.
constexpr const char* kWalled = R"({
  "table": "pool_9ft",
  "balls": [
    {"id": 0, "position": [1.0, 0.4]},
    {"id": 1, "position": [1.9, 0.9]},
    {"id": 2, "position": [1.479139, 0.597551]},
    {"id": 3, "position": [1.45, 0.65]},
    {"id": 4, "position": [1.420861, 0.702449]}
  ]
})";

// The 1 ball boxed in by six balls frozen around it.
constexpr const char* kBoxedIn = R"({
  "table": "pool_9ft",
  "balls": [
    {"id": 0, "position": [0.6, 0.6]},
    {"id": 1, "position": [1.6, 0.6]},
    {"id": 2, "position": [1.658, 0.6]},
    {"id": 3, "position": [1.542, 0.6]},
    {"id": 4, "position": [1.629, 0.6503]},
    {"id": 5, "position": [1.571, 0.6503]},
    {"id": 6, "position": [1.629, 0.5497]},
    {"id": 7, "position": [1.571, 0.5497]}
  ]
})";

TEST(CliPlanShot, JsonHasTheDocumentedKeys) {
  const TempDir dir;
  const std::string scenario = dir.write("cut.json", kCutShot);
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--seed", "3", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["target"], 1);
  for (const char* key : {"cue", "kind", "pocket", "success_probability", "success_standard_error", "aim_window_deg",
                          "speed_window", "robot", "simulations", "seconds", "alternatives"})
    EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"speed", "aim_deg", "elevation_deg", "side", "height", "ball"}) EXPECT_TRUE(j["cue"].contains(key)) << key;
  EXPECT_TRUE(j["robot"].contains("tip_height"));
  EXPECT_TRUE(j["robot"].contains("cue_speed"));
  EXPECT_EQ(j["aim_window_deg"].size(), 2u);
  EXPECT_EQ(j["speed_window"].size(), 2u);
  EXPECT_LE(j["aim_window_deg"][0].get<double>(), j["cue"]["aim_deg"].get<double>());
  EXPECT_GE(j["aim_window_deg"][1].get<double>(), j["cue"]["aim_deg"].get<double>());
  EXPECT_EQ(j["kind"], "direct");
  EXPECT_EQ(j["pocket"], "top-right");
  EXPECT_LE(j["simulations"].get<int>(), 4000);
  for (const auto& a : j["alternatives"]) {
    for (const char* key : {"cue", "kind", "pocket", "success_probability", "aim_window_deg", "speed_window", "robot"})
      EXPECT_TRUE(a.contains(key)) << key;
  }
  // The scenario's own noise (here none: every noisy shot is the nominal one).
  const CliRun own = run_cli({"plan-shot", scenario, "--ball", "1", "--noise", "scenario", "--json"});
  ASSERT_EQ(own.status, 0) << own.err;
  EXPECT_EQ(nlohmann::json::parse(own.out)["success_probability"].get<double>(), 1.0);
  // The text form says the same in a few lines.
  const CliRun text = run_cli({"plan-shot", scenario, "--ball", "1", "--seed", "3"});
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("direct into top-right"), std::string::npos) << text.out;
}

TEST(CliPlanShot, ScenarioOutReplaysThePlanBitForBit) {
  const TempDir dir;
  const std::string scenario = dir.write("cut.json", kCutShot);
  const std::string planned = dir.path("planned.json");
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--scenario-out", planned, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json plan = nlohmann::json::parse(r.out);
  const CliRun sim = run_cli({"simulate", planned, "--json"});
  ASSERT_EQ(sim.status, 0) << sim.err;
  const nlohmann::json result = nlohmann::json::parse(sim.out);
  ASSERT_EQ(result["balls"].size(), plan["predicted"].size());
  for (std::size_t i = 0; i < result["balls"].size(); ++i) {
    const auto& b = result["balls"][i];
    const auto& p = plan["predicted"][i];
    EXPECT_EQ(b["id"], p["id"]);
    EXPECT_EQ(b["pocketed"], p["pocketed"]);
    EXPECT_EQ(b["pocket"], p["pocket"]);
    EXPECT_EQ(b["position"][0].get<double>(), p["position"][0].get<double>());
    EXPECT_EQ(b["position"][1].get<double>(), p["position"][1].get<double>());
    if (b["id"] == 1) {
      EXPECT_TRUE(b["pocketed"].get<bool>());
      EXPECT_EQ(b["pocket"], plan["pocket"]);
    }
    if (b["id"] == 0) {
      EXPECT_FALSE(b["pocketed"].get<bool>());
    }
  }
  // The written cue is the plan's.
  EXPECT_EQ(result["cue_strike"]["given"], plan["cue"]);

  // And its noise: `batch` with the plan's seed draws the final estimate's
  // shots, so its outcomes give the same success count.
  const int shots = plan["noisy_shots"].get<int>();
  const std::string outcomes = dir.path("outcomes.csv");
  const CliRun batch = run_cli({"batch", planned, "--shots", std::to_string(shots), "--seed", "0", "--outcomes", outcomes});
  ASSERT_EQ(batch.status, 0) << batch.err;
  std::istringstream csv(test::read_text(outcomes));
  std::string line;
  std::getline(csv, line);  // header: shot,miscue,failure,..,first_contact, then 6 columns per ball (0, 1, 9)
  int rows = 0, hits = 0;
  const std::size_t pocket = [&] {
    for (std::size_t k = 0; k < result["table"]["pockets"].size(); ++k)
      if (result["table"]["pockets"][k]["name"] == plan["pocket"]) return k;
    return std::size_t{99};
  }();
  while (std::getline(csv, line)) {
    std::vector<std::string> cell;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) cell.push_back(c);
    ASSERT_EQ(cell.size(), 7u + 18u);
    ++rows;
    hits += cell[1] == "0" && cell[2] == "0" && cell[6] == "1" && cell[7] == "0" && cell[13] == "1" &&
            cell[14] == std::to_string(pocket);
  }
  EXPECT_EQ(rows, shots);
  EXPECT_EQ(static_cast<double>(hits) / shots, plan["success_probability"].get<double>());
}

TEST(CliPlanShot, BadInputExits2NamingTheFlag) {
  const TempDir dir;
  const std::string scenario = dir.write("cut.json", kCutShot);
  expect_usage_error({"plan-shot", scenario, "--ball", "4"}, "--ball");
  expect_usage_error({"plan-shot", scenario, "--ball", "0"}, "--ball");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--pocket", "middle"}, "--pocket");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--kinds", "direct,masse"}, "--kinds");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--kinds", ","}, "--kinds");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--noise", "loud"}, "--noise");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--simulations", "10"}, "--simulations");
  expect_usage_error({"plan-shot", scenario, "--ball", "1", "--seed", "-1"}, "--seed");
  expect_usage_error({"plan-shot", scenario}, "--ball");
  expect_usage_error({"plan-shot", scenario, "--targets", "1,x"}, "--targets");
  expect_usage_error({"plan-shot", scenario, "--targets", "1,7"}, "--targets");
  expect_usage_error({"plan-shot", scenario, "--targets", "0,1"}, "--targets");
  expect_usage_error({"plan-shot", scenario, "--targets", "1,1"}, "--targets");
  expect_usage_error({"plan-shot", scenario, "--targets", ","}, "--targets");
  expect_usage_error({"plan-shot", scenario, "--targets", "1", "--ball", "1"}, "--targets");
  // The value and the allowed ids in the one line.
  const CliRun r = run_cli({"plan-shot", scenario, "--targets", "1,7"});
  EXPECT_NE(r.err.find("--targets = \"1,7\": targets[1] = 7 is not the id of a ball on the table; allowed: 0, 1, 9"),
            std::string::npos)
      << r.err;
}

TEST(CliPlanShot, TargetsPotsTheOnlyPottableLegalTargetAndSaysWhich) {
  const TempDir dir;
  // docs/example-blocked.json: with direct shots only, the 3 is the one of 1, 3, 4 that pots.
  const std::string scenario = dir.write("crowded.json", R"({
  "table": "pool_9ft",
  "balls": [
    {"id": 0, "position": [1.985, 0.281]},
    {"id": 1, "position": [1.683, 0.623]},
    {"id": 2, "position": [1.805, 0.603]},
    {"id": 3, "position": [1.586, 0.527]},
    {"id": 4, "position": [1.608, 0.677]}
  ]
})");
  const CliRun r = run_cli({"plan-shot", scenario, "--targets", "1,3,4", "--kinds", "direct", "--simulations", "1000",
                            "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["target"], 3);
  for (const auto& a : j["alternatives"]) EXPECT_EQ(a["target"], 3);
  const CliRun text = run_cli({"plan-shot", scenario, "--targets", "1,3,4", "--kinds", "direct", "--simulations", "1000"});
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(text.out.rfind("plan-shot: ball 3, direct into ", 0), 0u) << text.out;
  const CliRun none = run_cli({"plan-shot", scenario, "--targets", "1,4", "--kinds", "direct", "--simulations", "1000"});
  EXPECT_EQ(none.status, 3);
  EXPECT_NE(none.err.find("no feasible shot pots any of balls 1, 4"), std::string::npos) << none.err;
}

// --pocket called is PlanRequest::call_shot: the same strike as --pocket any
// on the library test's layout (ShotPlanner.ACallShotCountsAPotOnlyInTheShotsOwnPocket),
// estimated lower, and the plan of the library's call shot to the bit.
TEST(CliPlanShot, PocketCalledCountsAPotOnlyInTheShotsOwnPocket) {
  const TempDir dir;
  const std::string scenario = dir.write("two.json", R"({"table": "pool_9ft", "balls": [
    {"id": 0, "position": [0.9637952625759938, 0.2051678989520107]},
    {"id": 1, "position": [1.9107061147082365, 0.4468972208536196]},
    {"id": 2, "position": [0.47856410301977315, 0.8823697581870137]},
    {"id": 3, "position": [0.4788933752081283, 0.45139904709695194]},
    {"id": 4, "position": [2.339371941354914, 0.09099373819723446]}]})");
  nlohmann::json plan[2];
  const char* pockets[2] = {"any", "called"};
  for (int k = 0; k < 2; ++k) {
    const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--seed", "17", "--simulations", "1000", "--pocket",
                              pockets[k], "--json"});
    ASSERT_EQ(r.status, 0) << r.err;
    plan[k] = nlohmann::json::parse(r.out);
  }
  EXPECT_EQ(plan[0]["cue"], plan[1]["cue"]);
  EXPECT_LT(plan[1]["success_probability"].get<double>(), plan[0]["success_probability"].get<double>());
  PlanRequest q;
  q.target = 1;
  q.seed = 17;
  q.simulations = 1000;
  q.call_shot = true;
  const ShotPlanResult library = plan_shot(scenario_from_json(test::read_text(scenario)), q);
  EXPECT_EQ(plan[1]["success_probability"].get<double>(), library.shot.success_probability);
}

TEST(CliPlanShot, KindsKickAndCombinationArePlannedAndSaidInTheJson) {
  const TempDir dir;
  const std::string scenario = dir.write("walled.json", kWalled);
  // Direct and bank: every straight path of the cue ball is blocked.
  const CliRun blocked = run_cli({"plan-shot", scenario, "--ball", "1", "--simulations", "1000"});
  EXPECT_EQ(blocked.status, 3) << blocked.err;
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--kinds", "kick,combination", "--simulations",
                            "1500", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  // Both kinds planned (the wall's middle ball, in line with the 1 and the
  // top-right pocket, makes a combination that beats the kicks).
  std::vector<nlohmann::json> all{j};
  for (const auto& a : j["alternatives"]) all.push_back(a);
  bool kick = false, combination = false;
  for (const auto& a : all) {
    ASSERT_TRUE(a["kind"] == "kick" || a["kind"] == "combination") << a["kind"];
    if (a["kind"] == "kick") {
      kick = true;
      ASSERT_EQ(a["cushions"].size(), 1u);
      EXPECT_EQ(a["cushion"], a["cushions"][0]);
      EXPECT_TRUE(a["intermediate_ball"].is_null());
    } else {
      combination = true;
      EXPECT_TRUE(a["cushions"].empty());
      EXPECT_FALSE(a.contains("cushion"));
      ASSERT_TRUE(a["intermediate_ball"].is_number_integer());
      const int via = a["intermediate_ball"].get<int>();
      EXPECT_TRUE(via >= 2 && via <= 4) << via;
      EXPECT_TRUE(a.contains("combination_cut_deg"));
    }
  }
  EXPECT_TRUE(kick);
  EXPECT_TRUE(combination);
  const CliRun text = run_cli({"plan-shot", scenario, "--ball", "1", "--kinds", "kick", "--simulations", "1000"});
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("kick off the "), std::string::npos) << text.out;
}

TEST(CliPlanShot, BallOnPlaysTheTargetOnlyThroughIt) {
  const TempDir dir;
  const std::string scenario = dir.write("walled.json", kWalled);
  const CliRun free = run_cli({"plan-shot", scenario, "--ball", "1", "--kinds", "combination", "--simulations",
                               "1000", "--json"});
  ASSERT_EQ(free.status, 0) << free.err;
  const int via = nlohmann::json::parse(free.out)["intermediate_ball"].get<int>();
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1", "--kinds", "combination", "--ball-on",
                            std::to_string(via), "--simulations", "1000", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["intermediate_ball"], via);
  for (const auto& a : j["alternatives"]) EXPECT_EQ(a["intermediate_ball"], via);
  // The 1 itself the ball on: no combination may meet another ball first.
  const CliRun none = run_cli({"plan-shot", scenario, "--ball", "1", "--kinds", "combination", "--ball-on", "1"});
  EXPECT_EQ(none.status, 3) << none.err;
  const CliRun bad = run_cli({"plan-shot", scenario, "--ball", "1", "--ball-on", "42"});
  EXPECT_EQ(bad.status, 2) << bad.err;
  EXPECT_EQ(count_lines(bad.err), 1) << bad.err;
  EXPECT_NE(bad.err.find("--ball-on = 42 is not the id of a ball on the table"), std::string::npos) << bad.err;
}

TEST(CliPlanShot, AnInfeasibleLayoutExits3WithOneLine) {
  const TempDir dir;
  const std::string scenario = dir.write("boxed.json", kBoxedIn);
  const CliRun r = run_cli({"plan-shot", scenario, "--ball", "1"});
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("no feasible shot"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("blocked"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

}  // namespace
}  // namespace cueball
