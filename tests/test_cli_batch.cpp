// End-to-end tests of `cueball batch` (the batch part of
// cli/command_simulate.cpp), run in-process: errors found in the workers exit
// with status 2 and one line naming the field for any --threads, the --shots
// bound, the reflection counts, and the table and rack errors a batch meets
// first, and the per-shot outcomes CSV of --outcomes. (The first batch tests
// live in tests/test_cli_simulate.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "temp_dir.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/table/table.hpp"

namespace cueball {
namespace {

using namespace test;  // the CLI tests' helpers (tests/support/)
using Json = nlohmann::json;


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

// ------------------------------------------------------------------ --outcomes

// docs/example-cut-shot.json with more height noise, so that some shots are miscues.
constexpr const char* kCutShot = R"({"table": "pool_9ft",
    "balls": [{"id": 0, "name": "cue", "position": [1.1, 0.7]}, {"id": 1, "name": "1", "position": [2.05, 0.95]},
              {"id": 9, "name": "9", "position": [0.8, 1.0]}],
    "cue": {"ball": 0, "aim_deg": 13.587, "speed": 2.5, "height": -0.2},
    "noise": {"speed": 0.05, "aim_deg": 0.25, "side": 0.02, "height": 0.3}})";

std::vector<std::vector<std::string>> read_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::istringstream cell(line);
    std::string c;
    while (std::getline(cell, c, ',')) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

TEST(CliBatchOutcomes, OneRowPerShotInShotOrderWithTheLibrarysValues) {
  TempDir dir;
  const std::string scenario = dir.write("cut.json", kCutShot);
  const std::string csv = dir.path("outcomes.csv");
  const CliRun r = run_cli({"batch", scenario, "--shots", "300", "--threads", "2", "--seed", "3", "--outcomes", csv});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("per-shot outcomes written to " + csv), std::string::npos) << r.out;
  const std::string text = read_text(csv);
  const auto rows = read_csv(text);
  ASSERT_EQ(rows.size(), 301u);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "shot,miscue,failure,speed_reflected,elevation_reflected,events,first_contact,"
            "pocketed_0,pocket_0,x_0,y_0,cushions_before_contact_0,cushions_0,"
            "pocketed_1,pocket_1,x_1,y_1,cushions_before_contact_1,cushions_1,"
            "pocketed_9,pocket_9,x_9,y_9,cushions_before_contact_9,cushions_9");
  // The library's outcomes of the same batch (one thread).
  std::vector<ShotOutcome> expected;
  simulate_batch(scenario_from_json(kCutShot), {300, 1, 3},
                 [&](int, const ShotOutcome& o) { expected.push_back(o); });
  ASSERT_EQ(expected.size(), 300u);
  int miscues = 0, potted = 0, contacts = 0;
  for (std::size_t k = 0; k < 300; ++k) {
    const std::vector<std::string>& row = rows[k + 1];
    const ShotOutcome& o = expected[k];
    ASSERT_EQ(row.size(), 7u + 3 * 6) << k;
    EXPECT_EQ(row[0], std::to_string(k));
    EXPECT_EQ(row[1], o.kind == ShotOutcome::Kind::miscue ? "1" : "0") << k;
    EXPECT_EQ(row[2], o.kind == ShotOutcome::Kind::failure ? "1" : "0") << k;
    EXPECT_EQ(row[3], o.speed_reflected ? "1" : "0") << k;
    EXPECT_EQ(row[4], o.elevation_reflected ? "1" : "0") << k;
    EXPECT_EQ(row[5], std::to_string(o.events)) << k;
    EXPECT_EQ(row[6], std::to_string(o.first_contact)) << k;
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t c = 7 + 6 * j;
      EXPECT_EQ(row[c], o.pocketed[j] ? "1" : "0") << k << " " << j;
      EXPECT_EQ(row[c + 1], std::to_string(o.pocket[j])) << k << " " << j;
      const double x = std::strtod(row[c + 2].c_str(), nullptr), y = std::strtod(row[c + 3].c_str(), nullptr);
      if (o.kind == ShotOutcome::Kind::simulated) {
        EXPECT_EQ(x, o.final_position[j].x) << k << " " << j;  // round trip, bit for bit
        EXPECT_EQ(y, o.final_position[j].y) << k << " " << j;
      } else {
        EXPECT_EQ(row[c + 2], "nan") << k;
        EXPECT_EQ(row[c + 3], "nan") << k;
      }
      EXPECT_EQ(row[c + 4], std::to_string(o.cushions_before_contact[j])) << k << " " << j;
      EXPECT_EQ(row[c + 5], std::to_string(o.cushions[j])) << k << " " << j;
    }
    miscues += o.kind == ShotOutcome::Kind::miscue;
    potted += o.pocketed[1];
    contacts += o.first_contact == 1;
  }
  EXPECT_GT(miscues, 10);
  EXPECT_GT(potted, 10);
  EXPECT_GT(contacts, 100);
}

