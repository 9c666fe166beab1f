// src/rl/env_action.cpp: the learner's action scales, its decoding into a
// game Action (illegal parts named, never thrown), the masks, the mirror.
#include <gtest/gtest.h>

#include <cmath>

#include "cueball/physics/cue_strike.hpp"
#include "cueball/rl/environment.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

GameState nine_ball_in_play() {
  return test::rotation_in_play(GameKind::nine_ball, {{0, {0.6, 0.6}}, {1, {1.8, 0.7}}, {9, {2.2, 0.3}}});
}

TEST(EnvAction, ScalesMapTheUnitCubeOntoTheStrikesRanges) {
  EnvOptions o;
  const GameState s = nine_ball_in_play();
  EnvAction a;
  a.strike = {-1.0, 0.5, 1.0, 0.0, 0.0};
  DecodedAction d = decode_action(o, s, a);
  EXPECT_TRUE(d.illegal.empty()) << d.illegal;
  EXPECT_DOUBLE_EQ(d.action.strike.speed, kEnvMinSpeed);
  EXPECT_DOUBLE_EQ(d.action.strike.aim_deg, 90.0);
  EXPECT_DOUBLE_EQ(d.action.strike.elevation_deg, kEnvMaxElevationDeg);
  a.strike = {1.0, -1.0, -1.0, 0.0, 0.0};
  d = decode_action(o, s, a);
  EXPECT_DOUBLE_EQ(d.action.strike.speed, o.max_speed);
  EXPECT_DOUBLE_EQ(d.action.strike.aim_deg, -180.0);
  EXPECT_DOUBLE_EQ(d.action.strike.elevation_deg, 0.0);
  a.strike = {std::nan(""), 7.0, -3.0, 0.0, 0.0};  // NaN reads as 0, the rest clipped
  d = decode_action(o, s, a);
  EXPECT_DOUBLE_EQ(d.action.strike.speed, kEnvMinSpeed + 0.5 * (o.max_speed - kEnvMinSpeed));
  EXPECT_DOUBLE_EQ(d.action.strike.aim_deg, 180.0);
}

// The square of tip offsets maps onto the miscue disc: the rim and every
// corner land within the limit, the axes keep their values.
TEST(EnvAction, TipOffsetsStayWithinTheMiscueLimit) {
  EnvOptions o;
  const GameState s = nine_ball_in_play();
  for (double side = -1.0; side <= 1.0; side += 0.125)
    for (double height = -1.0; height <= 1.0; height += 0.125) {
      EnvAction a;
      a.strike = {0.0, 0.0, 0.0, side, height};
      const DecodedAction d = decode_action(o, s, a);
      EXPECT_LE(std::hypot(d.action.strike.side, d.action.strike.height), kMiscueOffsetFraction);
      EXPECT_TRUE(d.illegal.empty());
    }
  EnvAction a;
  a.strike = {0.0, 0.0, 0.0, 0.6, 0.0};
  EXPECT_NEAR(decode_action(o, s, a).action.strike.side, 0.3, 1e-9);
  a.strike = {0.0, 0.0, 0.0, 1.0, 1.0};
  const DecodedAction d = decode_action(o, s, a);
  EXPECT_NEAR(std::hypot(d.action.strike.side, d.action.strike.height), 0.5, 1e-9);
  EXPECT_NEAR(d.action.strike.side, d.action.strike.height, 1e-15);
}

// The target form aims at the ghost ball: a straight-in shot (cue ball, ball
// and pocket on a line) aims along the line, and the offset adds to it.
TEST(EnvAction, TheTargetFormAimsAtTheGhostBall) {
  EnvOptions o;
  o.form = ActionForm::target;
  GameState s = nine_ball_in_play();
  const Vec2 pocket = s.table.table.pockets[2].centre;  // bottom-right
  const Vec2 ball{pocket.x - 0.4, pocket.y + 0.4};
  test::place_balls(s, {{0, {ball.x - 0.5, ball.y + 0.5}}, {1, ball}, {9, {0.3, 1.0}}});
  EnvAction a;
  a.ball = 1;
  a.pocket = 2;
  DecodedAction d = decode_action(o, s, a);
  EXPECT_TRUE(d.illegal.empty()) << d.illegal;
  EXPECT_NEAR(d.action.strike.aim_deg, -45.0, 1e-9);
  a.strike[1] = 0.5;
  EXPECT_NEAR(decode_action(o, s, a).action.strike.aim_deg, -45.0 + 0.5 * kEnvMaxCutOffsetDeg, 1e-9);
  a.ball = 4;  // not on the table
  EXPECT_NE(decode_action(o, s, a).illegal.find("ball"), std::string::npos);
}

