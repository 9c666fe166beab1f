// Tests of the event-driven table simulator (src/simulation/simulator.cpp) and of
// scenarios (src/simulation/scenario.cpp): the guarantees of issue 4, each checked on the
// exact trajectories the result carries.
#include "cueball/io/scenario_json.hpp"
#include "cueball/io/result_json.hpp"
#include "cueball/simulation/simulator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <thread>

#include "cueball/simulation/batch.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/table/rack.hpp"
#include "cueball/simulation/scenario.hpp"
#include "simulation_checks.hpp"

namespace cueball {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double total_kinetic_energy(const SimulationResult& r, double t, const Parameters& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    if (r.balls[i].pocketed && t >= r.balls[i].pocket_time) continue;
    e += kinetic_energy(r.state_at(i, t, p), p.ball);
  }
  return e;
}

// Checks, at every event time, that no two balls overlap and no ball is
// inside a cushion or a jaw by more than 1e-9 m; and that the total kinetic
// energy never increases from one event to the next.
void expect_physical_at_every_event(const Table& table, const SimulationResult& r, const Parameters& p) {
  ASSERT_LE(deepest_penetration(table, r, p, 1), 1e-9) << "an overlap, or a ball inside a cushion or jaw";
  double previous_energy = std::numeric_limits<double>::infinity();
  for (const Event& e : r.events) {
    const double t = e.time;
    const double energy = total_kinetic_energy(r, t, p);
    ASSERT_LE(energy, previous_energy * (1 + 1e-12) + 1e-15) << "energy rose at t = " << t << " (" << to_string(e.type) << ")";
    previous_energy = energy;
  }
}

std::string break_json(double speed, double aim_offset_deg, double side, double height, int seed) {
  char json[512];
  std::snprintf(json, sizeof json,
                R"({"table": "pool_9ft", "rack": {"type": "nine_ball", "gap_sigma": 0.0003, "seed": %d},
                    "cue": {"ball": 0, "target": 1, "speed": %.6f, "side": %.4f, "height": %.4f}})",
                seed, speed, side, height);
  Scenario s = scenario_from_json(json);
  s.cue->strike.aim += aim_offset_deg * kDeg;
  (void)s;
  return json;
}

// A moderate count here; the large run is the same test with, e.g.,
// CUEBALL_STRESS_SHOTS=5000 (see README).
int stress_shots() {
  const char* env = std::getenv("CUEBALL_STRESS_SHOTS");
  return env ? std::max(1, std::atoi(env)) : 200;
}

TEST(Simulator, SettingsDefaultToThePoolPreset) {
  // One default everywhere (README "Units and defaults"): the pool preset.
  const SimulationSettings s;
  const Parameters pool = pool_parameters();
  EXPECT_EQ(s.parameters.ball.mass, pool.ball.mass);
  EXPECT_EQ(s.parameters.ball.radius, pool.ball.radius);
  EXPECT_EQ(s.parameters.cloth.sliding_friction, pool.cloth.sliding_friction);
  EXPECT_EQ(s.parameters.cloth.rolling_resistance, pool.cloth.rolling_resistance);
  EXPECT_EQ(s.parameters.cloth.spin_friction, pool.cloth.spin_friction);
  EXPECT_EQ(s.parameters.cloth.gravity, pool.cloth.gravity);
  EXPECT_EQ(default_scenario().settings.parameters.ball.radius, pool.ball.radius);
}

TEST(Simulator, RandomBreaksStayPhysicalAtEveryEvent) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> speed(1.0, 11.0), aim(-2.0, 2.0), offset(-0.45, 0.45);
  int events = 0;
  const int shots = stress_shots();
  for (int shot = 0; shot < shots; ++shot) {
    const double v = speed(rng);
    const double side = 0.6 * offset(rng);
    const double height = 0.6 * offset(rng);
    Scenario s = scenario_from_json(break_json(v, 0.0, side, height, shot));
    s.cue->target.reset();
    const Vec2 d = s.balls[1].state.position - s.balls[0].state.position;
    s.cue->strike.aim = std::atan2(d.y, d.x) + aim(rng) * kDeg;
    SCOPED_TRACE("shot " + std::to_string(shot));
    const SimulationResult r = run_scenario(s);
    events += static_cast<int>(r.events.size());
    expect_physical_at_every_event(s.table, r, s.settings.parameters);
  }
  EXPECT_GT(events, shots * 20);
}

