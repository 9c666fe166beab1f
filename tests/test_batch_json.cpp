// Noisy batches as JSON (src/io/batch_json.cpp): what `cueball batch --json`
// prints and Python's simulate_batch returns, and `cueball many --json`.
#include "cueball/io/batch_json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cueball/io/scenario_json.hpp"

namespace cueball {
namespace {

Scenario cut_shot() {
  return scenario_from_json(R"({"table": "pool_9ft",
    "balls": [{"id": 0, "position": [0.9, 0.6]}, {"id": 1, "name": "one", "position": [1.6, 0.9]}],
    "cue": {"ball": 0, "target": 1, "speed": 2.5}, "noise": {"speed": 0.05, "aim_deg": 0.5}})");
}

TEST(BatchJson, TheReportsKeysThenEachBall) {
  const Scenario s = cut_shot();
  const BatchResult r = simulate_batch(s, {200, 1, 7});
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(batch_result_to_json(s, r));
  std::vector<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"shots", "simulated", "miscues", "failures", "speed_reflected",
                                            "elevation_reflected", "seconds", "shots_per_second", "events_per_shot",
                                            "pocketed_probability", "balls"}));
  // The JSON's first keys are batch_report's, the table the CLI prints.
  const nlohmann::ordered_json report = nlohmann::ordered_json::parse(report_to_json(batch_report(r, "title")));
  for (const auto& [key, value] : report.items()) EXPECT_EQ(j[key], value) << key;
  EXPECT_EQ(j["shots"], 200);
  EXPECT_TRUE(j["simulated"].is_number_integer());
  EXPECT_EQ(j["events_per_shot"].get<double>(), static_cast<double>(r.events) / r.simulated);
  ASSERT_EQ(j["balls"].size(), 2u);
  EXPECT_EQ(j["balls"][1]["name"], "one");
  EXPECT_EQ(j["balls"][1]["pocketed_probability"].get<double>(), r.balls[1].pocketed_probability);
  EXPECT_EQ(j["pocketed_probability"]["1"].get<double>(), r.balls[1].pocketed_probability);
  EXPECT_EQ(j["balls"][0]["mean_position"], nlohmann::ordered_json::array({r.balls[0].mean_position.x, r.balls[0].mean_position.y}));
}

TEST(BatchJson, ManyCountsEachBallsPotsAndNamesTheOutcomesFile) {
  const Scenario s = cut_shot();
  const std::vector<ShotAction> actions{{2.5, 23.2, 0.0, 0.0, 0.0}, {2.5, 90.0, 0.0, 0.0, 0.0}};
  const ManyResult r = simulate_many(s, actions, {}, {});
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(many_result_to_json(r, "out.csv"));
  EXPECT_EQ(j["shots"], 2);
  EXPECT_EQ(j["simulated"], 2);
  int pots = 0;
  for (int k = 0; k < 2; ++k) pots += r.pocketed[static_cast<std::size_t>(2 * k + 1)];
  EXPECT_EQ(j["pocketed"]["1"], pots);
  EXPECT_EQ(j["outcomes"], "out.csv");
  EXPECT_FALSE(nlohmann::json::parse(many_result_to_json(r)).contains("outcomes"));
}

}  // namespace
}  // namespace cueball
