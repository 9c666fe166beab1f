// The game ball by a combination through the ball on
// (src/agents/game_ball_combination.cpp): the game ball of each discipline;
// the run-out chance's closed form; the in-hand spots straight behind the
// ball on, none where a path is blocked; the planner agent with the option
// plays the 1 into the 9 where that wins more often than running the rack
// out, from where the cue ball lies and in hand, and the played shot wins
// the rack under the rules; without the option, or where the run-out is
// likelier, it pots the ball on; in 10-ball it calls the 10 in its pocket.
// Small budgets: the file runs in a few seconds in Release.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cueball/agents/agent.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

Vec2 unit(Vec2 v) { return v / norm(v); }

Vec2 pocket_centre(const Scenario& s, const std::string& name) {
  for (const Pocket& p : s.table.pockets)
    if (p.name == name) return p.centre;
  ADD_FAILURE() << "no pocket " << name;
  return {};
}

AgentOptions with_combinations(bool on) {
  AgentOptions o;
  o.kind = AgentKind::planner;
  o.simulations = 1000;
  o.game_ball_combinations = on;
  return o;
}

// The 1 and the 9 in line with the top-right pocket (the 9 0.3 m from it,
// the 1 0.2 m behind), the cue ball `cue_back` m behind the 1 on that line
// (none: in hand), and `others` of the balls 2-8 far from that line: the
// rack's nine balls take many shots to run out, the 9 one. Other distances
// make a harder combination.
struct LinedUp {
  GameState state;
  Vec2 nine, one, direction;
};

LinedUp lined_up(GameKind kind, std::optional<double> cue_back, int others, double nine_from_pocket = 0.3,
                 double one_behind = 0.2) {
  GameState s = new_game(default_config(kind));
  const Vec2 P = pocket_centre(s.table, "top-right");
  const Vec2 u = unit(Vec2{1.0, 1.0});
  const Vec2 nine = P - nine_from_pocket * u, one = nine - one_behind * u;
  const int game = kind == GameKind::ten_ball ? 10 : 9;
  std::vector<std::pair<int, Vec2>> balls{{1, one}, {game, nine}};
  if (cue_back) balls.insert(balls.begin(), {0, one - *cue_back * u});
  const std::vector<Vec2> spots{{0.4, 0.3}, {0.8, 0.95}, {1.2, 0.3}, {1.5, 1.0}, {0.4, 1.0}, {1.0, 0.6}, {2.3, 0.25}};
  for (int k = 0; k < others; ++k) balls.emplace_back(2 + k, spots[static_cast<std::size_t>(k)]);
  s = test::rotation_in_play(kind, balls);
  if (!cue_back) s.ball_in_hand = PlacementRegion{};
  return {s, nine, one, u};
}

TEST(GameBallCombination, TheGameBallIsTheNineOrTheTen) {
  EXPECT_EQ(game_ball(new_game(default_config(GameKind::nine_ball))), 9);
  EXPECT_EQ(game_ball(new_game(default_config(GameKind::ten_ball))), 10);
  EXPECT_FALSE(game_ball(new_game(default_config(GameKind::eight_ball))));
  EXPECT_FALSE(game_ball(new_game(default_config(GameKind::snooker))));
}

TEST(GameBallCombination, TheRunOutChanceIsThePotTimesItsLeaveTimesTheShotChanceForEachBallAfter) {
  EXPECT_DOUBLE_EQ(run_out_chance(0.9, 0.8, 3), 0.9 * 0.8 * std::pow(kRunOutShotChance, 3));
  EXPECT_DOUBLE_EQ(run_out_chance(0.9, 0.8, 0), 0.9 * 0.8);
  EXPECT_DOUBLE_EQ(run_out_chance(0.9, 0.8, -2), 0.9 * 0.8);  // nothing after the shots the leave covers
}

