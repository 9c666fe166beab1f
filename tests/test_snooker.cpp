// Snooker's rules (src/games/snooker.cpp): each foul value, the nomination,
// the clearance, the respotting of colours, the free ball, the miss and its
// restore, the end of the frame, from a crafted table and strike whose
// ruling is known; then random frames of 6, 10 and 15 reds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cueball/core/random.hpp"
#include "cueball/games/game.hpp"
#include "expect_invalid.hpp"
#include "game_actions.hpp"

namespace cueball {
namespace {

using test::aim_deg;
using test::strike;

constexpr int kYellow = 16, kGreen = 17, kBrown = 18, kBlue = 19, kPink = 20, kBlack = 21;

std::string name_of(int id) {
  static const char* const colours[] = {"yellow", "green", "brown", "blue", "pink", "black"};
  if (id == 0) return "cue";
  if (id <= 15) return "red" + std::to_string(id);
  return colours[id - kYellow];
}

// A frame in play, player 0 to shoot, with exactly these balls: on the reds
// when any is on the table, else on the lowest colour.
GameState frame(const std::vector<std::pair<int, Vec2>>& balls) {
  GameState s = new_game(default_config(GameKind::snooker));
  s.phase = GamePhase::play;
  s.ball_in_hand.reset();
  s.table.balls.clear();
  std::vector<int> reds, colours;
  for (const auto& [id, p] : balls) {
    SimulationBall b;
    b.id = id;
    b.name = name_of(id);
    b.state.position = p;
    s.table.balls.push_back(b);
    if (id >= 1 && id <= 15) reds.push_back(id);
    if (id >= kYellow) colours.push_back(id);
  }
  std::sort(s.table.balls.begin(), s.table.balls.end(),
            [](const SimulationBall& a, const SimulationBall& b) { return a.id < b.id; });
  std::sort(reds.begin(), reds.end());
  std::sort(colours.begin(), colours.end());
  if (!reds.empty()) {
    s.on = reds;
    s.colour_on = 0;
  } else {
    s.on = {colours.front()};
    s.colour_on = colours.front();
  }
  return s;
}

// On a colour after a red: the colours on the table, to nominate.
GameState on_colour(GameState s) {
  s.on.clear();
  for (const SimulationBall& b : s.table.balls)
    if (b.id >= kYellow) s.on.push_back(b.id);
  s.colour_on = 0;
  return s;
}

// A straight pot into the bottom-left corner: the object ball at (0.3, 0.3),
// the cue ball behind it on the diagonal, played with draw.
const Vec2 kPotBall{0.3, 0.3};
const Vec2 kPotCue{0.6, 0.6};
Action pot_stroke() {
  Action a = strike(1.6, aim_deg(kPotCue, kPotBall));
  a.strike.height = -0.3;
  return a;
}

Vec2 position(const GameState& s, int id) {
  const SimulationBall* b = find_ball(s.table.balls, id);
  EXPECT_TRUE(b) << "ball " << id << " is not on the table";
  return b ? b->state.position : Vec2{-1.0, -1.0};
}

SnookerSpots spots() { return snooker_spots(preset_table("snooker_12ft")); }

// The six colours on their spots, but those listed in `except`.
std::vector<std::pair<int, Vec2>> colours_on_spots(const std::vector<int>& except = {}) {
  const SnookerSpots sp = spots();
  std::vector<std::pair<int, Vec2>> out{{kYellow, sp.yellow}, {kGreen, sp.green}, {kBrown, sp.brown},
                                        {kBlue, sp.blue},     {kPink, sp.pink},   {kBlack, sp.black}};
  out.erase(std::remove_if(out.begin(), out.end(),
                           [&](const auto& b) { return std::find(except.begin(), except.end(), b.first) != except.end(); }),
            out.end());
  return out;
}

std::vector<std::pair<int, Vec2>> with(std::vector<std::pair<int, Vec2>> balls,
                                       const std::vector<std::pair<int, Vec2>>& more) {
  balls.insert(balls.end(), more.begin(), more.end());
  return balls;
}

Action decision(Decision d) {
  Action a;
  a.decision = d;
  return a;
}

// ------------------------------------------------------------------ the nomination and scoring

TEST(Snooker, RedPottedThenAColourIsNominated) {
  GameState s = frame(with(colours_on_spots(), {{0, kPotCue}, {1, kPotBall}, {2, {2.8, 0.9}}}));
  const GameStep step = play(s, pot_stroke(), 1);
  ASSERT_TRUE(step.facts.pocketed(1));
  ASSERT_FALSE(step.facts.pocketed(0));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{1, 0}));
  EXPECT_EQ(step.next.scores, (std::array<int, 2>{1, 0}));
  EXPECT_FALSE(step.ruling.turn_over);
  EXPECT_EQ(step.next.to_shoot, 0);
  const LegalActions legal = legal_actions(step.next);
  EXPECT_TRUE(legal.nominate_required);
  EXPECT_EQ(legal.nominable, (std::vector<int>{16, 17, 18, 19, 20, 21}));
  // The colour must be nominated, and only a colour.
  test::expect_invalid("nominate", [&] { (void)play(step.next, strike(1.0, 0.0), 2); });
  Action red = strike(1.0, 0.0);
  red.nominate = 2;
  test::expect_invalid("nominate", [&] { (void)play(step.next, red, 2); });
}

