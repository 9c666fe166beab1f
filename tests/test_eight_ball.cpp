// 8-ball's rules (src/games/eight_ball.cpp): each foul, win, loss and
// decision from a crafted table and strike whose ruling is known, then
// random games.
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

Group group_of(int id) { return id < 8 ? Group::solids : (id > 8 ? Group::stripes : Group::none); }

// The balls `s.to_shoot` may hit first, as the rules compute them.
std::vector<int> expected_on(const GameState& s) {
  const Group g = s.groups[static_cast<std::size_t>(s.to_shoot)];
  std::vector<int> on;
  for (const SimulationBall& b : s.table.balls)
    if (b.id != 0 && b.id != 8 && (g == Group::none || group_of(b.id) == g)) on.push_back(b.id);
  if (on.empty()) on.push_back(8);
  return on;
}

// An 8-ball game in play (after the break) with exactly these balls and groups.
GameState in_play(const std::vector<std::pair<int, Vec2>>& balls, std::array<Group, 2> groups = {}) {
  GameState s = new_game(default_config(GameKind::eight_ball));
  s.phase = GamePhase::play;
  s.ball_in_hand.reset();
  s.groups = groups;
  test::place_balls(s, balls);
  s.on = expected_on(s);
  return s;
}

// The same table as a break shot: the cue ball in hand in the kitchen.
GameState at_break(const std::vector<std::pair<int, Vec2>>& balls) {
  GameState s = in_play(balls);
  s.phase = GamePhase::break_shot;
  PlacementRegion kitchen;
  kitchen.kind = PlacementRegion::Kind::behind_head_string;
  s.ball_in_hand = kitchen;
  s.on.clear();
  for (const SimulationBall& b : s.table.balls)
    if (b.id != 0) s.on.push_back(b.id);
  return s;
}

TEST(EightBall, NewGameIsARackBrokenFromTheKitchen) {
  const GameState s = new_game(default_config(GameKind::eight_ball));
  EXPECT_EQ(s.table.balls.size(), 16u);
  EXPECT_EQ(s.phase, GamePhase::break_shot);
  ASSERT_TRUE(s.ball_in_hand);
  EXPECT_EQ(s.ball_in_hand->kind, PlacementRegion::Kind::behind_head_string);
  EXPECT_EQ(s.groups, (std::array<Group, 2>{Group::none, Group::none}));
  const LegalActions legal = legal_actions(s);
  EXPECT_FALSE(legal.call_required);  // WPA 3.3(b): no call on the break
  EXPECT_EQ(legal.on.size(), 15u);    // any ball may be hit first
  // A call on the break is refused, naming the field.
  test::expect_invalid("called_ball", [&] { (void)play(s, called(strike(5.0, 0.0), 1, 0), 1); });
}

TEST(EightBall, CallsAreValidated) {
  GameState s = in_play({{0, {1.0, 0.6}}, {3, {1.5, 0.6}}, {8, {2.2, 0.3}}, {12, {2.0, 1.0}}});
  const LegalActions legal = legal_actions(s);
  EXPECT_TRUE(legal.call_required);
  EXPECT_EQ(legal.callable, (std::vector<int>{3, 12}));  // open table: any ball but the 8
  test::expect_invalid("called_ball", [&] { validate_action(s, strike(2.0, 0.0)); });
  test::expect_invalid("called_ball", [&] { validate_action(s, called(strike(2.0, 0.0), 8, 0)); });
  test::expect_invalid("called_ball", [&] { validate_action(s, called(strike(2.0, 0.0), 5, 0)); });
  Action no_pocket = strike(2.0, 0.0);
  no_pocket.called_ball = 3;
  test::expect_invalid("called_pocket", [&] { validate_action(s, no_pocket); });
  test::expect_invalid("called_pocket", [&] { validate_action(s, called(strike(2.0, 0.0), 3, 6)); });
  test::expect_invalid("called_pocket", [&] { validate_action(s, called(strike(2.0, 0.0), 3, -1)); });
  validate_action(s, called(strike(2.0, 0.0), 12, 5));
  // With groups set, only the shooter's group may be called.
  s.groups = {Group::solids, Group::stripes};
  s.on = expected_on(s);
  EXPECT_EQ(legal_actions(s).callable, std::vector<int>{3});
  test::expect_invalid("called_ball", [&] { validate_action(s, called(strike(2.0, 0.0), 12, 5)); });
}

