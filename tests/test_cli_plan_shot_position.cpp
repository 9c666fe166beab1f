// Tests of `cueball plan-shot --position` (cli/command_plan_shot.cpp over
// position_play.hpp): the JSON's "position" objects, the choice by score,
// the text's position lines, and bad input naming --next and
// --next-simulations.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "cli_runner.hpp"
#include "temp_dir.hpp"

namespace cueball {
namespace {

using test::CliRun;
using test::expect_usage_error;
using test::run_cli;
using test::TempDir;

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
       {"next", "cue_ball", "next_feasible", "next_success_probability", "next_kind", "next_pocket",
        "screened_probability", "score"})
    EXPECT_TRUE(p.contains(key)) << key;
  EXPECT_EQ(p["next"], 2);  // the lowest id left
  EXPECT_DOUBLE_EQ(p["score"].get<double>(),
                   p["screened_probability"].get<double>() * p["next_success_probability"].get<double>());
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
}

}  // namespace
}  // namespace cueball
