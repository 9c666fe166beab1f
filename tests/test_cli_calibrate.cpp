// End-to-end tests of `cueball calibrate` (cli/command_calibrate.cpp), run
// in-process: a calibration of synthetic tracked shots (report, --json, -o
// written as a scenario fragment that `simulate` accepts, --constants
// --evaluate), and the one-line errors (exit 2) naming the flag or the JSON
// path, the value and the allowed range.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cueball/io/tracked_shots_json.hpp"
#include "cueball/models/ball_collision/model.hpp"
#include "synthetic_tracks.hpp"
#include "temp_dir.hpp"
#include "test_scale.hpp"

namespace cueball {
namespace {

using Json = nlohmann::json;
using test::expect_usage_error;
using test::run_cli;
using test::TempDir;

// Synthetic shots made under `m` as a tracked-shots file (ids from seed + 1).
std::string shots_file(const FitModel& m, const std::vector<ShotAction>& actions, std::uint64_t seed) {
  Json shots = Json::array();
  for (const ShotAction& a : actions) {
    const TrackedShot s = test::synthetic_shot(m, test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05}), a, 0.01, seed++);
    Json balls = Json::object();
    for (const TrackedBall& b : s.balls) balls[b.name] = {{"t", b.t}, {"x", b.x}, {"y", b.y}};
    shots.push_back({{"shot_id", seed}, {"cue_ball", s.cue_ball}, {"balls", balls}});
  }
  return Json{{"what", "synthetic"}, {"table", "carom_10ft"}, {"shots", shots}}.dump();
}

// Three synthetic shots as a tracked-shots file.
std::string synthetic_file() {
  return shots_file(test::carom_model(),
                    {{3.2, 25.0, 4.0, 0.2, 0.15}, {2.6, 4.0, 6.0, -0.25, -0.2}, {3.0, -20.0, 3.0, 0.1, 0.0}}, 31);
}

// Shots made under mathavan_2014's ball-ball contact (cut shots, where the
// models part) are fitted better under that model, which
// --ball-collision-model chooses and -o writes with the constants.
TEST(CliCalibrate, TheBallCollisionModelIsChosenAndWritten) {
  FitModel m = test::carom_model();
  m.settings.ball_collision_model = BallCollisionModel::mathavan_2014;
  m.settings.ball_collision = default_ball_collision(BallCollisionModel::mathavan_2014);
  TempDir dir;
  const std::string file = dir.write("shots.json", shots_file(m, {{3.0, 18.0, 2.0, 0.3, -0.3}, {2.5, 27.0, 2.0, -0.3, 0.3}}, 51));
  const std::string constants = dir.write("constants.json", constants_to_json(test::carom_model(), "carom_10ft"));
  const std::string out = dir.path("out.json");
  const auto coulomb = run_cli({"calibrate", file, "--constants", constants, "--evaluate", "--json"});
  const auto mathavan = run_cli({"calibrate", file, "--constants", constants, "--evaluate", "--json",
                                 "--ball-collision-model", "mathavan_2014", "-o", out});
  ASSERT_EQ(coulomb.status, 0) << coulomb.err;
  ASSERT_EQ(mathavan.status, 0) << mathavan.err;
  const double under_coulomb = Json::parse(coulomb.out)["summary"]["training"]["all_rmse_median"].get<double>();
  const double under_mathavan = Json::parse(mathavan.out)["summary"]["training"]["all_rmse_median"].get<double>();
  EXPECT_LT(under_mathavan, 2e-3);  // the noise and the layout read from it (0.5 mm)
  EXPECT_LT(under_mathavan, 0.5 * under_coulomb) << under_mathavan << " m against " << under_coulomb << " m";  // 5 mm
  EXPECT_EQ(Json::parse(test::read_text(out))["ball_collision"]["model"], "mathavan_2014");
}

