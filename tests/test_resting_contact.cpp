// Tests of resting contacts (src/physics/resting_contact.cpp): the kernels' claims
// in resting_contact.hpp (nothing left moving or pressed into the contact,
// energy never rises, the swerve along a rail kept), then the simulator on
// the shots that used to pass into a cushion or another ball, or never end
// (issue 11), checked densely between events.
#include "cueball/io/scenario_json.hpp"
#include "cueball/physics/resting_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "cueball/core/errors.hpp"
#include "cueball/physics/contact_prediction.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/simulator.hpp"
#include "simulation_checks.hpp"
#include "test_support.hpp"

namespace cueball {
namespace {

const Parameters kPool = pool_parameters();

Vec2 random_unit(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> angle(-std::numbers::pi, std::numbers::pi);
  const double a = angle(rng);
  return {std::cos(a), std::sin(a)};
}

double energy(const BallState& s) { return kinetic_energy(s, kPool.ball); }

TEST(RestingContact, EndSlipIsPaperEquationNine) {
  const double r = kPool.ball.radius;
  const BallState s{{0, 0}, {1.5, -0.5}, {10, -30, 4}};
  const BallState out = end_slip(s, r);
  const Vec2 u = slip_velocity(s, r);
  EXPECT_NEAR(out.velocity.x, s.velocity.x - 2.0 / 7.0 * u.x, 1e-15);
  EXPECT_NEAR(out.velocity.y, s.velocity.y - 2.0 / 7.0 * u.y, 1e-15);
  EXPECT_LT(norm(slip_velocity(out, r)), 1e-14);
  EXPECT_EQ(out.angular_velocity.z, 4.0);
  EXPECT_LT(energy(out), energy(s));
}

// 1. of resting_contact.hpp, over random states and walls.
TEST(RestingContact, AWallLeavesNothingMovingOrPressingIntoIt) {
  std::mt19937_64 rng(11);
  const double r = kPool.ball.radius;
  for (int k = 0; k < 20000; ++k) {
    BallState s = test::random_state(rng, 2.0, 100.0);
    const Vec2 n = random_unit(rng);
    const BallState out = rest_against_wall(s, n, r);
    ASSERT_GE(dot(out.velocity, n), -1e-15);
    // Still at the wall: nothing presses into it. Leaving it: nothing changed.
    if (dot(s.velocity, n) < kMinApproachSpeed) {
      ASSERT_LE(dot(slip_velocity(out, r), n), 1e-13);
    } else {
      ASSERT_EQ(out.angular_velocity, s.angular_velocity);
    }
    ASSERT_LE(energy(out), energy(s) * (1 + 1e-14));
    // Along the wall nothing changes: the swerve and the speed along it stay.
    const Vec2 t = perp(n);
    ASSERT_NEAR(dot(out.velocity, t), dot(s.velocity, t), 1e-13);
    ASSERT_NEAR(dot(slip_velocity(out, r), t), dot(slip_velocity(s, r), t), 1e-12);
    ASSERT_EQ(out.angular_velocity.z, s.angular_velocity.z);
    ASSERT_EQ(out.position, s.position);
    // Idempotent: a resolved contact stays resolved.
    const BallState again = rest_against_wall(out, n, r);
    ASSERT_NEAR(norm(again.velocity - out.velocity), 0.0, 1e-15);
    ASSERT_NEAR(norm(horizontal(again.angular_velocity - out.angular_velocity)), 0.0, 1e-12);
  }
}

// The cloth's friction impulse that removes a pressing slip u.n dissipates
// exactly (1/5) m (u.n)^2 when the ball does not move into the wall.
TEST(RestingContact, PressingSlipCostsAFifthOfMTimesItsSquare) {
  const double r = kPool.ball.radius, m = kPool.ball.mass;
  const Vec2 n{0, 1};  // the bottom rail's inward normal
  const BallState spinning{{1, r}, {0, 0}, {20, 0, 0}};  // u = (0, 20 R): friction drives it to -y
  const BallState out = rest_against_wall(spinning, n, r);
  EXPECT_EQ(out.velocity, (Vec2{0, 0}));
  EXPECT_NEAR(norm(out.angular_velocity), 0.0, 1e-12);
  const double un = 20 * r;
  EXPECT_NEAR(energy(spinning) - energy(out), m * un * un / 5.0, 1e-15);
  // A swerve along the rail (slip with both parts): only u.n goes.
  const BallState swerve{{1, r}, {2, 0}, {30, 0, 50}};
  const BallState along = rest_against_wall(swerve, n, r);
  EXPECT_EQ(along.velocity, swerve.velocity);
  EXPECT_NEAR(slip_velocity(along, r).y, 0.0, 1e-15);
  EXPECT_NEAR(slip_velocity(along, r).x, slip_velocity(swerve, r).x, 1e-15);
  EXPECT_NEAR(energy(swerve) - energy(along), m * (30 * r) * (30 * r) / 5.0, 1e-12);
  // Slip that pulls the ball off the wall is left alone.
  const BallState away{{1, r}, {0, 0}, {-20, 0, 0}};
  EXPECT_EQ(rest_against_wall(away, n, r).angular_velocity, away.angular_velocity);
}

// 2. of resting_contact.hpp, over random touching pairs with no closing speed.
TEST(RestingContact, PressedBallsArePartedAndLoseEnergy) {
  std::mt19937_64 rng(12);
  const double r = kPool.ball.radius;
  int pressed = 0;
  for (int k = 0; k < 20000; ++k) {
    BallState a = test::random_state(rng, 2.0, 100.0);
    BallState b = test::random_state(rng, 2.0, 100.0);
    b.position = a.position + 2 * r * random_unit(rng);
    const Vec2 n = (b.position - a.position) / norm(b.position - a.position);  // as press_apart sees it
    b.velocity = b.velocity - dot(b.velocity - a.velocity, n) * n;  // no normal speed
    const BallState a0 = a, b0 = b;
    const bool changed = press_apart(a, b, r);
    const bool a_pressed = dot(slip_velocity(a0, r), n) < 0.0, b_pressed = dot(slip_velocity(b0, r), n) > 0.0;
    if (a_pressed || b_pressed) {
      ASSERT_TRUE(changed);
    }
    ASSERT_EQ(changed, !(a.velocity == a0.velocity && b.velocity == b0.velocity &&
                         a.angular_velocity == a0.angular_velocity && b.angular_velocity == b0.angular_velocity));
    pressed += a_pressed || b_pressed;
    ASSERT_GE(dot(b.velocity - a.velocity, n), -1e-14);  // parted or at rest relative to each other
    ASSERT_LE(energy(a) + energy(b), (energy(a0) + energy(b0)) * (1 + 1e-14));
    // After the impulses neither slip presses into the contact beyond the
    // speed at which the other ball's reaction sends the ball away (which
    // its friction only slows, never reverses).
    ASSERT_GE(dot(slip_velocity(a, r), n), dot(a.velocity - a0.velocity, n) - 1e-12);
    ASSERT_LE(dot(slip_velocity(b, r), n), dot(b.velocity - b0.velocity, n) + 1e-12);
    // Each ball's reaction acts through the centres: tangential velocities stay.
    ASSERT_NEAR(dot(a.velocity - a0.velocity, perp(n)), 0.0, 1e-13);
    ASSERT_NEAR(dot(b.velocity - b0.velocity, perp(n)), 0.0, 1e-13);
  }
  EXPECT_GT(pressed, 10000);  // both kinds were exercised
}

TEST(RestingContact, ASpinningBallPushesTheBallItPressesAway) {
  const double r = kPool.ball.radius;
  BallState a{{1, 0.6}, {0, 0}, {0, -30, 0}};  // u = (30 R, 0): friction drives a to -x
  BallState b{{1 - 2 * r, 0.6}, {0, 0}, {0, 0, 0}};
  ASSERT_TRUE(press_apart(a, b, r));
  EXPECT_EQ(a.velocity, (Vec2{0, 0}));
  EXPECT_NEAR(b.velocity.x, -(2.0 / 5.0) * 30 * r, 1e-15);
  EXPECT_NEAR(b.velocity.y, 0.0, 1e-15);
  EXPECT_NEAR(norm(a.angular_velocity), 0.0, 1e-12);
}

// ------------------------------------------------------------ through the simulator

struct ShotRun {
  Scenario scenario;
  SimulationResult result;
};

ShotRun run(const std::string& json) {
  Scenario s = scenario_from_json(json);
  s.settings.max_events = 10000;  // no valid shot needs more (issue 11)
  SimulationResult r = run_scenario(s);
  return {std::move(s), std::move(r)};
}

void expect_clean(const ShotRun& x) {
  EXPECT_LE(deepest_penetration(x.scenario.table, x.result, x.scenario.settings.parameters), 1e-9);
  EXPECT_LE(energy_rise(x.result, x.scenario.settings.parameters), 1e-12);
  for (const BallTrajectory& b : x.result.balls) {
    if (!b.pocketed) {
      EXPECT_TRUE(ball_on_table(x.scenario.table, b.final_state.position)) << "ball " << b.id;
    }
  }
}

// shared/repro/frozen_to_cushion_spinning_penetrates_5mm.json: went 5.4 mm in.
TEST(RestingContactSimulation, SpinningBallFrozenToTheCushionStaysOut) {
  const ShotRun x = run(R"({"table": "snooker_12ft", "balls": [{"id": 0, "position": [1.0, 0.024058522398518162],
                        "angular_velocity": [20, 0, 0]}]})");
  expect_clean(x);
  EXPECT_EQ(x.result.events.at(0).type, EventType::ball_cushion);  // pressed at once
  EXPECT_NEAR(x.result.balls[0].final_state.position.y, 0.024058522398518162, 1e-12);
}