TEST(CliBatchOutcomes, TheSameFileForAnyThreadsAndTheReportsProbabilities) {
  TempDir dir;
  const std::string scenario = dir.write("cut.json", kCutShot);
  const std::string one = dir.path("one.csv"), four = dir.path("four.csv");
  const Json j = batch_json({scenario, "--shots", "500", "--threads", "1", "--seed", "8", "--outcomes", one});
  ASSERT_EQ(run_cli({"batch", scenario, "--shots", "500", "--threads", "4", "--seed", "8", "--outcomes", four}).status, 0);
  const std::string text = read_text(one);
  EXPECT_EQ(text, read_text(four));
  const auto rows = read_csv(text);
  ASSERT_EQ(rows.size(), 501u);
  int simulated = 0, miscues = 0, potted = 0;
  long long events = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    miscues += rows[k][1] == "1";
    if (rows[k][1] == "1" || rows[k][2] == "1") continue;
    ++simulated;
    events += std::stoll(rows[k][5]);
    potted += rows[k][13] == "1";  // pocketed_1
  }
  EXPECT_EQ(j.at("miscues").get<int>(), miscues);
  EXPECT_EQ(j.at("simulated").get<int>(), simulated);
  EXPECT_DOUBLE_EQ(j.at("pocketed_probability").at("1").get<double>(), static_cast<double>(potted) / simulated);
  EXPECT_DOUBLE_EQ(j.at("events_per_shot").get<double>(), static_cast<double>(events) / simulated);
}

TEST(CliBatchOutcomes, AnUnwritableFileIsAUsageError) {
  TempDir dir;
  expect_usage_error({"batch", "--shots", "10", "--outcomes", dir.path("no/such/dir.csv")},
                     "--outcomes \"" + dir.path("no/such/dir.csv") + "\": cannot write the outcomes file");
}

// ------------------------------------------------------------------ many

TEST(CliMany, ActionsAndLayoutsFromCsvGiveTheLibrarysOutcomes) {
  TempDir dir;
  const std::string scenario = dir.write("cut.json", kCutShot);
  const std::string actions = dir.write("actions.csv",
                                        "speed,aim_deg,elevation_deg,side,height\n"
                                        "2.5,13.587,0,0,-0.2\n"
                                        "2.0,-90,0,0,0\n"
                                        "1.0, 90,5,0.1,0.1\r\n");
  const std::string layouts = dir.write("layouts.csv",
                                        "x_0,y_0,x_1,y_1,x_9,y_9\n"
                                        "1.1,0.7,2.05,0.95,0.8,1.0\n"
                                        "1.0,0.3,1.0,0.9,0.5,1.0\n"
                                        "1.1,0.7,2.05,0.95,0.8,1.0\n");
  const std::string one = dir.path("one.csv"), two = dir.path("two.csv");
  const CliRun r = run_cli({"many", scenario, "--actions", actions, "--layouts", layouts, "--outcomes", one, "--noise",
                            "--seed", "4", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(Json::parse(r.out).at("shots"), 3);
  ASSERT_EQ(run_cli({"many", scenario, "--actions", actions, "--layouts", layouts, "--outcomes", two, "--noise", "--seed",
                     "4", "--threads", "3"})
                .status,
            0);
  const std::string text = read_text(one);
  EXPECT_EQ(text, read_text(two));
  const auto rows = read_csv(text);
  ASSERT_EQ(rows.size(), 4u);
  const std::vector<ShotAction> a{{2.5, 13.587, 0, 0, -0.2}, {2.0, -90, 0, 0, 0}, {1.0, 90, 5, 0.1, 0.1}};
  const std::vector<double> l{1.1, 0.7, 2.05, 0.95, 0.8, 1.0, 1.0, 0.3, 1.0, 0.9, 0.5, 1.0, 1.1, 0.7, 2.05, 0.95, 0.8, 1.0};
  const ManyResult m = simulate_many(scenario_from_json(kCutShot), a, l, {1, 4, true});
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(rows[k + 1][5], std::to_string(m.events[k])) << k;
    EXPECT_EQ(rows[k + 1][6], std::to_string(m.first_contact[k])) << k;
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_EQ(std::strtod(rows[k + 1][9 + 6 * j].c_str(), nullptr), m.final_position[(k * 3 + j) * 2]) << k << j;
      EXPECT_EQ(rows[k + 1][12 + 6 * j], std::to_string(m.cushions[k * 3 + j])) << k << j;
    }
  }
  // Shot 1 went into the near rail first, then hit ball 1 (layout 1).
  EXPECT_EQ(m.first_contact[1], 1);
  EXPECT_EQ(m.cushions_before_contact[3], 1);
}

