// End-to-end tests of `cueball simulate` and `cueball batch`
// (cli/command_simulate.cpp), run in-process: the summary, the result JSON
// (-o, --json, --sample) against the library, the one-line errors for bad
// scenarios and flags, the event limit, and batch determinism across threads.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "temp_dir.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/simulation/batch.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/table/table.hpp"

namespace cueball {
namespace {

using namespace test;  // the CLI tests' helpers (tests/support/)
using Json = nlohmann::json;

// The built-in 9-ball break, spelled out (scenario.cpp, default_scenario()).
constexpr const char* kBreak = R"({
  "table": "pool_9ft",
  "rack": { "type": "nine_ball" },
  "cue": { "ball": 0, "target": 1, "speed": 7.0 },
  "noise": { "speed": 0.1, "aim_deg": 0.2, "side": 0.02, "height": 0.02 }
})";

// One ball struck straight along the table (+x) into the far end cushion.
constexpr const char* kOneBall = R"({
  "table": "pool_9ft",
  "balls": [ { "id": 0, "name": "cue", "position": [0.5, 0.5] } ],
  "cue": { "ball": 0, "speed": 2.0, "aim_deg": 0 }
})";

// One ball sent at 45 degrees straight into the top-right corner pocket.
constexpr const char* kIntoThePocket = R"({
  "table": "pool_9ft",
  "balls": [ { "id": 0, "position": [2.2, 0.93] } ],
  "cue": { "speed": 2.0, "aim_deg": 45 }
})";

const std::set<std::string> kEventTypes = {"cue_strike", "slide_to_roll", "roll_to_spin", "roll_to_rest", "spin_stop",
                                           "ball_ball",  "ball_cushion",  "ball_jaw",     "ball_pocket"};
const std::set<std::string> kPhases = {"sliding", "rolling", "spinning", "stationary"};

void expect_vec(const Json& j, std::size_t n, const std::string& what) {
  ASSERT_TRUE(j.is_array()) << what;
  ASSERT_EQ(j.size(), n) << what;
  for (const Json& x : j) {
    ASSERT_TRUE(x.is_number()) << what;
    EXPECT_TRUE(std::isfinite(x.get<double>())) << what;
  }
}

void expect_state_keys(const Json& j, const std::string& what) {
  ASSERT_TRUE(j.contains("position")) << what;
  ASSERT_TRUE(j.contains("velocity")) << what;
  ASSERT_TRUE(j.contains("angular_velocity")) << what;
  expect_vec(j.at("position"), 2, what + ".position");
  expect_vec(j.at("velocity"), 2, what + ".velocity");
  expect_vec(j.at("angular_velocity"), 3, what + ".angular_velocity");
}