TEST(EightBall, ALegalCalledPotOnAnOpenTableSetsTheGroups) {
  GameState s = in_play({{0, {0.9, 0.9}}, {3, {0.45, 0.45}}, {5, {2.0, 0.4}}, {8, {2.2, 0.9}}, {12, {2.0, 1.0}}});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 3, kBottomLeft), 1);
  ASSERT_EQ(step.facts.pocket_of(3), kBottomLeft);
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_FALSE(step.ruling.turn_over);
  EXPECT_EQ(step.next.groups, (std::array<Group, 2>{Group::solids, Group::stripes}));
  EXPECT_EQ(step.next.to_shoot, 0);
  EXPECT_EQ(step.next.on, std::vector<int>{5});
  EXPECT_EQ(legal_actions(step.next).callable, std::vector<int>{5});
}

TEST(EightBall, TheCalledBallInAnotherPocketEndsTheTurnWithoutAFoul) {
  GameState s = in_play({{0, {0.9, 0.9}}, {3, {0.45, 0.45}}, {5, {2.0, 0.4}}, {8, {2.2, 0.9}}, {12, {2.0, 1.0}}});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 3, 5), 1);
  ASSERT_EQ(step.facts.pocket_of(3), kBottomLeft);
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_TRUE(step.ruling.turn_over);
  EXPECT_EQ(step.next.to_shoot, 1);
  EXPECT_FALSE(step.next.ball_in_hand);
  EXPECT_EQ(step.next.groups, (std::array<Group, 2>{Group::none, Group::none}));  // still open
  EXPECT_FALSE(find_ball(step.next.table.balls, 3));                                // it stays down
  // An uncalled ball that drops ends the turn the same way.
  const GameStep other = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 12, kBottomLeft), 1);
  ASSERT_TRUE(other.facts.pocketed(3));
  EXPECT_FALSE(other.ruling.foul);
  EXPECT_TRUE(other.ruling.turn_over);
  EXPECT_FALSE(find_ball(other.next.table.balls, 3));
}

