// The cushion commands' JSON (src/io/cushion_json.cpp): a report with the
// impact's history, a sweep's rows or history, the figures' files.
#include "cueball/io/cushion_json.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include <nlohmann/json.hpp>

namespace cueball {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

TEST(CushionJson, TheReportThenTheHistory) {
  Report report("cushion");
  report.add("speed", 1.5, "m/s");
  report.warn("fast");
  CushionImpactSample sample;
  sample.normal_impulse = 0.25;
  sample.cushion_slip_angle = 30.0 * kDegree;
  sample.velocity = {1.0, -2.0, 0.0};
  const std::vector<CushionImpactSample> history{sample};
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(cushion_report_to_json(report, &history));
  std::vector<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.push_back(key);
  EXPECT_EQ(keys, (std::vector<std::string>{"speed", "warnings", "history"}));
  EXPECT_EQ(j["history"][0]["P"], 0.25);
  EXPECT_NEAR(j["history"][0]["phi"].get<double>(), 30.0, 1e-12);
  EXPECT_EQ(j["history"][0]["v"], nlohmann::ordered_json::array({1.0, -2.0, 0.0}));
  EXPECT_EQ(cushion_report_to_json(report), report_to_json(report));
}

TEST(CushionJson, SweepRowsAreTheCsvsColumns) {
  const double radius = 0.02625;
  const CushionSweepRow row{{2.0, 45.0 * kDegree, 2.0 / radius, -1.0 / radius}, 1.25, 0.0};
  const nlohmann::ordered_json j =
      nlohmann::ordered_json::parse(cushion_sweep_to_json({"fig9", "mathavan_2010", "exact", "snooker"}, {row}, radius));
  EXPECT_EQ(j.dump(), nlohmann::ordered_json::parse(R"({"family": "fig9", "model": "mathavan_2010", "solver": "exact",
    "preset": "snooker", "rows": [{"v0": 2.0, "alpha_deg": 45.0, "topspin_k": 1.0, "sidespin_k": -0.5,
    "speed": 1.25, "angle_deg": 0.0}]})").dump());
  // A model without a solver has no "solver"; fig12 has the history instead of rows.
  const nlohmann::json other = nlohmann::json::parse(cushion_sweep_to_json({"fig8", "han_2005", "", "pool"}, {}, radius));
  EXPECT_FALSE(other.contains("solver"));
  EXPECT_EQ(other["rows"], nlohmann::json::array());
  const nlohmann::json fig12 =
      nlohmann::json::parse(cushion_sweep_history_to_json({"fig12", "mathavan_2010", "paper", "snooker"}, {{}, {}}));
  EXPECT_EQ(fig12["history"].size(), 2u);
  EXPECT_FALSE(fig12.contains("rows"));
}

TEST(CushionJson, FiguresListTheirFiles) {
  EXPECT_EQ(nlohmann::ordered_json::parse(figures_to_json("out", "svg", {"out/fig8.svg", "out/fig9.svg"})).dump(),
            R"({"out":"out","format":"svg","files":["out/fig8.svg","out/fig9.svg"]})");
}

}  // namespace
}  // namespace cueball
