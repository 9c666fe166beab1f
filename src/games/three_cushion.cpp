// three_cushion: its rules are being written (issue 25); until then new_game() refuses it.
#include "cueball/core/errors.hpp"
#include "games/rules.hpp"

namespace cueball {

namespace {
[[noreturn]] void not_yet() { throw InvalidArgument("kind", "three_cushion is not available yet (issue 25)"); }
}  // namespace

GameState three_cushion_new_game(GameState) { not_yet(); }
LegalActions three_cushion_legal_actions(const GameState&) { not_yet(); }
Judgement three_cushion_judge_shot(const ShotContext&) { not_yet(); }
Judgement three_cushion_decide(const GameState&, Decision) { not_yet(); }

}  // namespace cueball
