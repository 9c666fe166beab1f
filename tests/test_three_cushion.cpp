// Three-cushion's rules (src/games/three_cushion.cpp): the opening
// position, each ruling from a crafted table and strike whose facts decide
// it, then random games.
//
// A three-cushion strike that scores lies in an aim window a few tenths of a
// degree wide, which moves when the cushion model changes; so each crafted
// test scans a few degrees of aim on its table, in fine steps, for the
// strike whose facts show what the rule is about (three cushions before the
// second ball, two, cushions after it), and then checks the ruling of that
// strike. The scan failing to find one says the layout needs a new window,
// not that a rule is wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "cueball/core/random.hpp"
#include "cueball/games/game.hpp"
#include "cueball/table/placement.hpp"
#include "expect_invalid.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

using test::strike;

constexpr int kWhite = 0;
constexpr int kYellow = 1;
constexpr int kRed = 2;

// A game in play, player `shooter` to shoot, with the three balls here.
GameState in_play(Vec2 white, Vec2 yellow, Vec2 red, int shooter = 0) {
  GameState s = new_game(default_config(GameKind::three_cushion));
  s.phase = GamePhase::play;
  s.to_shoot = shooter;
  s.table.balls[0].state.position = white;
  s.table.balls[1].state.position = yellow;
  s.table.balls[2].state.position = red;
  s.on = shooter == 0 ? std::vector<int>{kYellow, kRed} : std::vector<int>{kWhite, kRed};
  return s;
}

// The layout the scans below were drawn on: white low on the head half,
// yellow in the middle, red up on the foot half.
GameState layout(int shooter = 0) {
  if (shooter == 0) return in_play({0.5, 0.4}, {1.5, 0.7}, {2.2, 1.0}, 0);
  return in_play({1.5, 0.7}, {0.5, 0.4}, {2.2, 1.0}, 1);  // the same balls, yellow the cue ball
}

// What the cue ball did: the first and second object balls it touched and
// its cushions before the second (-1: none).
struct CueRun {
  int first = -1;
  int second = -1;
  int cushions_before_second = -1;
};

CueRun cue_run(const ShotFacts& f) {
  CueRun r;
  for (const CueCushionsBeforeContact& c : f.cue_cushions_before_contact) {
    if (r.first < 0) {
      r.first = c.ball;
    } else if (c.ball != r.first) {
      r.second = c.ball;
      r.cushions_before_second = c.cushions;
      break;
    }
  }
  return r;
}

// The first strike at `speed` with aim in [from, to] (steps of 0.05 deg) whose
// noise-free shot has facts satisfying `wanted`.
std::optional<GameStep> scan(const GameState& s, double speed, double from, double to,
                             const std::function<bool(const ShotFacts&)>& wanted) {
  for (double aim = from; aim <= to; aim += 0.05) {
    GameStep step = play(s, strike(speed, aim), 0);
    if (wanted(step.facts)) return step;
  }
  return std::nullopt;
}

bool three_before_second(const ShotFacts& f) {
  const CueRun r = cue_run(f);
  return r.second >= 0 && r.cushions_before_second >= 3;
}

std::optional<GameStep> a_point(const GameState& s) { return scan(s, 3.0, 203.0, 206.0, three_before_second); }

TEST(ThreeCushion, OpeningPosition) {
  // UMB Art. 23: red on the top spot, yellow on the head spot, white on the
  // head string 0.182 m to the right of it; white to open, the red on.
  const GameState s = new_game(default_config(GameKind::three_cushion));
  const Table& t = s.table.table;
  EXPECT_TRUE(t.pockets.empty());
  EXPECT_EQ(s.config.table, "carom_10ft");
  ASSERT_EQ(s.table.balls.size(), 3u);
  EXPECT_EQ(s.table.balls[0].name, "white");
  EXPECT_EQ(s.table.balls[1].name, "yellow");
  EXPECT_EQ(s.table.balls[2].name, "red");
  const Vec2 red = find_ball(s.table.balls, kRed)->state.position;
  const Vec2 yellow = find_ball(s.table.balls, kYellow)->state.position;
  const Vec2 white = find_ball(s.table.balls, kWhite)->state.position;
  EXPECT_DOUBLE_EQ(red.x, 0.75 * t.length);
  EXPECT_DOUBLE_EQ(red.y, 0.5 * t.width);
  EXPECT_DOUBLE_EQ(yellow.x, 0.25 * t.length);
  EXPECT_DOUBLE_EQ(yellow.y, 0.5 * t.width);
  EXPECT_DOUBLE_EQ(white.x, 0.25 * t.length);
  EXPECT_NEAR(white.y, 0.5 * t.width - 0.182, 1e-12);
  EXPECT_EQ(s.phase, GamePhase::break_shot);
  EXPECT_EQ(s.to_shoot, 0);
  EXPECT_EQ(s.cue_ball(), kWhite);
  EXPECT_FALSE(s.ball_in_hand);
  const LegalActions legal = legal_actions(s);
  EXPECT_TRUE(legal.shoot);
  EXPECT_EQ(legal.cue_ball, kWhite);
  EXPECT_EQ(legal.on, std::vector<int>{kRed});
  EXPECT_FALSE(legal.ball_in_hand);
  EXPECT_TRUE(legal.decisions.empty());
}