// shared/repro/rail_swerve_pool_penetrates_38mm.json: went 38 mm in.
TEST(RestingContactSimulation, SwerveAlongAFrozenRailStaysOut) {
  const ShotRun x = run(R"({"table": "pool_9ft", "balls": [{"id": 0, "name": "cue", "position": [0.6, 0.02745044113944255]}],
                        "cue": {"ball": 0, "aim_deg": 0, "speed": 2, "elevation_deg": 30, "side": 0.3,
                                "end_mass": 0}})");
  expect_clean(x);
  // The swerve's pull into the rail is taken by the rail; the ball keeps
  // sliding along it (not forced to roll at once). Squirt is off: it would
  // send the ball off the rail first (FrozenRailShotsWithRaisedCueStayOut
  // below plays the shots with it).
  ASSERT_GE(x.result.events.size(), 3u);
  EXPECT_EQ(x.result.events[1].type, EventType::ball_cushion);
  EXPECT_EQ(x.result.events[2].type, EventType::slide_to_roll);
  EXPECT_GT(x.result.events[2].time, 0.1);
}

// Every raised-cue, side-spin shot along (and slightly into or off) a frozen
// rail, on both rails of two tables: the class that went in 30 % of the time.
TEST(RestingContactSimulation, FrozenRailShotsWithRaisedCueStayOut) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> elevation(5, 80), side(-0.45, 0.45), speed(0.3, 5), aim(-4, 4), x0(0.3, 1.5);
  int shots = 0;
  for (const char* table : {"pool_9ft", "snooker_12ft"}) {
    const Table t = preset_table(table);
    const double d = cushion_contact_distance(t.cushions.front().contact_height, t.ball.radius);
    for (int k = 0; k < 30; ++k) {
      const bool top = k % 2;
      const double y = top ? t.width - d : d;
      char json[512];
      std::snprintf(json, sizeof json,
                    R"({"table": "%s", "balls": [{"id": 0, "position": [%.17g, %.17g]}],
                        "cue": {"ball": 0, "aim_deg": %.6f, "speed": %.4f, "elevation_deg": %.3f, "side": %.3f}})",
                    table, x0(rng), y, (top ? 180.0 : 0.0) + aim(rng), speed(rng), elevation(rng), side(rng));
      try {
        const ShotRun x = run(json);
        expect_clean(x);
        ++shots;
      } catch (const InvalidArgument&) {
        // a miscue of the random tip offset: not this test's concern
      }
    }
  }
  EXPECT_GT(shots, 40);
}

