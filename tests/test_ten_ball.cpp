// 10-ball's rules (src/games/ten_ball.cpp): each foul, win and decision
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
using test::called;
using test::diagonal_draw;
using test::decide;

constexpr int kBottomLeft = 0;  // pocket index of the bottom-left corner (pool_9ft)

// A 10-ball game in play (after the break) with exactly these balls.
GameState in_play(const std::vector<std::pair<int, Vec2>>& balls) {
  return test::rotation_in_play(GameKind::ten_ball, balls);
}

TEST(TenBall, NewGameIsATriangleOfTenBrokenFromTheKitchen) {
  GameConfig frozen = default_config(GameKind::ten_ball);
  frozen.rack.gap_sigma = 0.0;  // the lattice itself, without the default gaps
  const GameState s = new_game(frozen);
  ASSERT_EQ(s.table.balls.size(), 11u);
  const Table& t = s.table.table;
  const double R = t.ball.radius;
  const SimulationBall* one = find_ball(s.table.balls, 1);
  const SimulationBall* ten = find_ball(s.table.balls, 10);
  ASSERT_TRUE(one && ten);
  EXPECT_NEAR(one->state.position.x, foot_spot(t).x, 1e-12);  // WPA 9.2: the 1 at the apex on the foot spot
  EXPECT_NEAR(ten->state.position.x, foot_spot(t).x + 2.0 * std::sqrt(3.0) * R, 1e-9);  // the middle of row three
  EXPECT_NEAR(ten->state.position.y, long_string_y(t), 1e-9);
  EXPECT_EQ(rack_ten_ball(t).size(), 11u);
  EXPECT_EQ(s.phase, GamePhase::break_shot);
  ASSERT_TRUE(s.ball_in_hand);
  EXPECT_EQ(s.ball_in_hand->kind, PlacementRegion::Kind::behind_head_string);
  EXPECT_EQ(s.on, std::vector<int>{1});
  const LegalActions legal = legal_actions(s);
  EXPECT_FALSE(legal.call_required);  // no call on the break
  test::expect_invalid("called_ball", [&] { (void)play(s, called(strike(5.0, 0.0), 1, 0), 1); });
}

TEST(TenBall, EveryShotAfterTheBreakIsCalled) {
  const GameState s = in_play({{0, {1.0, 0.6}}, {2, {1.5, 0.6}}, {5, {2.2, 1.0}}, {10, {2.2, 0.3}}});
  const LegalActions legal = legal_actions(s);
  EXPECT_TRUE(legal.call_required);
  EXPECT_EQ(legal.callable, (std::vector<int>{2, 5, 10}));  // any ball on the table
  test::expect_invalid("called_ball", [&] { validate_action(s, strike(2.0, 0.0)); });
  test::expect_invalid("called_ball", [&] { validate_action(s, called(strike(2.0, 0.0), 3, 0)); });
  test::expect_invalid("called_ball", [&] { validate_action(s, called(strike(2.0, 0.0), 0, 0)); });
  Action no_pocket = strike(2.0, 0.0);
  no_pocket.called_ball = 2;
  test::expect_invalid("called_pocket", [&] { validate_action(s, no_pocket); });
  test::expect_invalid("called_pocket", [&] { validate_action(s, called(strike(2.0, 0.0), 2, 6)); });
  validate_action(s, called(strike(2.0, 0.0), 10, 5));
}

TEST(TenBall, ALegallyCalledPotContinues) {
  GameState s = in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {2, {2.0, 1.0}}, {10, {2.2, 0.3}}});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 1, kBottomLeft), 1);
  ASSERT_EQ(step.facts.pocket_of(1), kBottomLeft);
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_FALSE(step.ruling.turn_over);
  EXPECT_EQ(step.next.to_shoot, 0);
  EXPECT_EQ(step.next.phase, GamePhase::play);
  EXPECT_EQ(step.next.on, std::vector<int>{2});
}

TEST(TenBall, TheCalledBallInAnotherPocketLetsTheOpponentPlayOrPass) {
  GameState s = in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {2, {2.0, 1.0}}, {10, {2.2, 0.3}}});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 1, 5), 1);
  ASSERT_EQ(step.facts.pocket_of(1), kBottomLeft);
  EXPECT_FALSE(step.ruling.foul);  // WPA 9.7: no foul
  EXPECT_TRUE(step.ruling.turn_over);
  EXPECT_EQ(step.next.phase, GamePhase::decision);
  EXPECT_EQ(step.next.to_shoot, 1);
  EXPECT_FALSE(step.next.ball_in_hand);
  EXPECT_FALSE(find_ball(step.next.table.balls, 1));  // it stays down
  const LegalActions legal = legal_actions(step.next);
  EXPECT_FALSE(legal.shoot);
  EXPECT_EQ(legal.decisions, (std::vector<Decision>{Decision::play, Decision::pass}));
  test::expect_invalid("decision", [&] { (void)play(step.next, called(strike(1.0, 0.0), 2, 0), 2); });
  test::expect_invalid("decision", [&] { (void)play(step.next, decide(Decision::rerack), 2); });

  const GameStep take = play(step.next, decide(Decision::play), 2);
  EXPECT_EQ(take.next.to_shoot, 1);
  EXPECT_EQ(take.next.phase, GamePhase::play);
  EXPECT_FALSE(take.ruling.turn_over);
  const GameStep back = play(step.next, decide(Decision::pass), 2);
  EXPECT_EQ(back.next.to_shoot, 0);  // the shooter plays again
  EXPECT_EQ(back.next.phase, GamePhase::play);
  EXPECT_TRUE(back.ruling.turn_over);
}

