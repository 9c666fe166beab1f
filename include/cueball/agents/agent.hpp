// Players: each agent chooses an Action for a GameState from its
// legal_actions() (games/game.hpp), deterministically for a seed.
//
//   Action a = choose_action(AgentOptions{AgentKind::planner}, state, seed);
//
// One file per agent in src/agents/, chosen by AgentKind in agent.cpp:
//   random        any legal action, uniformly drawn (a baseline and the
//                 rules' stress test);
//   ghost_ball    ghost-ball aiming at the easiest clear pot of a ball on,
//                 no simulation (the planner benchmark's baseline);
//   planner       plan_shot (planning/shot_planner.hpp) over the legal
//                 targets, with position play, ball-in-hand placement,
//                 calls, nominations, a kick when nothing pots, and the
//                 decisions by a documented simple policy;
//   carom_search  three-cushion: searches strikes with the engine for a
//                 point (a simple search; the strong one is issue 27's).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "cueball/games/game.hpp"

namespace cueball {

enum class AgentKind : char { random, ghost_ball, planner, carom_search };

/// "random", "ghost_ball", "planner", "carom_search".
const char* to_string(AgentKind kind);
std::optional<AgentKind> agent_kind_from_string(std::string_view name);
std::string agent_kind_names();

struct AgentOptions {
  AgentKind kind = AgentKind::planner;
  /// Engine runs a decision may spend (planner, carom_search).
  int simulations = 2000;
  /// Engine runs of each next-shot plan in position play (planner; 0: no position play).
  int position_simulations = 0;
  /// The execution noise the agent plans under (planner), usually the game's.
  std::optional<CueStrikeNoise> noise;
};

/// Throws InvalidArgument naming the field ("simulations", ...).
void validate(const AgentOptions& options);

/// The agent's action for the player to act in `state` (a game not over).
/// Always legal: play(state, choose_action(...), s) never throws
/// InvalidArgument for it.
Action choose_action(const AgentOptions& options, const GameState& state, std::uint64_t seed);

// The agents, one file each (src/agents/<agent>.cpp).
Action random_action(const GameState& state, std::uint64_t seed);
Action ghost_ball_action(const GameState& state, std::uint64_t seed);
Action planner_action(const AgentOptions& options, const GameState& state, std::uint64_t seed);
Action carom_search_action(const AgentOptions& options, const GameState& state, std::uint64_t seed);

/// What carom_search found, for tests and benchmarks: its action, the
/// engine runs it spent (never more than options.simulations), whether the
/// action scores noise-free, and the share of its noisy repeats that scored.
struct CaromSearchResult {
  Action action;
  int simulations = 0;
  bool point = false;
  int noisy_points = 0;
  int noisy_tries = 0;
};
CaromSearchResult carom_search(const AgentOptions& options, const GameState& state, std::uint64_t seed);

}  // namespace cueball