TEST(CliMany, FilesSplitWithTheirFirstShotGiveTheWholesOutcomes) {
  TempDir dir;
  const std::string scenario = dir.write("cut.json", kCutShot);
  const std::string header = "speed,aim_deg,elevation_deg,side,height\n";
  const std::string rows[] = {"2.5,13.587,0,0,-0.2\n", "2.0,-90,0,0,0\n", "1.0,90,5,0.1,0.1\n", "3.0,45,0,0.2,0\n"};
  const std::string whole = dir.write("whole.csv", header + rows[0] + rows[1] + rows[2] + rows[3]);
  const std::string first = dir.write("first.csv", header + rows[0]);
  const std::string rest = dir.write("rest.csv", header + rows[1] + rows[2] + rows[3]);
  const std::string w = dir.path("w.csv"), a = dir.path("a.csv"), b = dir.path("b.csv");
  const auto many = [&](const std::string& actions, const std::string& outcomes, const char* first_shot) {
    return run_cli({"many", scenario, "--actions", actions, "--outcomes", outcomes, "--noise", "--seed", "6",
                    "--first-shot", first_shot});
  };
  ASSERT_EQ(many(whole, w, "0").status, 0);
  ASSERT_EQ(many(first, a, "0").status, 0);
  ASSERT_EQ(many(rest, b, "1").status, 0);
  const std::string parts = read_text(a) + read_text(b).substr(read_text(b).find('\n') + 1);  // b's header dropped
  EXPECT_EQ(parts, read_text(w));
  // Unshifted, the rest draws other noise (the whole's first rows').
  const std::string c = dir.path("c.csv");
  ASSERT_EQ(many(rest, c, "0").status, 0);
  EXPECT_NE(read_csv(read_text(c))[1], read_csv(read_text(w))[2]);
  // A bad row is named in the whole study's numbering.
  const std::string bad = dir.write("bad.csv", header + rows[1] + "0,0,0,0,0\n");
  const CliRun r = many(bad, c, "10");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--actions (data row k is actions[10 + k]): actions[11].speed"), std::string::npos) << r.err;
  const CliRun negative = many(whole, c, "-1");
  EXPECT_EQ(negative.status, 2);
  EXPECT_NE(negative.err.find("--first-shot"), std::string::npos) << negative.err;
}