// Runs `simulate` and parses the JSON it prints.
Json simulate_json(const std::vector<std::string>& args) {
  std::vector<std::string> all{"simulate"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back("--json");
  const CliRun r = run_cli(all);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  return Json::parse(r.out);
}


// ------------------------------------------------------------------ simulate: summary

TEST(CliSimulate, BuiltInBreakSummaryCountsTheEventsAndListsTenBalls) {
  const CliRun r = run_cli({"simulate"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("built-in 9-ball break"), std::string::npos) << r.out;

  const SimulationResult expected = run_scenario(default_scenario());
  EXPECT_NE(r.out.find(std::to_string(expected.events.size()) + " events"), std::string::npos) << r.out;

  std::istringstream in(r.out);
  std::string line;
  int listed_events = 0;
  bool in_ball_table = false;
  std::vector<int> ids;
  std::map<std::string, int> counts;
  while (std::getline(in, line)) {
    if (line.rfind("  events:", 0) == 0) {
      // "  events: ball_ball 21, ball_cushion 24, cue_strike 1, ..."
      std::istringstream items(line.substr(9));
      std::string item;
      while (std::getline(items, item, ',')) {
        std::istringstream kv(item);
        std::string type;
        int n = 0;
        ASSERT_TRUE(kv >> type >> n) << line;
        EXPECT_EQ(kEventTypes.count(type), 1u) << type;
        counts[type] = n;
        listed_events += n;
      }
    } else if (line.find("ball  name") != std::string::npos) {
      in_ball_table = true;
    } else if (in_ball_table) {
      std::istringstream cols(line);
      int id = -1;
      ASSERT_TRUE(cols >> id) << line;
      ids.push_back(id);
    }
  }
  EXPECT_EQ(listed_events, static_cast<int>(expected.events.size())) << r.out;
  EXPECT_EQ(counts["cue_strike"], 1) << r.out;
  EXPECT_GT(counts["ball_ball"], 0) << r.out;
  ASSERT_EQ(ids.size(), 10u) << r.out;
  EXPECT_EQ(std::set<int>(ids.begin(), ids.end()), (std::set<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9})) << r.out;
}

// The summary must not depend on the output stream being seekable (a pipe,
// a socket, a logging streambuf): everything written must reach it.
class AppendOnlyBuf : public std::streambuf {
 public:
  std::string text;

 protected:
  int_type overflow(int_type c) override {
    if (!traits_type::eq_int_type(c, traits_type::eof())) text.push_back(traits_type::to_char_type(c));
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    text.append(s, static_cast<std::size_t>(n));
    return n;
  }
};

TEST(CliSimulate, SummaryReachesANonSeekableStream) {
  // Regression: the summary used to trim the trailing comma of the "events:"
  // line with out.seekp(-1, cur), which fails on a stream that cannot seek,
  // sets failbit and loses the rest of the summary while exiting 0.
  const char* argv[] = {"cueball", "simulate"};
  AppendOnlyBuf out_buf;
  std::ostream out(&out_buf);
  std::ostringstream err;
  const int status = cli::run(2, argv, out, err);
  EXPECT_EQ(status, 0) << err.str();
  EXPECT_TRUE(out.good()) << "the CLI left the output stream failed";
  EXPECT_NE(out_buf.text.find("ball  name"), std::string::npos) << out_buf.text;
  EXPECT_EQ(count_lines(out_buf.text), 13) << out_buf.text;  // title, events, header, 10 balls
}

// ------------------------------------------------------------------ simulate: result JSON

TEST(CliSimulate, ResultFileHasTheDocumentedStructure) {
  const TempDir dir;
  const std::string scenario = dir.write("break.json", kBreak);
  const std::string result = dir.path("result.json");
  const CliRun r = run_cli({"simulate", scenario, "-o", result});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("result written to " + result), std::string::npos) << r.out;
  ASSERT_TRUE(std::filesystem::exists(result));
  const Json j = Json::parse(read_text(result));

  ASSERT_TRUE(j.contains("table"));
  EXPECT_TRUE(j.at("table").is_object());
  const double length = j.at("table").at("length").get<double>();
  const double width = j.at("table").at("width").get<double>();
  EXPECT_NEAR(length, 100 * 0.0254, 1e-9);
  EXPECT_NEAR(width, 50 * 0.0254, 1e-9);
  ASSERT_TRUE(j.contains("parameters"));
  for (const char* key : {"mass", "radius", "mu_s", "mu_r", "mu_sp", "g", "cushion_restitution", "cushion_friction"})
    EXPECT_TRUE(j.at("parameters").at(key).is_number()) << key;
  EXPECT_DOUBLE_EQ(j.at("parameters").at("radius").get<double>(), 0.028575);
  EXPECT_EQ(j.at("parameters").at("cushion_model"), "mathavan_2010");

  // Balls.
  const Json& balls = j.at("balls");
  ASSERT_TRUE(balls.is_array());
  ASSERT_EQ(balls.size(), 10u);
  std::set<int> ids;
  std::set<int> pocketed_ids;
  for (const Json& b : balls) {
    const int id = b.at("id").get<int>();
    const std::string what = "ball " + std::to_string(id);
    EXPECT_TRUE(ids.insert(id).second) << what << " listed twice";
    ASSERT_TRUE(b.at("pocketed").is_boolean()) << what;
    expect_state_keys(b, what);
    const Json& segments = b.at("segments");
    ASSERT_TRUE(segments.is_array()) << what;
    ASSERT_FALSE(segments.empty()) << what;
    EXPECT_EQ(segments.front().at("t").get<double>(), 0.0) << what;
    double previous = 0.0;
    for (const Json& seg : segments) {
      expect_state_keys(seg, what + " segment");
      const double t = seg.at("t").get<double>();
      EXPECT_GE(t, previous) << what;
      previous = t;
      EXPECT_EQ(kPhases.count(seg.at("phase").get<std::string>()), 1u) << seg.at("phase");
    }
    if (b.at("pocketed").get<bool>()) {
      pocketed_ids.insert(id);
      EXPECT_TRUE(b.at("pocket").is_string()) << what;
      EXPECT_TRUE(b.at("pocket_time").is_number()) << what;
    } else {
      // At rest on the table at the end.
      const double x = b.at("position")[0].get<double>();
      const double y = b.at("position")[1].get<double>();
      EXPECT_GT(x, 0.0) << what;
      EXPECT_LT(x, length) << what;
      EXPECT_GT(y, 0.0) << what;
      EXPECT_LT(y, width) << what;
      EXPECT_EQ(b.at("velocity")[0].get<double>(), 0.0) << what;
      EXPECT_EQ(b.at("velocity")[1].get<double>(), 0.0) << what;
    }
  }
  EXPECT_EQ(ids, (std::set<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));

  // Events.
  const Json& events = j.at("events");
  ASSERT_TRUE(events.is_array());
  ASSERT_GT(events.size(), 10u);
  EXPECT_EQ(events.front().at("type"), "cue_strike");
  EXPECT_EQ(events.front().at("time").get<double>(), 0.0);
  EXPECT_EQ(events.front().at("balls"), Json::array({0}));
  double previous = 0.0;
  std::set<int> pocket_events;
  int ball_ball = 0;
  for (const Json& e : events) {
    const double t = e.at("time").get<double>();
    EXPECT_GE(t, previous) << e;
    previous = t;
    const std::string type = e.at("type").get<std::string>();
    EXPECT_EQ(kEventTypes.count(type), 1u) << type;
    const Json& involved = e.at("balls");
    ASSERT_TRUE(involved.is_array()) << e;
    ASSERT_EQ(involved.size(), type == "ball_ball" ? 2u : 1u) << e;
    for (const Json& id : involved) EXPECT_EQ(ids.count(id.get<int>()), 1u) << e;
    if (type == "ball_ball") {
      ++ball_ball;
      EXPECT_NE(involved[0], involved[1]) << e;
    }
    if (type == "ball_pocket") {
      EXPECT_TRUE(pocket_events.insert(involved[0].get<int>()).second) << e;
    }
  }
  EXPECT_GT(ball_ball, 0);
  EXPECT_EQ(pocket_events, pocketed_ids) << "a ball_pocket event for exactly the pocketed balls";
  EXPECT_GE(j.at("end_time").get<double>(), previous);
  EXPECT_FALSE(j.contains("samples"));
}

