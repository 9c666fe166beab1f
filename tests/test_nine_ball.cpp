// 9-ball's rules (src/games/nine_ball.cpp): each foul, win and decision
// from a crafted table and strike whose ruling is known, then random games.
#include <gtest/gtest.h>

#include <cmath>

#include "cueball/core/random.hpp"
#include "cueball/games/game.hpp"
#include "expect_invalid.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

using test::aim_deg;
using test::strike;


// A 9-ball game in play (after the break) with exactly these balls.
GameState in_play(const std::vector<std::pair<int, Vec2>>& balls) {
  return test::rotation_in_play(GameKind::nine_ball, balls);
}

// The bottom-left corner pocket's centre and a straight line into it.
Vec2 corner(const GameState& s) { return s.table.table.pockets[0].centre; }

TEST(NineBall, StraightInPotKeepsTheTurn) {
  // The 1 half a metre from the bottom-left pocket on the diagonal, the cue
  // ball behind it, the 2 far away: a legal pot, the shooter continues.
  GameState s = in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {2, {2.0, 1.0}}, {9, {2.2, 0.3}}});
  const Vec2 pocket = corner(s);
  Action a = strike(2.0, aim_deg({0.9, 0.9}, {0.45, 0.45}));
  a.strike.height = -0.3;  // draw: the cue ball stays out of the pocket
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(1)) << "pocket " << pocket.x << "," << pocket.y;
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_FALSE(step.ruling.turn_over);
  EXPECT_EQ(step.next.to_shoot, 0);
  EXPECT_EQ(step.next.on, std::vector<int>{2});
  EXPECT_FALSE(step.next.ball_in_hand);
}

TEST(NineBall, ScratchGivesBallInHandAnywhere) {
  GameState s = in_play({{0, {0.5, 0.5}}, {1, {2.0, 1.0}}, {9, {2.2, 0.3}}});
  const GameStep step = play(s, strike(2.0, 225.0), 1);  // straight into the bottom-left pocket
  ASSERT_TRUE(step.facts.pocketed(0));
  EXPECT_EQ(step.ruling.foul, Foul::scratch);
  EXPECT_TRUE(step.ruling.turn_over);
  EXPECT_EQ(step.next.to_shoot, 1);
  ASSERT_TRUE(step.next.ball_in_hand);
  EXPECT_EQ(step.next.ball_in_hand->kind, PlacementRegion::Kind::anywhere);
  EXPECT_EQ(step.next.fouls_in_a_row[0], 1);
  EXPECT_FALSE(find_ball(step.next.table.balls, 0));
  // The incoming player must place the cue ball, inside the bed, on no ball.
  test::expect_invalid("place", [&] { (void)play(step.next, strike(2.0, 0.0), 2); });
  Action on_a_ball = strike(2.0, 0.0);
  on_a_ball.place = Vec2{2.0, 1.0};
  test::expect_invalid("place", [&] { (void)play(step.next, on_a_ball, 2); });
  Action placed = strike(2.0, aim_deg({1.0, 0.6}, {2.0, 1.0}));
  placed.place = Vec2{1.0, 0.6};
  const GameStep next = play(step.next, placed, 2);
  EXPECT_EQ(next.facts.first_contact, 1);
}