// shared/repro/overlap_passthrough_roundoff_1e-15.json: two balls
// overlapping by round-off, the moving one spun into the other, ended 15 mm
// into each other.
TEST(RestingContactSimulation, RoundOffOverlapDrivenTogetherIsAContact) {
  const ShotRun x = run(R"({"table": "pool_9ft", "balls": [{"id": 1, "name": "A", "position": [1.0, 0.6]},
                        {"id": 0, "name": "B", "position": [1.057149999999999, 0.6], "velocity": [1e-09, 0],
                         "angular_velocity": [0, -30, 0]}]})");
  expect_clean(x);
  EXPECT_EQ(x.result.events.at(0).type, EventType::ball_ball);
  EXPECT_EQ(x.result.events.at(0).time, 0.0);
  EXPECT_GT(norm(x.result.balls[0].final_state.position - Vec2{1.0, 0.6}), 0.01);  // A was pushed away
}

// shared/repro/frozen_cluster_event_limit_zeno.json: eight frozen balls
// nudged at 3.6 mm/s took 146,657 events at t = 1e-12 s.
TEST(RestingContactSimulation, NudgedFrozenClusterEndsInAFewEvents) {
  const ShotRun x = run(R"({"table": "snooker_12ft", "balls": [
    {"id": 0, "position": [1.5157843704209482, 0.6441794916002361], "velocity": [-0.0009880762740813612, 0.0034830627128319535],
     "angular_velocity": [-0.04639516161545824, -0.038926120509527797, -0.05781276844916958]},
    {"id": 1, "position": [1.5131732299283103, 0.6966145175402289]}, {"id": 2, "position": [1.4642777088888799, 0.7157319970362981]},
    {"id": 3, "position": [1.480966767810697, 0.7655087517748718]}, {"id": 4, "position": [1.440474885281376, 0.7989251766170309]},
    {"id": 5, "position": [1.4479722234879429, 0.8508870849712893]}, {"id": 6, "position": [1.423203456089962, 0.8971770208276364]},
    {"id": 9, "position": [1.4127676565976799, 0.9486293685773444]}]})");
  expect_clean(x);
  EXPECT_LT(x.result.events.size(), 100u);
}