TEST(ThreeCushion, OpeningShotMustHitTheRedFirst) {
  const GameState s = new_game(default_config(GameKind::three_cushion));
  Action at_yellow = strike(2.0, 0.0);
  at_yellow.aim_at = kYellow;
  const GameStep step = play(s, at_yellow, 1);
  ASSERT_EQ(step.facts.first_contact, kYellow);
  EXPECT_EQ(step.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{0, 0}));
  EXPECT_TRUE(step.ruling.turn_over);
  EXPECT_EQ(step.next.to_shoot, 1);
  EXPECT_EQ(step.next.cue_ball(), kYellow);
  EXPECT_EQ(step.next.phase, GamePhase::play);
  EXPECT_EQ(step.next.on, (std::vector<int>{kWhite, kRed}));
  EXPECT_FALSE(step.next.ball_in_hand);  // the opponent plays the balls where they lie
  EXPECT_EQ(step.next.fouls_in_a_row[0], 1);

  Action at_red = strike(2.0, 0.0);
  at_red.aim_at = kRed;
  const GameStep legal = play(s, at_red, 1);
  ASSERT_EQ(legal.facts.first_contact, kRed);
  EXPECT_FALSE(legal.ruling.foul);
}

TEST(ThreeCushion, ThreeCushionsBeforeTheSecondBallScoreAndTheInningGoesOn) {
  const GameState s = layout();
  const std::optional<GameStep> step = a_point(s);
  ASSERT_TRUE(step) << "no strike in the window reached the second ball after three cushions";
  EXPECT_FALSE(step->ruling.foul);
  EXPECT_EQ(step->ruling.points, (std::array<int, 2>{1, 0}));
  EXPECT_FALSE(step->ruling.turn_over);
  EXPECT_EQ(step->next.scores, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(step->next.inning_points, 1);
  EXPECT_EQ(step->next.to_shoot, 0);
  EXPECT_EQ(step->next.cue_ball(), kWhite);
  EXPECT_EQ(step->next.on, (std::vector<int>{kYellow, kRed}));
  EXPECT_EQ(step->next.phase, GamePhase::play);
  // A second point in the inning adds to the run; a miss then ends it.
  GameState again = s;
  again.scores = {1, 0};
  again.inning_points = 1;
  const GameStep second = play(again, step->action, 0);
  EXPECT_EQ(second.next.scores, (std::array<int, 2>{2, 0}));
  EXPECT_EQ(second.next.inning_points, 2);
  const GameStep miss = play(second.next, strike(1.0, 90.0), 0);
  EXPECT_TRUE(miss.ruling.turn_over);
  EXPECT_FALSE(miss.ruling.foul);
  EXPECT_EQ(miss.next.to_shoot, 1);
  EXPECT_EQ(miss.next.inning_points, 0);
  EXPECT_EQ(miss.next.scores, (std::array<int, 2>{2, 0}));
  EXPECT_EQ(legal_actions(miss.next).cue_ball, kYellow);
}

TEST(ThreeCushion, TheSecondPlayerScoresWithTheYellow) {
  // The same table with white and yellow swapped: player 1 plays the point.
  const GameState s = layout(1);
  EXPECT_EQ(legal_actions(s).cue_ball, kYellow);
  const std::optional<GameStep> step = a_point(s);
  ASSERT_TRUE(step);
  EXPECT_EQ(step->facts.cue_ball, kYellow);
  EXPECT_EQ(step->ruling.points, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(step->next.scores, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(step->next.to_shoot, 1);
}

TEST(ThreeCushion, TwoCushionsBeforeTheSecondBallIsNoPoint) {
  const GameState s = layout();
  const std::optional<GameStep> step = scan(s, 3.0, 36.0, 39.0, [](const ShotFacts& f) {
    const CueRun r = cue_run(f);
    return r.second >= 0 && r.cushions_before_second == 2;
  });
  ASSERT_TRUE(step) << "no near miss with two cushions in the window";
  EXPECT_FALSE(step->ruling.foul);
  EXPECT_EQ(step->ruling.points, (std::array<int, 2>{0, 0}));
  EXPECT_TRUE(step->ruling.turn_over);
  EXPECT_EQ(step->next.to_shoot, 1);
  EXPECT_EQ(step->next.scores, (std::array<int, 2>{0, 0}));
}

TEST(ThreeCushion, CushionsAfterTheSecondBallDoNotCount) {
  // Both balls touched with fewer than three cushions between, three or
  // more cushions in the whole shot: no point.
  const GameState s = layout();
  const std::optional<GameStep> step = scan(s, 3.0, 165.0, 168.0, [](const ShotFacts& f) {
    const CueRun r = cue_run(f);
    return r.second >= 0 && r.cushions_before_second < 3 && f.cushion_count(f.cue_ball) >= 3;
  });
  ASSERT_TRUE(step) << "no strike in the window touched both balls early and went on round the table";
  EXPECT_EQ(step->ruling.points, (std::array<int, 2>{0, 0}));
  EXPECT_TRUE(step->ruling.turn_over);
  EXPECT_FALSE(step->ruling.foul);
}

TEST(ThreeCushion, TheRaceIsWonOnTheLastPoint) {
  GameState s = layout();
  s.config.race_to = 5;
  s.scores = {4, 2};
  const std::optional<GameStep> step = a_point(s);
  ASSERT_TRUE(step);
  EXPECT_TRUE(step->ruling.game_over);
  EXPECT_EQ(step->ruling.winner, 0);
  EXPECT_TRUE(step->next.over);
  EXPECT_EQ(step->next.winner, 0);
  EXPECT_FALSE(step->next.truncated);
  EXPECT_EQ(step->next.scores, (std::array<int, 2>{5, 2}));
  EXPECT_FALSE(legal_actions(step->next).shoot);
  test::expect_invalid("action", [&] { (void)play(step->next, strike(1.0, 0.0), 2); });
  // One point short of the race, the same point only adds to the score.
  s.scores = {3, 2};
  const GameStep short_of = play(s, step->action, 0);
  EXPECT_FALSE(short_of.ruling.game_over);
  EXPECT_EQ(short_of.next.scores, (std::array<int, 2>{4, 2}));
}

TEST(ThreeCushion, AContactWithABallFrozenToTheCueBallAtTheStrikeDoesNotCount) {
  // White frozen to the red and played straight into it (UMB Art. 27, the
  // engine plays frozen balls away): the contact at the strike is not
  // counted, so nothing was touched.
  const double r = preset_table("carom_10ft").ball.radius;
  GameState s = in_play({1.0, 0.71}, {0.3, 0.3}, {1.0 + 2.0 * r, 0.71});
  const GameStep step = play(s, strike(0.7, 0.0), 0);  // soft: the white stays short of the far cushion
  ASSERT_FALSE(step.facts.frozen_balls.empty());
  ASSERT_EQ(step.facts.first_contact, kRed);
  ASSERT_EQ(step.facts.cue_cushions_before_contact.size(), 1u);  // the push at the strike, nothing after
  EXPECT_NE(step.ruling.reason.find("no ball touched"), std::string::npos) << step.ruling.reason;
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{0, 0}));
  // Away from the red, into the yellow: the yellow is the first ball.
  const GameStep away = play(s, strike(1.0, std::atan2(0.3 - 0.71, 0.3 - 1.0) * 180.0 / std::numbers::pi), 0);
  ASSERT_EQ(away.facts.first_contact, kYellow);
  EXPECT_NE(away.ruling.reason.find("only the yellow touched"), std::string::npos) << away.ruling.reason;
}

TEST(ThreeCushion, AMiscueIsAFoul) {
  GameState s = layout();
  s.config.noise.side_offset = 0.004;  // m: a strike near the miscue limit miscues about half the time
  Action a = strike(3.0, 90.0);
  a.strike.side = 0.49;
  bool seen = false;
  for (std::uint64_t seed = 0; seed < 20 && !seen; ++seed) {
    const GameStep step = play(s, a, seed);
    if (step.ruling.foul != Foul::miscue) continue;
    seen = true;
    EXPECT_TRUE(step.ruling.turn_over);
    EXPECT_EQ(step.next.to_shoot, 1);
    EXPECT_EQ(step.next.table.balls[0].state.position.x, s.table.balls[0].state.position.x);
  }
  EXPECT_TRUE(seen);
}

TEST(ThreeCushion, ABallOffTheTableIsAFoulAndIsSpotted) {
  // Not reachable on the carom table (no pockets, no airborne phase): on a
  // custom table with pockets a ball captured by one has left the bed.
  GameState s = layout();
  s.table.table = preset_table("pool_9ft");
  s.table.settings.parameters = default_parameters(s.table.table);
  const Table& t = s.table.table;
  s.table.balls[0].state.position = {0.5, 0.5};
  s.table.balls[1].state.position = {1.5, 0.9};
  s.table.balls[2].state.position = {2.0, 1.0};
  const GameStep step = play(s, strike(2.0, 225.0), 1);  // straight into the bottom-left pocket
  ASSERT_TRUE(step.facts.pocketed(kWhite));
  EXPECT_EQ(step.ruling.foul, Foul::ball_off_table);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{0, 0}));
  EXPECT_EQ(step.ruling.respotted, std::vector<int>{kWhite});
  EXPECT_EQ(step.next.to_shoot, 1);
  const SimulationBall* white = find_ball(step.next.table.balls, kWhite);
  ASSERT_TRUE(white);
  EXPECT_DOUBLE_EQ(white->state.position.x, head_string_x(t));
  EXPECT_DOUBLE_EQ(white->state.position.y, long_string_y(t));
}