TEST(CliSimulate, JsonFlagPrintsWhatTheResultFileHolds) {
  const TempDir dir;
  const std::string scenario = dir.write("break.json", kBreak);
  const std::string result = dir.path("result.json");
  const CliRun both = run_cli({"simulate", scenario, "-o", result, "--json"});
  ASSERT_EQ(both.status, 0) << both.err;
  EXPECT_EQ(both.out, read_text(result));
  EXPECT_TRUE(Json::accept(both.out));

  // --json alone (no -o) prints the same, and nothing else.
  const CliRun json_only = run_cli({"simulate", scenario, "--json"});
  ASSERT_EQ(json_only.status, 0) << json_only.err;
  EXPECT_EQ(json_only.out, both.out);

  // And the scenario file equal to the built-in break gives the built-in's result.
  const CliRun builtin = run_cli({"simulate", "--json"});
  ASSERT_EQ(builtin.status, 0) << builtin.err;
  EXPECT_EQ(Json::parse(builtin.out), Json::parse(both.out));
}

TEST(CliSimulate, SampleAddsStatesAtTheRequestedRate) {
  const TempDir dir;
  const std::string scenario = dir.write("one_ball.json", kOneBall);
  const Json j = simulate_json({scenario, "--sample", "30"});
  ASSERT_TRUE(j.contains("samples"));
  const Json& samples = j.at("samples");
  EXPECT_EQ(samples.at("rate_hz").get<double>(), 30.0);
  const Json& times = samples.at("times");
  ASSERT_TRUE(times.is_array());
  ASSERT_GT(times.size(), 30u) << "a shot of several seconds";
  const double end_time = j.at("end_time").get<double>();
  EXPECT_EQ(times[0].get<double>(), 0.0);
  for (std::size_t k = 1; k < times.size(); ++k)
    EXPECT_NEAR(times[k].get<double>() - times[k - 1].get<double>(), 1.0 / 30.0, 1e-12) << k;
  EXPECT_LE(times.back().get<double>(), end_time);
  EXPECT_GT(times.back().get<double>(), end_time - 1.0 / 30.0) << "sampled up to the end";

  // Against the library's exact trajectory.
  const Scenario s = scenario_from_json(kOneBall);
  const SimulationResult r = run_scenario(s);
  const Json& per_ball = samples.at("balls");
  ASSERT_EQ(per_ball.size(), j.at("balls").size());
  ASSERT_EQ(per_ball.size(), 1u);
  const Json& ball = per_ball[0];
  EXPECT_EQ(ball.at("id").get<int>(), 0);
  ASSERT_EQ(ball.at("position").size(), times.size());
  ASSERT_EQ(ball.at("velocity").size(), times.size());
  ASSERT_EQ(ball.at("angular_velocity").size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    const BallState expected = r.state_at(0, times[k].get<double>(), s.settings.parameters);
    EXPECT_DOUBLE_EQ(ball.at("position")[k][0].get<double>(), expected.position.x) << k;
    EXPECT_DOUBLE_EQ(ball.at("position")[k][1].get<double>(), expected.position.y) << k;
    EXPECT_DOUBLE_EQ(ball.at("velocity")[k][0].get<double>(), expected.velocity.x) << k;
  }
  EXPECT_DOUBLE_EQ(ball.at("position")[0][0].get<double>(), 0.5);

  // A different rate gives a different count; the default has no samples.
  const Json j10 = simulate_json({scenario, "--sample", "10"});
  EXPECT_EQ(j10.at("samples").at("times").size(),
            static_cast<std::size_t>(std::floor(end_time * 10.0)) + 1u);
  EXPECT_FALSE(simulate_json({scenario}).contains("samples"));
}