// 20 random breaks with these settings (a model and its constants), checked
// at every event; returns how many of their events are of the given types.
int physical_breaks_counting(const SimulationSettings& settings, std::initializer_list<EventType> counted) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> speed(2.0, 11.0), offset(-0.3, 0.3);
  int count = 0;
  for (int shot = 0; shot < 20; ++shot) {
    Scenario s = scenario_from_json(break_json(speed(rng), 0.0, offset(rng), offset(rng), shot));
    s.settings.cushion = settings.cushion;
    s.settings.ball_collision_model = settings.ball_collision_model;
    s.settings.ball_collision = settings.ball_collision;
    SCOPED_TRACE("shot " + std::to_string(shot));
    const SimulationResult r = run_scenario(s);
    for (const Event& e : r.events) count += std::find(counted.begin(), counted.end(), e.type) != counted.end();
    expect_physical_at_every_event(s.table, r, s.settings.parameters);
  }
  return count;
}

// The same invariants under every cushion model (the break's balls meet
// cushions and jaws many times each) and every ball-ball model.
TEST(Simulator, BreaksStayPhysicalUnderEveryModel) {
  std::vector<CushionSettings> cushions;
  for (const CushionModel model : kCushionModels) cushions.push_back(default_cushion_settings(model));
  cushions.push_back(cushions[1]);
  cushions.back().restitution = 0.1;  // Han 2005 leaves such balls pressing on the cushion
  for (const CushionSettings& cushion : cushions) {
    SimulationSettings settings;
    settings.cushion = cushion;
    SCOPED_TRACE(std::string(to_string(cushion.model)) + " e = " + std::to_string(cushion.restitution));
    EXPECT_GT(physical_breaks_counting(settings, {EventType::ball_cushion, EventType::ball_jaw}), 100);
  }
  for (const BallCollisionModel model : kBallCollisionModels) {
    SimulationSettings settings;
    settings.ball_collision_model = model;
    settings.ball_collision = default_ball_collision(model);
    SCOPED_TRACE(to_string(model));
    EXPECT_GT(physical_breaks_counting(settings, {EventType::ball_ball}), 200);
  }
}

// The same invariants on the other tables and racks: snooker and 8-ball
// breaks, and random three-ball shots (any aim, raised cue) on pool and carom.
TEST(Simulator, OtherTablesAndRacksStayPhysicalAtEveryEvent) {
  std::mt19937_64 rng(31);
  // Offsets within +-0.35 R on each axis stay inside the 0.5 R miscue limit.
  std::uniform_real_distribution<double> speed(0.5, 11.0), aim(-180.0, 180.0), offset(-0.35, 0.35), elevation(0.0, 25.0);
  int simulated = 0;
  const auto check = [&simulated](const std::string& json) {
    SCOPED_TRACE(json);
    Scenario s;
    try {
      s = scenario_from_json(json);
    } catch (const InvalidArgument& e) {
      ADD_FAILURE() << e.what();
      return;
    }
    const SimulationResult r = run_scenario(s);
    expect_physical_at_every_event(s.table, r, s.settings.parameters);
    ++simulated;
  };
  char json[512];
  for (int shot = 0; shot < 12; ++shot) {
    const double v = speed(rng), side = offset(rng), height = offset(rng);
    std::snprintf(json, sizeof json,
                  R"({"table": "%s", "rack": {"type": "%s", "gap_sigma": 0.0002, "seed": %d},
                      "cue": {"ball": 0, "target": 1, "speed": %.4f, "side": %.4f, "height": %.4f}})",
                  shot % 2 ? "snooker_12ft" : "pool_9ft", shot % 2 ? "snooker" : "eight_ball", shot, v, side, height);
    check(json);
  }
  for (int shot = 0; shot < 40; ++shot) {
    const double v = speed(rng), a = aim(rng), side = offset(rng), height = offset(rng), e = elevation(rng);
    std::snprintf(json, sizeof json,
                  R"({"table": "%s", "balls": [{"id": 0, "position": [0.7, 0.5]}, {"id": 1, "position": [1.3, 0.7]},
                                               {"id": 2, "position": [1.9, 0.9]}],
                      "cue": {"ball": 0, "aim_deg": %.4f, "speed": %.4f, "side": %.4f, "height": %.4f, "elevation_deg": %.3f}})",
                  shot % 2 ? "carom_10ft" : "pool_9ft", a, v, side, height, e);
    check(json);
  }
  EXPECT_EQ(simulated, 52);
}

