// Scenario JSON and result JSON (src/simulation/scenario.cpp): self-describing results.
// A result's "scenario" read back and simulated reproduces the result bit for
// bit; events name their cushion or jaw; "cue_strike" records the strike as
// given and as resolved.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "cueball/io/scenario_json.hpp"
#include "cueball/io/result_json.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball {
namespace {

using Json = nlohmann::json;
constexpr double kDegree = std::numbers::pi / 180.0;

void expect_same_state(const BallState& a, const BallState& b, const std::string& what) {
  EXPECT_EQ(a.position.x, b.position.x) << what;
  EXPECT_EQ(a.position.y, b.position.y) << what;
  EXPECT_EQ(a.velocity.x, b.velocity.x) << what;
  EXPECT_EQ(a.velocity.y, b.velocity.y) << what;
  EXPECT_EQ(a.angular_velocity.x, b.angular_velocity.x) << what;
  EXPECT_EQ(a.angular_velocity.y, b.angular_velocity.y) << what;
  EXPECT_EQ(a.angular_velocity.z, b.angular_velocity.z) << what;
}

// Bit for bit: every event and every ball's segments, final state, pocketing.
void expect_same_result(const SimulationResult& a, const SimulationResult& b) {
  EXPECT_EQ(a.end_time, b.end_time);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].time, b.events[i].time) << "event " << i;
    EXPECT_EQ(a.events[i].type, b.events[i].type) << "event " << i;
    EXPECT_EQ(a.events[i].ball, b.events[i].ball) << "event " << i;
    EXPECT_EQ(a.events[i].other, b.events[i].other) << "event " << i;
  }
  ASSERT_EQ(a.balls.size(), b.balls.size());
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    const std::string what = "ball " + std::to_string(a.balls[i].id);
    EXPECT_EQ(a.balls[i].id, b.balls[i].id) << what;
    EXPECT_EQ(a.balls[i].name, b.balls[i].name) << what;
    EXPECT_EQ(a.balls[i].pocketed, b.balls[i].pocketed) << what;
    EXPECT_EQ(a.balls[i].pocket, b.balls[i].pocket) << what;
    EXPECT_EQ(a.balls[i].pocket_time, b.balls[i].pocket_time) << what;
    expect_same_state(a.balls[i].final_state, b.balls[i].final_state, what + " final");
    ASSERT_EQ(a.balls[i].segments.size(), b.balls[i].segments.size()) << what;
    for (std::size_t k = 0; k < a.balls[i].segments.size(); ++k) {
      EXPECT_EQ(a.balls[i].segments[k].start_time, b.balls[i].segments[k].start_time) << what;
      expect_same_state(a.balls[i].segments[k].state, b.balls[i].segments[k].state, what + " segment");
    }
  }
}