TEST(TenBall, AnUncalledPotLetsTheOpponentPlayOrPass) {
  GameState s = in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {2, {2.0, 1.0}}, {10, {2.2, 0.3}}});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 2, kBottomLeft), 1);
  ASSERT_TRUE(step.facts.pocketed(1));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_EQ(step.next.phase, GamePhase::decision);
  EXPECT_EQ(step.next.to_shoot, 1);
}

TEST(TenBall, NothingPocketedPassesTheTurn) {
  GameState s = in_play({{0, {1.0, 0.6}}, {1, {1.5, 0.6}}, {10, {2.2, 0.3}}});
  const GameStep step = play(s, called(strike(2.0, 0.0), 1, 1), 1);
  ASSERT_EQ(step.facts.first_contact, 1);
  ASSERT_TRUE(step.facts.pots.empty());
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_EQ(step.next.to_shoot, 1);
  EXPECT_EQ(step.next.phase, GamePhase::play);
}

TEST(TenBall, TheTenCalledAndPocketedWins) {
  GameState s = in_play({{0, {0.9, 0.9}}, {10, {0.45, 0.45}}});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 10, kBottomLeft), 1);
  ASSERT_EQ(step.facts.pocket_of(10), kBottomLeft);
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 0);
  EXPECT_EQ(step.next.scores[0], 1);
  // Early, on a combination off the 1, called: a win too.
  GameState c = in_play({{0, {0.9, 0.9}}, {1, {0.62, 0.62}}, {10, {0.45, 0.45}}, {2, {2.0, 1.0}}});
  const GameStep combo = play(c, called(diagonal_draw({0.9, 0.9}, {0.62, 0.62}), 10, kBottomLeft), 1);
  ASSERT_EQ(combo.facts.first_contact, 1);
  ASSERT_EQ(combo.facts.pocket_of(10), kBottomLeft);
  EXPECT_EQ(combo.ruling.winner, 0);
}

TEST(TenBall, TheTenPocketedIllegallyIsSpotted) {
  // The combination again, the 1 called: the 10 drops uncalled.
  GameState c = in_play({{0, {0.9, 0.9}}, {1, {0.62, 0.62}}, {10, {0.45, 0.45}}, {2, {2.0, 1.0}}});
  const GameStep uncalled = play(c, called(diagonal_draw({0.9, 0.9}, {0.62, 0.62}), 1, kBottomLeft), 1);
  ASSERT_TRUE(uncalled.facts.pocketed(10));
  EXPECT_FALSE(uncalled.ruling.game_over);
  EXPECT_EQ(uncalled.ruling.respotted, std::vector<int>{10});
  const SimulationBall* ten = find_ball(uncalled.next.table.balls, 10);
  ASSERT_TRUE(ten);
  EXPECT_NEAR(ten->state.position.y, long_string_y(c.table.table), 1e-12);
  // The 10 called, in another pocket: spotted, and the opponent's choice.
  const GameStep elsewhere = play(c, called(diagonal_draw({0.9, 0.9}, {0.62, 0.62}), 10, 3), 1);
  ASSERT_EQ(elsewhere.facts.pocket_of(10), kBottomLeft);
  EXPECT_FALSE(elsewhere.ruling.game_over);
  EXPECT_EQ(elsewhere.ruling.respotted, std::vector<int>{10});
  EXPECT_EQ(elsewhere.next.phase, GamePhase::decision);
  // On a foul (the 10 hit first, the 1 on): spotted, ball in hand.
  GameState f = in_play({{0, {0.9, 0.9}}, {1, {2.0, 1.0}}, {10, {0.45, 0.45}}});
  const GameStep foul = play(f, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 10, kBottomLeft), 1);
  ASSERT_TRUE(foul.facts.pocketed(10));
  EXPECT_EQ(foul.ruling.foul, Foul::wrong_ball_first);
  EXPECT_FALSE(foul.ruling.game_over);
  EXPECT_EQ(foul.ruling.respotted, std::vector<int>{10});
  ASSERT_TRUE(foul.next.ball_in_hand);
  EXPECT_EQ(foul.next.ball_in_hand->kind, PlacementRegion::Kind::anywhere);
}

