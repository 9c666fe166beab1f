// The tracked-shots reader and the report and constants writers
// (io/tracked_shots_json.cpp): errors name the JSON path; the constants
// fragment is a scenario; the shared match reads (skipped without ../shared).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cueball/io/scenario_json.hpp"
#include "cueball/io/tracked_shots_json.hpp"
#include "cueball/simulation/scenario.hpp"
#include "expect_invalid.hpp"
#include "cueball/models/ball_collision/model.hpp"
#include "synthetic_tracks.hpp"

namespace cueball {
namespace {

using test::expect_invalid;
using Json = nlohmann::json;

Json good() {
  return Json::parse(R"({
    "what": "two balls", "units": "m, s",
    "table": "carom_10ft",
    "shots": [ { "shot_id": 17, "cue_ball": "white",
                 "balls": { "white": { "t": [0, 0.02, 0.04, 1.0], "x": [0.5, 0.56, 0.62, 1.4], "y": [0.5, 0.5, 0.5, 0.5] },
                            "red":   { "t": [0, 1.0], "x": [2.0, 2.0], "y": [0.7, 0.7] } } } ] })");
}

TEST(TrackedShotsJson, ReadsTheSharedLayout) {
  const TrackedShots s = tracked_shots_from_json(good().dump());
  EXPECT_EQ(s.table_name, "carom_10ft");
  ASSERT_EQ(s.shots.size(), 1u);
  EXPECT_EQ(s.shots[0].id, "17");
  EXPECT_EQ(s.shots[0].cue_ball, "white");
  ASSERT_EQ(s.shots[0].balls.size(), 2u);
}

TEST(TrackedShotsJson, ErrorsNameTheJsonPath) {
  const auto bad = [](const std::string& field, const std::function<void(Json&)>& edit) {
    Json j = good();
    edit(j);
    expect_invalid(field, [&] { tracked_shots_from_json(j.dump()); });
  };
  bad("table", [](Json& j) { j["table"] = "bagatelle"; });
  bad("table", [](Json& j) { j.erase("table"); });
  bad("shots", [](Json& j) { j["shots"] = Json::array(); });
  bad("extra", [](Json& j) { j["extra"] = 3; });
  bad("shots[0].cue_ball", [](Json& j) { j["shots"][0].erase("cue_ball"); });
  bad("shots[0].cue_ball", [](Json& j) { j["shots"][0]["cue_ball"] = "yellow"; });
  bad("shots[0].speed", [](Json& j) { j["shots"][0]["speed"] = 3; });
  bad("shots[0].balls.red.t", [](Json& j) { j["shots"][0]["balls"]["red"].erase("t"); });
  bad("shots[0].balls.red.x[1]", [](Json& j) { j["shots"][0]["balls"]["red"]["x"][1] = "2"; });
  bad("shots[0].balls.red.x[1]", [](Json& j) { j["shots"][0]["balls"]["red"]["x"][1] = 9.0; });
  bad("shots[0].balls.white.t[2]", [](Json& j) { j["shots"][0]["balls"]["white"]["t"][2] = 0.01; });
  bad("shots[0].balls.red.y", [](Json& j) { j["shots"][0]["balls"]["red"]["y"] = Json::array({0.7}); });
  bad("shots[0].balls.red.z", [](Json& j) { j["shots"][0]["balls"]["red"]["z"] = Json::array({0.7}); });
  bad("shots[0].shot_id", [](Json& j) { j["shots"][0]["shot_id"] = 1.5; });
  expect_invalid("shots[0].balls.red.t[1]", [] {
    tracked_shots_from_json(R"({"table": "carom_10ft", "shots": [{"cue_ball": "w", "balls": {
      "w": {"t": [0, 0.02], "x": [0.5, 0.6], "y": [0.5, 0.5]}, "red": {"t": [0, 1e999], "x": [1, 1], "y": [1, 1]}}}]})");
  });
}

