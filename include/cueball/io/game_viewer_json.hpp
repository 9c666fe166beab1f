// A whole game as the HTML viewer's game document (viewer/README.md "The
// game document"): every shot's result, with a caption, the scores and the
// foul or decision, for `cueball game play --html` and the Python module.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "cueball/games/game.hpp"
#include "cueball/games/record.hpp"

namespace cueball {

/// One line describing a step, e.g. "shot 3, player 0: 2, 5 potted; foul:
/// scratch (WPA 6.1: the cue ball was pocketed)" or "shot 4, player 1: pass
/// (...)": the shot's number (from 1, decisions counted, as `cueball game
/// shoot` counts), the player (0 or 1, as game.hpp and the CLI), what
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
/// game goes on). `indent` as result_to_json (-1: one line). `reasoning`,
/// when not empty, holds each step's agent reasoning (games/record.hpp), in
/// order: an entry with any gets "reasoning": {"summary", "considered":
/// [{"what", "estimate", "next_estimate"}]}, as a record writes it.
std::string game_viewer_json(const GameState& start, const std::vector<GameStep>& steps,
                             const std::array<std::string, 2>& players, int indent = -1,
                             const std::vector<Reasoning>& reasoning = {});

/// The game document of a record (games/record.hpp: `cueball game play
/// --record`): its steps re-played from record.start with each step's action
/// and seed (play() is deterministic, so the shots are the recorded ones),
/// with the record's players and each step's reasoning.
std::string game_viewer_json(const GameRecord& record, int indent = -1);

}  // namespace cueball
