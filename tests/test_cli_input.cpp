// Bad input at every door of the CLI (issue 11): exit status 2 and one line
// naming the flag or the JSON path as the user wrote it, the value and the
// allowed range; no shell; resources bounded before the work.
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include <nlohmann/json.hpp>

#include "cueball/simulation/scenario.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/table/table.hpp"
#include "temp_dir.hpp"

namespace cueball {
namespace {

using namespace test;  // the CLI tests' helpers (tests/support/)

bool gnuplot_installed() {
  for (const char* dir : {"/usr/bin/", "/usr/local/bin/", "/bin/"})
    if (::access((std::string(dir) + "gnuplot").c_str(), X_OK) == 0) return true;
  return false;
}

// ------------------------------------------------------------------ figures: no shell

TEST(CliInput, FiguresOutWithShellMetacharactersRunsNoInjectedCommand) {
  if (!gnuplot_installed()) GTEST_SKIP() << "gnuplot is not installed";
  const TempDir dir;
  const std::filesystem::path root = dir.path("");
  const std::vector<std::string> names = {
      "it's",  "say \"hi\"", "two words", "$(touch injected_dollar)", "`touch injected_backtick`",
      "x'; touch injected_quote; '", "x\"; touch injected_dq; \"",
  };
  for (const std::string& name : names) {
    const std::string out = (root / name).string();
    const CliRun r = run_cli({"figures", "--out", out, "--steps", "20", "--format", "svg"});
    ASSERT_EQ(r.status, 0) << name << ": " << r.err;
    for (const char* fig : {"fig8.svg", "fig9.svg", "fig10.svg", "fig12.svg"})
      EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(out) / fig)) << name << " " << fig;
  }
  // No file named by an injected command, in the test's directory, inside
  // the output directories or in the working directory.
  for (const char* injected : {"injected_dollar", "injected_backtick", "injected_quote", "injected_dq"}) {
    EXPECT_FALSE(std::filesystem::exists(root / injected)) << injected;
    EXPECT_FALSE(std::filesystem::exists(injected)) << injected;
    for (const std::string& name : names)
      EXPECT_FALSE(std::filesystem::exists(root / name / injected)) << name << "/" << injected;
  }
}

TEST(CliInput, FiguresOutThatCannotBeWrittenNamesOut) {
  expect_usage_error({"figures", "--out", "/proc/self", "--steps", "20"}, "--out");
  expect_usage_error({"figures", "--out", "/dev/null/figures", "--steps", "20"}, "--out");
  expect_usage_error({"figures", "--out", ""}, "--out");
  const TempDir dir;
  expect_usage_error({"figures", "--out", dir.write("a_file", "x"), "--steps", "20"}, "--out");
}

// ------------------------------------------------------------------ flags

TEST(CliInput, EmptyValuesAreErrorsForEveryNumericFlag) {
  const std::vector<std::vector<std::string>> cases = {
      {"roll", "--v0", ""},
      {"roll", "--v0", "1", "--w0", ""},
      {"roll", "--v0", "1", "--side", ""},
      {"roll", "--v0", "1", "--at", ""},
      {"roll", "--v0", "1", "--mu-s", ""},
      {"roll", "--v0", "1", "--radius", ""},
      {"plan", "--x2", ""},
      {"plan", "--x2", "1", "--v0", ""},
      {"plan", "--x2", "1", "--natural-roll", "--v2", ""},
      {"cushion", "--alpha", "45", "--v0", ""},
      {"cushion", "--v0", "1", "--alpha", ""},
      {"cushion", "--v0", "1", "--alpha", "45", "--steps", ""},
      {"cushion-sweep", "--e", ""},
      {"simulate", "--sample", ""},
      {"fit-cushion", "data.csv", "--grid-step", ""},
  };
  for (const auto& args : cases) {
    const std::string& flag = args[args.size() - 2];
    SCOPED_TRACE(args[0] + " " + flag);
    expect_usage_error(args, flag);
    const CliRun r = run_cli(args);
    EXPECT_NE(r.err.find("empty"), std::string::npos) << r.err;
  }
}

