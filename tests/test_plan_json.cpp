// The plan's JSON (src/io/plan_json.cpp): every field is the plan's own, the
// "cue" replays the planned shot, and position play and ball in hand add
// their keys only when asked.
#include "cueball/io/plan_json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "ball_layout.hpp"
#include "cueball/io/scenario_json.hpp"

namespace cueball {
namespace {

const Scenario kLayout = test::layout({{0, {1.6, 0.5}}, {1, {2.0, 0.85}}, {2, {1.0, 0.9}}});

TEST(PlanJson, EveryFieldIsThePlansOwn) {
  PlanRequest q;
  q.target = 1;
  q.simulations = 1000;
  const ShotPlanResult plan = plan_shot(kLayout, q);
  const nlohmann::json j = nlohmann::json::parse(plan_to_json(kLayout, plan, q.noise));
  EXPECT_EQ(j["target"], 1);
  EXPECT_EQ(j["kind"], to_string(plan.shot.kind));
  EXPECT_EQ(j["pocket"], plan.shot.pocket_name);
  EXPECT_EQ(j["success_probability"].get<double>(), plan.shot.success_probability);
  EXPECT_EQ(j["simulations"].get<int>(), plan.simulations);
  EXPECT_EQ(j["alternatives"].size(), plan.alternatives.size());
  EXPECT_EQ(j["rejected"].size(), plan.rejected.size());
  EXPECT_EQ(j["predicted"].size(), plan.shot.predicted.size());
  EXPECT_FALSE(j.contains("position"));
  EXPECT_FALSE(j.contains("in_hand"));
  // The "cue" is the scenario's that plays the shot.
  const Scenario played = scenario_with_shot(kLayout, plan.cue_ball, plan.shot, q.noise);
  const nlohmann::json cue = nlohmann::json::parse(scenario_to_json(played))["cue"];
  EXPECT_EQ(j["cue"], cue);
}

TEST(PlanJson, PositionPlayAndBallInHandAddTheirKeys) {
  // The writer, not the planners: a plain plan with a leave for it and each
  // alternative and a placed cue ball, as plan_shot_for_position and
  // plan_ball_in_hand fill them (the planners' own JSON, end to end, is
  // test_cli_plan_shot_position.cpp's and the Python tests'; a real ball in
  // hand took ~50 s of the sanitizer run here).
  PlanRequest q;
  q.target = 1;
  q.simulations = 1000;
  BallInHandResult hand;
  hand.table = kLayout;
  hand.cue_ball = {1.6, 0.5};
  hand.spots = 7;
  hand.spots_played = 3;
  hand.plan.plan = plan_shot(kLayout, q);
  hand.plan.next_target = 2;
  hand.plan.leave = {{1.25, 0.75}, true, 0.5, 0.875, "direct", "top-left", 2, 0.4375};
  for (std::size_t k = 0; k < hand.plan.plan.alternatives.size(); ++k)
    hand.plan.alternative_leaves.push_back({{1.0, 0.5}, false, 0.0, 0.25 / static_cast<double>(k + 1), "", "", -1, 0.0});
  ASSERT_FALSE(hand.plan.plan.alternatives.empty());
  const nlohmann::json j =
      nlohmann::json::parse(plan_to_json(hand.table, hand.plan.plan, q.noise, &hand.plan, &hand));
  ASSERT_TRUE(j.contains("in_hand"));
  EXPECT_EQ(j["in_hand"]["cue_ball"][0].get<double>(), hand.cue_ball.x);
  EXPECT_EQ(j["in_hand"]["spots"].get<int>(), hand.spots);
  EXPECT_EQ(j["in_hand"]["spots_played"].get<int>(), hand.spots_played);
  ASSERT_TRUE(j.contains("position"));
  EXPECT_EQ(j["position"]["next"], hand.plan.next_target);
  EXPECT_EQ(j["position"]["score"].get<double>(), hand.plan.leave.score);
  EXPECT_EQ(j["position"]["next_pocket"], "top-left");
  EXPECT_EQ(j["position"]["cue_ball"], nlohmann::json::array({1.25, 0.75}));
  ASSERT_EQ(j["alternatives"].size(), hand.plan.plan.alternatives.size());
  for (std::size_t k = 0; k < hand.plan.plan.alternatives.size(); ++k) {
    EXPECT_EQ(j["alternatives"][k]["position"]["screened_probability"].get<double>(),
              hand.plan.alternative_leaves[k].screened_probability);
    EXPECT_TRUE(j["alternatives"][k]["position"]["next_kind"].is_null());
    EXPECT_TRUE(j["alternatives"][k]["position"]["next_ball"].is_null());
  }
}

}  // namespace
}  // namespace cueball
