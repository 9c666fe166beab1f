// Tests of ball in hand (src/planning/ball_in_hand.cpp): the spot is a legal place
// with the shot planned from it potting the target, it scores at least as
// well as a straight-in placed by hand, it stays in the region given, it is
// deterministic, and bad input and layouts with no spot say why; where no
// straight pot exists, the ghost-ball valuation falls back to the window
// search of the grid and finds the bank. The grid is also exercised by the
// run-outs of cueball-planner-benchmark (docs/planner-benchmark.md).
#include "cueball/planning/ball_in_hand.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ball_layout.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"
#include "cueball/simulation/simulator.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/planning/ghost_ball.hpp"
#include "cueball/table/rack.hpp"

namespace cueball {
namespace {

using test::layout;

BallInHandRequest request_for(int target) {
  BallInHandRequest q;
  q.position.shot.target = target;
  q.position.shot.simulations = 1000;
  q.position.next_simulations = 500;
  return q;
}

// The 1 near the foot spot, the 2 on the far side of the table, the cue
// ball wherever the last shot left it (in a corner, to be moved).
Scenario two_balls() { return layout({{0, {0.2, 0.2}}, {1, {1.9, 0.7}}, {2, {0.9, 0.35}}}); }

TEST(BallInHand, PlacesTheCueBallOnAFreeSpotAndTheShotFromThereDropsTheTarget) {
  const Scenario s = two_balls();
  const BallInHandRequest q = request_for(1);
  const BallInHandResult r = plan_ball_in_hand(s, q);
  const double R = s.settings.parameters.ball.radius;
  EXPECT_GT(r.spots, 0);
  EXPECT_GE(r.spots_played, 1);
  EXPECT_LE(static_cast<std::size_t>(r.spots_played), kInHandSpots);
  EXPECT_TRUE(ball_on_table(s.table, r.cue_ball, R));
  // The table: the cue ball at the spot, every other ball where it was.
  ASSERT_EQ(r.table.balls.size(), s.balls.size());
  for (const SimulationBall& b : r.table.balls) {
    if (b.id == 0) {
      EXPECT_EQ(b.state.position.x, r.cue_ball.x);
      EXPECT_EQ(b.state.position.y, r.cue_ball.y);
      continue;
    }
    for (const SimulationBall& o : s.balls)
      if (o.id == b.id) {
        EXPECT_EQ(b.state.position.x, o.state.position.x);
        EXPECT_GE(norm(o.state.position - r.cue_ball), 2.0 * R + kInHandGap);
      }
  }
  // The planned shot, replayed noise-free from the spot, drops the 1 and not the cue ball.
  const SimulationResult played = run_scenario(scenario_with_shot(r.table, 0, r.plan.plan.shot, q.position.shot.noise));
  for (const BallTrajectory& b : played.balls) EXPECT_EQ(b.pocketed, b.id == 1) << "ball " << b.id;
  EXPECT_EQ(r.plan.next_target, 2);
  EXPECT_GT(r.plan.plan.shot.success_probability, 0.5);
}

TEST(BallInHand, ScoresAtLeastAsWellAsAStraightInPlacedByHand) {
  const Scenario s = two_balls();
  const BallInHandRequest q = request_for(1);
  const BallInHandResult r = plan_ball_in_hand(s, q);
  // By hand: a straight-in into the nearest pocket, 0.3 m behind the ghost ball.
  const double R = s.settings.parameters.ball.radius;
  const Vec2 O{1.9, 0.7};
  const Pocket* nearest = &s.table.pockets.front();
  for (const Pocket& p : s.table.pockets)
    if (norm(p.centre - O) < norm(nearest->centre - O)) nearest = &p;
  const Vec2 u = (nearest->centre - O) / norm(nearest->centre - O);
  Scenario by_hand = s;
  by_hand.balls[0].state.position = O - (2.0 * R + 0.3) * u;
  const PositionPlanResult h = plan_shot_for_position(by_hand, q.position);
  // Both scores are estimates (the pot screened on 200 shots): not worse by
  // more than three of the screen's standard errors.
  const double se = std::sqrt(0.25 / (q.position.shot.simulations / kPositionScreenFraction));
  EXPECT_GE(r.plan.leave.score, h.leave.score - 3.0 * se);
}

// LeaveValuation::ghost_ball: the spots scored by their ghost-ball chance,
// no engine run for them; the spot chosen is as legal and its shot pots.
TEST(BallInHand, TheGhostBallValuationPlacesTheCueBallWithFewerRunsAndPots) {
  const Scenario s = two_balls();
  BallInHandRequest q = request_for(1);
  const BallInHandResult by_windows = plan_ball_in_hand(s, q);
  q.position.valuation = LeaveValuation::ghost_ball;
  const BallInHandResult r = plan_ball_in_hand(s, q);
  EXPECT_LT(r.plan.plan.simulations, by_windows.plan.plan.simulations);
  EXPECT_TRUE(ball_on_table(s.table, r.cue_ball, s.settings.parameters.ball.radius));
  const SimulationResult played = run_scenario(scenario_with_shot(r.table, 0, r.plan.plan.shot, q.position.shot.noise));
  for (const BallTrajectory& b : played.balls) EXPECT_EQ(b.pocketed, b.id == 1) << "ball " << b.id;
  EXPECT_GT(r.plan.plan.shot.success_probability, 0.5);
  EXPECT_EQ(r.plan.leave.next_kind, r.plan.leave.next_feasible ? "direct" : "");
}

TEST(BallInHand, StaysInTheRegionAndIsDeterministic) {
  const Scenario s = two_balls();
  BallInHandRequest q = request_for(1);
  q.region = InHandRegion{0.0, 1.3, 0.0, 1.3};  // the half of the table away from the 1
  const BallInHandResult a = plan_ball_in_hand(s, q);
  EXPECT_LE(a.cue_ball.x, 1.3);
  const BallInHandResult b = plan_ball_in_hand(s, q);
  EXPECT_EQ(a.cue_ball.x, b.cue_ball.x);
  EXPECT_EQ(a.cue_ball.y, b.cue_ball.y);
  EXPECT_EQ(a.plan.plan.shot.strike.aim_deg, b.plan.plan.shot.strike.aim_deg);
  EXPECT_EQ(a.plan.plan.shot.strike.speed, b.plan.plan.shot.strike.speed);
  EXPECT_EQ(a.plan.plan.simulations, b.plan.plan.simulations);
}

// The table-level regions (placement.hpp): the kitchen on a pool table, the
// D on a snooker table; the old rectangle type converts to the same plan.
TEST(BallInHand, PlacesInTheKitchenAndInTheD) {
  const Scenario s = two_balls();
  BallInHandRequest q = request_for(1);
  q.region = PlacementRegion{PlacementRegion::Kind::behind_head_string};
  const BallInHandResult kitchen = plan_ball_in_hand(s, q);
  EXPECT_LE(kitchen.cue_ball.x, head_string_x(s.table) + kPlacementTolerance);

  const Scenario snooker = scenario_from_json(R"({"table": "snooker_12ft",
      "balls": [{"id": 0, "position": [0.3, 0.9]}, {"id": 1, "position": [2.6, 1.2]}]})");
  q.region = PlacementRegion{PlacementRegion::Kind::inside_d};
  const BallInHandResult d = plan_ball_in_hand(snooker, q);
  EXPECT_TRUE(in_region(snooker.table, *q.region, d.cue_ball));
  const SnookerSpots spots = snooker_spots(snooker.table);
  EXPECT_LE(norm(d.cue_ball - spots.brown), spots.d_radius + 1e-9);