TEST(Snooker, NominatedColourPottedScoresAndIsRespottedOnItsSpot) {
  // On a colour after a red; the pink is nominated and potted: 6, respotted
  // on its own spot, and the striker is on the reds again.
  GameState s = on_colour(frame(with(colours_on_spots({kPink}), {{0, kPotCue}, {kPink, kPotBall}, {1, {2.8, 0.9}}})));
  Action a = pot_stroke();
  a.nominate = kPink;
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(kPink));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{6, 0}));
  EXPECT_EQ(step.ruling.respotted, std::vector<int>{kPink});
  const Vec2 p = position(step.next, kPink);
  EXPECT_NEAR(p.x, spots().pink.x, 1e-12);
  EXPECT_NEAR(p.y, spots().pink.y, 1e-12);
  EXPECT_EQ(step.next.on, std::vector<int>{1});
  EXPECT_EQ(step.next.to_shoot, 0);
}

TEST(Snooker, AColourOtherThanTheNominatedIsAFoul) {
  // The yellow nominated, the pink potted: a ball not on hit and potted, 6 to the opponent.
  GameState s = on_colour(frame(with(colours_on_spots({kPink}), {{0, kPotCue}, {kPink, kPotBall}, {1, {2.8, 0.9}}})));
  Action a = pot_stroke();
  a.nominate = kYellow;
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(kPink));
  EXPECT_EQ(step.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{0, 6}));
  EXPECT_EQ(step.ruling.respotted, std::vector<int>{kPink});
}

// ------------------------------------------------------------------ respotting colours

TEST(Snooker, ColourOnAnOccupiedSpotGoesToTheHighestFreeSpot) {
  // A red sits on the pink spot and the black is off its spot: the potted
  // pink goes to the black spot, the highest free one.
  const SnookerSpots sp = spots();
  GameState s = on_colour(frame(with(colours_on_spots({kPink, kBlack}),
                                     {{0, kPotCue}, {kPink, kPotBall}, {1, sp.pink}, {kBlack, {3.0, 0.3}}})));
  Action a = pot_stroke();
  a.nominate = kPink;
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(kPink));
  ASSERT_EQ(step.ruling.respotted, std::vector<int>{kPink});
  const Vec2 p = position(step.next, kPink);
  EXPECT_NEAR(p.x, sp.black.x, 1e-12);
  EXPECT_NEAR(p.y, sp.black.y, 1e-12);
}

