// The ghost-ball agent (src/agents/ghost_ball.cpp) and what the pool agents
// share (src/agents/agent.cpp): it pots a straight-in ball, places the cue
// ball in hand behind a ghost ball inside the region, hits a ball on when
// nothing pots, calls and nominates when asked, takes the decisions by the
// policy, and breaks legally.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cueball/agents/agent.hpp"
#include "cueball/planning/ghost_ball.hpp"
#include "cueball/games/break_shot.hpp"
#include "cueball/core/random.hpp"
#include "game_actions.hpp"
#include "expect_invalid.hpp"

namespace cueball {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A 9-ball game in play (after the break) with exactly these balls.
GameState in_play(const std::vector<std::pair<int, Vec2>>& balls) {
  return test::rotation_in_play(GameKind::nine_ball, balls);
}

TEST(GhostBall, PotsAStraightInBall) {
  // The 1 on the diagonal of the bottom-left corner pocket, the cue ball
  // close behind it on that line (still sliding at the contact: it stops
  // short of the pocket): the ghost ball of that pocket, straight in.
  GameState s = in_play({{0, {0.62, 0.62}}, {1, {0.45, 0.45}}, {9, {2.2, 0.3}}});
  const Action a = ghost_ball_action(s, 1);
  EXPECT_FALSE(a.decision);
  EXPECT_FALSE(a.place);
  EXPECT_FALSE(a.push_out);
  EXPECT_EQ(a.strike.speed, kGhostBallSpeed);
  EXPECT_EQ(a.strike.side, 0.0);
  EXPECT_EQ(a.strike.height, 0.0);
  const Vec2 P = s.table.table.pockets[0].centre, O{0.45, 0.45};
  const Vec2 G = O - 2.0 * s.table.table.ball.radius * ((P - O) / norm(P - O));
  EXPECT_NEAR(a.strike.aim_deg, std::atan2(G.y - 0.62, G.x - 0.62) / kDeg, 1e-9);
  const GameStep step = play(s, a, 1);
  EXPECT_TRUE(step.facts.pocketed(1));
  EXPECT_FALSE(step.ruling.foul) << step.ruling.reason;
  EXPECT_FALSE(step.ruling.turn_over);
}

TEST(GhostBall, ShotIsTheEasiestClearPocket) {
  // The 1 near the top-right corner; the cue ball in front of it: that corner is easiest.
  GameState s = in_play({{0, {1.9, 0.9}}, {1, {2.3, 1.05}}, {9, {0.5, 0.3}}});
  const std::optional<GhostBallShot> g = ghost_ball_shot(s.table, 0, {1});
  ASSERT_TRUE(g);
  EXPECT_EQ(g->target, 1);
  const Vec2 P = s.table.table.pockets[static_cast<std::size_t>(g->pocket)].centre;
  EXPECT_GT(P.x, 2.0);
  EXPECT_GT(P.y, 1.0);
  // A ball on the only straight line blocks it: another pocket, or none.
  GameState blocked = in_play({{0, {1.9, 0.9}}, {1, {2.3, 1.05}}, {2, {2.45, 1.15}}, {9, {0.5, 0.3}}});
  const std::optional<GhostBallShot> other = ghost_ball_shot(blocked.table, 0, {1});
  if (other) {
    EXPECT_NE(other->pocket, g->pocket);
  }
  // No cue ball on the table: no shot.
  GameState no_cue = in_play({{1, {2.3, 1.05}}, {9, {0.5, 0.3}}});
  EXPECT_FALSE(ghost_ball_shot(no_cue.table, 0, {1}));
}

// The 1 near the bottom rail, 0.35 m short of the side pocket, the cue ball
// behind it on the line from that pocket: the straight-in to the side pocket
// has the best score (the geometry), but the ball comes at it from along the
// rail, where its window is nearly closed. The ghost-ball agent keeps the
// score's choice; the likeliest pot (the safety screen's) is another
// pocket, with the larger aim tolerance.
TEST(GhostBall, TheLikeliestPotCountsThePocketsWindowTheAgentsChoiceDoesNot) {
  const Vec2 O{0.92, 0.08};
  GameState probe = in_play({{1, O}, {9, {2.2, 1.1}}});
  std::size_t side = 0;
  for (std::size_t p = 0; p < probe.table.table.pockets.size(); ++p)
    if (probe.table.table.pockets[p].centre.y < 0.0 &&
        std::abs(probe.table.table.pockets[p].centre.x - 0.5 * probe.table.table.length) < 0.1)
      side = p;
  const Vec2 P = probe.table.table.pockets[side].centre;
  const Vec2 C = O - 0.3 * ((P - O) / norm(P - O));
  const GameState s = in_play({{0, C}, {1, O}, {9, {2.2, 1.1}}});
  const std::optional<GhostBallShot> by_score = ghost_ball_shot(s.table, 0, {1});
  const std::optional<GhostBallShot> likeliest = likeliest_ghost_ball_shot(s.table, 0, {1});
  ASSERT_TRUE(by_score && likeliest);
  EXPECT_EQ(by_score->pocket, static_cast<int>(side));
  EXPECT_NE(likeliest->pocket, by_score->pocket);
  EXPECT_GT(by_score->score, likeliest->score);
  EXPECT_GT(likeliest->aim_tolerance, 4.0 * by_score->aim_tolerance);
  const CueStrikeNoise noise = tournament_noise();
  EXPECT_EQ(pot_chance(s, noise), ghost_ball_pot_chance(likeliest->aim_tolerance, noise.aim));
}

TEST(GhostBall, BallInHandGoesBehindTheGhostBallInsideTheRegion) {
  for (const PlacementRegion::Kind kind : {PlacementRegion::Kind::anywhere, PlacementRegion::Kind::behind_head_string}) {
    GameState s = in_play({{1, {2.2, 0.35}}, {5, {2.1, 1.0}}, {9, {1.0, 1.0}}});  // the cue ball off the table
    PlacementRegion r;
    r.kind = kind;
    s.ball_in_hand = r;
    const Action a = ghost_ball_action(s, 7);
    ASSERT_TRUE(a.place);
    EXPECT_TRUE(in_region(s.table.table, r, *a.place)) << a.place->x << ", " << a.place->y;
    const GameStep step = play(s, a, 7);  // legal: play() validates the placement
    EXPECT_EQ(step.facts.first_contact, 1);
    if (kind == PlacementRegion::Kind::anywhere) {
      // The rule's spot: kGhostBallInHandBack behind the ghost ball, straight in.
      EXPECT_TRUE(step.facts.pocketed(1));
      EXPECT_FALSE(step.ruling.foul) << step.ruling.reason;
    }
  }
}

// Balls 2..7 in front of the six pockets: no straight path reaches a pocket.
GameState pockets_guarded() {
  GameState s = new_game(default_config(GameKind::nine_ball));
  const Table& t = s.table.table;
  const Vec2 centre{t.length / 2, t.width / 2};
  std::vector<std::pair<int, Vec2>> balls{{0, {0.8, 0.35}}, {1, {1.6, 0.75}}};
  for (std::size_t k = 0; k < t.pockets.size(); ++k) {
    const Vec2 P = t.pockets[k].centre;
    balls.emplace_back(static_cast<int>(k) + 2, P + 0.16 * ((centre - P) / norm(centre - P)));
  }
  return in_play(balls);
}

TEST(GhostBall, WithNoClearPotItHitsABallOn) {
  const GameState s = pockets_guarded();
  ASSERT_FALSE(ghost_ball_shot(s.table, 0, {1}));
  const Action a = ghost_ball_action(s, 3);
  EXPECT_EQ(a.strike.speed, kSafeHitSpeed);
  const GameStep step = play(s, a, 3);
  EXPECT_EQ(step.facts.first_contact, 1);
  EXPECT_FALSE(step.ruling.foul) << step.ruling.reason;
  // On the shot after the break it pushes out instead (nothing to lose).
  GameState push = s;
  push.push_out_available = true;
  EXPECT_TRUE(ghost_ball_action(push, 3).push_out);
  EXPECT_FALSE(ghost_ball_action(in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {9, {2.2, 0.3}}}), 3).push_out);
}