TEST(CliInput, FlagValuesWithNewlinesOrAMegabyteStayOnOneShortLine) {
  {
    const CliRun r = run_cli({"roll", "--v0", "1\n2"});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--v0"), std::string::npos) << r.err;
  }
  {
    const CliRun r = run_cli({"roll", "--v0", std::string(1 << 20, '1')});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(count_lines(r.err), 1);
    EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 400);
    EXPECT_NE(r.err.find("--v0"), std::string::npos) << r.err.substr(0, 400);
  }
  {
    const CliRun r = run_cli({"no\nsuch" + std::string(100000, 'x')});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(count_lines(r.err), 1);
    EXPECT_LT(r.err.size(), 400u);
  }
}

TEST(CliInput, LibraryErrorsAreShownAsTheFlagThatSetsThem) {
  // mu_w beyond the wedge limit with a large mu_s: the library names "mu_w", the CLI --mu-w.
  const CliRun r = run_cli({"cushion", "--v0", "1", "--alpha", "45", "--mu-w", "0.3", "--height", "0.0289"});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("cueball: error: --mu-w", 0), 0u) << r.err;
}

TEST(CliInput, PlansBeyondTheSpeedCapNameTheInput) {
  const CliRun r = run_cli({"plan", "--x2", "999", "--v2", "29", "--natural-roll"});
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--x2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("30"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

// Issue 24: 0.50000000001 was printed as 0.5, equal to its bound.
TEST(CliInput, AValueJustBeyondItsBoundIsPrintedApartFromIt) {
  const TempDir dir;
  expect_usage_error({"simulate", dir.write("side.json", R"({"balls": [{"id": 0, "position": [1, 0.6]}],
                        "cue": {"speed": 2, "side": 0.50000000001}})")},
                     "scenario.cue.side = 0.50000000001 is outside the allowed range [-0.5, 0.5]");
  expect_usage_error({"simulate", dir.write("offset.json", R"({"balls": [{"id": 0, "position": [1, 0.6]}],
                        "cue": {"speed": 2, "side": 0.4, "height": 0.30000000001}})")},
                     "tip offset = 0.0142875000001");
  expect_usage_error({"cushion", "--v0", "1", "--alpha", "30", "--e", "1.00000000001"},
                     "--e = 1.00000000001 is outside the allowed range [1e-09, 1]");
  expect_usage_error({"plan-shot", "--ball", "1", "--simulations", "4000.0000001"},
                     "--simulations = 4000.0000001 is not a whole number");
}

// Issue 24: a scenario without the cue ball was reported as "cue_ball", a name the user never wrote.
TEST(CliInput, AMissingCueBallIsNamedAsTheScenarioWritesIt) {
  const TempDir dir;
  expect_usage_error({"plan-shot", dir.write("no_cue.json", R"({"balls": [{"id": 3, "position": [1, 0.6]},
                        {"id": 4, "position": [1.5, 0.6]}]})"), "--ball", "4"},
                     "cueball: error: scenario.cue.ball = 0 (the default: no cue given) is not the id of a ball on "
                     "the table; allowed: 3, 4");
  const CliRun r = run_cli({"plan-shot", dir.write("cue_5.json", R"({"balls": [{"id": 3, "position": [1, 0.6]},
                              {"id": 4, "position": [1.5, 0.6]}], "cue": {"ball": 3, "speed": 1}})"), "--ball", "4"});
  EXPECT_EQ(r.status, 0) << r.err;  // the scenario's cue ball is the planner's
  expect_usage_error({"simulate", dir.write("cue_ball.json", R"({"balls": [{"id": 3, "position": [1, 0.6]}],
                        "cue": {"ball": 5, "speed": 1}})")},
                     "scenario.cue.ball = 5 is not a ball on the table");
}

// ------------------------------------------------------------------ scenario JSON

TEST(CliInput, ScenarioErrorsNameTheJsonPathTheUserWrote) {
  const TempDir dir;
  // Once reported as scenario.h (the cushion contact height the radius breaks).
  expect_usage_error({"simulate", dir.write("radius.json", R"({"parameters": {"radius": 0.05}})")},
                     "scenario.parameters.radius");
  {
    const CliRun r = run_cli({"simulate", dir.path("radius.json")});
    EXPECT_EQ(r.err.find("scenario.h "), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("--"), std::string::npos) << r.err;
  }
  // A jaw's contact height: once "--h" (the jaws' impact models were first built by the simulator).
  {
    nlohmann::json table = nlohmann::json::parse(table_to_json(pool_table_9ft()));
    for (auto& c : table["cushions"]) c["contact_height"] = 0.03;
    for (auto& j : table["jaws"]) j["contact_height"] = 0.04;  // within (R, 2R) of the table's ball, not of R = 0.019
    const nlohmann::json scenario = {{"table", table},
                                     {"parameters", {{"radius", 0.019}}},
                                     {"balls", {{{"id", 0}, {"position", {0.5, 0.5}}}}}};
    const std::string path = dir.write("jaw.json", scenario.dump());
    expect_usage_error({"simulate", path}, "scenario.parameters.radius: h = 0.04");
    EXPECT_EQ(run_cli({"simulate", path}).err.find("--h"), std::string::npos);
  }
  // Once scenario.mu_w: with R = 0.033 m the pool cushions' contact normal is nearly
  // horizontal, tan(theta) = 0.107.
  expect_usage_error(
      {"simulate", dir.write("friction.json", R"({"cushion": {"friction": 0.3}, "parameters": {"radius": 0.033}})")},
      "scenario.cushion.friction");
  expect_usage_error({"simulate", dir.write("excess.json", R"({"ball_collision": {"friction": 0.9, "friction_excess": 0.9}})")},
                     "scenario.ball_collision.friction_excess");
  // A ball replacing a rack's ball is named by its place in "balls", not in the merged list.
  expect_usage_error({"simulate", dir.write("rack_ball.json", R"({"rack": {"type": "nine_ball"},
                        "balls": [{"id": 3, "position": [0.3, 0.3], "velocity": [25, 25]}]})")},
                     "scenario.balls[0].velocity");
  expect_usage_error({"simulate", dir.write("name.json", R"({"balls": [{"id": 0, "position": [0.5, 0.5], "name": "a\nb"}]})")},
                     "scenario.balls[0].name");
}

TEST(CliInput, NulBytesTrailingBytesAndDuplicateKeysAreErrors) {
  const TempDir dir;
  expect_usage_error({"simulate", dir.write("nul.json", std::string("{}\0{\"tabel\": 1}", 15))}, "NUL byte");
  expect_usage_error({"simulate", dir.write("nul_in.json", std::string("{\"max_events\": 5\0}", 18))}, "NUL byte");
  expect_usage_error({"simulate", dir.write("trailing.json", "{} {}")}, "malformed JSON");
  expect_usage_error({"simulate", dir.write("trailing2.json", "{}x")}, "malformed JSON");
  expect_usage_error({"simulate", dir.write("dup.json", R"({"max_events": 5, "max_events": 6})")},
                     "scenario.max_events is given twice");
  expect_usage_error({"simulate", dir.write("dup_cue.json", R"({"cue": {"speed": 1, "speed": 2}})")},
                     "scenario.cue.speed is given twice");
  expect_usage_error({"simulate", dir.write("dup_ball.json", R"({"balls": [{"id": 0, "position": [0.5, 0.5]},
                        {"id": 1, "position": [1, 1], "position": [1, 0.5]}]})")},
                     "scenario.balls[1].position is given twice");
}