TEST(EnvAction, IllegalPartsAreNamedNeverThrown) {
  EnvOptions o;
  GameState s = nine_ball_in_play();
  EnvAction a;
  a.decision = 2;  // a decision during a shot
  EXPECT_EQ(decode_action(o, s, a).illegal.rfind("decision", 0), 0u);
  a = EnvAction{};
  a.push_out = 1;  // not the shot after the break
  EXPECT_EQ(decode_action(o, s, a).illegal.rfind("push_out", 0), 0u);
  s.ball_in_hand = PlacementRegion{};
  a = EnvAction{};
  a.place = {0.0, 0.0};  // the centre of the bed: free
  EXPECT_TRUE(decode_action(o, s, a).illegal.empty());
  s.table.balls[1].state.position = {s.table.table.length / 2, s.table.table.width / 2};  // the 1 on that spot
  EXPECT_EQ(decode_action(o, s, a).illegal.rfind("place", 0), 0u);
  // A decision that is not open is replaced by the first open one.
  s.phase = GamePhase::decision;
  s.decisions = {Decision::play, Decision::pass};
  a = EnvAction{};
  a.decision = 1 + static_cast<int>(Decision::restore);
  const DecodedAction d = decode_action(o, s, a);
  ASSERT_TRUE(d.action.decision);
  EXPECT_EQ(*d.action.decision, Decision::play);
  EXPECT_FALSE(d.illegal.empty());
  a.decision = 1 + static_cast<int>(Decision::pass);
  EXPECT_EQ(*decode_action(o, s, a).action.decision, Decision::pass);
  EXPECT_TRUE(decode_action(o, s, a).illegal.empty());
}

// 10-ball asks for a call: the ball mask is the callable balls, and a call
// of another ball is illegal.
TEST(EnvAction, MasksFollowTheLegalActions) {
  GameState ten = test::rotation_in_play(GameKind::ten_ball, {{0, {0.6, 0.6}}, {3, {1.8, 0.7}}, {10, {2.2, 0.3}}});
  const LegalActions legal = legal_actions(ten);
  ASSERT_TRUE(legal.call_required);
  const ActionMasks m = action_masks(ten);
  ASSERT_EQ(m.ball.size(), 11u);
  for (int id = 0; id < 11; ++id)
    EXPECT_EQ(m.ball[static_cast<std::size_t>(id)] != 0,
              std::find(legal.callable.begin(), legal.callable.end(), id) != legal.callable.end()) << id;
  EXPECT_EQ(m.decision[0], 1);
  EXPECT_EQ(m.push_out[1], 0);
  EnvOptions o;
  o.game = GameKind::ten_ball;
  EnvAction a;
  a.ball = 4;  // not on the table
  a.pocket = 0;
  EXPECT_EQ(decode_action(o, ten, a).illegal.rfind("ball", 0), 0u);
  a.ball = 3;
  a.pocket = 6;
  EXPECT_EQ(decode_action(o, ten, a).illegal.rfind("pocket", 0), 0u);
  a.pocket = 0;
  a.ball = 3;
  EXPECT_TRUE(decode_action(o, ten, a).illegal.empty());
  // A decision phase: only the open decisions.
  ten.phase = GamePhase::decision;
  ten.decisions = {Decision::play, Decision::pass};
  const ActionMasks d = action_masks(ten);
  EXPECT_EQ(d.decision[0], 0);
  EXPECT_EQ(d.decision[1], 1);
  EXPECT_EQ(d.decision[2], 1);
  EXPECT_EQ(d.decision[3], 0);
}

// The mirror about the long string swaps the bottom and top pockets and is
// its own inverse.
TEST(EnvAction, TheMirrorSwapsPocketsAndIsAnInvolution) {
  const Table t = nine_ball_in_play().table.table;
  EnvAction a;
  a.strike = {0.1, 0.3, 0.2, 0.4, -0.2};
  a.place = {0.5, -0.25};
  for (int p = 0; p < 6; ++p) {
    a.pocket = p;
    const EnvAction m = mirror_action(t, a);
    const Vec2 c = t.pockets[static_cast<std::size_t>(p)].centre;
    const Vec2 mc = t.pockets[static_cast<std::size_t>(m.pocket)].centre;
    EXPECT_NEAR(mc.x, c.x, 1e-12);
    EXPECT_NEAR(mc.y, t.width - c.y, 1e-12);
    const EnvAction back = mirror_action(t, m);
    EXPECT_EQ(back.pocket, p);
    EXPECT_EQ(back.strike, a.strike);
    EXPECT_EQ(back.place, a.place);
  }
  EXPECT_EQ(mirror_action(t, a).strike[1], -0.3);
  EXPECT_EQ(mirror_action(t, a).strike[3], -0.4);
  EXPECT_EQ(mirror_action(t, a).place[1], 0.25);
}

}  // namespace
}  // namespace cueball
