// Tests of the command-line interface (cli/), run in-process: exit codes,
// the one-line errors, JSON keys and values.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "cueball/physics/cloth_motion.hpp"
#include "cueball/physics/straight_shot_inverse.hpp"

namespace cueball {
namespace {

using namespace test;  // the CLI tests' helpers (tests/support/)

TEST(Cli, RollJsonHasThePhasesInSiUnits) {
  const CliRun r = run_cli({"roll", "--v0", "2", "--w0", "-40", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const StraightShot shot = straight_shot(2.0, -40.0, 0.0, pool_parameters());
  EXPECT_DOUBLE_EQ(j.at("t1").get<double>(), shot.t1);
  EXPECT_DOUBLE_EQ(j.at("x1").get<double>(), shot.x1);
  EXPECT_DOUBLE_EQ(j.at("v1").get<double>(), shot.v1);
  EXPECT_DOUBLE_EQ(j.at("t2").get<double>(), shot.t2);
  EXPECT_DOUBLE_EQ(j.at("x2").get<double>(), shot.x2);
  EXPECT_EQ(j.at("parameters").at("mass").get<double>(), 0.17);  // the pool preset by default
}

TEST(Cli, RollAtGivesTheFullState) {
  const CliRun r = run_cli({"roll", "--v0", "1.5", "--side", "20", "--at", "0.1", "--preset", "pool", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto at = nlohmann::json::parse(r.out).at("at");
  const BallState s = straight_shot_state(1.5, 0.0, 20.0, 0.1, pool_parameters());
  EXPECT_EQ(at.at("phase"), "sliding");
  EXPECT_DOUBLE_EQ(at.at("position")[0].get<double>(), s.position.x);
  EXPECT_DOUBLE_EQ(at.at("velocity")[0].get<double>(), s.velocity.x);
  EXPECT_DOUBLE_EQ(at.at("angular_velocity")[2].get<double>(), s.angular_velocity.z);
  EXPECT_EQ(at.at("angular_velocity").size(), 3u);
}

TEST(Cli, ParameterOverridesApply) {
  const CliRun r = run_cli({"roll", "--v0", "1", "--mu-s", "0.5", "--mu-r", "0.02", "--g", "9.8", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("parameters").at("mu_s").get<double>(), 0.5);
  Parameters p = pool_parameters();
  p.cloth.sliding_friction = 0.5;
  p.cloth.rolling_resistance = 0.02;
  p.cloth.gravity = 9.8;
  EXPECT_DOUBLE_EQ(j.at("x2").get<double>(), straight_shot(1.0, 0.0, 0.0, p).x2);
}

TEST(Cli, TableOutputShowsUnits) {
  const CliRun r = run_cli({"roll", "--v0", "1"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("t1"), std::string::npos);
  EXPECT_NE(r.out.find("m/s"), std::string::npos);
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
}

TEST(Cli, PlanVariantsMatchTheLibrary) {
  const Parameters p = pool_parameters();
  const ShotTarget target{0.0, 1.5, 0.2};
  const struct {
    std::vector<std::string> flags;
    ShotPlan expected;
  } cases[] = {
      {{"--x1", "0.3"}, plan_shot_with_slide_end(target, 0.3, p)},
      {{"--natural-roll"}, plan_natural_roll_shot(target, p)},
      {{"--w0", "-20"}, plan_shot_with_spin(target, -20.0, p)},
      {{"--v0", "2"}, plan_shot_with_speed(target, 2.0, p)},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args{"plan", "--x2", "1.5", "--v2", "0.2", "--json"};
    args.insert(args.end(), c.flags.begin(), c.flags.end());
    const CliRun r = run_cli(args);
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("variant"), to_string(c.expected.variant));
    EXPECT_DOUBLE_EQ(j.at("v0").get<double>(), c.expected.v0);
    EXPECT_DOUBLE_EQ(j.at("w0").get<double>(), c.expected.w0);
    EXPECT_DOUBLE_EQ(j.at("t1").get<double>(), c.expected.t1);
    EXPECT_DOUBLE_EQ(j.at("t2").get<double>(), c.expected.t2);
    EXPECT_TRUE(j.contains("cue_tip_height"));
  }
}

TEST(Cli, PlanWarnsBeyondTheMiscueLimit) {
  // A stop shot at the end of a long slide needs heavy draw: b = -R.
  const CliRun r = run_cli({"plan", "--x1", "0.4", "--x2", "0.4", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("miscue"), std::string::npos) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("warnings").size(), 1u);
}

TEST(Cli, BadNumbersExitWithStatusTwoNamingTheFlag) {
  expect_usage_error({"roll", "--v0", "nan"}, "--v0");
  expect_usage_error({"roll", "--v0", "inf"}, "--v0");
  expect_usage_error({"roll", "--v0", "-1"}, "--v0");
  expect_usage_error({"roll", "--v0", "abc"}, "--v0");
  expect_usage_error({"roll", "--v0", "1", "--w0", "1e9"}, "--w0");
  expect_usage_error({"roll", "--v0", "1", "--at", "-2"}, "--at");
  expect_usage_error({"roll", "--v0", "1", "--mass", "-0.17"}, "--mass");
  expect_usage_error({"roll", "--v0", "1", "--radius", "nan"}, "--radius");
  expect_usage_error({"roll", "--v0", "1", "--mu-s", "0"}, "--mu-s");
  expect_usage_error({"roll", "--v0", "1", "--mu-r", "5"}, "--mu-r");
  expect_usage_error({"roll", "--v0", "1", "--mu-sp", "-1"}, "--mu-sp");
  expect_usage_error({"roll", "--v0", "1", "--g", "0"}, "--g");
  expect_usage_error({"roll", "--v0", "1", "--preset", "croquet"}, "--preset");
  expect_usage_error({"plan", "--x2", "nan", "--natural-roll"}, "--x2");
  expect_usage_error({"plan", "--x2", "1", "--v2", "-1", "--natural-roll"}, "--v2");
}

TEST(Cli, MissingOrConflictingFlagsExitWithStatusTwo) {
  expect_usage_error({"roll"}, "--v0");
  expect_usage_error({"plan", "--natural-roll"}, "--x2");
  expect_usage_error({"plan", "--x2", "1"}, "--natural-roll");
  expect_usage_error({"plan", "--x2", "1", "--natural-roll", "--w0", "3"}, "--w0");
  expect_usage_error({"roll", "--v0", "1", "--bogus"}, "--bogus");
  expect_usage_error({"juggle"}, "juggle");
}

TEST(Cli, InfeasiblePlansExitWithStatusTwoNamingTheCondition) {
  expect_usage_error({"plan", "--x1", "2", "--x2", "1"}, "x2 >= x1");
  expect_usage_error({"plan", "--x2", "0.3", "--w0", "400"}, "x1 >= x0");
  expect_usage_error({"plan", "--x2", "0.5", "--v0", "0.1", "--v2", "0.3"}, "v0 >= v2");
}

TEST(Cli, HelpStatesUnitsAndSignConventions) {
  for (const char* sub : {"roll", "plan"}) {
    const CliRun r = run_cli({sub, "--help"});
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("m/s"), std::string::npos) << sub;
    EXPECT_NE(r.out.find("rad/s"), std::string::npos) << sub;
    EXPECT_NE(r.out.find("natural roll"), std::string::npos) << sub;
  }
  const CliRun top = run_cli({"--help"});
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.out.find("SI"), std::string::npos);
}

}  // namespace
}  // namespace cueball
