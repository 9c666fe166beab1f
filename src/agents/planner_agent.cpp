// The planner_agent agent: being written (issue 25); until then it refuses.
#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {

Action planner_action(const AgentOptions&, const GameState&, std::uint64_t) { throw InvalidArgument("agent", "planner_agent is not available yet (issue 25)"); }

}  // namespace cueball
