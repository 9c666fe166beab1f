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

/// One option an agent weighed for an action (information only).
struct ConsideredOption {
  std::string what;            ///< the shot or decision, one line ("direct 3 into top-right ...")
  double estimate = -1.0;      ///< its success probability, or a safety's value; -1 not estimated
  double next_estimate = -1.0; ///< position play: the next shot's success probability from its leave; -1 none
};

/// Why an agent chose an action (information only: replaying a record does
/// not use it): a one-line summary and the options it weighed, the chosen
/// one first. Empty for a user's action or an agent that does not say.
struct Reasoning {
  std::string summary;
  std::vector<ConsideredOption> considered;
};

/// One play() of a record: the action, the seed it was played with, and
/// what it gave.
struct RecordedStep {
  Action action;
  std::uint64_t seed = 0;  ///< play()'s seed (the execution noise)
  Ruling ruling;
  GameState state;         ///< the state after it
  Reasoning reasoning;     ///< the agent's, when an agent chose the action
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