TEST(NineBall, WrongBallFirstIsAFoul) {
  // The 3 straight ahead, the 2 (lowest) elsewhere.
  GameState s = in_play({{0, {1.0, 0.6}}, {2, {2.2, 1.0}}, {3, {1.5, 0.6}}, {9, {2.2, 0.3}}});
  const GameStep step = play(s, strike(3.0, 0.0), 1);
  EXPECT_EQ(step.facts.first_contact, 3);
  EXPECT_EQ(step.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(step.next.to_shoot, 1);
  ASSERT_TRUE(step.next.ball_in_hand);
}

TEST(NineBall, NoContactIsAFoul) {
  GameState s = in_play({{0, {1.0, 0.6}}, {1, {2.2, 1.0}}, {9, {2.2, 0.3}}});
  const GameStep step = play(s, strike(1.0, 180.0), 1);  // towards the empty head end
  EXPECT_EQ(step.facts.first_contact, -1);
  EXPECT_EQ(step.ruling.foul, Foul::no_contact);
}

TEST(NineBall, NoRailAfterContactIsAFoul) {
  // A soft tap on the 1 in the middle of the table: nothing reaches a rail.
  GameState s = in_play({{0, {1.0, 0.635}}, {1, {1.3, 0.635}}, {9, {2.2, 0.3}}});
  const GameStep step = play(s, strike(0.6, 0.0), 1);
  ASSERT_EQ(step.facts.first_contact, 1);
  ASSERT_TRUE(step.facts.cushions.empty());
  EXPECT_EQ(step.ruling.foul, Foul::no_rail_after_contact);
}

TEST(NineBall, TheNineOnALegalShotWins) {
  GameState s = in_play({{0, {0.9, 0.9}}, {9, {0.45, 0.45}}});
  Action a = strike(2.0, aim_deg({0.9, 0.9}, {0.45, 0.45}));
  a.strike.height = -0.3;
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(9));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 0);
  EXPECT_TRUE(step.next.over);
  EXPECT_EQ(step.next.scores[0], 1);
  test::expect_invalid("action", [&] { (void)play(step.next, strike(1.0, 0.0), 2); });
}

TEST(NineBall, TheNineOnAFoulIsRespotted) {
  // Combination the wrong way round: the 9 is hit first (the 1 is on) and drops.
  GameState s = in_play({{0, {0.9, 0.9}}, {1, {2.0, 1.0}}, {9, {0.45, 0.45}}});
  Action a = strike(2.0, aim_deg({0.9, 0.9}, {0.45, 0.45}));
  a.strike.height = -0.3;
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(9));
  EXPECT_EQ(step.ruling.foul, Foul::wrong_ball_first);
  EXPECT_FALSE(step.ruling.game_over);
  ASSERT_EQ(step.ruling.respotted, std::vector<int>{9});
  const SimulationBall* nine = find_ball(step.next.table.balls, 9);
  ASSERT_TRUE(nine);
  EXPECT_NEAR(nine->state.position.y, long_string_y(s.table.table), 1e-12);
  EXPECT_NEAR(nine->state.position.x, foot_spot(s.table.table).x, 1e-12);
}

TEST(NineBall, ThreeConsecutiveFoulsLose) {
  GameState s = in_play({{0, {1.0, 0.6}}, {1, {2.2, 1.0}}, {9, {2.2, 0.3}}});
  s.fouls_in_a_row = {2, 0};
  const GameStep step = play(s, strike(1.0, 180.0), 1);
  EXPECT_EQ(step.ruling.foul, Foul::no_contact);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 1);
  EXPECT_EQ(step.next.scores, (std::array<int, 2>{0, 1}));
  // With the rule off, the game goes on.
  s.config.fouls_to_lose = 0;
  EXPECT_FALSE(play(s, strike(1.0, 180.0), 1).ruling.game_over);
}

TEST(NineBall, PushOutThenPassBack) {
  GameState s = in_play({{0, {1.0, 0.6}}, {1, {2.2, 1.0}}, {9, {2.2, 0.3}}});
  s.push_out_available = true;
  EXPECT_TRUE(legal_actions(s).push_out);
  Action push = strike(0.8, 180.0);  // touches nothing: legal as a push-out (WPA 2.4)
  push.push_out = true;
  const GameStep step = play(s, push, 1);
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_TRUE(step.ruling.push_out);
  EXPECT_EQ(step.next.phase, GamePhase::decision);
  EXPECT_EQ(step.next.to_shoot, 1);
  const LegalActions legal = legal_actions(step.next);
  EXPECT_FALSE(legal.shoot);
  EXPECT_EQ(legal.decisions, (std::vector<Decision>{Decision::play, Decision::pass}));
  test::expect_invalid("decision", [&] { (void)play(step.next, strike(1.0, 0.0), 2); });
  Action restore;
  restore.decision = Decision::restore;
  test::expect_invalid("decision", [&] { (void)play(step.next, restore, 2); });
  Action pass;
  pass.decision = Decision::pass;
  const GameStep passed = play(step.next, pass, 2);
  EXPECT_EQ(passed.next.to_shoot, 0);
  EXPECT_EQ(passed.next.phase, GamePhase::play);
  EXPECT_FALSE(passed.next.push_out_available);
  // No second push-out.
  Action again = strike(0.8, 180.0);
  again.push_out = true;
  test::expect_invalid("push_out", [&] { (void)play(passed.next, again, 3); });
}