TEST(EightBall, OnAnOpenTableTheEightFirstIsAFoul) {
  GameState s = in_play({{0, {1.0, 0.6}}, {3, {2.2, 1.0}}, {8, {1.5, 0.6}}, {12, {2.0, 0.3}}});
  const GameStep step = play(s, called(strike(3.0, 0.0), 3, 2), 1);
  ASSERT_EQ(step.facts.first_contact, 8);
  ASSERT_FALSE(step.facts.pocketed(8));
  EXPECT_EQ(step.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(step.next.to_shoot, 1);
  ASSERT_TRUE(step.next.ball_in_hand);
  EXPECT_EQ(step.next.ball_in_hand->kind, PlacementRegion::Kind::anywhere);  // WPA 3.6
}

TEST(EightBall, WithGroupsSetTheOpponentsBallFirstIsAFoul) {
  GameState s = in_play({{0, {1.0, 0.6}}, {3, {2.2, 1.0}}, {8, {2.0, 0.3}}, {12, {1.5, 0.6}}},
                        {Group::solids, Group::stripes});
  const GameStep step = play(s, called(strike(3.0, 0.0), 3, 2), 1);
  ASSERT_EQ(step.facts.first_contact, 12);
  EXPECT_EQ(step.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(step.next.to_shoot, 1);
  EXPECT_EQ(step.next.on, std::vector<int>{12});  // the stripes player's balls
}

TEST(EightBall, ScratchNoContactAndNoRailAreFoulsWithBallInHandAnywhere) {
  GameState s = in_play({{0, {0.5, 0.5}}, {3, {2.0, 1.0}}, {8, {2.2, 0.3}}, {12, {1.5, 0.3}}});
  const GameStep scratch = play(s, called(strike(2.0, 225.0), 3, 2), 1);
  ASSERT_TRUE(scratch.facts.pocketed(0));
  EXPECT_EQ(scratch.ruling.foul, Foul::scratch);
  ASSERT_TRUE(scratch.next.ball_in_hand);
  EXPECT_EQ(scratch.next.ball_in_hand->kind, PlacementRegion::Kind::anywhere);
  EXPECT_FALSE(scratch.next.cue_must_leave_kitchen);
  test::expect_invalid("place", [&] { (void)play(scratch.next, called(strike(2.0, 0.0), 3, 2), 2); });

  GameState t = in_play({{0, {1.0, 0.6}}, {3, {2.2, 1.0}}, {8, {2.2, 0.3}}});
  EXPECT_EQ(play(t, called(strike(1.0, 180.0), 3, 2), 1).ruling.foul, Foul::no_contact);
  GameState u = in_play({{0, {1.0, 0.635}}, {3, {1.3, 0.635}}, {8, {2.2, 0.3}}});
  const GameStep soft = play(u, called(strike(0.6, 0.0), 3, 2), 1);
  ASSERT_EQ(soft.facts.first_contact, 3);
  ASSERT_TRUE(soft.facts.cushions.empty());
  EXPECT_EQ(soft.ruling.foul, Foul::no_rail_after_contact);
}

TEST(EightBall, NoThreeFoulRule) {
  GameState s = in_play({{0, {1.0, 0.6}}, {3, {2.2, 1.0}}, {8, {2.2, 0.3}}});
  s.fouls_in_a_row = {5, 0};
  const GameStep step = play(s, called(strike(1.0, 180.0), 3, 2), 1);
  EXPECT_EQ(step.ruling.foul, Foul::no_contact);
  EXPECT_FALSE(step.ruling.game_over);
  EXPECT_EQ(step.next.fouls_in_a_row[0], 6);
}

TEST(EightBall, TheEightInTheCalledPocketWins) {
  GameState s = in_play({{0, {0.9, 0.9}}, {8, {0.45, 0.45}}, {12, {2.0, 1.0}}}, {Group::solids, Group::stripes});
  EXPECT_EQ(legal_actions(s).callable, std::vector<int>{8});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 8, kBottomLeft), 1);
  ASSERT_EQ(step.facts.pocket_of(8), kBottomLeft);
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 0);
  EXPECT_EQ(step.next.scores[0], 1);
  test::expect_invalid("action", [&] { (void)play(step.next, called(strike(1.0, 0.0), 8, 0), 2); });
}

TEST(EightBall, TheEightInAnotherPocketLoses) {
  GameState s = in_play({{0, {0.9, 0.9}}, {8, {0.45, 0.45}}, {12, {2.0, 1.0}}}, {Group::solids, Group::stripes});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 8, 2), 1);
  ASSERT_EQ(step.facts.pocket_of(8), kBottomLeft);
  EXPECT_EQ(step.ruling.foul, Foul::wrong_pocket);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 1);
  EXPECT_EQ(step.next.scores[1], 1);
}

TEST(EightBall, TheEightBeforeTheGroupIsClearedLoses) {
  // A legal hit on the 3 that carries the 8 in: the solids are not cleared.
  GameState s = in_play({{0, {0.9, 0.9}}, {3, {0.62, 0.62}}, {8, {0.45, 0.45}}, {12, {2.0, 1.0}}},
                        {Group::solids, Group::stripes});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.62, 0.62}), 3, kBottomLeft), 1);
  ASSERT_EQ(step.facts.first_contact, 3);
  ASSERT_TRUE(step.facts.pocketed(8));
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 1);
  // The same on an open table.
  s.groups = {Group::none, Group::none};
  s.on = expected_on(s);
  const GameStep open = play(s, called(diagonal_draw({0.9, 0.9}, {0.62, 0.62}), 3, kBottomLeft), 1);
  ASSERT_TRUE(open.facts.pocketed(8));
  EXPECT_EQ(open.ruling.winner, 1);
}