// Simulates s, reads the result's "scenario" back, simulates that: the same
// result, the same result JSON text, and the same scenario.
void expect_replays(const Scenario& s) {
  const SimulationResult r = run_scenario(s);
  const std::string text = result_to_json(s, r);
  const Json j = Json::parse(text);
  ASSERT_TRUE(j.contains("scenario"));
  const Scenario back = scenario_from_json(j.at("scenario").dump());
  EXPECT_TRUE(back.table == s.table);
  EXPECT_EQ(back.settings.parameters.ball.mass, s.settings.parameters.ball.mass);
  EXPECT_EQ(back.settings.parameters.ball.radius, s.settings.parameters.ball.radius);
  EXPECT_EQ(back.settings.parameters.cloth.sliding_friction, s.settings.parameters.cloth.sliding_friction);
  EXPECT_EQ(back.settings.parameters.cloth.rolling_resistance, s.settings.parameters.cloth.rolling_resistance);
  EXPECT_EQ(back.settings.parameters.cloth.spin_friction, s.settings.parameters.cloth.spin_friction);
  EXPECT_EQ(back.settings.parameters.cloth.gravity, s.settings.parameters.cloth.gravity);
  EXPECT_EQ(back.settings.cushion.restitution, s.settings.cushion.restitution);
  EXPECT_EQ(back.settings.cushion.friction, s.settings.cushion.friction);
  EXPECT_EQ(back.settings.ball_collision.restitution, s.settings.ball_collision.restitution);
  EXPECT_EQ(back.settings.ball_collision.friction, s.settings.ball_collision.friction);
  EXPECT_EQ(back.settings.ball_collision.friction_excess, s.settings.ball_collision.friction_excess);
  EXPECT_EQ(back.settings.ball_collision.friction_decay, s.settings.ball_collision.friction_decay);
  EXPECT_EQ(back.settings.max_events, s.settings.max_events);
  EXPECT_EQ(back.cue_parameters.mass, s.cue_parameters.mass);
  EXPECT_EQ(back.cue_parameters.tip_restitution, s.cue_parameters.tip_restitution);
  EXPECT_EQ(back.noise.speed, s.noise.speed);
  EXPECT_EQ(back.noise.aim, s.noise.aim);
  EXPECT_EQ(back.noise.side_offset, s.noise.side_offset);
  EXPECT_EQ(back.noise.height_offset, s.noise.height_offset);
  ASSERT_EQ(back.balls.size(), s.balls.size());
  for (std::size_t i = 0; i < s.balls.size(); ++i) {
    EXPECT_EQ(back.balls[i].id, s.balls[i].id);
    EXPECT_EQ(back.balls[i].name, s.balls[i].name);
    expect_same_state(back.balls[i].state, s.balls[i].state, "placed ball " + std::to_string(i));
  }
  ASSERT_EQ(back.cue.has_value(), s.cue.has_value());
  if (s.cue) {
    EXPECT_EQ(back.cue->ball, s.cue->ball);
    EXPECT_EQ(back.cue->target, s.cue->target);
    EXPECT_EQ(back.cue->strike.speed, s.cue->strike.speed);
    EXPECT_EQ(back.cue->strike.aim, s.cue->strike.aim);
    EXPECT_EQ(back.cue->strike.elevation, s.cue->strike.elevation);
    EXPECT_EQ(back.cue->strike.side_offset, s.cue->strike.side_offset);
    EXPECT_EQ(back.cue->strike.height_offset, s.cue->strike.height_offset);
  }
  const SimulationResult again = run_scenario(back);
  expect_same_result(r, again);
  EXPECT_EQ(result_to_json(back, again), text);
  // scenario_from_document takes the whole result file too.
  const SimulationResult from_document = run_scenario(scenario_from_document(text));
  expect_same_result(r, from_document);
}

// A random layout: up to 9 balls where they fit, a random strike with side,
// height and elevation (values with many digits in degrees and radii).
std::string random_layout_json(unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Table t = pool_table_9ft();
  const double r = t.ball.radius;
  std::vector<Vec2> placed;
  while (placed.size() < 9) {
    const Vec2 p{r + 0.01 + u(rng) * (t.length - 2 * r - 0.02), r + 0.01 + u(rng) * (t.width - 2 * r - 0.02)};
    bool free = ball_on_table(t, p);
    for (Vec2 q : placed) free = free && norm(p - q) > 2 * r + 1e-3;
    if (free) placed.push_back(p);
  }
  Json j;
  j["table"] = "pool_9ft";
  j["balls"] = Json::array();
  for (std::size_t i = 0; i < placed.size(); ++i)
    j["balls"].push_back({{"id", i}, {"position", {placed[i].x, placed[i].y}}});
  j["cue"] = {{"ball", 0},
              {"speed", 0.5 + 6.0 * u(rng)},
              {"aim_deg", -180.0 + 360.0 * u(rng)},
              {"elevation_deg", 20.0 * u(rng)},
              {"side", -0.35 + 0.7 * u(rng)},
              {"height", -0.35 + 0.7 * u(rng)}};
  return j.dump();
}

TEST(ScenarioReplay, DefaultBreakReplaysBitForBit) { expect_replays(default_scenario()); }

TEST(ScenarioReplay, RandomLayoutShotsReplayBitForBit) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_replays(scenario_from_json(random_layout_json(seed)));
  }
}

