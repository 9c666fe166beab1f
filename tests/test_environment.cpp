// src/rl/environment.cpp: episodes, steps, rewards and the bounds of the
// learning environment.
#include <gtest/gtest.h>

#include <cmath>

#include "cueball/core/errors.hpp"
#include "cueball/rl/environment.hpp"
#include "expect_invalid.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

EnvAction aimed(double speed_unit, double aim_unit) {
  EnvAction a;
  a.strike = {speed_unit, aim_unit, -1.0, 0.0, 0.0};
  return a;
}

// A seed gives the same episode, step for step; another seed another one.
TEST(Environment, IsDeterministicForASeed) {
  EnvOptions o;
  o.noise.base = CueStrikeNoise{0.075, 0.002, 0.0, 0.0, 0.0};
  EnvTable a, b, c;
  env_reset(o, a, 11);
  env_reset(o, b, 11);
  env_reset(o, c, 12);
  EXPECT_EQ(a.observation, b.observation);
  for (int k = 0; k < 6 && !a.state.over; ++k) {
    const EnvAction act = aimed(0.2 * k - 0.5, 0.3 * k - 0.7);
    const EnvStepResult ra = env_step(o, a, act);
    const EnvStepResult rb = env_step(o, b, act);
    EXPECT_EQ(a.observation, b.observation);
    EXPECT_EQ(ra.reward, rb.reward);
    EXPECT_TRUE(a.state == b.state);
  }
  EXPECT_NE(a.game_seed, c.game_seed);
}

// Against an opponent every step ends on the learner's turn (or the game's
// end); the recommended break is played for whoever breaks.
TEST(Environment, TheOpponentRepliesUntilItIsTheLearnersTurn) {
  EnvOptions o;
  o.opponent.kind = AgentKind::random;
  o.seat = 1;  // the opponent breaks
  EnvTable t;
  env_reset(o, t, 3);
  EXPECT_NE(t.state.phase, GamePhase::break_shot);
  EXPECT_TRUE(t.state.over || t.state.to_shoot == 1);
  int steps = 0;
  while (!t.state.over && steps < 200) {
    const EnvStepResult r = env_step(o, t, aimed(0.0, 0.1 * steps));
    EXPECT_EQ(r.player, 1);
    ASSERT_FALSE(r.players.empty());
    EXPECT_EQ(r.players.front(), 1);
    EXPECT_TRUE(t.state.over || t.state.to_shoot == 1);
    ++steps;
  }
  EXPECT_TRUE(t.state.over);
}

// An opponent given in full (EnvOpponent::agent, how "strongest" is given)
// plays those options: the same as the kind and budget it names, step for
// step; none of the two is self-play; a bad field is named as
// validate(AgentOptions) names it, under "opponent.".
TEST(Environment, AnOpponentGivenInFullPlaysThoseOptions) {
  EnvOptions by_kind;
  by_kind.opponent.kind = AgentKind::random;
  by_kind.seat = 1;
  EnvOptions in_full = by_kind;
  in_full.opponent.kind = AgentKind::ghost_ball;  // not read when agent is set
  AgentOptions random;
  random.kind = AgentKind::random;
  random.simulations = by_kind.opponent.simulations;
  in_full.opponent.agent = random;
  ASSERT_TRUE(opponent_agent(in_full.opponent));
  EXPECT_EQ(opponent_agent(in_full.opponent)->kind, AgentKind::random);
  EXPECT_EQ(opponent_agent(by_kind.opponent)->simulations, 300);
  EXPECT_FALSE(opponent_agent(EnvOpponent{std::nullopt, 300, std::nullopt}));
  EnvTable a, b;
  env_reset(by_kind, a, 5);
  env_reset(in_full, b, 5);
  for (int step = 0; step < 12 && !a.state.over; ++step) {
    const EnvStepResult ra = env_step(by_kind, a, aimed(0.0, 0.3 * step));
    const EnvStepResult rb = env_step(in_full, b, aimed(0.0, 0.3 * step));
    EXPECT_EQ(ra.players, rb.players);
    EXPECT_EQ(a.state, b.state) << "step " << step;
  }
  EnvOptions bad = in_full;
  bad.opponent.agent->simulations = 0;
  test::expect_invalid("opponent.simulations", [&] { validate(bad); });
}

// An illegal action is a foul stroke: nothing moves, the opponent (self-play:
// the other player) has ball in hand, the illegal and foul terms count it.
TEST(Environment, AnIllegalActionIsAFoulNotAnError) {
  EnvOptions o;
  o.opponent.kind.reset();
  o.reward = {0.0, 0.0, 0.0, -1.0, -10.0};
  EnvTable t;
  env_reset(o, t, 5);
  ASSERT_FALSE(t.state.over);
  const GameState before = t.state;
  EnvAction a = aimed(0.0, 0.0);
  a.decision = 3;
  const EnvStepResult r = env_step(o, t, a);
  EXPECT_EQ(r.illegal.rfind("decision", 0), 0u) << r.illegal;
  ASSERT_EQ(r.rulings.size(), 1u);
  ASSERT_TRUE(r.rulings[0].foul);
  EXPECT_EQ(*r.rulings[0].foul, Foul::miscue);
  EXPECT_EQ(r.terms[static_cast<std::size_t>(r.player)].illegal, 1.0);
  EXPECT_EQ(r.terms[static_cast<std::size_t>(r.player)].fouls, 1.0);
  EXPECT_DOUBLE_EQ(r.reward, -11.0);
  EXPECT_EQ(t.state.to_shoot, 1 - before.to_shoot);
  EXPECT_TRUE(t.state.ball_in_hand);
  for (std::size_t i = 0; i < before.table.balls.size(); ++i)
    EXPECT_EQ(t.state.table.balls[i].state.position, before.table.balls[i].state.position);
}