  BallInHandRequest old = request_for(1), now = request_for(1);
  old.region = InHandRegion{0.0, 1.3, 0.0, 1.3};
  now.region = PlacementRegion{PlacementRegion::Kind::rectangle, 0.0, 1.3, 0.0, 1.3};
  EXPECT_EQ(plan_ball_in_hand(s, old).cue_ball.x, plan_ball_in_hand(s, now).cue_ball.x);
}

TEST(BallInHand, ATargetWithEveryPathBlockedHasNoSpotOnTheGridEither) {
  // The 1 ringed by six balls at 2R + 1 mm: no straight path to any pocket,
  // and from the grid's places no shot reaches it.
  const double R = layout({}).settings.parameters.ball.radius;
  const Vec2 O{1.27, 0.635};
  std::vector<test::Placed> balls{{0, {0.3, 0.3}}, {1, O}};
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::acos(-1.0) / 3.0 + 0.3;
    balls.push_back({2 + k, O + (2.0 * R + 1e-3) * Vec2{std::cos(a), std::sin(a)}});
  }
  try {
    plan_ball_in_hand(layout(balls), request_for(1));
    FAIL() << "expected NoFeasibleShot";
  } catch (const NoFeasibleShot& e) {
    EXPECT_NE(std::string(e.what()).find("no spot for the cue ball pots ball 1 ("), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("places on a grid tried"), std::string::npos) << e.what();
  }
}

// The 1 with a ball on its straight path to each of the six pockets, 0.2 m
// out, and the cue ball in the corner.
Scenario every_straight_path_blocked() {
  const Scenario empty = layout({});
  const Vec2 O{1.9, 0.5};
  std::vector<test::Placed> balls{{0, {0.2, 0.2}}, {1, O}};
  for (std::size_t k = 0; k < empty.table.pockets.size(); ++k) {
    const Vec2 P = empty.table.pockets[k].centre;
    balls.push_back({2 + static_cast<int>(k), O + 0.2 * (P - O) / norm(P - O)});
  }
  return layout(balls);
}

