// Choosing an agent by name (agent.hpp).
#include "cueball/agents/agent.hpp"

#include <array>

#include "core/enum_names.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {

namespace {
constexpr std::array kAgentKinds{AgentKind::random, AgentKind::ghost_ball, AgentKind::planner, AgentKind::carom_search};
}  // namespace

const char* to_string(AgentKind kind) {
  switch (kind) {
    case AgentKind::random: return "random";
    case AgentKind::ghost_ball: return "ghost_ball";
    case AgentKind::planner: return "planner";
    case AgentKind::carom_search: return "carom_search";
  }
  return "?";
}
std::optional<AgentKind> agent_kind_from_string(std::string_view name) { return value_named(kAgentKinds, name); }
std::string agent_kind_names() { return names_of(kAgentKinds, ""); }

void validate(const AgentOptions& options) {
  if (options.simulations < 1 || options.simulations > 1'000'000)
    throw InvalidArgument("simulations", std::to_string(options.simulations) + " is out of range [1, 1000000]");
  if (options.position_simulations < 0 || options.position_simulations > 1'000'000)
    throw InvalidArgument("position_simulations",
                          std::to_string(options.position_simulations) + " is out of range [0, 1000000]");
  if (options.noise) validate(*options.noise);
}

Action choose_action(const AgentOptions& options, const GameState& state, std::uint64_t seed) {
  validate(options);
  if (state.over) throw InvalidArgument("state", "the game is over (" + state.end_reason + ")");
  switch (options.kind) {
    case AgentKind::random: return random_action(state, seed);
    case AgentKind::ghost_ball: return ghost_ball_action(state, seed);
    case AgentKind::planner: return planner_action(options, state, seed);
    case AgentKind::carom_search: return carom_search_action(options, state, seed);
  }
  throw InvalidArgument("kind", "unknown agent; allowed: " + agent_kind_names());
}

}  // namespace cueball
