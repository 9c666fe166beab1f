// The carom_search agent (src/agents/carom_search.cpp): on fixed
// three-cushion tables it finds a strike that scores noise-free, the same
// one for the same seed, within its budget of engine runs; with position
// play it weighs the next point on the table each finalist leaves, within
// its budget, and a point that wins the game leaves nothing to weigh.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "cueball/agents/agent.hpp"
#include "cueball/games/game.hpp"
#include "expect_invalid.hpp"

namespace cueball {
namespace {

GameState in_play(Vec2 white, Vec2 yellow, Vec2 red, int shooter = 0) {
  GameState s = new_game(default_config(GameKind::three_cushion));
  s.phase = GamePhase::play;
  s.to_shoot = shooter;
  s.table.balls[0].state.position = white;
  s.table.balls[1].state.position = yellow;
  s.table.balls[2].state.position = red;
  s.on = shooter == 0 ? std::vector<int>{1, 2} : std::vector<int>{0, 2};
  return s;
}

AgentOptions options(int simulations) {
  AgentOptions o;
  o.kind = AgentKind::carom_search;
  o.simulations = simulations;
  return o;
}

// The strike scores when played noise-free through the game.
bool scores(const GameState& s, const Action& a) {
  GameState quiet = s;
  quiet.config.noise = CueStrikeNoise{};
  return play(quiet, a, 0).ruling.points[static_cast<std::size_t>(s.to_shoot)] == 1;
}

TEST(CaromSearch, FindsAPointOnFixedTables) {
  const std::vector<GameState> tables{
      new_game(default_config(GameKind::three_cushion)),  // the opening: the red first
      in_play({0.5, 0.4}, {1.5, 0.7}, {2.2, 1.0}),
      in_play({1.0, 1.1}, {2.4, 0.3}, {1.8, 0.9}),
      in_play({2.3, 0.5}, {0.6, 1.0}, {1.2, 0.3}, 1),  // yellow to play
  };
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const CaromSearchResult r = carom_search(options(600), tables[k], 7);
    EXPECT_TRUE(r.point) << "table " << k;
    EXPECT_TRUE(scores(tables[k], r.action)) << "table " << k;
    EXPECT_LE(r.simulations, 600);
    EXPECT_GT(r.noisy_tries, 0) << "table " << k;
    // What choose_action plays is the search's action.
    const Action a = choose_action(options(600), tables[k], 7);
    EXPECT_EQ(a.strike, r.action.strike);
  }
}

TEST(CaromSearch, IsDeterministicForTheSeed) {
  const GameState s = in_play({1.0, 1.1}, {2.4, 0.3}, {1.8, 0.9});
  const CaromSearchResult a = carom_search(options(300), s, 11);
  const CaromSearchResult b = carom_search(options(300), s, 11);
  EXPECT_EQ(a.action.strike, b.action.strike);
  EXPECT_EQ(a.simulations, b.simulations);
  EXPECT_EQ(a.noisy_points, b.noisy_points);
}

TEST(CaromSearch, RespectsTheBudget) {
  const GameState s = in_play({0.5, 0.4}, {1.5, 0.7}, {2.2, 1.0});
  for (const int budget : {1, 2, 7, 40, 150}) {
    const CaromSearchResult r = carom_search(options(budget), s, 3);
    EXPECT_GE(r.simulations, 1);
    EXPECT_LE(r.simulations, budget) << "budget " << budget;
    EXPECT_NO_THROW((void)play(s, r.action, 0)) << "budget " << budget;  // always a legal action
  }
}

AgentOptions with_position(int simulations, int position_simulations) {
  AgentOptions o = options(simulations);
  o.position_simulations = position_simulations;
  return o;
}

// Position play (AgentOptions::position_simulations): the strike played
// scores noise-free, the next point's rate on the table it leaves is a
// share in [0, 1] (-1 without position play), the runs stay within the
// budget it states (each leave's search capped at `simulations`), the same
// for the same seed, and what choose_action plays.
TEST(CaromSearch, PositionPlayWeighsTheNextPointWithinItsBudget) {
  const std::vector<GameState> tables{
      in_play({0.5, 0.4}, {1.5, 0.7}, {2.2, 1.0}),
      in_play({1.0, 1.1}, {2.4, 0.3}, {1.8, 0.9}),
  };
  for (std::size_t k = 0; k < tables.size(); ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(carom_search(options(300), tables[k], 5).next_point_rate, -1.0);
    for (const int position : {100, 1000}) {
      const CaromSearchResult r = carom_search(with_position(300, position), tables[k], 5);
      EXPECT_TRUE(r.point);
      EXPECT_TRUE(scores(tables[k], r.action));
      EXPECT_GE(r.next_point_rate, 0.0);
      EXPECT_LE(r.next_point_rate, 1.0);
      const int per_leave = std::min(position, 300);
      EXPECT_GT(r.simulations, 300);  // some leave was searched
      EXPECT_LE(r.simulations, 300 + static_cast<int>(kCaromPositionFinalists) * (per_leave + 1));
      const CaromSearchResult again = carom_search(with_position(300, position), tables[k], 5);
      EXPECT_EQ(again.action.strike, r.action.strike);
      EXPECT_EQ(again.simulations, r.simulations);
      EXPECT_EQ(again.next_point_rate, r.next_point_rate);
      EXPECT_EQ(choose_action(with_position(300, position), tables[k], 5).strike, r.action.strike);
    }
  }
}

// A point that wins the game (the shooter one short of race_to) leaves no
// next point to search: every finalist's next counts as certain, and
// nothing is spent on a leave.
TEST(CaromSearch, AWinningPointCountsTheNextAsCertain) {
  GameState s = in_play({0.5, 0.4}, {1.5, 0.7}, {2.2, 1.0});
  s.scores = {s.config.race_to - 1, 0};
  const CaromSearchResult r = carom_search(with_position(300, 200), s, 5);
  EXPECT_TRUE(r.point);
  EXPECT_EQ(r.next_point_rate, 1.0);
  EXPECT_LE(r.simulations, 300 + static_cast<int>(kCaromPositionFinalists));
}

TEST(CaromSearch, RefusesOtherGamesAndBadOptions) {
  const GameState nine = new_game(default_config(GameKind::nine_ball));
  test::expect_invalid("kind", [&] { (void)carom_search(options(10), nine, 0); });
  const GameState s = new_game(default_config(GameKind::three_cushion));
  test::expect_invalid("simulations", [&] { (void)carom_search(options(0), s, 0); });
}

}  // namespace
}  // namespace cueball