TEST(ScenarioReplay, CustomTableAndConstantsReplayBitForBit) {
  // The pool table's geometry as a custom table, some parts renamed, some
  // unnamed (default names), every constant away from its default.
  Json table = Json::parse(table_to_json(pool_table_9ft()));
  table["name"] = "custom pool";
  table["cushions"][0]["name"] = "my first facing";
  table["cushions"][2].erase("name");
  table["jaws"][1].erase("name");
  for (Json& c : table["cushions"]) c["contact_height"] = 0.0371;
  for (Json& c : table["jaws"]) c["contact_height"] = 0.0371;
  Json s;
  s["table"] = table;
  s["parameters"] = {{"mu_s", 0.21}, {"mu_r", 0.0123}, {"mu_sp", 0.0456}, {"g", 9.80665}, {"mass", 0.17}};
  s["cushion"] = {{"restitution", 0.91}, {"friction", 0.2}};
  s["ball_collision"] = {{"restitution", 0.93}, {"friction", 0.05}, {"friction_excess", 0.07}, {"friction_decay", 1.3}};
  s["max_events"] = 5000;
  s["rack"] = {{"type", "eight_ball"}, {"gap_sigma", 1e-4}, {"seed", 7}};
  s["cue"] = {{"target", 1}, {"speed", 8.123}, {"elevation_deg", 3.3}, {"side", 0.1}, {"height", -0.2},
              {"mass", 0.6}, {"tip_restitution", 0.8}};
  s["noise"] = {{"speed", 0.05}, {"aim_deg", 0.3}, {"elevation_deg", 0.1}, {"side", 0.01}, {"height", 0.03}};
  const Scenario sc = scenario_from_json(s.dump());
  EXPECT_EQ(sc.table.cushions[0].name, "my first facing");
  EXPECT_EQ(sc.table.cushions[2].name, "cushions[2]");
  EXPECT_EQ(sc.table.jaws[1].name, "jaws[1]");
  expect_replays(sc);
  const Json result = Json::parse(result_to_json(sc, run_scenario(sc)));
  EXPECT_EQ(result.at("scenario").at("noise").at("aim_deg").get<double>(), 0.3);
  EXPECT_EQ(result.at("scenario").at("cue").at("target").get<int>(), 1);
  EXPECT_FALSE(result.at("scenario").at("cue").contains("aim_deg"));
  EXPECT_FALSE(result.at("scenario").contains("rack"));
  EXPECT_EQ(result.at("scenario").at("balls").size(), 16u);
}

TEST(ScenarioReplay, SnookerShotReplaysBitForBit) {
  const Scenario s = scenario_from_json(R"({"table": "snooker_12ft", "rack": {"type": "snooker"},
      "cue": {"ball": 0, "target": 1, "speed": 6.5, "side": -0.15, "height": 0.25, "elevation_deg": 2.5}})");
  expect_replays(s);
}

TEST(ScenarioReplay, StrikeSetInCppReplaysBitForBitWhenItsUnitsAllow) {
  // No "given" values: the writer finds degrees and radii that convert back exactly.
  Scenario s = scenario_from_json(R"({"balls": [{"id": 0, "position": [0.6, 0.4]}, {"id": 1, "position": [1.5, 0.7]}],
      "cue": {"speed": 2}})");
  s.cue->given.reset();
  int exact = 0;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    s.cue->strike.aim = 3.0 * u(rng);
    s.cue->strike.elevation = 0.2 * (1.0 + u(rng));
    s.cue->strike.side_offset = 0.35 * s.table.ball.radius * u(rng);
    s.cue->strike.height_offset = 0.35 * s.table.ball.radius * u(rng);
    const Scenario back = scenario_from_json(scenario_to_json(s));
    const CueStrike& a = s.cue->strike;
    const CueStrike& b = back.cue->strike;
    exact += a.aim == b.aim && a.elevation == b.elevation && a.side_offset == b.side_offset &&
             a.height_offset == b.height_offset;
    EXPECT_NEAR(b.aim, a.aim, 4e-16 * std::abs(a.aim) + 1e-300);
    EXPECT_NEAR(b.side_offset, a.side_offset, 4e-16 * std::abs(a.side_offset) + 1e-300);
  }
  // "a few per cent of doubles" have no exact value in degrees or radii; a
  // strike needs all four, so most strikes (not all) replay exactly.
  EXPECT_GT(exact, 100);
  // And values that came from degrees and radii always do.
  s.cue->strike.aim = 33.3 * kDegree;
  s.cue->strike.side_offset = 0.3 * s.table.ball.radius;
  const Scenario back = scenario_from_json(scenario_to_json(s));
  EXPECT_EQ(back.cue->strike.aim, s.cue->strike.aim);
  EXPECT_EQ(back.cue->strike.side_offset, s.cue->strike.side_offset);
  expect_replays(s);
}