TEST(TenBall, FoulsGiveBallInHandAnywhere) {
  GameState s = in_play({{0, {0.5, 0.5}}, {1, {2.0, 1.0}}, {10, {2.2, 0.3}}});
  const GameStep scratch = play(s, called(strike(2.0, 225.0), 1, 2), 1);
  ASSERT_TRUE(scratch.facts.pocketed(0));
  EXPECT_EQ(scratch.ruling.foul, Foul::scratch);
  EXPECT_EQ(scratch.next.to_shoot, 1);
  ASSERT_TRUE(scratch.next.ball_in_hand);
  EXPECT_EQ(scratch.next.ball_in_hand->kind, PlacementRegion::Kind::anywhere);
  EXPECT_EQ(scratch.next.fouls_in_a_row[0], 1);

  GameState t = in_play({{0, {1.0, 0.6}}, {1, {2.2, 1.0}}, {10, {2.2, 0.3}}});
  EXPECT_EQ(play(t, called(strike(1.0, 180.0), 1, 2), 1).ruling.foul, Foul::no_contact);
  GameState u = in_play({{0, {1.0, 0.635}}, {1, {1.3, 0.635}}, {10, {2.2, 0.3}}});
  const GameStep soft = play(u, called(strike(0.6, 0.0), 1, 2), 1);
  ASSERT_TRUE(soft.facts.cushions.empty());
  EXPECT_EQ(soft.ruling.foul, Foul::no_rail_after_contact);
  GameState w = in_play({{0, {1.0, 0.6}}, {2, {2.2, 1.0}}, {3, {1.5, 0.6}}, {10, {2.2, 0.3}}});
  EXPECT_EQ(play(w, called(strike(3.0, 0.0), 3, 2), 1).ruling.foul, Foul::wrong_ball_first);
}

TEST(TenBall, ThreeConsecutiveFoulsLose) {
  GameState s = in_play({{0, {1.0, 0.6}}, {1, {2.2, 1.0}}, {10, {2.2, 0.3}}});
  s.fouls_in_a_row = {2, 0};
  const GameStep step = play(s, called(strike(1.0, 180.0), 1, 2), 1);
  EXPECT_EQ(step.ruling.foul, Foul::no_contact);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 1);
  // A legal shot clears the count.
  s.fouls_in_a_row = {2, 0};
  GameState t = in_play({{0, {1.0, 0.6}}, {1, {1.5, 0.6}}, {10, {2.2, 0.3}}});
  t.fouls_in_a_row = {2, 0};
  EXPECT_EQ(play(t, called(strike(2.0, 0.0), 1, 1), 1).next.fouls_in_a_row[0], 0);
  s.config.fouls_to_lose = 0;
  EXPECT_FALSE(play(s, called(strike(1.0, 180.0), 1, 2), 1).ruling.game_over);
}

TEST(TenBall, PushOutThenPassBackAndTheTenSpotted) {
  GameState s = in_play({{0, {0.9, 0.9}}, {1, {2.2, 1.0}}, {10, {0.45, 0.45}}});
  s.push_out_available = true;
  EXPECT_TRUE(legal_actions(s).push_out);
  // A push-out that pockets the 10 (hit first: 6.2 is suspended): spotted, no foul.
  Action push = called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 1, 2);
  push.push_out = true;
  const GameStep step = play(s, push, 1);
  ASSERT_TRUE(step.facts.pocketed(10));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_TRUE(step.ruling.push_out);
  EXPECT_FALSE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.respotted, std::vector<int>{10});
  EXPECT_EQ(step.next.phase, GamePhase::decision);
  EXPECT_EQ(step.next.to_shoot, 1);
  const GameStep passed = play(step.next, decide(Decision::pass), 2);
  EXPECT_EQ(passed.next.to_shoot, 0);
  EXPECT_FALSE(passed.next.push_out_available);
  Action again = called(strike(0.8, 180.0), 1, 2);
  again.push_out = true;
  test::expect_invalid("push_out", [&] { (void)play(passed.next, again, 3); });
}