TEST(CliCalibrate, CalibratesAndWritesAScenarioFragment) {
  TempDir dir;
  const std::string file = dir.write("shots.json", synthetic_file());
  const std::string out = dir.path("constants.json");
  // Under the sanitizers each strike fit from 8 starts, not the default 32
  // (the same paths: test_scale.hpp; 58 s of the asan run with 32).
  const std::string starts = std::to_string(test::scaled(32, 8));
  const auto r = run_cli({"calibrate", file, "--held-out", "0.34", "--seed", "2", "--max-evaluations", "20",
                          "--max-iterations", "1", "--starts", starts, "-o", out, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["summary"]["held_out"]["shots"], 1);
  EXPECT_EQ(j["summary"]["training"]["shots"], 2);
  EXPECT_EQ(j["shots"].size(), 3u);
  // The fragment: a scenario simulate accepts, with a shot added to it.
  Json scenario = Json::parse(test::read_text(out));
  EXPECT_EQ(scenario["table"], "carom_10ft");
  EXPECT_TRUE(scenario["parameters"].contains("mu_r"));
  scenario["balls"] = Json::array({{{"id", 0}, {"position", {0.7, 0.5}}}});
  scenario["cue"] = {{"speed", 2.0}, {"aim_deg", 10.0}};
  const std::string shot = dir.write("shot.json", scenario.dump());
  const auto sim = run_cli({"simulate", shot});
  EXPECT_EQ(sim.status, 0) << sim.err;
  // --constants --evaluate: the strikes only, under those constants; the text summary.
  const auto ev = run_cli({"calibrate", file, "--constants", out, "--evaluate", "--starts", starts});
  ASSERT_EQ(ev.status, 0) << ev.err;
  EXPECT_NE(ev.out.find("cue_rmse_median"), std::string::npos) << ev.out;
}

// The synthetic shots as CSV files, one a shot (ball,t,x,y).
std::vector<std::string> synthetic_csv(const TempDir& dir) {
  const Json j = Json::parse(synthetic_file());
  std::vector<std::string> files;
  for (const Json& shot : j["shots"]) {
    std::string text = "ball,t,x,y\n";
    for (const auto& [name, b] : shot["balls"].items())
      for (std::size_t k = 0; k < b["t"].size(); ++k)
        text += name + "," + b["t"][k].dump() + "," + b["x"][k].dump() + "," + b["y"][k].dump() + "\n";
    files.push_back(dir.write(shot["shot_id"].dump() + ".csv", text));
  }
  return files;
}

TEST(CliCalibrate, ReadsCsvShotsAndWritesTheHtmlReport) {
  TempDir dir;
  const std::vector<std::string> csv = synthetic_csv(dir);
  const std::string html = dir.path("report.html");
  std::vector<std::string> args{"calibrate"};
  args.insert(args.end(), csv.begin(), csv.end());
  for (const char* a : {"--table", "carom_10ft", "--held-out", "0.34", "--max-evaluations", "6", "--max-iterations", "0",
                        "--restarts", "1", "--bootstrap", "2", "--bootstrap-evaluations", "4", "--starts", "4", "--json",
                        "--html"})
    args.emplace_back(a);
  args.push_back(html);
  const auto r = run_cli(args);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  ASSERT_EQ(j["shots"].size(), 3u);
  EXPECT_EQ(j["shots"][0]["id"], "32");  // the file's name
  EXPECT_EQ(j["uncertainty"]["replicates"], 2);
  EXPECT_TRUE(j["uncertainty"]["constants"]["mu_r"]["std_dev"].is_number());
  EXPECT_LE(j["uncertainty"]["constants"]["mu_r"]["p05"].get<double>(), j["uncertainty"]["constants"]["mu_r"]["p95"].get<double>());
  const std::string page = test::read_text(html);
  EXPECT_NE(page.find("<figure"), std::string::npos);
  EXPECT_NE(page.find("id=\"shot-33\""), std::string::npos);
  EXPECT_NE(page.find("std. dev."), std::string::npos);
  // The text report shows the spread beside each constant.
  args = {"calibrate", csv[0], csv[1], "--table", "carom_10ft", "--held-out", "0", "--max-evaluations", "3",
          "--max-iterations", "0", "--restarts", "0", "--bootstrap", "2", "--bootstrap-evaluations", "3", "--starts", "2"};
  const auto text = run_cli(args);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("+- "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("5-95 %"), std::string::npos) << text.out;
}

TEST(CliCalibrate, BadCsvInputIsOneLineNamingFileRowAndColumn) {
  TempDir dir;
  const std::vector<std::string> csv = synthetic_csv(dir);
  expect_usage_error({"calibrate", csv[0]}, "--table is needed with CSV shots");
  expect_usage_error({"calibrate", csv[0], "--table", "carom_10ft", "--bootstrap", "-1"}, "--bootstrap = -1");
  expect_usage_error({"calibrate", csv[0], "--table", "carom_10ft", "--restarts", "20"}, "--restarts = 20");
  expect_usage_error({"calibrate", csv[0], "--table", "carom_10ft", "--spin-profile", "17"}, "--spin-profile = 17");
  const std::string bad = dir.write("bad.csv", "ball,t,x,y\nwhite,0,0.7,0.5\nwhite,0.02,0.7q,0.5\n");
  expect_usage_error({"calibrate", csv[0], bad, "--table", "carom_10ft"}, "bad.csv\": row 3, column x: \"0.7q\" is not a finite number");
  const std::string json = dir.write("shots.json", synthetic_file());
  expect_usage_error({"calibrate", json, "--table", "carom_10ft"}, "--table and --cue-ball are for CSV shots");
  expect_usage_error({"calibrate", csv[0], json, "--table", "carom_10ft"}, "is not a .csv file");
}

TEST(CliCalibrate, BadInputIsOneLineNamingTheFieldAndExitsTwo) {
  TempDir dir;
  const std::string file = dir.write("shots.json", synthetic_file());
  expect_usage_error({"calibrate", file, "--held-out", "0.95"}, "--held-out = 0.95");
  expect_usage_error({"calibrate", file, "--threads", "0"}, "--threads");
  expect_usage_error({"calibrate", file, "--starts", "100"}, "--starts");
  expect_usage_error({"calibrate", file, "--evaluate"}, "--constants");
  expect_usage_error({"calibrate", file, "--cushion-model", "rubber"}, "--cushion-model");
  expect_usage_error({"calibrate", file, "--ball-collision-model", "glue"}, "--ball-collision-model");
  expect_usage_error({"calibrate", dir.path("missing.json")}, "missing.json");
  Json j = Json::parse(synthetic_file());
  j["shots"][1]["balls"]["red"]["x"][0] = 7.5;
  expect_usage_error({"calibrate", dir.write("bad1.json", j.dump())}, "shots[1].balls.red.x[0] = 7.5");
  j = Json::parse(synthetic_file());
  j["shots"][2]["balls"]["white"]["t"][3] = -1.0;
  expect_usage_error({"calibrate", dir.write("bad2.json", j.dump())}, "shots[2].balls.white.t[3]");
  j = Json::parse(synthetic_file());
  j["shots"][0]["cue_ball"] = "blue";
  expect_usage_error({"calibrate", dir.write("bad3.json", j.dump())}, "shots[0].cue_ball");
  const std::string constants = dir.write("c.json", R"({"table": "carom_10ft", "parameters": {"mu_r": 2}})");
  expect_usage_error({"calibrate", file, "--constants", constants, "--evaluate"}, "scenario.parameters.mu_r = 2");
}

}  // namespace
}  // namespace cueball
