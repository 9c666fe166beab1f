// The ghost_ball agent: being written (issue 25); until then it refuses.
#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {

Action ghost_ball_action(const GameState&, std::uint64_t) { throw InvalidArgument("agent", "ghost_ball is not available yet (issue 25)"); }

}  // namespace cueball