TEST(EightBall, TheEightOnAFoulLoses) {
  // The 8 hit first (the 3 is on) and pocketed: WPA 3.8(a).
  GameState s = in_play({{0, {0.9, 0.9}}, {3, {2.0, 1.0}}, {8, {0.45, 0.45}}}, {Group::solids, Group::stripes});
  const GameStep wrong = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 3, 2), 1);
  ASSERT_TRUE(wrong.facts.pocketed(8));
  EXPECT_EQ(wrong.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(wrong.ruling.winner, 1);
  // The 8 on, called and in its pocket, but the cue ball follows it in.
  GameState t = in_play({{0, {0.9, 0.9}}, {8, {0.45, 0.45}}}, {Group::solids, Group::stripes});
  Action follow = called(strike(3.0, aim_deg({0.9, 0.9}, {0.45, 0.45})), 8, kBottomLeft);
  follow.strike.height = 0.4;
  const GameStep scratch = play(t, follow, 1);
  ASSERT_EQ(scratch.facts.pocket_of(8), kBottomLeft);
  ASSERT_TRUE(scratch.facts.pocketed(0));
  EXPECT_EQ(scratch.ruling.foul, Foul::scratch);
  EXPECT_TRUE(scratch.ruling.game_over);
  EXPECT_EQ(scratch.ruling.winner, 1);
}

TEST(EightBall, TheEightIsOnWhenNoGroupBallIsLeftOnAnOpenTable) {
  GameState s = in_play({{0, {0.9, 0.9}}, {8, {0.45, 0.45}}});
  EXPECT_EQ(s.on, std::vector<int>{8});
  const GameStep step = play(s, called(diagonal_draw({0.9, 0.9}, {0.45, 0.45}), 8, kBottomLeft), 1);
  EXPECT_EQ(step.ruling.winner, 0);
}

TEST(EightBall, IllegalBreakGivesTheOpponentThreeOptions) {
  const GameState s = new_game(default_config(GameKind::eight_ball));
  Action soft = strike(0.8, 0.0);
  soft.aim_at = 1;
  const GameStep step = play(s, soft, 1);
  ASSERT_TRUE(step.facts.pots.empty());
  EXPECT_EQ(step.ruling.foul, Foul::illegal_break);
  EXPECT_EQ(step.next.phase, GamePhase::decision);
  EXPECT_EQ(step.next.to_shoot, 1);
  const LegalActions legal = legal_actions(step.next);
  EXPECT_FALSE(legal.shoot);
  EXPECT_EQ(legal.decisions,
            (std::vector<Decision>{Decision::play, Decision::rerack_and_break, Decision::rerack_opponent_breaks}));
  test::expect_invalid("decision", [&] { (void)play(step.next, decide(Decision::respot_eight), 2); });
  test::expect_invalid("decision", [&] { (void)play(step.next, called(strike(1.0, 0.0), 3, 0), 2); });

  const GameStep accept = play(step.next, decide(Decision::play), 2);
  EXPECT_EQ(accept.next.phase, GamePhase::play);
  EXPECT_EQ(accept.next.to_shoot, 1);
  EXPECT_FALSE(accept.next.ball_in_hand);  // the cue ball stayed on the table
  EXPECT_TRUE(legal_actions(accept.next).call_required);
  EXPECT_EQ(accept.next.on.size(), 14u);  // open table: all but the 8

  const GameStep mine = play(step.next, decide(Decision::rerack_and_break), 2);
  EXPECT_EQ(mine.next.phase, GamePhase::break_shot);
  EXPECT_EQ(mine.next.breaker, 1);
  EXPECT_EQ(mine.next.to_shoot, 1);
  EXPECT_EQ(mine.next.table.balls.size(), 16u);
  ASSERT_TRUE(mine.next.ball_in_hand);
  EXPECT_EQ(mine.next.ball_in_hand->kind, PlacementRegion::Kind::behind_head_string);

  const GameStep theirs = play(step.next, decide(Decision::rerack_opponent_breaks), 2);
  EXPECT_EQ(theirs.next.phase, GamePhase::break_shot);
  EXPECT_EQ(theirs.next.breaker, 0);
  EXPECT_EQ(theirs.next.to_shoot, 0);
  EXPECT_TRUE(theirs.ruling.turn_over);
  EXPECT_EQ(theirs.next.table.balls.size(), 16u);
}

