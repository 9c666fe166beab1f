// eight_ball: its rules are being written (issue 25); until then new_game() refuses it.
#include "cueball/core/errors.hpp"
#include "games/rules.hpp"

namespace cueball {

namespace {
[[noreturn]] void not_yet() { throw InvalidArgument("kind", "eight_ball is not available yet (issue 25)"); }
}  // namespace

GameState eight_ball_new_game(GameState) { not_yet(); }
LegalActions eight_ball_legal_actions(const GameState&) { not_yet(); }
Judgement eight_ball_judge_shot(const ShotContext&) { not_yet(); }
Judgement eight_ball_decide(const GameState&, Decision) { not_yet(); }

}  // namespace cueball
