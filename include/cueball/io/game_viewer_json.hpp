// A whole game as the HTML viewer's game document (viewer/README.md "The
// game document"): every shot's result, with a caption, the scores and the
// foul or decision, for `cueball game play --html` and the Python module.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "cueball/games/game.hpp"

namespace cueball {

/// One line describing a step, e.g. "shot 3, player 1: 2, 5 potted; foul:
/// scratch (cue ball pocketed (WPA 6.1))" or "shot 4, player 2: pass (...)":
/// the shot's number (1-based, decisions counted), the player (1 or 2), what
/// was potted ("played" on a table without pockets), the foul, the points
/// scored, the balls respotted and the ruling's reason.
/// `before` is the state the step was played from.
std::string game_step_caption(const GameState& before, const GameStep& step);

/// The game document the viewer page reads in place of one result:
///   {"game": {"kind", "players": [name0, name1], "winner": 0 | 1 | null,
///             "end_reason", "shots": [...]}}
/// with one entry per step, in order: {"player", "caption", "scores" (after
/// the step), "foul": name or null, "result": result_to_json(step.shot,
/// step.result)} for a shot, and {"player", "caption", "scores", "decision":
/// name, "result": the table as it stands (a result of the balls at rest,
/// no cue)} for a decision. `start` is the state the first step was played
/// from; winner and end_reason are the last step's (null and "" while the
/// game goes on). `indent` as result_to_json (-1: one line).
std::string game_viewer_json(const GameState& start, const std::vector<GameStep>& steps,
                             const std::array<std::string, 2>& players, int indent = -1);

}  // namespace cueball