TEST(Simulator, SameInputGivesBitIdenticalOutput) {
  const Scenario s = default_scenario();
  const SimulationResult a = run_scenario(s);
  const SimulationResult b = run_scenario(s);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].time, b.events[i].time);
    EXPECT_EQ(a.events[i].type, b.events[i].type);
    EXPECT_EQ(a.events[i].ball, b.events[i].ball);
    EXPECT_EQ(a.events[i].other, b.events[i].other);
  }
  EXPECT_EQ(result_to_json(s, a), result_to_json(s, b));
}

// A shot across the symmetric pool table and its mirror image in y = W/2.
TEST(Simulator, MirroredShotGivesTheMirroredOutcome) {
  const char* json = R"({"table": "pool_9ft",
      "balls": [{"id": 0, "position": [0.6, 0.35]}, {"id": 1, "position": [1.7, 0.52]}, {"id": 2, "position": [2.0, 1.0]}],
      "cue": {"ball": 0, "target": 1, "speed": 3.0, "side": 0.3, "height": 0.2}})";
  const Scenario s = scenario_from_json(json);
  Scenario m = s;
  const double w = s.table.width;
  for (SimulationBall& b : m.balls) b.state.position.y = w - b.state.position.y;
  m.cue->strike.side_offset = -s.cue->strike.side_offset;
  const SimulationResult r = run_scenario(s);
  const SimulationResult rm = run_scenario(m);
  ASSERT_EQ(r.events.size(), rm.events.size());
  for (std::size_t i = 0; i < r.events.size(); ++i) {
    EXPECT_EQ(r.events[i].type, rm.events[i].type);
    EXPECT_NEAR(r.events[i].time, rm.events[i].time, 1e-9);
  }
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const BallState a = r.balls[i].final_state, b = rm.balls[i].final_state;
    EXPECT_NEAR(a.position.x, b.position.x, 1e-9);
    EXPECT_NEAR(a.position.y, w - b.position.y, 1e-9);
  }
  EXPECT_GE(std::count_if(r.events.begin(), r.events.end(), [](const Event& e) { return e.type == EventType::ball_cushion; }), 2);
}

Scenario two_balls_on_carom(BallState cue, Vec2 object, BallCollisionParameters collision) {
  Scenario s = scenario_from_json(R"({"table": "carom_10ft", "balls": [{"id": 0, "position": [0.5, 0.7]}, {"id": 1, "position": [1.5, 0.7]}]})");
  s.balls[0].state = cue;
  s.balls[1].state = {object, {}, {}};
  s.settings.ball_collision = collision;
  return s;
}