TEST(Snooker, ColourWithEverySpotOccupiedGoesNearItsOwnTowardsTheTopCushion) {
  // Every spot taken (a red on the pink's): the pink is put on the long
  // string just beyond that red, towards the top cushion, not touching it.
  const SnookerSpots sp = spots();
  GameState s = on_colour(
      frame(with(colours_on_spots({kPink}), {{0, kPotCue}, {kPink, kPotBall}, {1, sp.pink}})));
  Action a = pot_stroke();
  a.nominate = kPink;
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(kPink));
  const Vec2 p = position(step.next, kPink);
  const double R = s.table.table.ball.radius;
  EXPECT_NEAR(p.y, sp.pink.y, 1e-12);
  EXPECT_GT(p.x, sp.pink.x + 2.0 * R);
  EXPECT_LT(p.x, sp.pink.x + 2.0 * R + 1e-3);
}

// ------------------------------------------------------------------ foul values

TEST(Snooker, FoulValueIsFourAtLeast) {
  // On the reds, the cue ball touches nothing: 4 to the opponent.
  GameState s = frame(with(colours_on_spots(), {{0, {1.0, 0.3}}, {1, {2.8, 0.9}}}));
  const GameStep step = play(s, strike(0.5, 180.0), 1);
  EXPECT_EQ(step.ruling.foul, Foul::no_contact);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{0, 4}));
  EXPECT_EQ(step.next.scores, (std::array<int, 2>{0, 4}));
}

TEST(Snooker, FoulValueIsTheBallOnWhenHigher) {
  // The clearance on the pink: missing it costs 6.
  GameState s = frame({{0, {1.0, 0.3}}, {kPink, spots().pink}, {kBlack, spots().black}});
  ASSERT_EQ(s.on, std::vector<int>{kPink});
  const GameStep step = play(s, strike(0.5, 180.0), 1);
  EXPECT_EQ(step.ruling.foul, Foul::no_contact);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{0, 6}));
}

TEST(Snooker, FoulValueIsTheHighestBallConcerned) {
  // On the reds, the cue ball hits the blue first: 5.
  GameState s = frame(with(colours_on_spots({kBlue}), {{0, {1.3, 0.4}}, {kBlue, {1.6, 0.4}}, {1, {2.8, 0.9}}}));
  const GameStep hit = play(s, strike(1.0, 0.0), 1);
  EXPECT_EQ(hit.facts.first_contact, kBlue);
  EXPECT_EQ(hit.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(hit.ruling.points, (std::array<int, 2>{0, 5}));
  // On the reds, the red hit first sends the black into the pocket: a ball
  // not on potted, 7, and the black is respotted.
  GameState c = frame(with(colours_on_spots({kBlack}), {{0, {0.9, 0.9}}, {1, {0.6, 0.6}}, {kBlack, kPotBall}}));
  Action a = strike(2.5, 225.0);
  a.strike.height = -0.2;
  const GameStep combo = play(c, a, 1);
  ASSERT_EQ(combo.facts.first_contact, 1);
  ASSERT_TRUE(combo.facts.pocketed(kBlack));
  EXPECT_EQ(combo.ruling.foul, combo.facts.pocketed(0) ? Foul::scratch : Foul::wrong_pocket);
  EXPECT_EQ(combo.ruling.points, (std::array<int, 2>{0, 7}));
  EXPECT_TRUE(std::find(combo.ruling.respotted.begin(), combo.ruling.respotted.end(), kBlack) !=
              combo.ruling.respotted.end());
  const Vec2 black = position(combo.next, kBlack);
  EXPECT_NEAR(black.x, spots().black.x, 1e-12);
}

// ------------------------------------------------------------------ after a foul: play, pass, in-off

TEST(Snooker, InOffGivesTheNextPlayerTheChoiceAndBallInHandInTheD) {
  GameState s = frame(with(colours_on_spots(), {{0, {0.5, 0.5}}, {1, {2.8, 0.9}}}));
  const GameStep step = play(s, strike(1.5, 225.0), 1);  // straight into the bottom-left pocket
  ASSERT_TRUE(step.facts.pocketed(0));
  EXPECT_EQ(step.ruling.foul, Foul::scratch);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{0, 4}));
  EXPECT_EQ(step.next.phase, GamePhase::decision);
  EXPECT_EQ(step.next.to_shoot, 1);
  EXPECT_EQ(legal_actions(step.next).decisions, (std::vector<Decision>{Decision::play, Decision::pass}));
  test::expect_invalid("decision", [&] { (void)play(step.next, decision(Decision::restore), 2); });
  const GameStep played = play(step.next, decision(Decision::play), 2);
  EXPECT_EQ(played.next.to_shoot, 1);
  const LegalActions legal = legal_actions(played.next);
  ASSERT_TRUE(legal.ball_in_hand);
  EXPECT_EQ(legal.ball_in_hand->kind, PlacementRegion::Kind::inside_d);
  EXPECT_EQ(legal.on, std::vector<int>{1});
  // Outside the D is refused.
  Action outside = strike(1.0, 0.0);
  outside.place = Vec2{1.5, 0.9};
  test::expect_invalid("place", [&] { (void)play(played.next, outside, 3); });
  // Pass: the offender plays again.
  const GameStep passed = play(step.next, decision(Decision::pass), 2);
  EXPECT_EQ(passed.next.to_shoot, 0);
  EXPECT_EQ(passed.next.phase, GamePhase::play);
  ASSERT_TRUE(passed.next.ball_in_hand);
}