TEST(TrackedShotsJson, ConstantsFragmentIsAScenario) {
  FitModel m = test::carom_model();
  m.settings.parameters.cloth.rolling_resistance = 0.0081;
  m.settings.cushion = default_cushion_settings(CushionModel::han_2005);
  m.settings.cushion.friction = 0.21;
  const std::string text = constants_to_json(m, "carom_10ft");
  const Scenario s = scenario_from_json(text);
  EXPECT_EQ(s.settings.parameters.cloth.rolling_resistance, 0.0081);
  EXPECT_EQ(s.settings.cushion.model, CushionModel::han_2005);
  EXPECT_EQ(s.settings.cushion.friction, 0.21);
  TrackedShots shots;
  shots.table_name = "carom_10ft";
  shots.table = preset_table("carom_10ft");
  const FitModel back = fit_model_from_json(text, shots);
  EXPECT_EQ(back.settings.parameters.cloth.rolling_resistance, 0.0081);
  EXPECT_EQ(back.settings.cushion.friction, 0.21);
  EXPECT_EQ(back.settings.ball_collision_model, BallCollisionModel::coulomb_impulse);
  EXPECT_EQ(back.settings.ball_collision, m.settings.ball_collision);
  // The ball-ball model the strikes were fitted under comes back with the constants.
  m.settings.ball_collision_model = BallCollisionModel::mathavan_2014;
  m.settings.ball_collision = default_ball_collision(BallCollisionModel::mathavan_2014);
  const FitModel mathavan = fit_model_from_json(constants_to_json(m, "carom_10ft"), shots);
  EXPECT_EQ(mathavan.settings.ball_collision_model, BallCollisionModel::mathavan_2014);
  EXPECT_EQ(mathavan.settings.ball_collision, m.settings.ball_collision);
  expect_invalid("scenario.parameters.mu_r",
                 [&] { fit_model_from_json(R"({"table": "carom_10ft", "parameters": {"mu_r": -1}})", shots); });
}

TEST(TrackedShotsJson, ReportHasTheDocumentedKeys) {
  const FitModel truth = test::carom_model();
  TrackedShots shots;
  shots.table_name = "carom_10ft";
  shots.table = truth.table;
  shots.shots.push_back(test::synthetic_shot(truth, test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05}),
                                             {3.0, 20.0, 3.0, 0.1, 0.1}, 0.01, 21));
  CalibrationOptions o;
  o.evaluate_only = true;
  const Json j = Json::parse(calibration_report_to_json(calibrate(shots, truth, o)));
  for (const char* key : {"table", "constants", "start_constants", "summary", "shots"}) EXPECT_TRUE(j.contains(key)) << key;
  for (const char* key : {"cue_rmse_median", "cue_rmse_p90", "cue_rmse_mean", "all_rmse_median", "contact_mismatches"})
    EXPECT_TRUE(j["summary"]["training"].contains(key)) << key;
  EXPECT_TRUE(j["summary"]["held_out"]["cue_rmse_median"].is_null());
  ASSERT_EQ(j["shots"].size(), 1u);
  EXPECT_LT(j["shots"][0]["cue_rmse"].get<double>(), 0.01);
  EXPECT_TRUE(j["shots"][0]["balls"].contains("red"));
  const Json& first = j["shots"][0]["first_contact"];
  EXPECT_TRUE(first.is_null() || first == "yellow" || first == "red") << first;
  EXPECT_EQ(j["constants"]["ball_collision"]["model"], "coulomb_impulse");
}

TEST(TrackedShotsJson, TheSharedMatchReads) {
  const std::string path = test::shared_match_path();
  if (path.empty()) GTEST_SKIP() << "../shared/data/measured-three-cushion/shots.json is not here: the match is not checked";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const TrackedShots s = tracked_shots_from_json(text.str());
  EXPECT_EQ(s.table_name, "carom_10ft");
  EXPECT_GE(s.shots.size(), 121u);
  for (std::size_t i = 0; i < s.shots.size(); ++i)
    EXPECT_NO_THROW(prepare_shot(s.shots[i], s.table, "shots[" + std::to_string(i) + "]")) << i;
}

}  // namespace
}  // namespace cueball