TEST(EightBall, TheEightOnTheBreakLetsTheBreakerSpotItOrRerack) {
  // A crafted break: the 8 on the bottom-left diagonal, the cue ball in the kitchen.
  GameState s = at_break({{3, {2.0, 1.0}}, {8, {0.35, 0.35}}, {12, {2.0, 0.3}}});
  Action a = diagonal_draw({0.6, 0.6}, {0.35, 0.35});
  a.place = Vec2{0.6, 0.6};
  const GameStep step = play(s, a, 1);
  ASSERT_EQ(step.facts.pocket_of(8), kBottomLeft);
  ASSERT_FALSE(step.facts.pocketed(0));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_FALSE(step.ruling.game_over);
  EXPECT_EQ(step.next.phase, GamePhase::decision);
  EXPECT_EQ(step.next.to_shoot, 0);  // the breaker decides
  EXPECT_EQ(step.next.decisions, (std::vector<Decision>{Decision::respot_eight, Decision::rerack}));

  const GameStep spot = play(step.next, decide(Decision::respot_eight), 2);
  ASSERT_EQ(spot.ruling.respotted, std::vector<int>{8});
  const SimulationBall* eight = find_ball(spot.next.table.balls, 8);
  ASSERT_TRUE(eight);
  EXPECT_NEAR(eight->state.position.x, foot_spot(s.table.table).x, 1e-12);
  EXPECT_NEAR(eight->state.position.y, long_string_y(s.table.table), 1e-12);
  EXPECT_EQ(spot.next.phase, GamePhase::play);
  EXPECT_EQ(spot.next.to_shoot, 0);
  EXPECT_FALSE(spot.next.ball_in_hand);
  EXPECT_EQ(spot.next.groups, (std::array<Group, 2>{Group::none, Group::none}));

  const GameStep again = play(step.next, decide(Decision::rerack), 2);
  EXPECT_EQ(again.next.phase, GamePhase::break_shot);
  EXPECT_EQ(again.next.breaker, 0);
  EXPECT_EQ(again.next.table.balls.size(), 16u);
}

TEST(EightBall, TheEightAndAScratchOnTheBreakGiveTheOpponentTheOptions) {
  GameState s = at_break({{3, {2.0, 1.0}}, {8, {0.35, 0.35}}, {12, {2.0, 0.3}}});
  Action a = strike(3.0, aim_deg({0.6, 0.6}, {0.35, 0.35}));
  a.strike.height = 0.4;  // follow: the cue ball goes in after the 8
  a.place = Vec2{0.6, 0.6};
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(8));
  ASSERT_TRUE(step.facts.pocketed(0));
  EXPECT_EQ(step.ruling.foul, Foul::scratch);
  EXPECT_FALSE(step.ruling.game_over);
  EXPECT_EQ(step.next.to_shoot, 1);
  EXPECT_EQ(step.next.decisions, (std::vector<Decision>{Decision::respot_eight, Decision::rerack}));
  const GameStep spot = play(step.next, decide(Decision::respot_eight), 2);
  EXPECT_EQ(spot.ruling.respotted, std::vector<int>{8});
  EXPECT_EQ(spot.next.to_shoot, 1);
  ASSERT_TRUE(spot.next.ball_in_hand);
  EXPECT_EQ(spot.next.ball_in_hand->kind, PlacementRegion::Kind::behind_head_string);
  EXPECT_TRUE(spot.next.cue_must_leave_kitchen);
  const GameStep again = play(step.next, decide(Decision::rerack), 2);
  EXPECT_EQ(again.next.breaker, 1);
  EXPECT_EQ(again.next.to_shoot, 1);
  EXPECT_EQ(again.next.phase, GamePhase::break_shot);
}