TEST(CliSimulate, OneBallIntoACushionMatchesTheLibrary) {
  const TempDir dir;
  const std::string scenario = dir.write("one_ball.json", kOneBall);
  const Json j = simulate_json({scenario});

  const Scenario s = scenario_from_json(kOneBall);
  const SimulationResult r = run_scenario(s);
  EXPECT_DOUBLE_EQ(j.at("end_time").get<double>(), r.end_time);
  ASSERT_EQ(j.at("events").size(), r.events.size());
  int cushions = 0;
  for (std::size_t k = 0; k < r.events.size(); ++k) {
    EXPECT_EQ(j.at("events")[k].at("type"), to_string(r.events[k].type)) << k;
    EXPECT_DOUBLE_EQ(j.at("events")[k].at("time").get<double>(), r.events[k].time) << k;
    cushions += (r.events[k].type == EventType::ball_cushion);
  }
  EXPECT_GE(cushions, 1) << "the ball reaches the end cushion";

  ASSERT_EQ(j.at("balls").size(), 1u);
  const Json& b = j.at("balls")[0];
  const BallTrajectory& expected = r.balls[0];
  EXPECT_EQ(b.at("id").get<int>(), 0);
  EXPECT_EQ(b.at("name"), "cue");
  EXPECT_FALSE(b.at("pocketed").get<bool>());
  EXPECT_TRUE(b.at("pocket").is_null());
  EXPECT_DOUBLE_EQ(b.at("position")[0].get<double>(), expected.final_state.position.x);
  EXPECT_DOUBLE_EQ(b.at("position")[1].get<double>(), expected.final_state.position.y);
  EXPECT_DOUBLE_EQ(b.at("velocity")[0].get<double>(), expected.final_state.velocity.x);
  EXPECT_DOUBLE_EQ(b.at("velocity")[1].get<double>(), expected.final_state.velocity.y);
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3 w = expected.final_state.angular_velocity;
    EXPECT_DOUBLE_EQ(b.at("angular_velocity")[k].get<double>(), k == 0 ? w.x : k == 1 ? w.y : w.z) << k;
  }
  ASSERT_EQ(b.at("segments").size(), expected.segments.size());
  for (std::size_t k = 0; k < expected.segments.size(); ++k) {
    EXPECT_DOUBLE_EQ(b.at("segments")[k].at("t").get<double>(), expected.segments[k].start_time) << k;
    EXPECT_DOUBLE_EQ(b.at("segments")[k].at("position")[0].get<double>(), expected.segments[k].state.position.x) << k;
  }

  // Physically: struck at the centre with a level cue it starts sliding along
  // +x, comes back off the end cushion and stops on the same line, at rest.
  EXPECT_EQ(b.at("segments")[0].at("phase"), "sliding");
  EXPECT_GT(b.at("segments")[0].at("velocity")[0].get<double>(), 0.0);
  EXPECT_EQ(b.at("segments")[0].at("velocity")[1].get<double>(), 0.0);
  const double radius = s.settings.parameters.ball.radius;
  EXPECT_NEAR(b.at("position")[1].get<double>(), 0.5, 1e-9);
  EXPECT_GT(b.at("position")[0].get<double>(), radius);
  EXPECT_LT(b.at("position")[0].get<double>(), s.table.length - radius);
  EXPECT_EQ(b.at("velocity")[0].get<double>(), 0.0);
}