TEST(Simulator, NinetyDegreeRuleForAStunShot) {
  // Stun (no spin) cue ball already touching, frictionless balls, e = 1.
  const double r = 0.03075;  // carom ball radius
  for (double cut : {10.0, 30.0, 55.0}) {
    const Vec2 object{1.4, 0.7};
    const Vec2 contact_normal{std::cos(cut * kDeg), std::sin(cut * kDeg)};
    const BallState cue{object - 2 * r * contact_normal, {1.0, 0.0}, {}};
    const Scenario s = two_balls_on_carom(cue, object, ball_collision_frictionless(1.0));
    ASSERT_NEAR(s.settings.parameters.ball.radius, r, 1e-12);
    const SimulationResult res = simulate(s.table, s.balls, s.settings);
    ASSERT_EQ(res.events.front().type, EventType::ball_ball);
    const double t = res.events.front().time;
    EXPECT_LT(t, 1e-12);  // touching up to the round-off of placing it
    const Vec2 v0 = res.balls[0].segments[1].state.velocity, v1 = res.balls[1].segments[1].state.velocity;
    EXPECT_NEAR(dot(v0, v1), 0.0, 1e-12) << "cut " << cut;
    // Momentum conserved by the frictionless collision.
    EXPECT_NEAR(v0.x + v1.x, 1.0, 1e-12);
    EXPECT_NEAR(v0.y + v1.y, 0.0, 1e-12);
  }
}

TEST(Simulator, ThirtyDegreeRuleForARollingHalfBallHit) {
  const double r = 0.03075;
  const Vec2 object{1.5, 0.7};
  // Half-ball hit: the line of centres at 30 degrees to the cue ball's path.
  const Vec2 normal{std::cos(30 * kDeg), std::sin(30 * kDeg)};
  const Vec2 contact = object - 2 * r * normal;
  const Vec2 start = contact - Vec2{0.5, 0.0};
  const double v = 1.0;
  const BallState rolling{start, {v, 0.0}, {0.0, v / r, 0.0}};
  const Scenario s = two_balls_on_carom(rolling, object, ball_collision_frictionless(1.0));
  const SimulationResult res = simulate(s.table, s.balls, s.settings);
  // The cue ball's first slide_to_roll after the collision gives its final line.
  bool collided = false;
  for (const Event& e : res.events) {
    if (e.type == EventType::ball_ball) collided = true;
    if (collided && e.type == EventType::slide_to_roll && e.ball == 0) {
      const BallState after = res.state_at(0, e.time, s.settings.parameters);
      const double deflection = std::atan2(-after.velocity.y, after.velocity.x) / kDeg;
      EXPECT_NEAR(deflection, std::atan(5 * std::sqrt(3.0) / 13) / kDeg, 1e-6);  // 33.67 deg
      return;
    }
  }
  FAIL() << "the cue ball never settled into rolling after the collision";
}

TEST(Simulator, BallRolledIntoACornerIsPocketed) {
  Scenario s = scenario_from_json(R"({"table": "pool_9ft", "balls": [{"id": 0, "position": [0.5, 0.5]}],
                                      "cue": {"ball": 0, "aim_deg": 0, "speed": 1.0}})");
  // Aim at the corner pocket at the origin.
  const Pocket& corner = s.table.pockets.front();
  const Vec2 d = corner.centre - s.balls[0].state.position;
  s.cue->strike.aim = std::atan2(d.y, d.x);
  const SimulationResult r = run_scenario(s);
  ASSERT_TRUE(r.balls[0].pocketed);
  EXPECT_EQ(r.balls[0].pocket, 0);
  EXPECT_EQ(r.events.back().type, EventType::ball_pocket);
  const BallState later = r.state_at(0, r.balls[0].pocket_time + 1.0, s.settings.parameters);
  EXPECT_EQ(later.velocity, Vec2{});
}

TEST(Simulator, EventLimitStopsWithAClearError) {
  Scenario s = default_scenario();
  s.settings.max_events = 10;
  try {
    run_scenario(s);
    FAIL() << "expected SimulationError";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("event limit of 10"), std::string::npos) << e.what();
  }
}