// ------------------------------------------------------------------ the clearance

TEST(Snooker, ColoursAreClearedInOrderAndStayDown) {
  const SnookerSpots sp = spots();
  GameState s = frame({{0, kPotCue}, {kYellow, kPotBall}, {kGreen, sp.green}, {kBrown, sp.brown}, {kBlue, sp.blue},
                       {kPink, sp.pink}, {kBlack, sp.black}});
  EXPECT_EQ(s.on, std::vector<int>{kYellow});
  EXPECT_FALSE(legal_actions(s).nominate_required);
  const GameStep step = play(s, pot_stroke(), 1);
  ASSERT_TRUE(step.facts.pocketed(kYellow));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{2, 0}));
  EXPECT_TRUE(step.ruling.respotted.empty());
  EXPECT_FALSE(find_ball(step.next.table.balls, kYellow));
  EXPECT_EQ(step.next.on, std::vector<int>{kGreen});
  EXPECT_EQ(step.next.colour_on, kGreen);
  EXPECT_EQ(step.next.to_shoot, 0);
  // Out of order: with the green on, the blue hit first is a foul worth 5.
  GameState g = frame({{0, {1.5, 0.4}}, {kGreen, sp.green}, {kBlue, {1.8, 0.4}}, {kPink, sp.pink}, {kBlack, sp.black}});
  const GameStep wrong = play(g, strike(1.0, 0.0), 1);
  EXPECT_EQ(wrong.facts.first_contact, kBlue);
  EXPECT_EQ(wrong.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(wrong.ruling.points, (std::array<int, 2>{0, 5}));
}

TEST(Snooker, TheLastRedThenAColourThenTheYellow) {
  // The last red potted: a colour to nominate; after that colour (potted
  // and respotted, or not), the yellow is on (the clearance).
  GameState s = frame(with(colours_on_spots(), {{0, kPotCue}, {1, kPotBall}}));
  const GameStep red = play(s, pot_stroke(), 1);
  ASSERT_TRUE(red.facts.pocketed(1));
  EXPECT_TRUE(legal_actions(red.next).nominate_required);
  Action at_blue = strike(1.5, 0.0);
  at_blue.aim_at = kBlue;
  at_blue.nominate = kBlue;
  const GameStep colour = play(red.next, at_blue, 2);
  ASSERT_EQ(colour.facts.first_contact, kBlue);
  ASSERT_FALSE(colour.ruling.foul) << colour.ruling.reason;
  EXPECT_EQ(colour.next.to_shoot, colour.facts.pocketed(kBlue) ? 0 : 1);
  EXPECT_TRUE(find_ball(colour.next.table.balls, kBlue));
  EXPECT_EQ(colour.next.on, std::vector<int>{kYellow});
  EXPECT_EQ(colour.next.colour_on, kYellow);
}

