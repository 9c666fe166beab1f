// The random_agent agent: being written (issue 25); until then it refuses.
#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {

Action random_action(const GameState&, std::uint64_t) { throw InvalidArgument("agent", "random_agent is not available yet (issue 25)"); }

}  // namespace cueball
