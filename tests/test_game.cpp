// src/games/game.cpp: the driver's entry points beyond the disciplines'
// rules (those have their own tests): play_foul_stroke.
#include <gtest/gtest.h>

#include "cueball/core/errors.hpp"
#include "cueball/games/game.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

// A foul stroke moves nothing and is judged as the discipline's miscue foul:
// in 9-ball, ball in hand anywhere for the opponent (WPA 2.7), one foul counted.
TEST(PlayFoulStroke, IsTheDisciplinesMiscueFoulAndMovesNothing) {
  const GameState s = test::rotation_in_play(GameKind::nine_ball, {{0, {0.6, 0.6}}, {1, {1.8, 0.7}}, {9, {2.2, 0.3}}});
  const GameStep step = play_foul_stroke(s, std::nullopt, 1, "illegal action (test)");
  ASSERT_TRUE(step.ruling.foul);
  EXPECT_EQ(*step.ruling.foul, Foul::miscue);
  EXPECT_TRUE(step.ruling.turn_over);
  EXPECT_EQ(step.ruling.reason.rfind("illegal action (test)", 0), 0u) << step.ruling.reason;
  EXPECT_EQ(step.next.to_shoot, 1);
  ASSERT_TRUE(step.next.ball_in_hand);
  EXPECT_EQ(step.next.ball_in_hand->kind, PlacementRegion::Kind::anywhere);
  EXPECT_EQ(step.next.fouls_in_a_row[0], 1);
  ASSERT_EQ(step.next.table.balls.size(), s.table.balls.size());
  for (std::size_t i = 0; i < s.table.balls.size(); ++i)
    EXPECT_EQ(step.next.table.balls[i].state.position, s.table.balls[i].state.position);
  EXPECT_EQ(step.next.shots, s.shots + 1);
}

// With the cue ball in hand and off the table, an illegal spot is replaced
// by a legal one drawn from the seed; a legal spot is used as given.
TEST(PlayFoulStroke, PlacesTheCueBallInHandLegally) {
  GameState s = test::rotation_in_play(GameKind::nine_ball, {{1, {1.8, 0.7}}, {9, {2.2, 0.3}}});
  s.ball_in_hand = PlacementRegion{};
  const GameStep bad = play_foul_stroke(s, Vec2{1.8, 0.7}, 5, "illegal");  // on the 1
  ASSERT_TRUE(bad.action.place);
  EXPECT_GT(std::hypot(bad.action.place->x - 1.8, bad.action.place->y - 0.7), 2 * s.table.table.ball.radius);
  EXPECT_EQ(bad.action.place, play_foul_stroke(s, Vec2{1.8, 0.7}, 5, "illegal").action.place);  // seeded
  const GameStep good = play_foul_stroke(s, Vec2{0.5, 0.5}, 5, "illegal");
  EXPECT_EQ(good.action.place, (Vec2{0.5, 0.5}));
}

TEST(PlayFoulStroke, RefusesAnOverGameAndADecision) {
  GameState s = new_game(default_config(GameKind::nine_ball));
  s.phase = GamePhase::decision;
  s.decisions = {Decision::play, Decision::pass};
  EXPECT_THROW(play_foul_stroke(s, std::nullopt, 0, "x"), InvalidArgument);
  s.over = true;
  EXPECT_THROW(play_foul_stroke(s, std::nullopt, 0, "x"), InvalidArgument);
}

}  // namespace
}  // namespace cueball