// ------------------------------------------------------------------ free ball

TEST(Snooker, SnookeredAfterAFoulGivesAFreeBall) {
  // The blue hides the only red from the cue ball. The striker, snookered,
  // taps the cue ball sideways and touches nothing: a foul, but not a miss
  // (he was snookered); the cue ball is still snookered, so the next player
  // has a free ball.
  const SnookerSpots sp = spots();
  GameState s = frame(with(colours_on_spots(), {{0, {1.5, sp.blue.y}}, {1, {2.5, sp.blue.y}}}));
  const GameStep foul = play(s, strike(0.08, 90.0), 1);
  EXPECT_EQ(foul.ruling.foul, Foul::no_contact);
  EXPECT_FALSE(foul.ruling.miss);
  EXPECT_TRUE(foul.next.free_ball);
  const GameStep played = play(foul.next, decision(Decision::play), 2);
  const LegalActions legal = legal_actions(played.next);
  EXPECT_TRUE(legal.free_ball);
  EXPECT_FALSE(legal.nominate_required);
  EXPECT_EQ(legal.nominable, (std::vector<int>{16, 17, 18, 19, 20, 21}));
  // The blue nominated as the free ball: hitting it first is fair.
  const Vec2 cue = position(played.next, 0);
  Action free_ball = strike(0.6, aim_deg(cue, sp.blue));
  free_ball.nominate = kBlue;
  const GameStep fair = play(played.next, free_ball, 3);
  EXPECT_EQ(fair.facts.first_contact, kBlue);
  EXPECT_FALSE(fair.ruling.foul) << fair.ruling.reason;
  // Without the nomination, the same stroke is a foul (5).
  const GameStep unfair = play(played.next, strike(0.6, aim_deg(cue, sp.blue)), 3);
  EXPECT_EQ(unfair.ruling.foul, Foul::wrong_ball_first);
  EXPECT_EQ(unfair.ruling.points, (std::array<int, 2>{5, 0}));
  // Passed back to the offender, there is no free ball.
  const GameStep passed = play(foul.next, decision(Decision::pass), 2);
  EXPECT_FALSE(legal_actions(passed.next).free_ball);
}

TEST(Snooker, APottedFreeBallScoresAsTheBallOnAndIsRespotted) {
  GameState s = frame(with(colours_on_spots({kBlue}), {{0, kPotCue}, {kBlue, kPotBall}, {1, {2.8, 0.9}}}));
  s.free_ball = true;
  Action a = pot_stroke();
  a.nominate = kBlue;
  const GameStep step = play(s, a, 1);
  ASSERT_TRUE(step.facts.pocketed(kBlue));
  EXPECT_FALSE(step.ruling.foul);
  EXPECT_EQ(step.ruling.points, (std::array<int, 2>{1, 0}));  // the value of a red
  EXPECT_EQ(step.ruling.respotted, std::vector<int>{kBlue});
  EXPECT_TRUE(legal_actions(step.next).nominate_required);  // now on a colour
}

// ------------------------------------------------------------------ the miss

