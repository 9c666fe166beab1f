// Tests of position play (src/position_play.cpp): the table a shot leaves,
// the choice maximising P(this pot) x P(next pot), each leave's next
// probability reproduced by an independent plan on that table, the
// lookahead doing at least as well as the shot planned without it (and
// better somewhere), the default next ball, and bad input.
#include "cueball/position_play.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "ball_layout.hpp"
#include "cueball/errors.hpp"
#include "cueball/scenario.hpp"

namespace cueball {
namespace {

using test::layout;
using test::Placed;

// Cue ball 0, target 1 and the next ball 2 at random places on the 9-ft
// table (at least 3 R from the cushions and 3 R apart), from `seed`.
Scenario random_layout(unsigned seed) {
  const Scenario empty = layout({});
  const double R = empty.settings.parameters.ball.radius;
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (const CushionSegment& c : empty.table.cushions)
    for (Vec2 p : {c.start, c.end})
      xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x), ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(xmin + 3 * R, xmax - 3 * R), uy(ymin + 3 * R, ymax - 3 * R);
  std::vector<Placed> balls;
  while (balls.size() < 3) {
    const Vec2 p{ux(rng), uy(rng)};
    bool apart = true;
    for (const Placed& b : balls) apart = apart && norm(b.p - p) > 3.0 * R;
    if (apart) balls.push_back({static_cast<int>(balls.size()), p});
  }
  return layout(balls);
}

PositionRequest request_for(int target) {
  PositionRequest q;
  q.shot.target = target;
  q.shot.simulations = 1000;
  q.next_simulations = 500;
  return q;
}

// The two-ball score of a shot: its probability times that of the next
// ball's plan on the table it leaves (0 when there is no feasible next shot).
double two_ball_score(const Scenario& s, const PlannedShot& shot, int cue_ball, int next, int next_simulations) {
  PlanRequest q;
  q.cue_ball = cue_ball;
  q.target = next;
  q.simulations = next_simulations;
  try {
    return shot.success_probability * plan_shot(table_left_by(s, shot), q).shot.success_probability;
  } catch (const NoFeasibleShot&) {
    return 0.0;
  }
}

TEST(TableLeftBy, KeepsTheBallsNotPocketedAtRestWhereTheShotLeavesThem) {
  const Scenario s = layout({{0, {0.5, 0.6}}, {1, {1.0, 0.7}}, {2, {2.0, 0.3}}});
  PlannedShot shot;
  shot.predicted = {{0, {0.9, 0.65}, false, -1}, {1, {2.5, 1.27}, true, 3}, {2, {2.0, 0.3}, false, -1}};
  const Scenario left = table_left_by(s, shot);
  ASSERT_EQ(left.balls.size(), 2u);
  EXPECT_EQ(left.balls[0].id, 0);
  EXPECT_EQ(left.balls[0].state.position.x, 0.9);
  EXPECT_EQ(left.balls[0].state.position.y, 0.65);
  EXPECT_EQ(left.balls[1].id, 2);
  for (const SimulationBall& b : left.balls) {
    EXPECT_EQ(norm(b.state.velocity), 0.0);
    EXPECT_EQ(norm(b.state.angular_velocity), 0.0);
  }
  EXPECT_FALSE(left.cue.has_value());
}

TEST(PositionPlay, PlaysTheCandidateWithTheBestTwoBallScoreAndEachLeaveIsReproduced) {
  const Scenario s = random_layout(3);
  const PositionRequest q = request_for(1);
  const PositionPlanResult r = plan_shot_for_position(s, q);
  EXPECT_EQ(r.next_target, 2);  // the lowest id left
  ASSERT_EQ(r.plan.alternatives.size(), r.alternative_leaves.size());
  EXPECT_LE(r.plan.alternatives.size() + 1, kMaxPositionCandidates);
  for (const Leave& l : r.alternative_leaves) EXPECT_LE(l.score, r.leave.score);
  // Each leave's next probability is that of an independent plan on the table it leaves.
  const auto check = [&](const PlannedShot& shot, const Leave& leave) {
    EXPECT_DOUBLE_EQ(leave.score, two_ball_score(s, shot, r.plan.cue_ball, 2, q.next_simulations));
    EXPECT_DOUBLE_EQ(leave.score, shot.success_probability * leave.next_success_probability);
    const PredictedBall& cue = shot.predicted[0];
    EXPECT_EQ(leave.cue_ball.x, cue.position.x);
    EXPECT_EQ(leave.cue_ball.y, cue.position.y);
  };
  check(r.plan.shot, r.leave);
  for (std::size_t k = 0; k < r.plan.alternatives.size(); ++k) check(r.plan.alternatives[k], r.alternative_leaves[k]);
}

TEST(PositionPlay, DoesAtLeastAsWellAsThePlanWithoutLookaheadAndBetterSomewhere) {
  int better = 0;
  for (unsigned seed = 10; seed < 16; ++seed) {
    SCOPED_TRACE(seed);
    const Scenario s = random_layout(seed);
    const PositionRequest q = request_for(1);
    PositionPlanResult with;
    try {
      with = plan_shot_for_position(s, q);
    } catch (const NoFeasibleShot&) {
      EXPECT_THROW(plan_shot(s, q.shot), NoFeasibleShot);
      continue;
    }
    PlanRequest centre = q.shot;
    centre.height = 0.0;  // the centre-ball plan is one of the candidates position play weighs
    double without = 0.0;
    try {
      without = two_ball_score(s, plan_shot(s, centre).shot, with.plan.cue_ball, 2, q.next_simulations);
    } catch (const NoFeasibleShot&) {
    }
    EXPECT_GE(with.leave.score, without);
    better += with.leave.score > without + 0.05 ? 1 : 0;
  }
  EXPECT_GE(better, 1);
}

TEST(PositionPlay, WithNoBallLeftAfterTheTargetThereIsNoLookahead) {
  const Scenario s = layout({{0, {0.6, 0.6}}, {1, {1.5, 0.8}}});
  const PositionPlanResult r = plan_shot_for_position(s, request_for(1));
  EXPECT_EQ(r.next_target, -1);
  EXPECT_EQ(r.leave.score, r.plan.shot.success_probability);
  EXPECT_FALSE(r.leave.next_feasible);
}

TEST(PositionPlay, BadInputNamesTheField) {
  const Scenario s = random_layout(3);
  const auto field = [&](PositionRequest q) -> std::string {
    try {
      plan_shot_for_position(s, q);
    } catch (const InvalidArgument& e) {
      return e.field();
    }
    return "(none)";
  };
  PositionRequest q = request_for(1);
  q.next_target = 7;
  EXPECT_EQ(field(q), "next");
  q.next_target = 0;  // the cue ball
  EXPECT_EQ(field(q), "next");
  q.next_target = 1;  // the target
  EXPECT_EQ(field(q), "next");
  q = request_for(1);
  q.next_simulations = 10;
  EXPECT_EQ(field(q), "next_simulations");
  q = request_for(5);
  EXPECT_EQ(field(q), "target");
}

}  // namespace
}  // namespace cueball
