// A game record: where a game started, and every action played with its
// seed, the ruling and the state after it. Replaying the actions with their
// seeds from the start (play(), game.hpp) gives the same rulings and states
// bit for bit; io/game_json.hpp writes, reads and checks records.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cueball/games/game.hpp"

namespace cueball {

/// One play() of a record: the action, the seed it was played with, and
/// what it gave.
struct RecordedStep {
  Action action;
  std::uint64_t seed = 0;  ///< play()'s seed (the execution noise)
  Ruling ruling;
  GameState state;         ///< the state after it
};

/// One game.
struct GameRecord {
  /// Who played (agent names, "user", ...): information only.
  std::array<std::string, 2> players{"", ""};
  std::uint64_t seed = 0;  ///< new_game()'s seed (and the root of the agents' and shots' seeds)
  GameState start;         ///< the state before the first step
  std::vector<RecordedStep> steps;
};

}  // namespace cueball