TEST(Snooker, AMissMayBeRestoredAndTheOffenderPlaysAgain) {
  // A red in full view; the striker plays away from it.
  GameState s = frame(with(colours_on_spots(), {{0, {1.2, 0.4}}, {1, {2.0, 0.4}}}));
  const GameStep miss = play(s, strike(1.0, 180.0), 1);
  EXPECT_EQ(miss.ruling.foul, Foul::no_contact);
  EXPECT_TRUE(miss.ruling.miss);
  EXPECT_EQ(miss.next.misses_in_a_row, 1);
  EXPECT_EQ(legal_actions(miss.next).decisions,
            (std::vector<Decision>{Decision::play, Decision::pass, Decision::restore}));
  const GameStep restored = play(miss.next, decision(Decision::restore), 2);
  EXPECT_EQ(restored.next.to_shoot, 0);
  EXPECT_EQ(restored.next.phase, GamePhase::play);
  EXPECT_EQ(restored.next.scores, (std::array<int, 2>{0, 4}));  // the points stand
  EXPECT_EQ(restored.next.on, std::vector<int>{1});
  const Vec2 cue = position(restored.next, 0);
  EXPECT_EQ(cue.x, 1.2);
  EXPECT_EQ(cue.y, 0.4);
  EXPECT_EQ(restored.next.misses_in_a_row, 1);
  // With the miss rule off, no restore is offered.
  s.config.miss_rule = false;
  const GameStep plain = play(s, strike(1.0, 180.0), 1);
  EXPECT_FALSE(plain.ruling.miss);
  EXPECT_EQ(legal_actions(plain.next).decisions, (std::vector<Decision>{Decision::play, Decision::pass}));
}

TEST(Snooker, AMissedNominatedColourIsRestoredAsAColourStroke) {
  // On a colour after a red: the restore gives the offender the colour
  // stroke back (a nomination again), not the reds.
  GameState s = on_colour(frame(with(colours_on_spots(), {{0, {1.2, 0.4}}, {1, {2.8, 0.9}}})));
  Action away = strike(1.0, 180.0);
  away.nominate = kBlue;
  const GameStep miss = play(s, away, 1);
  EXPECT_EQ(miss.ruling.foul, Foul::no_contact);
  EXPECT_TRUE(miss.ruling.miss);
  EXPECT_EQ(miss.ruling.points, (std::array<int, 2>{0, 5}));  // the nominated blue is the ball on
  const GameStep restored = play(miss.next, decision(Decision::restore), 2);
  EXPECT_EQ(restored.next.to_shoot, 0);
  const LegalActions legal = legal_actions(restored.next);
  EXPECT_TRUE(legal.nominate_required);
  EXPECT_EQ(legal.nominable, (std::vector<int>{16, 17, 18, 19, 20, 21}));
  // Played from where the balls lie instead, the next player is on the reds.
  const GameStep played = play(miss.next, decision(Decision::play), 2);
  EXPECT_EQ(played.next.to_shoot, 1);
  EXPECT_EQ(legal_actions(played.next).on, std::vector<int>{1});
  EXPECT_FALSE(legal_actions(played.next).nominate_required);
}

TEST(Snooker, ThreeMissesWithAFullBallViewLoseTheFrame) {
  GameState s = frame(with(colours_on_spots(), {{0, {1.2, 0.4}}, {1, {2.0, 0.4}}}));
  s.misses_in_a_row = 2;
  s.scores = {30, 0};
  const GameStep step = play(s, strike(1.0, 180.0), 1);
  EXPECT_TRUE(step.ruling.miss);
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 1);
  EXPECT_TRUE(step.next.over);
}

// ------------------------------------------------------------------ the end of the frame

TEST(Snooker, TheFrameIsWonOnTheBlack) {
  GameState s = frame({{0, kPotCue}, {kBlack, kPotBall}});
  s.scores = {30, 33};
  const GameStep step = play(s, pot_stroke(), 1);
  ASSERT_TRUE(step.facts.pocketed(kBlack));
  EXPECT_EQ(step.next.scores, (std::array<int, 2>{37, 33}));
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 0);
}