TEST(CliMany, EmptyLayoutCellsLeaveTheBallOffTheTableAndMiscuesAreCounted) {
  TempDir dir;
  const std::string scenario = dir.write("cut.json", kCutShot);
  // Row 1 leaves ball 1 out; row 2 asks for a tip offset of 0.57 R (a miscue).
  const std::string cut = "2.5,13.587,0,0,-0.2\n", rack = "1.1,0.7,2.05,0.95,0.8,1.0\n";
  const std::string actions =
      dir.write("actions.csv", "speed,aim_deg,elevation_deg,side,height\n" + cut + cut + "2.5,13.587,0,0.4,0.4\n");
  const std::string layouts = dir.write("layouts.csv", "x_0,y_0,x_1,y_1,x_9,y_9\n" + rack + "1.1,0.7,,,0.8,1.0\n" + rack);
  const std::string out = dir.path("out.csv");
  const CliRun r = run_cli({"many", scenario, "--actions", actions, "--layouts", layouts, "--outcomes", out, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(Json::parse(r.out).at("miscues"), 1);
  const std::vector<ShotAction> a{{2.5, 13.587, 0, 0, -0.2}, {2.5, 13.587, 0, 0, -0.2}, {2.5, 13.587, 0, 0.4, 0.4}};
  const std::vector<double> l{1.1, 0.7, 2.05, 0.95, 0.8, 1.0, 1.1, 0.7, 0, 0, 0.8, 1.0, 1.1, 0.7, 2.05, 0.95, 0.8, 1.0};
  const std::vector<std::uint8_t> present{1, 1, 1, 1, 0, 1, 1, 1, 1};
  const ManyResult m = simulate_many(scenario_from_json(kCutShot), a, l, {}, present);
  const auto rows = read_csv(read_text(out));
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(m.first_contact[0], 1);
  EXPECT_NE(m.first_contact[1], 1);  // ball 1 is not there to hit
  EXPECT_EQ(rows[2][6], std::to_string(m.first_contact[1]));
  EXPECT_EQ(rows[2][6 + 6 * 1 + 3], "nan");  // x_1 of the shot without ball 1
  EXPECT_EQ(rows[3][1], "1");                // row 2: a miscue
  // One of a ball's two cells empty is an error naming the line.
  const std::string half = dir.write("half.csv", "x_0,y_0,x_1,y_1,x_9,y_9\n1.1,0.7,2.05,,0.8,1.0\n");
  const std::string one_action = dir.write("one.csv", "speed,aim_deg,elevation_deg,side,height\n2.5,13.587,0,0,-0.2\n");
  expect_usage_error({"many", scenario, "--actions", one_action, "--layouts", half},
                     "line 2: one of x_1, y_1 is empty; leave both empty for a ball not on the table");
  const std::string no_cue = dir.write("no_cue.csv", "x_0,y_0,x_1,y_1,x_9,y_9\n,,2.05,0.95,0.8,1.0\n");
  expect_usage_error({"many", scenario, "--actions", one_action, "--layouts", no_cue},
                     "--layouts (data row k is layouts[k]): present[0][0] is false: the cue ball (id 0) must be on the table");
  // Empty action cells stay an error.
  const std::string empty_action = dir.write("e.csv", "speed,aim_deg,elevation_deg,side,height\n2.5,,0,0,0\n");
  expect_usage_error({"many", scenario, "--actions", empty_action}, "line 2, column 2: \"\" is not a number");
}

TEST(CliBatchNoise, NoNoiseAtAllIsAWarning) {
  TempDir dir;
  Json quiet = Json::parse(kCutShot);
  quiet.erase("noise");
  const std::string scenario = dir.write("quiet.json", quiet.dump());
  const CliRun batch = run_cli({"batch", scenario, "--shots", "3"});
  ASSERT_EQ(batch.status, 0) << batch.err;
  EXPECT_NE(batch.err.find("cueball: warning: the noise is zero (the scenario has no \"noise\" and no --sigma-* flag"),
            std::string::npos)
      << batch.err;
  const CliRun sigma = run_cli({"batch", scenario, "--shots", "3", "--sigma-aim", "0.1"});
  ASSERT_EQ(sigma.status, 0) << sigma.err;
  EXPECT_EQ(sigma.err.find("warning"), std::string::npos) << sigma.err;
  const std::string actions = dir.write("a.csv", "speed,aim_deg,elevation_deg,side,height\n2.5,13.587,0,0,-0.2\n");
  EXPECT_NE(run_cli({"many", scenario, "--actions", actions, "--noise"}).err.find("warning: the noise is zero"),
            std::string::npos);
  EXPECT_EQ(run_cli({"many", scenario, "--actions", actions}).err.find("warning"), std::string::npos);
}

TEST(CliMany, BadFilesAndActionsAreOneLineNamingTheRow) {
  TempDir dir;
  const std::string bad_speed = dir.write("a.csv", "speed,aim_deg,elevation_deg,side,height\n2,0,0,0,0\n0,1,0,0,0\n");
  expect_usage_error({"many", "--actions", bad_speed},
                     "--actions (data row k is actions[k]): actions[1].speed = 0 is outside the allowed range [1e-06, 12]");
  const std::string not_a_number = dir.write("b.csv", "speed,aim_deg,elevation_deg,side,height\n2,x,0,0,0\n");
  expect_usage_error({"many", "--actions", not_a_number}, "line 2, column 2: \"x\" is not a number");
  const std::string short_row = dir.write("c.csv", "speed,aim_deg,elevation_deg,side,height\n2,0,0,0\n");
  expect_usage_error({"many", "--actions", short_row}, "line 2: 4 values, expected 5");
  const std::string header = dir.write("d.csv", "speed,aim,elevation,side,height\n2,0,0,0,0\n");
  expect_usage_error({"many", "--actions", header}, "line 1: the header must be \"speed,aim_deg,elevation_deg,side,height\"");
  const std::string none = dir.write("e.csv", "speed,aim_deg,elevation_deg,side,height\n");
  expect_usage_error({"many", "--actions", none}, "0 shots; allowed [1, 1000000]");
  const std::string scenario = dir.write("two.json", R"({"balls": [{"id": 0, "position": [0.5, 0.5]}, {"id": 5, "position": [2.0, 0.5]}]})");
  const std::string actions = dir.write("f.csv", "speed,aim_deg,elevation_deg,side,height\n2,0,0,0,0\n2,0,0,0,0\n");
  const std::string overlap = dir.write("g.csv", "x_0,y_0,x_5,y_5\n0.5,0.5,2.0,0.5\n0.5,0.5,0.52,0.5\n");
  expect_usage_error({"many", scenario, "--actions", actions, "--layouts", overlap},
                     "--layouts (data row k is layouts[k]): layouts[1][1] overlaps layouts[1][0]");
  const std::string one_layout = dir.write("h.csv", "x_0,y_0,x_5,y_5\n0.5,0.5,2.0,0.5\n");
  expect_usage_error({"many", scenario, "--actions", actions, "--layouts", one_layout}, "1 layouts for 2 actions");
}

}  // namespace
}  // namespace cueball