TEST(EightBall, AScratchOnALegalBreakGivesBallInHandBehindTheHeadString) {
  GameState s = at_break({{3, {0.35, 0.35}}, {8, {2.2, 0.9}}, {12, {2.0, 0.3}}});
  Action a = strike(3.0, aim_deg({0.6, 0.6}, {0.35, 0.35}));
  a.strike.height = 0.4;
  a.place = Vec2{0.6, 0.6};
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(3));
  ASSERT_TRUE(step.facts.pocketed(0));
  EXPECT_EQ(step.ruling.foul, Foul::scratch);
  EXPECT_EQ(step.next.to_shoot, 1);
  EXPECT_EQ(step.next.phase, GamePhase::play);
  ASSERT_TRUE(step.next.ball_in_hand);
  EXPECT_EQ(step.next.ball_in_hand->kind, PlacementRegion::Kind::behind_head_string);
  EXPECT_TRUE(step.next.cue_must_leave_kitchen);
  EXPECT_TRUE(legal_actions(step.next).cue_must_leave_kitchen);
  EXPECT_FALSE(find_ball(step.next.table.balls, 3));  // stays down; the table is open
  EXPECT_EQ(step.next.groups, (std::array<Group, 2>{Group::none, Group::none}));
  // Placing the cue ball past the head string is refused.
  Action out = called(strike(2.0, 0.0), 12, 2);
  out.place = Vec2{1.0, 0.6};
  test::expect_invalid("place", [&] { (void)play(step.next, out, 2); });

  // The league variant: ball in hand anywhere, no kitchen rule.
  s.config.break_scratch_region = PlacementRegion::Kind::anywhere;
  const GameStep anywhere = play(s, a, 1);
  ASSERT_TRUE(anywhere.next.ball_in_hand);
  EXPECT_EQ(anywhere.next.ball_in_hand->kind, PlacementRegion::Kind::anywhere);
  EXPECT_FALSE(anywhere.next.cue_must_leave_kitchen);
}

// After a scratch on the break: the cue ball in hand behind the head string.
GameState kitchen_in_hand(const std::vector<std::pair<int, Vec2>>& balls) {
  GameState s = in_play(balls);
  PlacementRegion kitchen;
  kitchen.kind = PlacementRegion::Kind::behind_head_string;
  s.ball_in_hand = kitchen;
  s.cue_must_leave_kitchen = true;
  return s;
}

TEST(EightBall, FromTheKitchenTheCueBallMustCrossTheHeadStringFirst) {
  // The 3 lies behind the head string (x < L/4 = 0.635 m), straight ahead.
  const GameState s = kitchen_in_hand({{3, {0.45, 0.635}}, {8, {2.2, 0.3}}, {12, {2.0, 1.0}}});
  Action direct = called(strike(2.0, 0.0), 3, 3);
  direct.place = Vec2{0.2, 0.635};
  const GameStep step = play(s, direct, 1);
  ASSERT_EQ(step.facts.first_contact, 3);
  EXPECT_EQ(step.ruling.foul, Foul::cue_ball_not_out_of_kitchen);
  EXPECT_EQ(step.next.to_shoot, 1);
  ASSERT_TRUE(step.next.ball_in_hand);
  EXPECT_EQ(step.next.ball_in_hand->kind, PlacementRegion::Kind::anywhere);
  EXPECT_FALSE(step.next.cue_must_leave_kitchen);

  // The same shot without the kitchen rule (ball in hand after any other foul): legal.
  GameState free = s;
  free.cue_must_leave_kitchen = false;
  EXPECT_NE(play(free, direct, 1).ruling.foul, Foul::cue_ball_not_out_of_kitchen);

  // A ball past the head string may be hit directly.
  const GameState t = kitchen_in_hand({{3, {1.2, 0.635}}, {8, {2.2, 0.3}}, {12, {2.0, 1.0}}});
  Action past = called(strike(2.0, 0.0), 3, 3);
  past.place = Vec2{0.2, 0.635};
  const GameStep ok = play(t, past, 1);
  ASSERT_EQ(ok.facts.first_contact, 3);
  EXPECT_FALSE(ok.ruling.foul);

  // The cue ball that crosses the string, comes back off the foot rail and
  // then hits a ball behind it: legal.
  const Vec2 cue{0.2, 0.3}, target{0.45, 0.95};
  const GameState u = kitchen_in_hand({{3, target}, {8, {2.2, 0.15}}, {12, {1.9, 1.15}}});
  const double foot = s.table.table.length - s.table.table.ball.radius;
  Action bank = called(strike(4.0, aim_deg(cue, {2.0 * foot - target.x, target.y})), 3, 3);
  bank.place = cue;
  bank.strike.height = -0.2;
  const GameStep back = play(u, bank, 1);
  ASSERT_EQ(back.facts.first_contact, 3);
  ASSERT_FALSE(back.facts.head_string_crossings.empty());
  EXPECT_NE(back.ruling.foul, Foul::cue_ball_not_out_of_kitchen);
}