TEST(TenBall, TheTenOnTheBreakIsSpottedAndTheBreakerContinues) {
  // A crafted break: the 1 and the 10 on the bottom-left diagonal, the cue
  // ball in the kitchen; the 1 carries the 10 in.
  GameState s = in_play({{1, {0.5, 0.5}}, {10, {0.33, 0.33}}, {2, {2.0, 1.0}}, {3, {2.0, 0.3}}});
  s.phase = GamePhase::break_shot;
  PlacementRegion kitchen;
  kitchen.kind = PlacementRegion::Kind::behind_head_string;
  s.ball_in_hand = kitchen;
  Action a = diagonal_draw({0.62, 0.62}, {0.5, 0.5});
  a.place = Vec2{0.62, 0.62};
  const GameStep step = play(s, a, 1);
  ASSERT_EQ(step.facts.first_contact, 1);
  ASSERT_TRUE(step.facts.pocketed(10));
  ASSERT_FALSE(step.facts.pocketed(0));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_FALSE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.respotted, std::vector<int>{10});
  EXPECT_EQ(step.next.to_shoot, 0);
  EXPECT_TRUE(step.next.push_out_available);
  EXPECT_TRUE(find_ball(step.next.table.balls, 10));
}

TEST(TenBall, BreakRulingFollowsItsFacts) {
  // Legal iff the 1 is hit first and a ball drops or four object balls reach a rail (WPA 9.3).
  for (std::uint64_t seed = 0; seed < 6; ++seed) {
    GameConfig config = default_config(GameKind::ten_ball);
    config.rack.gap_sigma = 2e-4;
    const GameState s = new_game(config, seed);
    Action a = strike(3.0 + 1.0 * static_cast<double>(seed), 0.0);
    a.aim_at = 1;
    const GameStep step = play(s, a, seed);
    int to_rail = 0;
    for (int id = 1; id <= 10; ++id) {
      bool railed = false;
      for (const CushionHit& c : step.facts.cushions) railed = railed || c.ball == id;
      for (const JawHit& j : step.facts.jaws) railed = railed || j.ball == id;
      to_rail += railed ? 1 : 0;
    }
    int potted = 0;
    for (const Pot& p : step.facts.pots) potted += p.ball != 0 ? 1 : 0;
    const bool legal = step.facts.first_contact == 1 && !step.facts.pocketed(0) && (potted > 0 || to_rail >= 4);
    EXPECT_EQ(!step.ruling.foul.has_value(), legal) << "seed " << seed;
    EXPECT_FALSE(step.ruling.game_over) << "seed " << seed;  // the 10 on the break never wins
    if (legal) {
      EXPECT_TRUE(step.next.push_out_available);
    }
  }
}

// A random legal action: any strike, a random free spot when in hand, a
// random call, a random decision.
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
  if (legal.call_required) {
    a.called_ball = legal.callable[static_cast<std::size_t>(rng.integer(0, static_cast<int>(legal.callable.size()) - 1))];
    a.called_pocket = rng.integer(0, static_cast<int>(s.table.table.pockets.size()) - 1);
  }
  a.push_out = legal.push_out && rng.chance(0.3);
  if (!legal.on.empty() && rng.chance(0.8)) a.aim_at = legal.on.front();  // mostly at the ball on, so that racks progress
  return a;
}

TEST(TenBall, RandomGamesEndConserveBallsAndReplay) {
  int won = 0;
  int decisions = 0, respots = 0, fouls = 0;  // the rulings the games went through
  for (std::uint64_t game = 0; game < 25; ++game) {
    // Every other game without the three-foul rule, so that the racks run to the 10.
    GameConfig config = default_config(GameKind::ten_ball);
    if (game % 2 == 1) config.fouls_to_lose = 0;
    GameState s = new_game(config, game);
    RandomStream rng(splitmix64(game));
    std::vector<GameStep> steps;
    std::vector<int> down;  // object balls pocketed and not respotted
    while (!s.over) {
      const Action a = random_action(s, rng);
      GameStep step = play(s, a, stream_seed(game, static_cast<std::uint64_t>(s.shots)));
      decisions += a.decision ? 1 : 0;
      respots += static_cast<int>(step.ruling.respotted.size());
      fouls += step.ruling.foul ? 1 : 0;
      for (const int id : step.ruling.pocketed)
        if (id != 0) down.push_back(id);
      for (const int id : step.ruling.respotted) down.erase(std::find(down.begin(), down.end(), id));
      EXPECT_EQ(object_balls(step.next).size() + down.size(), 10u) << "game " << game << " shot " << s.shots;
      if (!step.next.over) {
        EXPECT_TRUE(find_ball(step.next.table.balls, 10)) << "the 10 stays down only when it wins";
      }
      s = step.next;
      steps.push_back(std::move(step));
    }
    EXPECT_TRUE(s.winner.has_value() || s.truncated);
    won += s.winner.has_value() ? 1 : 0;
    GameState r = new_game(config, game);
    for (const GameStep& step : steps) r = play(r, step.action, stream_seed(game, static_cast<std::uint64_t>(r.shots))).next;
    EXPECT_TRUE(r == s);
  }
  EXPECT_GT(won, 0);
  EXPECT_GT(decisions, 0);
  EXPECT_GT(respots, 0);
  EXPECT_GT(fouls, 0);
}

}  // namespace
}  // namespace cueball