TEST(ThreeCushion, NoDecisionNoPlacementNoCall) {
  const GameState s = layout();
  Action decide;
  decide.decision = Decision::play;
  test::expect_invalid("decision", [&] { (void)play(s, decide, 0); });
  Action placed = strike(2.0, 0.0);
  placed.place = Vec2{1.0, 1.0};
  test::expect_invalid("place", [&] { (void)play(s, placed, 0); });
  Action called = strike(2.0, 0.0);
  called.called_ball = kRed;
  test::expect_invalid("called_ball", [&] { (void)play(s, called, 0); });
}

TEST(ThreeCushion, RandomGamesEndScoreConsistentlyAndReplay) {
  for (std::uint64_t game = 0; game < 16; ++game) {
    GameConfig config = default_config(GameKind::three_cushion);
    config.max_shots = 120;
    config.race_to = 2;
    if (game % 2 == 1) {
      config.noise.speed = 0.075;
      config.noise.aim = 0.125 * std::numbers::pi / 180.0;
    }
    GameState s = new_game(config, game);
    RandomStream rng(splitmix64(game));
    std::vector<GameStep> steps;
    std::array<int, 2> points{};
    while (!s.over) {
      const LegalActions legal = legal_actions(s);
      ASSERT_TRUE(legal.shoot);
      ASSERT_EQ(legal.cue_ball, s.to_shoot);
      Action a;
      a.strike.speed = rng.uniform(0.5, 8.0);
      a.strike.aim_deg = rng.uniform(-180.0, 180.0);
      a.strike.side = rng.uniform(-0.3, 0.3);
      a.strike.height = rng.uniform(-0.3, 0.3);
      GameStep step = play(s, a, stream_seed(game, static_cast<std::uint64_t>(s.shots)));
      EXPECT_EQ(step.next.table.balls.size(), 3u);
      points[0] += step.ruling.points[0];
      points[1] += step.ruling.points[1];
      EXPECT_EQ(step.next.scores, points) << "game " << game << " shot " << s.shots;
      const bool scored = step.ruling.points[static_cast<std::size_t>(s.to_shoot)] == 1;
      if (!step.next.over) {
        EXPECT_EQ(step.ruling.turn_over, !scored);
        EXPECT_EQ(step.next.inning_points, scored ? s.inning_points + 1 : 0);
      }
      s = step.next;
      steps.push_back(std::move(step));
    }
    EXPECT_LE(s.shots, config.max_shots);
    EXPECT_TRUE(s.winner.has_value() != s.truncated) << "game " << game;
    if (s.winner) {
      EXPECT_EQ(s.scores[static_cast<std::size_t>(*s.winner)], config.race_to);
    }
    GameState r = new_game(config, game);
    for (const GameStep& step : steps) r = play(r, step.action, stream_seed(game, static_cast<std::uint64_t>(r.shots))).next;
    EXPECT_TRUE(r == s);
  }
}

}  // namespace
}  // namespace cueball