// A Newton's cradle: a ball struck into a line of five frozen balls. The
// impulse passes down the line and the last ball leaves, in a few events.
TEST(RestingContactSimulation, NewtonsCradlePassesTheImpulseDownTheLine) {
  std::string balls = R"({"id": 0, "position": [0.5, 0.635]})";
  const double r = pool_parameters().ball.radius;
  for (int k = 1; k <= 5; ++k) balls += R"(, {"id": )" + std::to_string(k) + R"(, "position": [)" + std::to_string(1.0 + 2 * r * (k - 1)) + ", 0.635]}";
  const ShotRun x = run(R"({"table": "pool_9ft", "balls": [)" + balls + R"(], "cue": {"ball": 0, "aim_deg": 0, "speed": 2}})");
  expect_clean(x);
  EXPECT_LT(x.result.events.size(), 200u);
  // Just after the strike the last ball carries the impulse; the others are
  // left with the small remainder that restitution below 1 leaves behind.
  const double t = x.result.events[1].time + 0.01;
  const Parameters& p = x.scenario.settings.parameters;
  EXPECT_GT(norm(x.result.state_at(5, t, p).velocity), 1.5);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_LT(norm(x.result.state_at(k, t, p).velocity), 0.3) << "ball " << k;
}

}  // namespace
}  // namespace cueball