// A jaw whose nose is too high for the ball is rejected before the run, as a
// cushion is (it used to surface mid-shot, from a worker thread in a batch).
TEST(Simulator, JawTooHighForTheBallIsRejectedUpFront) {
  Scenario s = default_scenario();
  ASSERT_FALSE(s.table.jaws.empty());
  s.table.jaws[3].contact_height = 2.0 * s.settings.parameters.ball.radius;
  EXPECT_THROW(validate_simulation_input(s.table, s.balls, s.settings), InvalidArgument);
  s.table.jaws[3].contact_height = 1.28 * s.settings.parameters.ball.radius;
  EXPECT_NO_THROW(validate_simulation_input(s.table, s.balls, s.settings));
}

// simulate() in a loop over one scenario checks its table and settings once
// (per thread; validate_simulation_input keeps the last ones that passed, and
// the positions of the last balls that passed), and still the balls every
// time (a ball's place on the table again only where it moved), and a table
// or settings that changed, even to an invalid value and back, are checked
// again.
TEST(Simulator, ValidationOfAnUnchangedTableAndSettingsIsNotRepeatedButStillCatchesChanges) {
  Scenario s = default_scenario();
  const std::vector<SimulationBall> balls = balls_after_strike(s);
  const SimulationResult first = simulate(s.table, balls, s.settings);
  const SimulationResult again = simulate(s.table, balls, s.settings);
  EXPECT_EQ(again.events.size(), first.events.size());
  EXPECT_EQ(again.end_time, first.end_time);
  // The balls are checked on every call.
  std::vector<SimulationBall> bad_balls = balls;
  bad_balls[1].state.position = bad_balls[0].state.position;
  EXPECT_THROW(simulate(s.table, bad_balls, s.settings), InvalidArgument);
  bad_balls = balls;
  bad_balls[0].state.position = {-0.5, 0.3};  // off the table: positions already checked are not checked again, others are
  EXPECT_THROW(simulate(s.table, bad_balls, s.settings), InvalidArgument);
  bad_balls = balls;
  bad_balls[0].state.velocity.x = std::nan("");
  EXPECT_THROW(simulate(s.table, bad_balls, s.settings), InvalidArgument);
  // A changed setting or table is checked again.
  SimulationSettings bad = s.settings;
  bad.cushion.friction = 5.0;
  EXPECT_THROW(simulate(s.table, balls, bad), InvalidArgument);
  bad = s.settings;
  bad.parameters.cloth.sliding_friction = std::nan("");
  EXPECT_THROW(simulate(s.table, balls, bad), InvalidArgument);
  EXPECT_THROW(simulate(s.table, balls, bad), InvalidArgument);  // NaN equals nothing: checked again
  Table bad_table = s.table;
  bad_table.jaws[3].contact_height = 2.0 * s.settings.parameters.ball.radius;
  EXPECT_THROW(simulate(bad_table, balls, s.settings), InvalidArgument);
  EXPECT_EQ(simulate(s.table, balls, s.settings).end_time, first.end_time);
  // On another thread, checked there.
  std::thread t([&] { EXPECT_THROW(simulate(bad_table, balls, s.settings), InvalidArgument); });
  t.join();
  EXPECT_THROW(simulate(bad_table, balls, s.settings), InvalidArgument);
}

