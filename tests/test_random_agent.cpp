// The random agent (src/agents/random_agent.cpp): always legal, deterministic
// for a seed, and it reaches the decisions and placements of the rules.
#include <gtest/gtest.h>

#include "cueball/agents/agent.hpp"
#include "cueball/core/random.hpp"

namespace cueball {
namespace {

TEST(RandomAgent, PlaysWholeNineBallGamesLegallyAndDeterministically) {
  AgentOptions random;
  random.kind = AgentKind::random;
  int decisions = 0, placements = 0, games_won = 0;
  for (std::uint64_t game = 0; game < 200; ++game) {
    GameState s = new_game(default_config(GameKind::nine_ball), game);
    while (!s.over) {
      const std::uint64_t seed = stream_seed(game, static_cast<std::uint64_t>(s.shots));
      const Action a = choose_action(random, s, seed);
      const Action again = choose_action(random, s, seed);
      EXPECT_EQ(a.decision, again.decision);
      EXPECT_EQ(a.strike, again.strike);
      decisions += a.decision ? 1 : 0;
      placements += a.place ? 1 : 0;
      s = play(s, a, seed).next;  // throws InvalidArgument for an illegal action
    }
    games_won += s.winner ? 1 : 0;
  }
  EXPECT_GT(decisions, 0);
  EXPECT_GT(placements, 0);
  EXPECT_GT(games_won, 0);
}

}  // namespace
}  // namespace cueball