TEST(CliSimulate, PocketedBallIsReportedWithItsPocket) {
  const TempDir dir;
  const Json j = simulate_json({dir.write("pocket.json", kIntoThePocket)});
  const Json& b = j.at("balls").at(0);
  ASSERT_TRUE(b.at("pocketed").get<bool>()) << j.at("events");
  EXPECT_EQ(b.at("pocket"), "top-right");
  EXPECT_EQ(j.at("events").back().at("type"), "ball_pocket");
  EXPECT_EQ(j.at("events").back().at("pocket"), "top-right");
  EXPECT_DOUBLE_EQ(b.at("pocket_time").get<double>(), j.at("events").back().at("time").get<double>());
}

TEST(CliSimulate, ResultFlagsAnObstructedCue) {
  // Ball 2 right behind the cue ball on the cue's line; the cue ball 1.8 m
  // from the head rail, so a level cue reaches no rail.
  const auto scenario = [](const char* behind, const char* elevation) {
    return std::string(R"({"table": "pool_9ft", "balls": [{"id": 0, "position": [1.8, 0.635]},
        {"id": 1, "position": [2.1, 0.635]})") + behind + R"(], "cue": {"ball": 0, "target": 1, "speed": 2.0,
        "elevation_deg": )" + elevation + "}}";
  };
  const TempDir dir;
  const Json blocked = simulate_json({dir.write("blocked.json", scenario(R"(, {"id": 2, "position": [1.7, 0.635]})", "0"))});
  EXPECT_EQ(blocked.at("cue_obstructed"), true);
  bool hit = false;  // simulated all the same: the cue ball hits the 1
  for (const Json& e : blocked.at("events")) hit = hit || (e.at("type") == "ball_ball" && e.at("balls") == Json::array({0, 1}));
  EXPECT_TRUE(hit) << blocked.at("events");
  EXPECT_EQ(simulate_json({dir.write("clear.json", scenario("", "0"))}).at("cue_obstructed"), false);
  EXPECT_EQ(simulate_json({dir.write("raised.json", scenario(R"(, {"id": 2, "position": [1.7, 0.635]})", "60"))})
                .at("cue_obstructed"),
            false);
  // No cue: false, never missing.
  EXPECT_EQ(simulate_json({dir.write("none.json", R"({"balls": [{"id": 0, "position": [1, 0.6]}]})")}).at("cue_obstructed"),
            false);
}

// ------------------------------------------------------------------ simulate: bad input

TEST(CliSimulate, BadScenariosExitWithStatusTwoNamingTheField) {
  const TempDir dir;
  const std::string missing = dir.path("no_such_scenario.json");
  expect_usage_error({"simulate", missing}, missing);

  // Malformed JSON: the byte position of the error (the '}' after a trailing comma is byte 18).
  {
    const CliRun r = run_cli({"simulate", dir.write("comma.json", R"({"max_events": 5,})")});
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("byte 18"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
  // Over several lines, cut short: still one line on stderr; the end of
  // input is byte 53, one past the 52 bytes of the file.
  expect_usage_error({"simulate", dir.write("cut.json", "{\n \"balls\": [\n   {\"id\": 0, \"position\": [0.5, 0.5]},\n")},
                     "byte 53");
  expect_usage_error({"simulate", dir.write("empty.json", "")}, "malformed JSON");

  expect_usage_error({"simulate", dir.write("tabel.json", R"({"tabel": "pool_9ft"})")}, "scenario.tabel");
  expect_usage_error({"simulate", dir.write("cue_key.json", R"({"cue": {"spead": 2}})")}, "scenario.cue.spead");
  expect_usage_error({"simulate", dir.write("ball_key.json",
                                            R"({"balls": [{"id": 0, "position": [0.5, 0.5], "spin": [0, 0, 1]}]})")},
                     "scenario.balls[0].spin");
  expect_usage_error({"simulate", dir.write("overlap.json",
                                            R"({"balls": [{"id": 0, "position": [0.5, 0.5]},
                                                          {"id": 1, "position": [0.52, 0.5]}]})")},
                     "scenario.balls[1].position");
  expect_usage_error({"simulate", dir.write("off_table.json", R"({"balls": [{"id": 0, "position": [3.0, 0.5]}]})")},
                     "scenario.balls[0].position");
  expect_usage_error(
      {"simulate", dir.write("in_cushion.json", R"({"balls": [{"id": 0, "position": [0.5, 0.5]},
                                                             {"id": 1, "position": [1.0, 0.01]}]})")},
      "scenario.balls[1].position");
  expect_usage_error({"simulate", dir.write("inf_speed.json", R"({"cue": {"speed": 1e999}})")}, "scenario.cue.speed");
  expect_usage_error({"simulate", dir.write("inf_position.json",
                                            R"({"balls": [{"id": 0, "position": [0.5, 0.5]},
                                                          {"id": 1, "position": [1.0, 1e999]}]})")},
                     "scenario.balls[1].position[1]");
  expect_usage_error({"simulate", dir.write("miscue.json", R"({"cue": {"side": 0.7}})")}, "scenario.cue.side");
  expect_usage_error({"simulate", dir.write("miscue_h.json", R"({"cue": {"height": -0.6}})")}, "scenario.cue.height");
  expect_usage_error({"simulate", dir.write("no_target.json", R"({"cue": {"target": 42}})")}, "scenario.cue.target");

  // A bad scenario writes no result file.
  const std::string result = dir.path("result.json");
  expect_usage_error({"simulate", dir.path("tabel.json"), "-o", result}, "scenario.tabel");
  EXPECT_FALSE(std::filesystem::exists(result));
}