TEST(GameBallCombination, TheInHandSpotIsStraightBehindTheBallOnAndNoneWhereAPathIsBlocked) {
  const LinedUp l = lined_up(GameKind::nine_ball, std::nullopt, 7);
  const double R = l.state.table.settings.parameters.ball.radius;
  const std::vector<Vec2> spots = combination_in_hand_spots(l.state.table, 0, 1, 9, PlacementRegion{});
  ASSERT_FALSE(spots.empty());
  // The 1 straight at the 9's ghost ball for the top-right pocket: the cue
  // ball 2R + back behind the 1 on the line through it.
  const Vec2 ghost = l.nine - 2.0 * R * l.direction;
  const Vec2 expected = l.one - (2.0 * R + kGhostBallInHandBack) * unit(ghost - l.one);
  EXPECT_NEAR(norm(spots.front() - expected), 0.0, 1e-12);
  for (const Vec2& p : spots) EXPECT_TRUE(is_free_spot(l.state.table.table, {l.one, l.nine}, p, R));
  // A ball between the 1 and the 9: that pocket's spot is gone.
  GameState blocked = l.state;
  test::place_balls(blocked, {{1, l.one}, {9, l.nine}, {5, 0.5 * (l.one + l.nine)}});
  for (const Vec2& p : combination_in_hand_spots(blocked.table, 0, 1, 9, PlacementRegion{}))
    EXPECT_GT(norm(p - expected), 1e-6);
  // A region that leaves the spot out (the kitchen).
  PlacementRegion kitchen;
  kitchen.kind = PlacementRegion::Kind::behind_head_string;
  for (const Vec2& p : combination_in_hand_spots(l.state.table, 0, 1, 9, kitchen))
    EXPECT_TRUE(in_region(l.state.table.table, kitchen, p));
  EXPECT_TRUE(combination_in_hand_spots(l.state.table, 0, 9, 9, PlacementRegion{}).empty());
}

// The planner's choice `c` with the option, and the shot played noise-free
// under the rules.
void expect_plays_the_combination(const GameState& s, const PlannerChoice& c, std::uint64_t seed) {
  ASSERT_EQ(c.kind, PlannerChoice::Kind::pot) << c.detail;
  EXPECT_NE(c.detail.find("combination 9 via 1"), std::string::npos) << c.detail;
  EXPECT_NE(c.detail.find("against a run-out"), std::string::npos) << c.detail;
  EXPECT_GE(c.success_probability, kSafetyThreshold);
  EXPECT_EQ(c.next_success_probability, -1.0);
  EXPECT_EQ(c.considered.front().estimate, c.success_probability);
  const GameStep step = play(s, c.action, seed);
  EXPECT_EQ(step.facts.first_contact, 1);
  EXPECT_TRUE(step.facts.pocketed(9));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, s.to_shoot);
}

TEST(GameBallCombination, ThePlannerSendsTheOneIntoTheNineWhenThatBeatsTheRunOut) {
  const GameState s = lined_up(GameKind::nine_ball, 0.4, 7).state;
  expect_plays_the_combination(s, planner_choice(with_combinations(true), s, 3), 3);
  const PlannerChoice without = planner_choice(with_combinations(false), s, 3);
  EXPECT_EQ(without.detail.find("via 1"), std::string::npos) << without.detail;
}

TEST(GameBallCombination, InHandTheCueBallGoesBehindTheOne) {
  const GameState s = lined_up(GameKind::nine_ball, std::nullopt, 1).state;
  const PlannerChoice c = planner_choice(with_combinations(true), s, 4);
  ASSERT_TRUE(c.action.place) << c.detail;
  const std::vector<Vec2> spots = combination_in_hand_spots(s.table, 0, 1, 9, PlacementRegion{});
  EXPECT_TRUE(std::any_of(spots.begin(), spots.end(), [&](Vec2 p) { return norm(p - *c.action.place) == 0.0; }));
  expect_plays_the_combination(s, c, 4);
}

