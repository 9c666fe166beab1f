// End-to-end tests of `cueball batch` (the batch part of
// cli/command_simulate.cpp), run in-process: errors found in the workers exit
// with status 2 and one line naming the field for any --threads, the --shots
// bound, the reflection counts, and the table and rack errors a batch meets
// first. (The first batch tests live in tests/test_cli_simulate.cpp.)
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "temp_dir.hpp"
#include "cueball/table.hpp"

namespace cueball {
namespace {

using test::CliRun;
using test::count_lines;
using test::expect_usage_error;
using test::run_cli;
using test::TempDir;
using Json = nlohmann::json;

Json batch_json(const std::vector<std::string>& args) {
  std::vector<std::string> all{"batch"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("--json");
  const CliRun r = run_cli(all);
  EXPECT_EQ(r.status, 0) << r.err;
  return Json::parse(r.out);
}

// The 9-ball break on the pool table written out in full, with jaws[0]
// raised to a height valid for the table's ball but not for the smaller
// ball the parameters give: an error found only when a shot runs.
std::string jaw_too_high_for_the_ball() {
  Json table = Json::parse(table_to_json(pool_table_9ft()));
  table["jaws"][0]["contact_height"] = 0.056;  // (R, 2R) = (0.028575, 0.05715) for the table's ball
  const Json s{{"table", table},
               {"parameters", {{"radius", 0.0275}}},  // 2R = 0.055
               {"rack", {{"type", "nine_ball"}}},
               {"cue", {{"ball", 0}, {"target", 1}, {"speed", 7.0}}},
               {"noise", {{"speed", 0.1}}}};
  return s.dump();
}

TEST(CliBatchErrors, AnErrorInAWorkerExitsWithStatusTwoLikeTheSingleShot) {
  TempDir dir;
  const std::string path = dir.write("jaw.json", jaw_too_high_for_the_ball());
  const CliRun single = run_cli({"simulate", path});
  ASSERT_EQ(single.status, 2) << single.err;
  for (const char* threads : {"1", "2", "4"}) {
    const CliRun r = run_cli({"batch", path, "--shots", "300", "--threads", threads});
    EXPECT_EQ(r.status, 2) << threads << " threads: " << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_EQ(r.err, single.err) << threads << " threads";
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(CliBatchErrors, ShotsAreBoundedAndNamed) {
  expect_usage_error({"batch", "--shots", "1e9"}, "--shots = 1000000000 is outside the allowed range [1, 100000000]");
  expect_usage_error({"batch", "--shots", "1e20"}, "--shots");
  expect_usage_error({"batch", "--shots", "2.5"}, "--shots = 2.5 is not a whole number");
  expect_usage_error({"batch", "--shots", "nan"}, "--shots");
  EXPECT_EQ(batch_json({"--shots", "1e1", "--seed", "2"}).at("shots"), 10);
}

TEST(CliBatchErrors, AnOpenTableNamesTheCushionByItsJsonPath) {
  // shared/repro/open_table_internal_error.json: the pool table's facings
  // and jaws without the noses between the pockets.
  Table t = pool_table_9ft();
  std::vector<CushionSegment> facings;
  for (std::size_t i = 0; i < t.cushions.size(); ++i)
    if (i % 3 != 2) facings.push_back(t.cushions[i]);
  t.cushions = facings;
  const Json s{{"table", Json::parse(table_to_json(t))},
               {"balls", {{{"id", 0}, {"position", {0.6, 0.6}}}}},
               {"cue", {{"ball", 0}, {"aim_deg", 90}, {"speed", 3}}}};
  TempDir dir;
  const std::string path = dir.write("open.json", s.dump());
  expect_usage_error({"batch", path, "--threads", "2"}, "scenario.table.cushions[1].end = (");
}

TEST(CliBatchErrors, ARackTooBigForTheTableNamesTheRack) {
  TempDir dir;
  const std::string path = dir.write(
      "small.json",
      R"({"table": {"preset": "carom_10ft", "length": 0.4, "width": 0.2}, "rack": {"type": "eight_ball"},
          "cue": {"ball": 0, "target": 1, "speed": 3}})");
  expect_usage_error({"batch", path}, "rack: the eight_ball rack does not fit");
  expect_usage_error({"batch", path}, "needs length >= ");
}

TEST(CliBatchNoise, ReflectedStrikesAreCountedAndEveryShotIsSimulated) {
  TempDir dir;
  const std::string at_the_cap = dir.write("cap.json", R"({"rack": {"type": "nine_ball"},
      "cue": {"ball": 0, "target": 1, "speed": 12}, "noise": {"speed": 0.3, "elevation_deg": 1}})");
  const Json j = batch_json({at_the_cap, "--shots", "64", "--threads", "2", "--seed", "4"});
  EXPECT_EQ(j.at("miscues"), 0);
  EXPECT_EQ(j.at("simulated").get<int>() + j.at("failures").get<int>(), 64);
  EXPECT_GT(j.at("speed_reflected").get<int>(), 16);
  EXPECT_LT(j.at("speed_reflected").get<int>(), 48);
  EXPECT_GT(j.at("elevation_reflected").get<int>(), 16);
  EXPECT_LT(j.at("elevation_reflected").get<int>(), 48);
  const CliRun text = run_cli({"batch", at_the_cap, "--shots", "8"});
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("speed_reflected"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("elevation_reflected"), std::string::npos) << text.out;
  // Beyond the miscue limit: counted as miscues, the rest simulated.
  const Json miscues = batch_json({"--shots", "64", "--sigma-height", "0.5", "--seed", "4"});
  EXPECT_GT(miscues.at("miscues").get<int>(), 5);
  EXPECT_EQ(miscues.at("simulated").get<int>() + miscues.at("miscues").get<int>() + miscues.at("failures").get<int>(),
            64);
  EXPECT_EQ(miscues.at("speed_reflected"), 0);
}

}  // namespace
}  // namespace cueball