TEST(EightBall, BreakRulingFollowsItsFacts) {
  // Legal iff a ball drops or four distinct object balls reach a rail (WPA 3.3(d)).
  for (std::uint64_t seed = 0; seed < 6; ++seed) {
    GameConfig config = default_config(GameKind::eight_ball);
    config.rack.gap_sigma = 2e-4;
    const GameState s = new_game(config, seed);
    Action a = strike(4.0 + 1.0 * static_cast<double>(seed), 0.0);
    a.aim_at = 1;
    const GameStep step = play(s, a, seed);
    int to_rail = 0;
    for (int id = 1; id <= 15; ++id) {
      bool railed = false;
      for (const CushionHit& c : step.facts.cushions) railed = railed || c.ball == id;
      for (const JawHit& j : step.facts.jaws) railed = railed || j.ball == id;
      to_rail += railed ? 1 : 0;
    }
    int potted = 0;
    for (const Pot& p : step.facts.pots) potted += p.ball != 0 ? 1 : 0;
    const bool legal = potted > 0 || to_rail >= 4;
    EXPECT_EQ(step.ruling.foul == Foul::illegal_break, !legal) << "seed " << seed;
    EXPECT_EQ(step.next.groups, (std::array<Group, 2>{Group::none, Group::none}));
    if (legal && !step.facts.pocketed(0) && !step.facts.pocketed(8)) {
      EXPECT_FALSE(step.ruling.foul) << "seed " << seed;
      EXPECT_EQ(step.next.to_shoot, potted > 0 ? 0 : 1) << "seed " << seed;
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
  // Aim at a ball on half the time, so that games progress.
  if (!legal.on.empty() && rng.chance(0.5))
    a.aim_at = legal.on[static_cast<std::size_t>(rng.integer(0, static_cast<int>(legal.on.size()) - 1))];
  return a;
}

TEST(EightBall, RandomGamesEndConserveBallsAndReplay) {
  int won = 0;
  int decisions = 0, fouls = 0;  // the rulings the games went through (the illegal-break options among them)
  for (std::uint64_t game = 0; game < 20; ++game) {
    GameState s = new_game(default_config(GameKind::eight_ball), game);
    RandomStream rng(splitmix64(game));
    std::vector<GameStep> steps;
    std::vector<int> down;  // object balls pocketed and not respotted since the last rack
    while (!s.over) {
      const Action a = random_action(s, rng);
      GameStep step = play(s, a, stream_seed(game, static_cast<std::uint64_t>(s.shots)));
      decisions += a.decision ? 1 : 0;
      fouls += step.ruling.foul ? 1 : 0;
      for (const int id : step.ruling.pocketed)
        if (id != 0) down.push_back(id);
      for (const int id : step.ruling.respotted) down.erase(std::find(down.begin(), down.end(), id));
      if (step.next.phase == GamePhase::break_shot) down.clear();
      EXPECT_EQ(object_balls(step.next).size() + down.size(), 15u) << "game " << game << " shot " << s.shots;
      // The groups, once set, are one each and never change.
      if (s.groups[0] != Group::none) {
        EXPECT_EQ(step.next.groups, s.groups);
      }
      if (step.next.groups[0] != Group::none) {
        EXPECT_NE(step.next.groups[0], step.next.groups[1]);
      }
      s = step.next;
      steps.push_back(std::move(step));
    }
    EXPECT_TRUE(s.winner.has_value() || s.truncated);
    won += s.winner.has_value() ? 1 : 0;
    GameState r = new_game(default_config(GameKind::eight_ball), game);
    for (const GameStep& step : steps) r = play(r, step.action, stream_seed(game, static_cast<std::uint64_t>(r.shots))).next;
    EXPECT_TRUE(r == s);
  }
  EXPECT_GT(won, 0);
  EXPECT_GT(decisions, 0);
  EXPECT_GT(fouls, 0);
}

}  // namespace
}  // namespace cueball