// The table's and settings' part of a simulation (its cushions' and jaws'
// impact models, contact lines, pocket groups) is kept per thread while the
// table and settings stay the same: a result never depends on the
// simulations before it. Shots on tables and settings that differ in one
// part each (another table, a cushion model, a cushion's constant, the
// cushions' contact height, the cloth), played interleaved on one thread, give to the
// bit what each gives first on a thread of its own.
TEST(Simulator, AResultDoesNotDependOnTheSimulationsBeforeIt) {
  const Scenario pool = default_scenario();
  std::vector<Scenario> shots(6, pool);
  shots[1] = scenario_from_json(R"({"table": "snooker_12ft", "rack": {"type": "snooker"},
                                   "cue": {"ball": 0, "target": 1, "speed": 8.0}})");
  shots[2].settings.cushion = default_cushion_settings(CushionModel::han_2005);
  shots[3].settings.cushion.friction = 0.2;
  for (CushionSegment& c : shots[4].table.cushions) c.contact_height = 1.35 * pool.settings.parameters.ball.radius;
  shots[5].settings.parameters.cloth.sliding_friction *= 1.5;
  const auto fingerprint = [](const Scenario& s) {
    const SimulationResult r = run_scenario(s);
    std::vector<double> f{r.end_time, static_cast<double>(r.events.size())};
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
      const BallState b = r.state_at(i, r.end_time, s.settings.parameters);
      f.insert(f.end(), {b.position.x, b.position.y});
    }
    return f;
  };
  std::vector<std::vector<double>> alone(shots.size());
  for (std::size_t k = 0; k < shots.size(); ++k) {
    std::thread t([&] { alone[k] = fingerprint(shots[k]); });  // a thread keeps nothing from another
    t.join();
  }
  for (std::size_t k = 1; k < shots.size(); ++k) EXPECT_NE(alone[k], alone[0]) << "shot " << k << " is not another shot";
  for (int round = 0; round < 2; ++round)
    for (std::size_t k = 0; k < shots.size(); ++k) {
      EXPECT_EQ(fingerprint(shots[k]), alone[k]) << "shot " << k << " after shot " << (k + shots.size() - 1) % shots.size();
      EXPECT_EQ(fingerprint(shots[0]), alone[0]) << "the pool shot after shot " << k;
    }
}

TEST(Simulator, TrajectorySegmentsReproduceTheStatesAtEvents) {
  const Scenario s = default_scenario();
  const SimulationResult r = run_scenario(s);
  const Parameters& p = s.settings.parameters;
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const auto& segs = r.balls[i].segments;
    for (std::size_t k = 1; k < segs.size(); ++k) {
      // Continuity of position across every event.
      const BallState before = evolve(segs[k - 1].state, segs[k].start_time - segs[k - 1].start_time, p);
      EXPECT_NEAR(norm(before.position - segs[k].state.position), 0.0, 1e-12);
    }
  }
  EXPECT_NEAR(r.end_time, r.events.back().time, 0.0);
}

std::string invalid_field(const std::string& json) {
  try {
    scenario_from_json(json);
  } catch (const InvalidArgument& e) {
    return e.field();
  }
  return "accepted";
}

TEST(Scenario, MalformedScenariosNameTheField) {
  EXPECT_EQ(invalid_field("{"), "scenario");
  EXPECT_EQ(invalid_field("[]"), "scenario");
  EXPECT_EQ(invalid_field(R"({"tabel": "pool_9ft"})"), "scenario.tabel");
  EXPECT_EQ(invalid_field(R"({"cue": {"speed": 1e999}})"), "scenario.cue.speed");
  EXPECT_EQ(invalid_field(R"({"cue": {"speed": -3}})"), "scenario.cue.speed");
  EXPECT_EQ(invalid_field(R"({"cue": {"speed": "fast"}})"), "scenario.cue.speed");
  EXPECT_EQ(invalid_field(R"({"cue": {"side": 0.7}})"), "scenario.cue.side");
  EXPECT_EQ(invalid_field(R"({"parameters": {"mass": -0.17}})"), "scenario.parameters.mass");
  EXPECT_EQ(invalid_field(R"({"parameters": {"mu_s": 0.2, "frobnicate": 1}})"), "scenario.parameters.frobnicate");
  EXPECT_EQ(invalid_field(R"({"balls": [{"id": 0, "position": [0.5, 0.5]}, {"id": 1, "position": [0.52, 0.5]}]})"),
            "scenario.balls[1].position");
  EXPECT_EQ(invalid_field(R"({"balls": [{"id": 0, "position": [-0.5, 0.5]}]})"), "scenario.balls[0].position");
  EXPECT_EQ(invalid_field(R"({"balls": [{"id": 0, "position": [0.5, 0.5]}, {"id": 0, "position": [1.5, 0.5]}]})"),
            "scenario.balls[1].id");
  EXPECT_EQ(invalid_field(R"({"balls": [{"id": 0, "position": [0.5]}]})"), "scenario.balls[0].position");
  EXPECT_EQ(invalid_field(R"({"balls": [{"id": 0}]})"), "scenario.balls[0].position");
  EXPECT_EQ(invalid_field(R"({"rack": {"type": "ten_ball"}})"), "scenario.rack.type");
  EXPECT_EQ(invalid_field(R"({"table": "croquet_lawn"})"), "scenario.table");
  EXPECT_EQ(invalid_field(R"({"table": {"preset": "pool_9ft", "length": -2}})"), "scenario.table.length");
  EXPECT_EQ(invalid_field(R"({"cue": {"ball": 42}})"), "scenario.cue.ball");
  EXPECT_EQ(invalid_field(R"({"cue": {"target": 1, "aim_deg": 3}})"), "scenario.cue.target");
  EXPECT_EQ(invalid_field(R"({"max_events": 0})"), "scenario.max_events");
  EXPECT_EQ(invalid_field(R"({"max_events": 18446744073709551615})"), "scenario.max_events");
  // Deep nesting is refused before anything recurses over it (a fuzzing find:
  // 100000 levels once overflowed the stack).
  EXPECT_EQ(invalid_field("{\"table\": " + std::string(100000, '[') + std::string(100000, ']') + "}"), "scenario");
}

