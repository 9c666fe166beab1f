// cueball-stress --games: random-agent games of every discipline, checked
// for the rules' invariants (game_stress.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "cueball/games/game.hpp"

namespace cueball {

/// True when ball `id` is on the table of `s`.
bool on_table_id(const GameState& s, int id);

/// Plays `games` games of each kind from seed `seed` on `threads` threads;
/// prints the report; 1 when any invariant was violated, else 0.
int run_game_stress(const std::vector<GameKind>& kinds, long long games, std::uint64_t seed, int threads);

}  // namespace cueball