// The ghost-ball chance sees straight pots only: where there is none from
// anywhere, the grid's places are scored by the engine's window search
// instead, and the bank it finds is played (before, no spot was found and
// the strongest agent played safe with ball in hand).
TEST(BallInHand, WithNoStraightPotTheGhostBallValuationFallsBackToTheWindowSearch) {
  const Scenario s = every_straight_path_blocked();
  BallInHandRequest q = request_for(1);
  q.position.valuation = LeaveValuation::ghost_ball;
  // No straight pot from here, nor from anywhere: each of the 1's paths to a pocket is blocked.
  EXPECT_TRUE(ghost_ball_pots(s, 0, {1}).empty());
  const BallInHandResult r = plan_ball_in_hand(s, q);
  EXPECT_NE(r.plan.plan.shot.kind, ShotKind::direct);
  EXPECT_GT(r.plan.plan.shot.success_probability, 0.0);
  EXPECT_TRUE(ball_on_table(s.table, r.cue_ball, s.settings.parameters.ball.radius));
  const SimulationResult played = run_scenario(scenario_with_shot(r.table, 0, r.plan.plan.shot, CueStrikeNoise{}));
  for (const BallTrajectory& b : played.balls) EXPECT_EQ(b.pocketed, b.id == 1) << "ball " << b.id;
  // The window search's spot, as the windows valuation scores the grid.
  q.position.valuation = LeaveValuation::windows;
  EXPECT_NO_THROW(plan_ball_in_hand(s, q));
}

TEST(BallInHand, AmongLegalTargetsPlacesTheCueBallForTheOneThatCanBePotted) {
  // The 1 ringed as above, the 9 open: with both legal, the cue ball goes
  // behind a ghost ball of the 9 and the shot drops it.
  const double R = layout({}).settings.parameters.ball.radius;
  const Vec2 O{1.27, 0.635};
  std::vector<test::Placed> balls{{0, {0.3, 0.3}}, {1, O}, {9, {2.0, 0.4}}};
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::acos(-1.0) / 3.0 + 0.3;
    balls.push_back({2 + k, O + (2.0 * R + 1e-3) * Vec2{std::cos(a), std::sin(a)}});
  }
  const Scenario s = layout(balls);
  BallInHandRequest q = request_for(1);
  q.position.shot.targets = {1, 9};
  const BallInHandResult r = plan_ball_in_hand(s, q);
  EXPECT_EQ(r.plan.plan.shot.target, 9);
  const SimulationResult played = run_scenario(scenario_with_shot(r.table, 0, r.plan.plan.shot, q.position.shot.noise));
  for (const BallTrajectory& b : played.balls) {
    if (b.id == 9 || b.id == 0) {
      EXPECT_EQ(b.pocketed, b.id == 9) << "ball " << b.id;
    }
  }
  q.position.shot.targets = {1, 12};
  try {
    plan_ball_in_hand(s, q);
    ADD_FAILURE() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.field(), "targets") << e.what();
  }
}

TEST(BallInHand, BadInputNamesTheField) {
  const Scenario s = two_balls();
  const auto field = [&](const BallInHandRequest& q) -> std::string {
    try {
      plan_ball_in_hand(s, q);
    } catch (const InvalidArgument& e) {
      return e.field();
    }
    return "(none)";
  };
  BallInHandRequest q = request_for(1);
  q.region = InHandRegion{1.0, 0.5, 0.0, 1.0};
  EXPECT_EQ(field(q), "region");
  q.region = InHandRegion{0.0, 1.0, 0.0, std::nan("")};
  EXPECT_EQ(field(q), "region");
  // Issue 24: a region wholly off the table was NoFeasibleShot (exit 3), not bad input.
  for (const InHandRegion off : {InHandRegion{5.0, 6.0, 0.2, 0.8}, InHandRegion{-1.0, 0.0, 0.2, 0.8},
                                 InHandRegion{0.5, 1.0, -0.5, -0.1}, InHandRegion{0.5, 1.0, s.table.width, 2.0}}) {
    q.region = off;
    EXPECT_EQ(field(q), "region") << off.x_min << " " << off.y_min;
  }
  EXPECT_EQ(field(request_for(0)), "target");  // the cue ball
  EXPECT_EQ(field(request_for(7)), "target");
  q = request_for(1);
  q.position.next_target = 1;
  EXPECT_EQ(field(q), "next");
}

}  // namespace
}  // namespace cueball