TEST(NineBall, BreakRulingFollowsItsFacts) {
  // Legal iff the 1 is hit first and a ball drops or four object balls reach a rail (WPA 2.3).
  for (std::uint64_t seed = 0; seed < 6; ++seed) {
    GameConfig config = default_config(GameKind::nine_ball);
    config.rack.gap_sigma = 2e-4;
    const GameState s = new_game(config, seed);
    EXPECT_EQ(s.phase, GamePhase::break_shot);
    ASSERT_TRUE(s.ball_in_hand);
    EXPECT_EQ(s.ball_in_hand->kind, PlacementRegion::Kind::behind_head_string);
    Action a = strike(7.0 + 0.3 * static_cast<double>(seed), 0.0);
    a.aim_at = 1;
    const GameStep step = play(s, a, seed);
    int to_rail = 0;
    for (int id = 1; id <= 9; ++id) {
      bool railed = false;
      for (const CushionHit& c : step.facts.cushions) railed = railed || c.ball == id;
      for (const JawHit& j : step.facts.jaws) railed = railed || j.ball == id;
      to_rail += railed ? 1 : 0;
    }
    int potted = 0;
    for (const Pot& p : step.facts.pots) potted += p.ball != 0 ? 1 : 0;
    const bool legal = step.facts.first_contact == 1 && !step.facts.pocketed(0) && (potted > 0 || to_rail >= 4);
    EXPECT_EQ(!step.ruling.foul.has_value(), legal) << "seed " << seed;
    if (legal && !step.ruling.game_over) {
      EXPECT_TRUE(step.next.push_out_available);
    }
  }
}

// A random legal action: any strike, a random free spot when in hand, a random decision.
Action random_action(const GameState& s, RandomStream& rng) {
  const LegalActions legal = legal_actions(s);
  Action a;
  if (!legal.shoot) {
    a.decision = legal.decisions[static_cast<std::size_t>(rng.integer(0, static_cast<int>(legal.decisions.size()) - 1))];
    return a;
  }
  a.strike.speed = rng.uniform(0.5, 8.0);
  a.strike.aim_deg = rng.uniform(-180.0, 180.0);
  a.strike.height = rng.uniform(-0.3, 0.3);
  if (legal.ball_in_hand && (!find_ball(s.table.balls, legal.cue_ball) || rng.chance(0.5))) {
    std::vector<Vec2> others;
    for (const SimulationBall& b : s.table.balls)
      if (b.id != legal.cue_ball) others.push_back(b.state.position);
    a.place = random_free_spot(s.table.table, others, s.table.table.ball.radius, rng, 1000, *legal.ball_in_hand);
  }
  a.push_out = legal.push_out && rng.chance(0.3);
  return a;
}

TEST(NineBall, RandomGamesEndConserveBallsAndReplay) {
  for (std::uint64_t game = 0; game < 30; ++game) {
    GameState s = new_game(default_config(GameKind::nine_ball), game);
    RandomStream rng(splitmix64(game));
    std::vector<GameStep> steps;
    std::vector<int> down;  // object balls pocketed and not respotted
    while (!s.over) {
      const Action a = random_action(s, rng);
      GameStep step = play(s, a, stream_seed(game, static_cast<std::uint64_t>(s.shots)));
      for (const int id : step.ruling.pocketed)
        if (id != 0) down.push_back(id);
      for (const int id : step.ruling.respotted) down.erase(std::find(down.begin(), down.end(), id));
      const std::size_t objects = object_balls(step.next).size();
      EXPECT_EQ(objects + down.size(), 9u) << "game " << game << " shot " << s.shots;
      s = step.next;
      steps.push_back(std::move(step));
    }
    EXPECT_TRUE(s.winner.has_value() || s.truncated);
    // Replaying the same actions and seeds gives the same game, bit for bit.
    GameState r = new_game(default_config(GameKind::nine_ball), game);
    for (const GameStep& step : steps) r = play(r, step.action, stream_seed(game, static_cast<std::uint64_t>(r.shots))).next;
    EXPECT_TRUE(r == s);
  }
}

}  // namespace
}  // namespace cueball