TEST(CliSimulate, BadFlagsExitWithStatusTwoNamingTheFlag) {
  expect_usage_error({"simulate", "--sample", "-1"}, "--sample");
  expect_usage_error({"simulate", "--sample", "nan"}, "--sample");
  expect_usage_error({"simulate", "--sample", "inf"}, "--sample");
  expect_usage_error({"simulate", "--sample", "1e9"}, "--sample");
  expect_usage_error({"simulate", "--bogus"}, "--bogus");
  const TempDir dir;
  const std::string unwritable = dir.path("no_such_dir/result.json");
  expect_usage_error({"simulate", "-o", unwritable}, unwritable);
}

TEST(CliSimulate, ScenarioErrorsNameTheJsonPathNotAFlag) {
  // Regression: cli::run() used to print every InvalidArgument as
  // flag_for_field(field) + ": " + message, turning a scenario's JSON path into
  // a made-up flag with its underscores rewritten:
  //   cueball: error: --scenario.balls[0].angular-velocity[2]: scenario.balls[0].angular_velocity[2] = ...
  const TempDir dir;
  const CliRun r = run_cli(
      {"simulate", dir.write("spin.json", R"({"balls": [{"id": 0, "position": [0.5, 0.5], "angular_velocity": [0, 0, 1e9]}]})")});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("scenario.balls[0].angular_velocity[2]"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--scenario"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("angular-velocity"), std::string::npos) << r.err;
}

TEST(CliSimulate, MalformedJsonErrorIsNotShownAsAFlag) {
  // Regression: the root path "scenario" (malformed JSON) was once printed
  // as a made-up flag, "--scenario: scenario: malformed JSON ...".
  const TempDir dir;
  const CliRun r = run_cli({"simulate", dir.write("comma.json", R"({"max_events": 5,})")});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("byte 18"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("--scenario"), std::string::npos) << r.err;
}

TEST(CliSimulate, EventLimitFailsWithStatusOne) {
  const TempDir dir;
  const std::string scenario = dir.write("limited.json", R"({
    "rack": { "type": "nine_ball" },
    "cue": { "target": 1, "speed": 7.0 },
    "max_events": 5
  })");
  const std::string result = dir.path("result.json");
  const CliRun r = run_cli({"simulate", scenario, "-o", result});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("event limit"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("5"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(std::filesystem::exists(result)) << "no partial result";

  // The same shot with the default limit runs.
  const std::string unlimited = dir.write("unlimited.json", R"({
    "rack": { "type": "nine_ball" },
    "cue": { "target": 1, "speed": 7.0 }
  })");
  EXPECT_EQ(run_cli({"simulate", unlimited}).status, 0);
}

// ------------------------------------------------------------------ batch

TEST(CliBatch, SameResultWhateverTheThreads) {
  const Json one = batch_json({"--shots", "40", "--threads", "1", "--seed", "3"});
  const Json two = batch_json({"--shots", "40", "--threads", "2", "--seed", "3"});
  for (const Json* j : {&one, &two}) {
    for (const char* key : {"shots", "seconds", "shots_per_second", "pocketed_probability", "balls"})
      EXPECT_TRUE(j->contains(key)) << key;
    EXPECT_EQ(j->at("shots").get<double>(), 40.0);
    EXPECT_GE(j->at("seconds").get<double>(), 0.0);
    EXPECT_GE(j->at("shots_per_second").get<double>(), 0.0);
    EXPECT_EQ(j->at("simulated").get<double>() + j->at("miscues").get<double>() + j->at("failures").get<double>(),
              40.0);
    const Json& p = j->at("pocketed_probability");
    ASSERT_TRUE(p.is_object());
    ASSERT_EQ(p.size(), 10u);
    for (int id = 0; id <= 9; ++id) {
      const double prob = p.at(std::to_string(id)).get<double>();
      EXPECT_GE(prob, 0.0) << id;
      EXPECT_LE(prob, 1.0) << id;
    }
    ASSERT_EQ(j->at("balls").size(), 10u);
    for (const Json& b : j->at("balls")) {
      EXPECT_EQ(b.at("pocketed_probability"), p.at(std::to_string(b.at("id").get<int>())));
      expect_vec(b.at("mean_position"), 2, "mean_position");
      expect_vec(b.at("position_std"), 2, "position_std");
    }
  }
  EXPECT_EQ(one.at("pocketed_probability"), two.at("pocketed_probability"));
  EXPECT_EQ(one.at("balls"), two.at("balls"));
  for (const char* key : {"simulated", "miscues", "failures", "events_per_shot"}) EXPECT_EQ(one.at(key), two.at(key)) << key;

  // The noise does something, and the seed matters.
  double spread = 0.0;
  for (const Json& b : one.at("balls")) spread += b.at("position_std")[0].get<double>() + b.at("position_std")[1].get<double>();
  EXPECT_GT(spread, 0.0);
  const Json other_seed = batch_json({"--shots", "40", "--threads", "2", "--seed", "4"});
  EXPECT_NE(one.at("balls"), other_seed.at("balls"));
}

TEST(CliBatch, NoNoiseRepeatsTheScenarioExactly) {
  const std::vector<std::string> no_noise{"--shots",     "6", "--threads",         "2", "--seed",       "3",
                                          "--sigma-aim", "0", "--sigma-speed",     "0", "--sigma-side", "0",
                                          "--sigma-height", "0", "--sigma-elevation", "0"};
  // The built-in break: every probability 0 or 1, the library's own outcome.
  {
    const Json j = batch_json(no_noise);
    const SimulationResult r = run_scenario(default_scenario());
    ASSERT_EQ(j.at("balls").size(), r.balls.size());
    EXPECT_EQ(j.at("simulated").get<double>(), 6.0);
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
      const Json& b = j.at("balls")[i];
      const double prob = b.at("pocketed_probability").get<double>();
      EXPECT_TRUE(prob == 0.0 || prob == 1.0) << prob;
      EXPECT_EQ(b.at("id").get<int>(), r.balls[i].id);
      EXPECT_EQ(prob, r.balls[i].pocketed ? 1.0 : 0.0) << "ball " << r.balls[i].id;
      if (!r.balls[i].pocketed) {
        EXPECT_NEAR(b.at("mean_position")[0].get<double>(), r.balls[i].final_state.position.x, 1e-12);
        EXPECT_NEAR(b.at("mean_position")[1].get<double>(), r.balls[i].final_state.position.y, 1e-12);
        EXPECT_NEAR(b.at("position_std")[0].get<double>(), 0.0, 1e-12);
        EXPECT_NEAR(b.at("position_std")[1].get<double>(), 0.0, 1e-12);
      }
    }
  }
  // A shot into a pocket, with noise in the scenario that the flags zero: probability exactly 1.
  {
    const TempDir dir;
    std::vector<std::string> args{dir.write("pocket.json", R"({
      "balls": [ { "id": 0, "position": [2.2, 0.93] } ],
      "cue": { "speed": 2.0, "aim_deg": 45 },
      "noise": { "speed": 0.5, "aim_deg": 10 }
    })")};
    args.insert(args.end(), no_noise.begin(), no_noise.end());
    const Json j = batch_json(args);
    EXPECT_EQ(j.at("pocketed_probability").at("0").get<double>(), 1.0);
    // Without the flags the scenario's own (large) noise makes it miss sometimes.
    const Json noisy = batch_json({args[0], "--shots", "40", "--seed", "3"});
    EXPECT_LT(noisy.at("pocketed_probability").at("0").get<double>(), 1.0);
  }
}