TEST(GhostBall, CallsAndNominatesWhenAsked) {
  // Legal actions as a called game (10-ball, 8-ball) and snooker give them.
  const GameState s = in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {2, {1.8, 0.9}}, {9, {2.2, 0.3}}});
  LegalActions legal = legal_actions(s);
  legal.on = {1, 2};
  legal.call_required = true;
  legal.callable = {1, 2};
  const Action called = ghost_ball_action(s, legal, 1);
  ASSERT_TRUE(called.called_ball);
  ASSERT_TRUE(called.called_pocket);
  EXPECT_EQ(*called.called_ball, 1);
  EXPECT_EQ(*called.called_pocket, 0);  // the straight-in's pocket
  legal.call_required = false;
  legal.nominate_required = true;
  legal.nominable = {2};
  const Action nominated = ghost_ball_action(s, legal, 1);
  ASSERT_TRUE(nominated.nominate);
  EXPECT_EQ(*nominated.nominate, 2);  // the ball nominated is the ball it plays
  EXPECT_FALSE(nominated.called_ball);
}

TEST(GhostBall, DecisionsFollowThePolicy) {
  GameState s = in_play({{0, {0.9, 0.9}}, {1, {0.45, 0.45}}, {9, {2.2, 0.3}}});
  s.phase = GamePhase::decision;
  s.decisions = {Decision::play, Decision::pass};
  const Action good = ghost_ball_action(s, 1);
  ASSERT_TRUE(good.decision);
  EXPECT_EQ(*good.decision, Decision::play);  // a clear pot: play
  EXPECT_NO_THROW((void)play(s, good, 1));
  GameState bad = pockets_guarded();
  bad.phase = GamePhase::decision;
  bad.decisions = {Decision::play, Decision::pass};
  EXPECT_EQ(ghost_ball_action(bad, 1).decision, Decision::pass);
  // The policy's order over every decision (agent.hpp).
  EXPECT_EQ(decision_by_policy({Decision::play, Decision::rerack_and_break, Decision::rerack_opponent_breaks}, false),
            Decision::rerack_and_break);
  EXPECT_EQ(decision_by_policy({Decision::play, Decision::rerack_and_break, Decision::rerack_opponent_breaks}, true),
            Decision::play);
  EXPECT_EQ(decision_by_policy({Decision::respot_eight, Decision::rerack}, true), Decision::respot_eight);
  EXPECT_EQ(decision_by_policy({Decision::respot_eight, Decision::rerack}, false), Decision::rerack);
  EXPECT_EQ(decision_by_policy({Decision::play, Decision::pass, Decision::restore}, false), Decision::restore);
  test::expect_invalid("decisions", [] { (void)decision_by_policy({}, true); });
}