TEST(ScenarioReplay, ScenarioWithoutCueReplays) {
  const Scenario s = scenario_from_json(R"({"table": "carom_10ft",
      "balls": [{"id": 0, "position": [0.7, 0.5], "velocity": [1.1, 0.3], "angular_velocity": [0.5, -2, 7]},
                {"id": 3, "name": "red", "position": [1.9, 0.9]}]})");
  expect_replays(s);
  const Json j = Json::parse(result_to_json(s, run_scenario(s)));
  EXPECT_TRUE(j.at("cue_strike").is_null());
  EXPECT_EQ(j.at("cue_obstructed"), false);
  EXPECT_FALSE(cue_strike_obstructed(s));
  EXPECT_FALSE(j.at("scenario").contains("cue"));
}

TEST(ScenarioDocument, ResultWithoutAScenarioObjectIsNamed) {
  try {
    (void)scenario_from_document(R"({"events": [], "scenario": 3})");
    FAIL() << "accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "scenario");
    EXPECT_NE(std::string(e.what()).find("must be a scenario object"), std::string::npos) << e.what();
  }
  // Errors inside it name the scenario's path.
  try {
    (void)scenario_from_document(R"({"events": [], "scenario": {"cue": {"speed": -1}}})");
    FAIL() << "accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "scenario.cue.speed");
  }
  // A plain scenario is read as one.
  EXPECT_EQ(scenario_from_document(R"({"max_events": 77})").settings.max_events, 77);
}

// ------------------------------------------------------------------ result JSON

TEST(ResultJson, CueStrikeRecordsTheGivenAndTheResolvedStrike) {
  const Scenario s = default_scenario();
  const Json j = Json::parse(result_to_json(s, run_scenario(s)));
  const Json& given = j.at("cue_strike").at("given");
  EXPECT_EQ(given, j.at("scenario").at("cue"));
  EXPECT_EQ(given.at("target").get<int>(), 1);
  EXPECT_EQ(given.at("speed").get<double>(), 7.0);
  const Json& resolved = j.at("cue_strike").at("resolved");
  EXPECT_EQ(resolved.at("ball").get<int>(), 0);
  EXPECT_EQ(resolved.at("target").get<int>(), 1);
  EXPECT_EQ(resolved.at("speed").get<double>(), 7.0);
  const CueStrike k = resolved_strike(s, s.cue->strike);
  EXPECT_EQ(resolved.at("aim_rad").get<double>(), k.aim);
  EXPECT_NEAR(resolved.at("aim_deg").get<double>(), k.aim / kDegree, 1e-12);
  // The head string to the foot spot: straight along the table.
  EXPECT_NEAR(resolved.at("aim_deg").get<double>(), 0.0, 1e-9);
  for (const char* key : {"elevation_deg", "side", "height", "elevation_rad", "side_m", "height_m"})
    EXPECT_EQ(resolved.at(key).get<double>(), 0.0) << key;
  EXPECT_EQ(resolved.at("mass").get<double>(), 0.54);
  EXPECT_EQ(resolved.at("tip_restitution").get<double>(), 0.75);

  const Scenario offsets = scenario_from_json(R"({"balls": [{"id": 0, "position": [0.6, 0.4]}],
      "cue": {"speed": 2, "aim_deg": 30, "side": 0.25, "height": -0.125, "elevation_deg": 10}})");
  const Json o = Json::parse(result_to_json(offsets, run_scenario(offsets)));
  const Json& ro = o.at("cue_strike").at("resolved");
  EXPECT_TRUE(ro.at("target").is_null());
  EXPECT_NEAR(ro.at("aim_deg").get<double>(), 30.0, 1e-12);
  EXPECT_NEAR(ro.at("side").get<double>(), 0.25, 1e-15);
  EXPECT_NEAR(ro.at("height").get<double>(), -0.125, 1e-15);
  EXPECT_NEAR(ro.at("elevation_deg").get<double>(), 10.0, 1e-12);
  EXPECT_EQ(ro.at("side_m").get<double>(), 0.25 * 0.028575);
  EXPECT_EQ(o.at("cue_strike").at("given").at("aim_deg").get<double>(), 30.0);
  EXPECT_EQ(o.at("cue_strike").at("given").at("side").get<double>(), 0.25);
}