TEST(CliBatch, TextSummaryListsEveryBall) {
  const CliRun r = run_cli({"batch", "--shots", "4", "--seed", "1"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("P(pocketed)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("shots_per_second"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  cue  "), std::string::npos) << r.out;
}

TEST(CliBatch, BadInputExitsWithStatusTwoNamingTheFlag) {
  expect_usage_error({"batch", "--shots", "0"}, "--shots");
  expect_usage_error({"batch", "--shots", "-3"}, "--shots");
  expect_usage_error({"batch", "--threads", "0"}, "--threads");
  expect_usage_error({"batch", "--threads", "1000"}, "--threads");
  expect_usage_error({"batch", "--seed", "-1"}, "--seed");
  expect_usage_error({"batch", "--sigma-aim", "-1"}, "--sigma-aim");
  expect_usage_error({"batch", "--sigma-speed", "nan"}, "--sigma-speed");
  expect_usage_error({"batch", "--sigma-side", "0.9"}, "--sigma-side");
  const TempDir dir;
  expect_usage_error({"batch", dir.write("no_cue.json", R"({"balls": [{"id": 0, "position": [0.5, 0.5]}]})")}, "cue");
  expect_usage_error({"batch", dir.path("missing.json")}, dir.path("missing.json"));
  expect_usage_error({"batch", dir.write("bad.json", R"({"noise": {"aim_deg": -1}})")}, "scenario.noise.aim_deg");
}

// ------------------------------------------------------------------ simulate: replaying a result

// A result file given back to `simulate` replays its "scenario": the same
// result file byte for byte; the extracted "scenario" object does the same.
TEST(CliSimulate, ResultFileReplaysBitForBit) {
  Json custom = Json::parse(table_to_json(pool_table_9ft()));
  custom["name"] = "custom";
  custom["cushions"][5]["name"] = "renamed rail";
  for (Json& c : custom["cushions"]) c["contact_height"] = 0.0368;
  for (Json& c : custom["jaws"]) c["contact_height"] = 0.0368;
  Json custom_scenario = {{"table", custom},
                          {"parameters", {{"mu_s", 0.19}, {"mu_r", 0.011}}},
                          {"cushion", {{"restitution", 0.9}, {"friction", 0.18}}},
                          {"ball_collision", {{"restitution", 0.94}}},
                          {"rack", {{"type", "nine_ball"}, {"gap_sigma", 2e-4}, {"seed", 11}}},
                          {"cue", {{"target", 1}, {"speed", 7.77}, {"side", 0.11}, {"height", 0.23}}}};
  const std::vector<std::pair<std::string, std::string>> scenarios = {
      {"break", kBreak},
      {"layout", R"({"table": "pool_9ft", "balls": [{"id": 0, "position": [0.61234, 0.41]},
                     {"id": 1, "position": [1.37, 0.73]}, {"id": 2, "position": [1.9, 0.2]},
                     {"id": 5, "name": "five", "position": [2.2, 1.0]}],
                     "cue": {"speed": 3.71, "aim_deg": 21.987654321, "elevation_deg": 7.3, "side": -0.271, "height": 0.137}})"},
      {"custom", custom_scenario.dump()},
      {"snooker", R"({"table": "snooker_12ft", "rack": {"type": "snooker"},
                      "cue": {"target": 1, "speed": 5.5, "side": 0.2, "height": -0.1}})"}};
  const TempDir dir;
  for (const auto& [name, text] : scenarios) {
    SCOPED_TRACE(name);
    const std::string scenario = dir.write(name + ".json", text);
    const std::string first = dir.path(name + "-result.json");
    const std::string second = dir.path(name + "-replay.json");
    const std::string third = dir.path(name + "-from-scenario.json");
    CliRun r = run_cli({"simulate", scenario, "-o", first});
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli({"simulate", first, "-o", second});
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string original = read_text(first);
    EXPECT_EQ(read_text(second), original);
    const Json result = Json::parse(original);
    const std::string extracted = dir.write(name + "-scenario.json", result.at("scenario").dump(2));
    r = run_cli({"simulate", extracted, "-o", third});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read_text(third), original);
    // The events name their cushions and jaws.
    int named = 0;
    for (const Json& e : result.at("events")) {
      if (e.at("type") == "ball_cushion") named += e.at("cushion_name").is_string();
      if (e.at("type") == "ball_jaw") named += e.at("jaw_name").is_string();
    }
    EXPECT_GT(named, 0);
  }
}

TEST(CliSimulate, BadResultFileNamesTheScenarioPath) {
  const TempDir dir;
  const std::string bad = dir.write("bad-result.json", R"({"events": [], "scenario": {"cue": {"speed": 99}}})");
  const CliRun r = run_cli({"simulate", bad});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("scenario.cue.speed"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace cueball