// The rule, on layouts where it goes either way: the combination is played
// exactly where it is found, is at least kSafetyThreshold and beats the
// run-out from the pot of the 1 the agent plays without it (no position
// play: the leave counts 1, each ball after the 1 kRunOutShotChance).
TEST(GameBallCombination, TheCombinationIsPlayedExactlyWhereItBeatsTheRunOut) {
  int played = 0, kept = 0;
  const auto check = [&](const GameState& s, std::uint64_t seed) {
    PlanRequest q;
    q.noise = tournament_noise();
    q.seed = seed;
    q.simulations = with_combinations(true).simulations;
    long long simulations = 0;
    const std::optional<GameBallCombination> c = plan_game_ball_combination(s, legal_actions(s), q, simulations);
    ASSERT_TRUE(c);
    const PlannerChoice pot = planner_choice(with_combinations(false), s, seed);
    ASSERT_EQ(pot.kind, PlannerChoice::Kind::pot) << pot.detail;
    const double run_out =
        run_out_chance(pot.success_probability, 1.0, static_cast<int>(object_balls(s).size()) - 1);
    const bool expected = c->shot.success_probability > run_out && c->shot.success_probability >= kSafetyThreshold;
    const PlannerChoice choice = planner_choice(with_combinations(true), s, seed);
    EXPECT_EQ(choice.detail.find("via 1") != std::string::npos, expected)
        << choice.detail << " | " << c->shot.success_probability << " against " << run_out;
    EXPECT_NE(choice.detail.find("the game ball by a combination"), std::string::npos) << choice.detail;
    (expected ? played : kept) += 1;
  };
  check(lined_up(GameKind::nine_ball, 0.4, 7).state, 3);
  // The 1 straight in the top-right corner from the cue ball; the 9 near
  // the top rail, beside the 1's path: a thin combination into the same
  // corner, with only the 9 after the 1.
  GameState s = new_game(default_config(GameKind::nine_ball));
  const Vec2 P = pocket_centre(s.table, "top-right");
  const Vec2 one = P + Vec2{-0.54, -0.52};
  check(test::rotation_in_play(GameKind::nine_ball,
                               {{0, one - 0.4 * unit(P - one)}, {1, one}, {9, P + Vec2{-0.34, -0.07}}}),
        5);
  EXPECT_GT(played, 0);
  EXPECT_GT(kept, 0);
}

TEST(GameBallCombination, TenBallCallsTheTenInItsPocket) {
  const GameState s = lined_up(GameKind::ten_ball, 0.4, 7).state;
  const PlannerChoice c = planner_choice(with_combinations(true), s, 6);
  ASSERT_NE(c.detail.find("combination 10 via 1"), std::string::npos) << c.detail;
  ASSERT_TRUE(c.action.called_ball);
  EXPECT_EQ(*c.action.called_ball, 10);
  ASSERT_TRUE(c.action.called_pocket);
  EXPECT_EQ(s.table.table.pockets[static_cast<std::size_t>(*c.action.called_pocket)].name, "top-right");
  const GameStep step = play(s, c.action, 6);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, s.to_shoot);
}

TEST(GameBallCombination, NoneInOtherGamesOrWhenTheNineIsTheBallOn) {
  long long simulations = 0;
  PlanRequest q;
  q.simulations = 1000;
  GameState eight = lined_up(GameKind::nine_ball, 0.4, 7).state;
  eight.config.kind = GameKind::eight_ball;
  EXPECT_FALSE(plan_game_ball_combination(eight, legal_actions(lined_up(GameKind::nine_ball, 0.4, 7).state), q,
                                          simulations));
  const GameState last = test::rotation_in_play(GameKind::nine_ball, {{0, {0.5, 0.5}}, {9, {1.5, 0.6}}});
  EXPECT_FALSE(plan_game_ball_combination(last, legal_actions(last), q, simulations));
  EXPECT_EQ(simulations, 0);
}

}  // namespace
}  // namespace cueball
