// A whole game between two agents, recorded (games/record.hpp).
//
//   GameRecord g = play_game(default_config(GameKind::nine_ball),
//                            {AgentOptions{AgentKind::random}, AgentOptions{AgentKind::random}}, 7);
//
// The seeds: new_game(config, seed); the agent of the k-th step (k from 0)
// chooses with stream_seed(seed, 2k) and the shot is played with
// stream_seed(seed, 2k + 1) (core/random.hpp). Deterministic for a seed;
// bounded by GameConfig::max_shots.
#pragma once

#include <array>
#include <cstdint>

#include "cueball/agents/agent.hpp"
#include "cueball/games/record.hpp"

namespace cueball {

/// The seed the agent of step `step` chooses with, and the one its action is played with.
std::uint64_t agent_seed(std::uint64_t game_seed, int step);
std::uint64_t shot_seed(std::uint64_t game_seed, int step);

/// Plays one game from new_game(config, seed): players[0] breaks. Throws
/// InvalidArgument for a bad config or agent options ("players[1].simulations").
GameRecord play_game(const GameConfig& config, const std::array<AgentOptions, 2>& players, std::uint64_t seed);

/// Counts over a record, per player: fouls committed, object balls
/// pocketed on that player's shots (respotted ones included), shots and
/// decisions taken.
struct GameTally {
  std::array<int, 2> fouls{};
  std::array<int, 2> pots{};
  std::array<int, 2> shots{};
};
GameTally tally(const GameRecord& record);

}  // namespace cueball