// The win term: +1 to the winner, -1 to the loser, and the game's end is
// `terminated`; self-play rewards are zero-sum with win alone.
TEST(Environment, WinRewardsAreZeroSumAndEndTheEpisode) {
  EnvOptions o;
  o.opponent.kind.reset();
  EnvTable t;
  env_reset(o, t, 8);
  EnvStepResult last;
  for (int k = 0; k < 300 && !t.state.over; ++k) {
    EnvAction a = aimed(0.3, std::sin(k) * 0.9);
    a.decision = t.state.phase == GamePhase::decision ? 1 + static_cast<int>(t.state.decisions.front()) : 0;
    last = env_step(o, t, a);
    EXPECT_DOUBLE_EQ(last.rewards[0] + last.rewards[1], 0.0);
  }
  ASSERT_TRUE(t.state.over);
  EXPECT_TRUE(last.terminated || last.truncated);
  if (last.terminated) {
    ASSERT_TRUE(t.state.winner);
    EXPECT_EQ(last.rewards[static_cast<std::size_t>(*t.state.winner)], 1.0);
  }
  EXPECT_THROW(env_step(o, t, EnvAction{}), InvalidArgument);
}

// max_shots bounds every episode: truncated, never endless.
TEST(Environment, MaxShotsTruncates) {
  EnvOptions o;
  o.opponent.kind.reset();
  o.max_shots = 3;
  EnvTable t;
  env_reset(o, t, 2);
  EnvStepResult r;
  int steps = 0;
  while (!t.state.over) {
    r = env_step(o, t, aimed(-0.9, 0.0));  // soft shots
    ASSERT_LT(++steps, 4);
  }
  EXPECT_TRUE(r.truncated);
  EXPECT_FALSE(r.terminated);
}

// From a given position, and the mirror symmetry of the physics: the mirror
// image of a position played with the mirrored action ends in the mirror
// image (no noise), exactly up to rounding.
TEST(Environment, AMirroredPositionAndActionEndMirrored) {
  EnvOptions o;
  o.opponent.kind.reset();
  o.form = ActionForm::target;
  const double w = 1.27;
  const GameState s = test::rotation_in_play(GameKind::nine_ball, {{0, {0.7, 0.4}}, {1, {1.6, 0.55}}, {9, {2.0, 0.9}}});
  GameState m = test::rotation_in_play(GameKind::nine_ball, {{0, {0.7, w - 0.4}}, {1, {1.6, w - 0.55}}, {9, {2.0, w - 0.9}}});
  EnvTable a, b;
  env_reset_from(o, a, s);
  env_reset_from(o, b, m);
  std::vector<float> mirrored = a.observation;
  mirror_observation(GameKind::nine_ball, mirrored.data());
  for (std::size_t i = 0; i < mirrored.size(); ++i) EXPECT_NEAR(b.observation[i], mirrored[i], 1e-6) << i;
  EnvAction act;
  act.strike = {-0.2, 0.1, -0.8, 0.3, -0.4};
  act.ball = 1;
  act.pocket = 2;
  env_step(o, a, act);
  env_step(o, b, mirror_action(s.table.table, act));
  ASSERT_EQ(a.state.table.balls.size(), b.state.table.balls.size());
  for (std::size_t i = 0; i < a.state.table.balls.size(); ++i) {
    EXPECT_NEAR(a.state.table.balls[i].state.position.x, b.state.table.balls[i].state.position.x, 1e-9);
    EXPECT_NEAR(a.state.table.balls[i].state.position.y, w - b.state.table.balls[i].state.position.y, 1e-9);
  }
  GameState other = new_game(default_config(GameKind::snooker));
  EXPECT_THROW(env_reset_from(o, a, other), InvalidArgument);
}

TEST(Environment, BadOptionsNameTheField) {
  auto field_of = [](EnvOptions o) {
    try {
      validate(o);
    } catch (const InvalidArgument& e) {
      return e.field();
    }
    return std::string();
  };
  EnvOptions o;
  o.max_shots = 0;
  EXPECT_EQ(field_of(o), "max_shots");
  o = EnvOptions{};
  o.max_speed = 13.0;
  EXPECT_EQ(field_of(o), "max_speed");
  o = EnvOptions{};
  o.seat = 2;
  EXPECT_EQ(field_of(o), "seat");
  o = EnvOptions{};
  o.noise.scale_min = 2.0;
  o.noise.scale_max = 1.0;
  EXPECT_EQ(field_of(o), "noise.scale");
  o = EnvOptions{};
  o.reward.pots = std::nan("");
  EXPECT_EQ(field_of(o), "reward");
}

// Every discipline plays whole episodes with arbitrary actions, bounded.
TEST(Environment, EveryDisciplinePlaysToTheEnd) {
  for (const GameKind kind : kGameKinds) {
    EnvOptions o;
    o.game = kind;
    o.opponent.kind = AgentKind::random;
    o.max_shots = 60;
    EnvTable t;
    env_reset(o, t, 21);
    RandomStream rng(4);
    int steps = 0;
    while (!t.state.over) {
      EnvAction a;
      for (double& x : a.strike) x = rng.uniform(-1, 1);
      for (double& x : a.place) x = rng.uniform(-1, 1);
      const ActionMasks m = action_masks(t.state);
      a.decision = m.decision[0] ? 0 : 1 + static_cast<int>(t.state.decisions.front());
      for (std::size_t id = 0; id < m.ball.size(); ++id)
        if (m.ball[id]) a.ball = static_cast<int>(id);
      env_step(o, t, a);
      ASSERT_LE(++steps, 60) << to_string(kind);
    }
  }
}

}  // namespace
}  // namespace cueball