TEST(Snooker, AFoulWithOnlyTheBlackLeftEndsTheFrame) {
  GameState s = frame({{0, {1.0, 0.3}}, {kBlack, spots().black}});
  s.scores = {40, 36};
  const GameStep step = play(s, strike(0.5, 180.0), 1);
  EXPECT_EQ(step.ruling.foul, Foul::no_contact);
  EXPECT_EQ(step.next.scores, (std::array<int, 2>{40, 43}));
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 1);
}

TEST(Snooker, OnlyTheBlackLeftAndMoreThanSevenApartEndsTheFrame) {
  GameState s = frame({{0, {1.0, 0.3}}, {kBlack, spots().black}});
  s.scores = {20, 40};
  Action safety = strike(0.8, 0.0);
  safety.aim_at = kBlack;
  const GameStep step = play(s, safety, 1);
  ASSERT_FALSE(step.ruling.foul) << step.ruling.reason;
  EXPECT_TRUE(step.ruling.game_over);
  EXPECT_EQ(step.ruling.winner, 1);
}

TEST(Snooker, LevelScoresRespotTheBlack) {
  GameState s = frame({{0, kPotCue}, {kBlack, kPotBall}});
  s.scores = {30, 37};
  s.shots = 5;  // the engine's coin: odd -> player 1 plays first
  const GameStep step = play(s, pot_stroke(), 1);
  ASSERT_TRUE(step.facts.pocketed(kBlack));
  EXPECT_FALSE(step.ruling.game_over);
  EXPECT_EQ(step.next.scores, (std::array<int, 2>{37, 37}));
  EXPECT_EQ(step.ruling.respotted, std::vector<int>{kBlack});
  ASSERT_EQ(step.next.table.balls.size(), 1u);
  const Vec2 black = position(step.next, kBlack);
  EXPECT_NEAR(black.x, spots().black.x, 1e-12);
  EXPECT_EQ(step.next.to_shoot, 1);
  ASSERT_TRUE(step.next.ball_in_hand);
  EXPECT_EQ(step.next.ball_in_hand->kind, PlacementRegion::Kind::inside_d);
  EXPECT_EQ(step.next.on, std::vector<int>{kBlack});
  // The next score or foul ends it: player 1 places the cue ball in the D and misses.
  Action miss = strike(0.5, 180.0);
  miss.place = Vec2{spots().brown.x - 0.1, spots().brown.y};
  const GameStep end = play(step.next, miss, 2);
  EXPECT_EQ(end.ruling.foul, Foul::no_contact);
  EXPECT_TRUE(end.ruling.game_over);
  EXPECT_EQ(end.ruling.winner, 0);
}

// ------------------------------------------------------------------ 6, 10, 15 reds

TEST(Snooker, SixTenOrFifteenReds) {
  for (const int reds : {6, 10, 15}) {
    GameConfig c = default_config(GameKind::snooker);
    c.reds = reds;
    const GameState s = new_game(c);
    int red_count = 0;
    for (const SimulationBall& b : s.table.balls) red_count += b.id >= 1 && b.id <= 15 ? 1 : 0;
    EXPECT_EQ(red_count, reds);
    EXPECT_EQ(object_balls(s).size(), static_cast<std::size_t>(reds + 6));
    EXPECT_EQ(s.on.size(), static_cast<std::size_t>(reds));
    EXPECT_EQ(s.phase, GamePhase::break_shot);
    ASSERT_TRUE(s.ball_in_hand);
    EXPECT_EQ(s.ball_in_hand->kind, PlacementRegion::Kind::inside_d);
  }
  GameConfig c = default_config(GameKind::snooker);
  c.reds = 7;
  test::expect_invalid("reds", [&] { (void)new_game(c); });
  test::expect_invalid("reds", [&] { (void)rack_snooker_with_reds(preset_table("snooker_12ft"), 9); });
}

// ------------------------------------------------------------------ random frames