TEST(CliInput, EchoedKeysAndValuesAreQuotedAndCut) {
  const TempDir dir;
  {
    const CliRun r = run_cli({"simulate", dir.write("newline_key.json", "{\"a\\nb\": 1}")});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(R"(scenario."a\nb")"), std::string::npos) << r.err;
  }
  {
    const CliRun r = run_cli({"simulate", dir.write("long.json", "{\"table\": \"" + std::string(1 << 20, 'x') + "\"}")});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(count_lines(r.err), 1);
    EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 400);
    EXPECT_NE(r.err.find("scenario.table"), std::string::npos);
    EXPECT_NE(r.err.find("\u2026"), std::string::npos);
  }
}

TEST(CliInput, AnArrayOfManyEmptyObjectsParsesInLinearTime) {
  // 400k empty objects (1.2 MB) once took 57 s: nlohmann's callback parser
  // scans the parent array after every object.
  const TempDir dir;
  std::string text = "{\"x\": [{}";
  for (int i = 1; i < 400000; ++i) text += ",{}";
  text += "]}";
  const auto start = std::chrono::steady_clock::now();
  expect_usage_error({"simulate", dir.write("many.json", text)}, "scenario.x");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10.0);
}

// ------------------------------------------------------------------ resources

TEST(CliInput, HugeOrNeverEndingScenarioFilesAreRefusedNamingTheFile) {
  expect_usage_error({"simulate", "/dev/zero"}, "/dev/zero");
  const CliRun r = run_cli({"simulate", "/dev/zero"});
  EXPECT_NE(r.err.find("16777216"), std::string::npos) << r.err;
  const TempDir dir;
  expect_usage_error({"simulate", dir.path("")}, "is a directory");
  std::string big = "{\"balls\": [], \"x\": \"" + std::string(kMaxScenarioBytes, 'y') + "\"}";
  expect_usage_error({"simulate", dir.write("big.json", big)}, "big.json");
  expect_usage_error({"view", "/dev/zero", "-o", dir.path("v.html")}, "/dev/zero");
  expect_usage_error({"fit-cushion", "/dev/zero"}, "/dev/zero");
}