TEST(Scenario, RackAndListedBallsCombine) {
  const Scenario s = scenario_from_json(R"({"rack": {"type": "nine_ball"}, "balls": [{"id": 0, "position": [0.4, 0.3]}]})");
  EXPECT_EQ(s.balls.size(), 10u);
  EXPECT_EQ(s.balls[0].state.position, (Vec2{0.4, 0.3}));
}

TEST(Batch, ResultsDoNotDependOnTheThreadCount) {
  const Scenario s = default_scenario();
  const BatchResult one = simulate_batch(s, {40, 1, 7});
  const BatchResult two = simulate_batch(s, {40, 2, 7});
  ASSERT_EQ(one.balls.size(), two.balls.size());
  EXPECT_EQ(one.events, two.events);
  for (std::size_t i = 0; i < one.balls.size(); ++i) {
    EXPECT_EQ(one.balls[i].pocketed_probability, two.balls[i].pocketed_probability);
    EXPECT_EQ(one.balls[i].mean_position, two.balls[i].mean_position);
    EXPECT_EQ(one.balls[i].position_std, two.balls[i].position_std);
  }
  const BatchResult other_seed = simulate_batch(s, {40, 1, 8});
  EXPECT_NE(one.events, other_seed.events);
  EXPECT_EQ(one.simulated + one.miscues + one.failures, 40);
  EXPECT_GT(one.shots_per_second, 0.0);
}

TEST(Batch, NoNoiseRepeatsTheSameShot) {
  Scenario s = default_scenario();
  s.noise = {};
  const BatchResult r = simulate_batch(s, {5, 2, 1});
  const SimulationResult single = run_scenario(s);
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    EXPECT_EQ(r.balls[i].pocketed_probability, single.balls[i].pocketed ? 1.0 : 0.0);
    if (!single.balls[i].pocketed) {
      EXPECT_NEAR(r.balls[i].mean_position.x, single.balls[i].final_state.position.x, 1e-12);
      EXPECT_NEAR(r.balls[i].mean_position.y, single.balls[i].final_state.position.y, 1e-12);
      EXPECT_NEAR(r.balls[i].position_std.x, 0.0, 1e-12);
    }
  }
}

TEST(Batch, BadOptionsAreRejected) {
  const Scenario s = default_scenario();
  EXPECT_THROW(simulate_batch(s, {0, 1, 0}), InvalidArgument);
  EXPECT_THROW(simulate_batch(s, {10, 0, 0}), InvalidArgument);
}

}  // namespace
}  // namespace cueball