TEST(ResultJson, CushionAndJawEventsCarryTheirNames) {
  // Straight along the table into the right end cushion, back to the left one.
  const Scenario one = scenario_from_json(R"({"balls": [{"id": 0, "position": [0.5, 0.5]}], "cue": {"speed": 2}})");
  const Json j = Json::parse(result_to_json(one, run_scenario(one)));
  std::vector<std::string> hit;
  for (const Json& e : j.at("events")) {
    if (e.at("type") != "ball_cushion") continue;
    hit.push_back(e.at("cushion_name").get<std::string>());
    EXPECT_EQ(one.table.cushions.at(e.at("cushion").get<std::size_t>()).name, hit.back()) << e;
  }
  ASSERT_GE(hit.size(), 2u);
  EXPECT_EQ(hit[0], "right rail");
  EXPECT_EQ(hit[1], "left rail");
  int cushions = 0;

  // Over many random shots, every cushion and jaw event names its part by index.
  int jaws = 0;
  for (unsigned seed = 1; seed <= 30; ++seed) {
    const Scenario s = scenario_from_json(random_layout_json(seed));
    const Json r = Json::parse(result_to_json(s, run_scenario(s)));
    for (const Json& e : r.at("events")) {
      if (e.at("type") == "ball_cushion") {
        ++cushions;
        EXPECT_EQ(e.at("cushion_name"), cushion_name(s.table, e.at("cushion").get<std::size_t>())) << e;
        EXPECT_FALSE(e.contains("jaw_name")) << e;
      } else if (e.at("type") == "ball_jaw") {
        ++jaws;
        EXPECT_EQ(e.at("jaw_name"), jaw_name(s.table, e.at("jaw").get<std::size_t>())) << e;
        EXPECT_NE(e.at("jaw_name").get<std::string>().find(" jaw"), std::string::npos) << e;
      } else {
        EXPECT_FALSE(e.contains("cushion_name") || e.contains("jaw_name")) << e;
      }
    }
  }
  EXPECT_GT(cushions, 30);
  EXPECT_GT(jaws, 0);
}

// A ball right behind the cue ball on the cue's line obstructs a level cue;
// the result flags it and the shot is simulated all the same. The cue ball
// sits 1.8 m from the head rail, so a level cue along +x reaches no rail.
std::string obstruction_scenario(bool ball_behind, double elevation_deg) {
  return std::string(R"({"table": "pool_9ft", "balls": [{"id": 0, "position": [1.8, 0.635]},
      {"id": 1, "position": [2.1, 0.635]})") +
         (ball_behind ? R"(, {"id": 2, "position": [1.7, 0.635]})" : "") + R"(],
      "cue": {"ball": 0, "target": 1, "speed": 2.0, "elevation_deg": )" +
         std::to_string(elevation_deg) + "}}";
}

