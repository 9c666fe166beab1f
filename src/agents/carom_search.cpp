// The carom_search agent: being written (issue 25); until then it refuses.
#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {

Action carom_search_action(const AgentOptions&, const GameState&, std::uint64_t) { throw InvalidArgument("agent", "carom_search is not available yet (issue 25)"); }

}  // namespace cueball