TEST(GhostBall, BreaksFromTheKitchenAtTheApex) {
  const GameState s = new_game(default_config(GameKind::nine_ball), 3);
  const Action a = ghost_ball_action(s, 1);
  const Action recommended = recommended_break(s);
  EXPECT_EQ(a.strike, recommended.strike);
  ASSERT_TRUE(a.place);
  EXPECT_LE(a.place->x, head_string_x(s.table.table));
  EXPECT_GT(a.place->x, head_string_x(s.table.table) - 0.05);
  const GameStep step = play(s, a, 1);
  EXPECT_EQ(step.facts.first_contact, 1);
  EXPECT_NE(step.ruling.foul, Foul::illegal_break) << step.ruling.reason;
}

TEST(GhostBall, PlaysWholeNineBallGamesLegally) {
  AgentOptions ghost;
  ghost.kind = AgentKind::ghost_ball;
  int won = 0, shots = 0;
  for (std::uint64_t game = 0; game < 10; ++game) {
    GameConfig c = default_config(GameKind::nine_ball);
    c.noise = tournament_noise();
    GameState s = new_game(c, game);
    while (!s.over) {
      const std::uint64_t seed = stream_seed(game, static_cast<std::uint64_t>(s.shots));
      const Action a = choose_action(ghost, s, seed);
      EXPECT_EQ(a.strike, choose_action(ghost, s, seed).strike);
      s = play(s, a, seed).next;  // throws InvalidArgument for an illegal action
      ++shots;
    }
    won += s.winner ? 1 : 0;
  }
  EXPECT_EQ(won, 10);
  EXPECT_GT(shots, 0);
}

}  // namespace
}  // namespace cueball