Action random_action(const GameState& s, RandomStream& rng) {
  const LegalActions legal = legal_actions(s);
  Action a;
  if (!legal.shoot) {
    a.decision = legal.decisions[static_cast<std::size_t>(rng.integer(0, static_cast<int>(legal.decisions.size()) - 1))];
    return a;
  }
  a.strike.speed = rng.uniform(0.5, 6.0);
  a.strike.aim_deg = rng.uniform(-180.0, 180.0);
  a.strike.height = rng.uniform(-0.3, 0.3);
  if (legal.ball_in_hand && (!find_ball(s.table.balls, 0) || rng.chance(0.5))) {
    std::vector<Vec2> others;
    for (const SimulationBall& b : s.table.balls)
      if (b.id != 0) others.push_back(b.state.position);
    a.place = random_free_spot(s.table.table, others, s.table.table.ball.radius, rng, 1000, *legal.ball_in_hand);
  }
  if (legal.nominate_required || (legal.free_ball && !legal.nominable.empty() && rng.chance(0.5)))
    a.nominate = legal.nominable[static_cast<std::size_t>(rng.integer(0, static_cast<int>(legal.nominable.size()) - 1))];
  // Half the strokes aimed at a ball on (or the nominated one), to pot now and then.
  const std::vector<int>& targets = a.nominate ? std::vector<int>{*a.nominate} : legal.on;
  if (!targets.empty() && rng.chance(0.5)) a.aim_at = targets[static_cast<std::size_t>(rng.integer(0, static_cast<int>(targets.size()) - 1))];
  return a;
}

TEST(Snooker, RandomFramesEndConserveBallsKeepScoresAndReplay) {
  // Random strokes foul often: with the miss rule most frames end on a third
  // miss (WPBSA 3.14), without it on the black (3.4); a few hit max_shots.
  int ended = 0, truncated = 0;
  for (const int reds : {6, 10, 15}) {
    for (std::uint64_t game = 0; game < 4; ++game) {
      GameConfig config = default_config(GameKind::snooker);
      config.reds = reds;
      config.max_shots = 150;
      config.miss_rule = game % 2 == 0;
      GameState s = new_game(config, game);
      RandomStream rng(splitmix64(game * 31 + static_cast<std::uint64_t>(reds)));
      std::vector<GameStep> steps;
      std::vector<int> down, down_before_miss;  // object balls potted and not respotted
      std::array<int, 2> points{};
      while (!s.over) {
        const Action a = random_action(s, rng);
        GameStep step = play(s, a, stream_seed(game, static_cast<std::uint64_t>(s.shots)));
        if (step.ruling.miss) down_before_miss = down;
        if (a.decision == Decision::restore) down = down_before_miss;
        for (const int id : step.ruling.pocketed)
          if (id != 0) down.push_back(id);
        for (const int id : step.ruling.respotted) {
          const auto it = std::find(down.begin(), down.end(), id);
          ASSERT_NE(it, down.end()) << "respotted " << id << " was not down";
          down.erase(it);
        }
        EXPECT_EQ(object_balls(step.next).size() + down.size(), static_cast<std::size_t>(reds + 6))
            << "reds " << reds << " game " << game << " shot " << s.shots;
        points[0] += step.ruling.points[0];
        points[1] += step.ruling.points[1];
        EXPECT_EQ(points, step.next.scores);
        s = step.next;
        steps.push_back(std::move(step));
      }
      EXPECT_TRUE(s.winner.has_value() || s.truncated);
      EXPECT_LE(s.shots, config.max_shots);
      (s.truncated ? truncated : ended) += 1;
      GameState r = new_game(config, game);
      for (const GameStep& step : steps)
        r = play(r, step.action, stream_seed(game, static_cast<std::uint64_t>(r.shots))).next;
      EXPECT_TRUE(r == s);
    }
  }
  EXPECT_GT(ended, 0);
  EXPECT_EQ(ended + truncated, 12);
}

}  // namespace
}  // namespace cueball