TEST(CliInput, SamplesEventsAndBallsAreBoundedNamingTheOption) {
  expect_usage_error({"simulate", "--sample", "10000"}, "--sample");
  {
    const CliRun r = run_cli({"simulate", "--sample", "10000"});
    EXPECT_NE(r.err.find("200000"), std::string::npos) << r.err;
  }
  const TempDir dir;
  expect_usage_error({"simulate", dir.write("events.json", R"({"max_events": 100000000})")}, "scenario.max_events");
  EXPECT_EQ(run_cli({"simulate", dir.write("events_ok.json", R"({"max_events": 1000000})")}).status, 0);
  std::string balls = "{\"balls\": [";
  for (int i = 0; i < 65; ++i) {
    balls += (i ? "," : "") + std::string("{\"id\": ") + std::to_string(i) + ", \"position\": [" +
             std::to_string(0.1 + 0.06 * (i % 30)) + ", " + std::to_string(0.1 + 0.06 * (i / 30)) + "]}";
  }
  balls += "]}";
  expect_usage_error({"simulate", dir.write("balls.json", balls)}, "scenario.balls has 65 balls; allowed: at most 64");
}

// ------------------------------------------------------------------ fit-cushion data

TEST(CliInput, FitCushionReadsEveryDataLine) {
  const TempDir dir;
  // A byte-order mark once made the first data line a "header" and dropped it.
  const std::string bom = dir.write("bom.csv", "\xEF\xBB\xBF" "1,0.8\n2,1.6\n3,2.4\n");
  const CliRun r = run_cli({"fit-cushion", bom, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"head_on_points\": 3"), std::string::npos) << r.out;
  // An empty first cell is an error naming the line and the cell, not a header.
  expect_usage_error({"fit-cushion", dir.write("empty_cell.csv", ",0.8\n1,0.8\n2,1.6\n3,2.4\n")}, "empty_cell.csv\":1: cell 1");
  expect_usage_error({"fit-cushion", dir.write("empty_cell2.csv", "1,0.8\n2,\n3,2.4\n")}, "empty_cell2.csv\":2: cell 2");
  // A real header is still skipped.
  EXPECT_EQ(run_cli({"fit-cushion", dir.write("header.csv", "v0,v_out\n1,0.8\n2,1.6\n3,2.4\n")}).status, 0);
}

TEST(CliInput, FitCushionNeedsEnoughMeasurements) {
  const TempDir dir;
  const std::string one = dir.write("one.csv", "1,0.8\n");
  expect_usage_error({"fit-cushion", one}, "one.csv");
  const CliRun r = run_cli({"fit-cushion", one});
  EXPECT_NE(r.err.find("at least 3"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("inf"), std::string::npos) << r.err;
  expect_usage_error({"fit-cushion", dir.write("two.csv", "1,0.8\n2,1.6\n")}, "at least 3");
  expect_usage_error({"fit-cushion", dir.write("none.csv", "v0,v_out\n")}, "at least 3");
}

}  // namespace
}  // namespace cueball