TEST(ScenarioResult, FlagsAnObstructedCue) {
  const Scenario blocked = scenario_from_json(obstruction_scenario(true, 0.0));
  EXPECT_TRUE(cue_strike_obstructed(blocked));
  const SimulationResult r = run_scenario(blocked);
  const Json j = Json::parse(result_to_json(blocked, r));
  EXPECT_EQ(j.at("cue_obstructed"), true);
  // Simulated all the same: the cue ball hits the 1.
  bool hit = false;
  for (const Event& e : r.events) hit = hit || (e.type == EventType::ball_ball && ((e.ball == 0 && e.other == 1) || (e.ball == 1 && e.other == 0)));
  EXPECT_TRUE(hit);

  const Scenario clear = scenario_from_json(obstruction_scenario(false, 0.0));
  EXPECT_FALSE(cue_strike_obstructed(clear));
  EXPECT_EQ(Json::parse(result_to_json(clear, run_scenario(clear))).at("cue_obstructed"), false);

  // Raised steeply enough the cue passes over the ball behind.
  const Scenario raised = scenario_from_json(obstruction_scenario(true, 60.0));
  EXPECT_FALSE(cue_strike_obstructed(raised));
  EXPECT_EQ(Json::parse(result_to_json(raised, run_scenario(raised))).at("cue_obstructed"), false);
  // Not steeply enough: still through it.
  EXPECT_TRUE(cue_strike_obstructed(scenario_from_json(obstruction_scenario(true, 10.0))));

  // The rail: a level cue from near the head rail runs below it.
  const Scenario rail = scenario_from_json(R"({"table": "pool_9ft", "balls": [{"id": 0, "position": [0.3, 0.635]},
      {"id": 1, "position": [1.0, 0.635]}], "cue": {"ball": 0, "target": 1, "speed": 2.0}})");
  EXPECT_TRUE(cue_strike_obstructed(rail));
}

TEST(ScenarioNoise, NoiseFromJsonIsTheScenariosReader) {
  const double radius = 0.028575;
  const CueStrikeNoise n = noise_from_json(R"({"speed": 0.05, "aim_deg": 0.2, "height": 0.1})", radius);
  EXPECT_EQ(n.speed, 0.05);
  EXPECT_EQ(n.aim, 0.2 * kDegree);
  EXPECT_EQ(n.elevation, 0.0);
  EXPECT_EQ(n.side_offset, 0.0);
  EXPECT_EQ(n.height_offset, 0.1 * radius);
  // The same numbers as the scenario's "noise" gives.
  const Scenario s = scenario_from_json(R"({"noise": {"speed": 0.05, "aim_deg": 0.2, "height": 0.1}})");
  EXPECT_EQ(s.noise.aim, n.aim);
  EXPECT_EQ(s.noise.height_offset, n.height_offset);
  for (const auto& [text, field] : std::vector<std::pair<std::string, std::string>>{
           {R"({"aim_deg": 50})", "noise.aim_deg"}, {R"({"loud": 1})", "noise.loud"}, {R"({"side": -0.1})", "noise.side"}}) {
    try {
      (void)noise_from_json(text, radius);
      ADD_FAILURE() << text << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field(), field) << e.what();
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  }
}

// The table a shot leaves (scenario.hpp table_after): the balls not pocketed
// at rest where they stopped, in their order, no cue; the next shot plays on it.
TEST(Scenario, TableAfterIsWhereTheBallsStopped) {
  const Scenario s = default_scenario();
  const SimulationResult r = run_scenario(s);
  const Scenario after = table_after(s, r);
  EXPECT_FALSE(after.cue);
  std::size_t k = 0;
  for (const BallTrajectory& b : r.balls) {
    if (b.pocketed) continue;
    ASSERT_LT(k, after.balls.size());
    EXPECT_EQ(after.balls[k].id, b.id);
    EXPECT_EQ(after.balls[k].state.position.x, b.final_state.position.x);
    EXPECT_EQ(after.balls[k].state.position.y, b.final_state.position.y);
    EXPECT_EQ(after.balls[k].state.velocity.x, 0.0);
    ++k;
  }
  EXPECT_EQ(k, after.balls.size());
  // A pocketed ball is left off; a ball `after` does not name is too.
  std::vector<BallAfterShot> ends = balls_after_shot(r);
  ends[1].pocketed = true;
  ends.pop_back();
  const Scenario fewer = table_after(s, ends);
  EXPECT_EQ(fewer.balls.size() + 2, s.balls.size() - static_cast<std::size_t>(std::count_if(
                                         r.balls.begin(), r.balls.end(), [](const BallTrajectory& b) { return b.pocketed; })));
  // The next shot plays on it: the cue ball struck from where it stopped.
  Scenario next = after;
  next.cue = s.cue;
  next.cue->target.reset();
  EXPECT_NO_THROW((void)run_scenario(next));
}

}  // namespace
}  // namespace cueball
