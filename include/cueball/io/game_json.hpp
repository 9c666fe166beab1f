// Games as JSON (games/game.hpp, games/record.hpp): states, actions,
// rulings, steps and records. Every reader refuses unknown keys and names
// the JSON path, the value and the allowed range of what it refuses.
//
// A state file is a scenario (io/scenario_json.hpp: "table", "parameters",
// "cushion", "ball_collision", "max_events", "balls", "noise"; no "cue")
// whose balls are at rest, plus a "game" object:
//   "game": {
//     "kind": "nine_ball" | "eight_ball" | "ten_ball" | "snooker" | "three_cushion",
//     "config": { "table": preset, "rack": {"gap_sigma": m, "seed": n},
//                 "noise": {"speed", "aim_deg", "elevation_deg", "side", "height"} (the scenario's units),
//                 "max_shots", "fouls_to_lose", "nine_on_break_wins", "push_out",
//                 "break_scratch_region", "reds", "miss_rule", "race_to" },  (every key optional: the
//                 discipline's default_config())
//     "phase": "break" | "play" | "decision" | "over",
//     "to_shoot": 0 | 1, "breaker": 0 | 1,
//     "ball_in_hand": null | "anywhere" | "behind_head_string" | "inside_d"
//                     | {"kind": "rectangle", "x_min", "x_max", "y_min", "y_max"} (m),
//     "cue_must_leave_kitchen": bool,
//     "scores": [p0, p1], "fouls_in_a_row": [p0, p1],
//     "on": [ids], "groups": ["none" | "solids" | "stripes", same],
//     "decisions": ["play", "pass", ...], "push_out_available": bool, "free_ball": bool,
//     "misses_in_a_row": n, "colour_on": id (0: none), "before_miss": [balls as in "balls"],
//     "shots": n, "inning_points": n,
//     "over": bool, "winner": null | 0 | 1, "truncated": bool, "end_reason": "..."
//   }
// The writer writes every key; the reader takes every "game" key but
// "kind" as optional (a new game's value), so that a hand-edited file may
// leave them out. The writer's numbers are the shortest decimals that read
// back to the same doubles: state -> JSON -> state is the same state, and
// JSON -> state -> JSON the same text.
//
// Reading checks the state against its discipline: ball ids in its set
// (pool: 0 and the rack's numbers; snooker: 0, reds 1..config.reds, colours
// 16..21; three-cushion 0, 1, 2), no two balls overlapping and every ball
// on the bed (the scenario's own checks), the ball-in-hand region one the
// table has (behind_head_string on the pool tables, inside_d on snooker's),
// to_shoot and breaker 0 or 1, a phase that agrees with "over" and
// "decisions", the cue ball on the table unless it is in hand. Errors name
// the path from "state" ("state.game.to_shoot = 2 is out of range [0, 1]",
// "state.balls[3].position ... overlap ...").
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "cueball/games/game.hpp"
#include "cueball/games/record.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

/// Longest game record read, bytes (256 MiB).
inline constexpr std::size_t kMaxGameRecordBytes = std::size_t{256} << 20;

/// The state as above; `indent` as in result_to_json (-1: one line).
std::string game_state_to_json(const GameState& state, int indent = 1);
/// Reads and checks a state file (above). Throws InvalidArgument naming the path.
GameState game_state_from_json(std::string_view json_text);

/// The config as the "config" object above (with "kind").
std::string game_config_to_json(const GameConfig& config, int indent = -1);
/// Reads a config: {"kind": ..., the keys above}; every key but "kind"
/// optional (default_config(kind)); validated. Errors name `path`.key.
GameConfig game_config_from_json(std::string_view json_text, const std::string& path = "config");

/// An action: a shot as the scenario's "cue" object,
///   {"speed": m/s, "aim_deg": deg | "target": id, "elevation_deg": deg, "side": R, "height": R,
///    "place": [x, y], "call": {"ball": id, "pocket": index | name}, "push_out": bool,
///    "nominate": id}
/// (speed required, the others optional: 0, none, false), or a decision,
///   {"decision": "play" | "pass" | ...}.
/// `table` resolves a called pocket given by name (none: indices only).
std::string action_to_json(const Action& action, int indent = -1);
Action action_from_json(std::string_view json_text, const Table* table = nullptr, const std::string& path = "action");

/// {"foul": null | name, "points": [p0, p1], "turn_over", "game_over", "winner": null | 0 | 1,
///  "respotted": [ids], "pocketed": [ids], "push_out", "miss", "truncated", "reason"}.
std::string ruling_to_json(const Ruling& ruling, int indent = -1);
Ruling ruling_from_json(std::string_view json_text, const std::string& path = "ruling");

/// One play(): {"action": ..., "ruling": ..., "facts": (io/shot_facts_json.hpp; null for a
/// decision), "state": the next state}.
std::string game_step_to_json(const GameStep& step, int indent = 1);

/// Records: {"format": "cueball-game-record", "version": 1, "games": [
///   {"players": [name, name], "seed": n, "start": state,
///    "steps": [{"action": ..., "seed": n, "ruling": ..., "state": ...}, ...]}, ...]}
/// The config of each game is its start state's "game.config".
std::string game_records_to_json(const std::vector<GameRecord>& records, int indent = -1);
std::vector<GameRecord> game_records_from_json(std::string_view json_text);

/// What `cueball game play --json` prints of played games: per game
///   {"seed", "players": [name, name], "scores": [p0, p1], "winner": null | 0 | 1,
///    "truncated", "end_reason", "steps", "fouls": [p0, p1], "pots": [p0, p1]}
/// (fouls and pots as agents/match.hpp's tally()), and the totals
///   {"games", "wins": [p0, p1], "truncated", "fouls": [p0, p1], "pots": [p0, p1], "steps"}.
std::string game_summary_to_json(const std::vector<GameRecord>& records, int indent = 1);

/// Where replaying a record first differs from it.
struct ReplayDifference {
  int game = 0;             ///< index in the file
  int step = 0;             ///< index in its steps
  std::string path;         ///< JSON path of the first difference ("games[0].steps[4].state.balls[2].position[0]")
  std::string recorded;     ///< the value in the record (JSON), or the error of the replay
  std::string replayed;     ///< the value the replay gave (JSON)
};

/// Replays every step of `record` (play(state, action, seed) from its
/// start) and compares each ruling and state with the recorded one, as
/// JSON text: none when all are identical. `game` numbers the record in its file.
std::optional<ReplayDifference> replay_difference(const GameRecord& record, int game = 0);

}  // namespace cueball
