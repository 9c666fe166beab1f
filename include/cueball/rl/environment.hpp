// A reinforcement-learning environment over the games layer (games/game.hpp):
// the real rules, the engine's speed, bounded steps, and actions a learner
// can use. Python's cueball.rl (CueballEnv, TwoPlayerEnv, VectorEnv) is a
// thin layer over these functions; python/README.md documents the spaces.
//
//   EnvOptions o;                        // 9-ball against the ghost-ball agent
//   EnvTable t = env_reset(o, seed);     // t.observation: what the agent sees
//   EnvStepResult r = env_step(o, t, a); // a: an EnvAction in [-1, 1] units
//
// One env step is one action of the learner (a shot or a decision); the
// opponent's replies (options.opponent) are played inside it, so the next
// observation is again the learner's turn. Without an opponent (self-play,
// AgentKind none) each step is the action of the player to act, whoever it
// is, and the observation is always from that player's point of view.
//
// Illegal actions are never errors: a placement outside the region or on a
// ball, a call or nomination of a ball that may not be called, a pocket out
// of range, a push-out that is not available or a decision in the middle of a
// shot is played as a stroke that moved nothing (play_foul_stroke(),
// games/game.hpp: the discipline's miscue foul) and EnvStepResult::illegal
// says why; a decision that is not open is replaced by the first open one.
// Both count in the reward's `illegal` term.
//
// Determinism: an EnvTable's episodes are drawn from its seed (episode e's
// game from stream_seed(seed, e)), every shot and opponent choice from
// stream_seed(game seed, k); a VectorEnvironment steps each table from its
// own seed, so results do not depend on the number of threads. Bounded: a
// game ends after options.max_shots shots (truncated), and a shot that
// reaches the simulator's event limit ends it as truncated too.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cueball/agents/agent.hpp"
#include "cueball/games/game.hpp"

namespace cueball {

// ------------------------------------------------------------------ options

/// How the strike's five numbers in [-1, 1] are read (EnvAction::strike).
enum class ActionForm : char {
  /// strike = speed, aim, elevation, side, height (kEnvAim* below).
  raw,
  /// The aim is the ghost-ball aim at EnvAction::ball for EnvAction::pocket
  /// (the cue ball at G = O - 2R u, u from the ball to the pocket's centre)
  /// plus strike[1] * kEnvMaxCutOffsetDeg; the other four as in raw. The
  /// ball and pocket are also the call and the nomination when the rules
  /// ask for one. On a table without pockets (three-cushion) the aim is at
  /// the ball's centre plus the offset, and the pocket is ignored.
  target,
};
const char* to_string(ActionForm form);
std::optional<ActionForm> action_form_from_string(std::string_view name);

/// Who breaks (or opens): the learner from its action, or the engine's
/// recommended break (games/break_shot.hpp) played for whoever breaks.
enum class BreakPolicy : char { recommended, agent };
const char* to_string(BreakPolicy p);
std::optional<BreakPolicy> break_policy_from_string(std::string_view name);

/// The reward of one step: the sum of each term times its weight, from the
/// point of view of the player who acted (the learner against an opponent).
/// Terms, over every shot the step played (the opponent's replies included):
///   win      +1 when the game ends won, -1 lost, 0 truncated or going on
///   points   points scored minus the opponent's (snooker, three-cushion)
///   pots     object balls the player pocketed on its own shots without a foul
///   fouls    fouls the player committed (a count: give it a negative weight)
///   illegal  illegal actions of the player (a count: a negative weight)
/// One struct holds the terms of a step (EnvStepResult::terms) and their
/// weights (EnvOptions::reward).
struct RewardTerms {
  double win = 0.0;
  double points = 0.0;
  double pots = 0.0;
  double fouls = 0.0;
  double illegal = 0.0;
};
/// The reward: the terms `t` weighted by `w`.
double weighted(const RewardTerms& w, const RewardTerms& t);

/// Execution noise drawn per episode: `base` times a factor drawn uniformly
/// from [scale_min, scale_max] (1 and 1 by default: exactly `base`).
struct NoiseRange {
  CueStrikeNoise base;
  double scale_min = 1.0;
  double scale_max = 1.0;
};

/// The opponent: an agent kind at a quick budget, or an agent's options in
/// full (`agent`: agent_named("strongest"), or any AgentOptions); neither:
/// self-play (each step is the action of the player to act).
struct EnvOpponent {
  std::optional<AgentKind> kind = AgentKind::ghost_ball;
  int simulations = 300;  ///< engine runs of a planner or carom_search decision
  /// When set, the opponent plays these options (kind and simulations are
  /// not read).
  std::optional<AgentOptions> agent;
};

/// The options the opponent plays: `agent` when set, else `kind` at
/// `simulations` runs (AgentOptions' other defaults); none: self-play.
std::optional<AgentOptions> opponent_agent(const EnvOpponent& opponent);

struct EnvOptions {
  GameKind game = GameKind::nine_ball;
  EnvOpponent opponent;
  NoiseRange noise;                 ///< none by default
  RewardTerms reward{1.0, 0.0, 0.0, 0.0, 0.0};  ///< the weights: win alone by default
  ActionForm form = ActionForm::raw;
  BreakPolicy break_policy = BreakPolicy::recommended;
  /// The learner's seat: 0 breaks, 1 is broken against; -1: drawn per episode.
  int seat = 0;
  int max_shots = 200;              ///< shots and decisions a game may last (GameConfig::max_shots)
  double max_speed = 8.0;           ///< m/s, the cue speed of strike[0] = 1 (kEnvMinSpeed at -1), (kEnvMinSpeed, 12]
};

/// Throws InvalidArgument naming the field ("max_shots", "max_speed",
/// "seat", "noise.scale", "opponent.simulations", an `opponent.agent`'s
/// field as validate(AgentOptions) names it, ...).
void validate(const EnvOptions& options);

/// The game a table plays: default_config(options.game) with max_shots.
GameConfig env_game_config(const EnvOptions& options);

// ------------------------------------------------------------------ actions

/// The scales of an EnvAction's strike, each component in [-1, 1]:
///   speed      kEnvMinSpeed + (s + 1)/2 (max_speed - kEnvMinSpeed), m/s
///   aim        a * 180 degrees (raw); a * kEnvMaxCutOffsetDeg off the ghost-ball aim (target)
///   elevation  (e + 1)/2 * kEnvMaxElevationDeg degrees
///   side, height  the square [-1, 1]^2 mapped onto the disc of radius
///              kMiscueOffsetFraction (0.5 ball radii) along rays from the
///              centre: (s, h) -> 0.5 max(|s|, |h|) (s, h) / |(s, h)|, so
///              every action is a stroke within the miscue limit
/// Values outside [-1, 1] are clipped; NaN reads as 0.
inline constexpr double kEnvMinSpeed = 0.2;
inline constexpr double kEnvMaxCutOffsetDeg = 10.0;
inline constexpr double kEnvMaxElevationDeg = 60.0;

/// Discrete choices of an EnvAction::decision: 0 is "no decision, shoot";
/// 1 + the Decision's value names a decision (Decision::play is 1, ...).
inline constexpr int kEnvDecisionChoices = 8;

/// One action of the learner.
struct EnvAction {
  std::array<double, 5> strike{};  ///< speed, aim (or cut offset), elevation, side, height in [-1, 1]
  /// The cue ball's spot when in hand: [-1, 1]^2 over the region's bounding
  /// rectangle (bounding_rectangle(), table/placement.hpp) inset by one ball
  /// radius; x then y.
  std::array<double, 2> place{};
  int ball = 0;      ///< a ball id: the target (form target), the call, the nomination
  int pocket = 0;    ///< an index into the table's pockets: the target's pocket and the call
  int decision = 0;  ///< 0: shoot; 1 + Decision
  int push_out = 0;  ///< 1: announce a push-out
};

/// The game Action an EnvAction stands for in `state`, with what makes it
/// illegal (empty when it is legal). Never throws for any EnvAction.
struct DecodedAction {
  Action action;
  std::string illegal;
};
DecodedAction decode_action(const EnvOptions& options, const GameState& state, const EnvAction& a);

/// The action masks of `state` (1: legal): over ball ids (the balls that
/// may be the target, the call or the nomination: LegalActions' nominable
/// when a nomination is required, else callable when a call is, else on),
/// pockets (a table without pockets: one entry, ignored), decisions
/// (kEnvDecisionChoices) and push-out (2).
struct ActionMasks {
  std::vector<std::uint8_t> ball;
  std::vector<std::uint8_t> pocket;
  std::array<std::uint8_t, kEnvDecisionChoices> decision{};
  std::array<std::uint8_t, 2> push_out{};
};
ActionMasks action_masks(const GameState& state);

/// The mirror image about the long string (y -> W - y) of an action: aim
/// and side change sign, place y too, the pocket becomes its mirror pocket.
EnvAction mirror_action(const Table& table, const EnvAction& a);

// ------------------------------------------------------------------ observations

/// The observation: a fixed-size float array from the point of view of the
/// player to act. Per ball id 0 .. balls-1 (the rack's ids, game.hpp),
/// kEnvBallFeatures numbers:
///   x, y      the centre, 2x/L - 1 and 2y/W - 1 in [-1, 1] (0 when off the table)
///   present   1 on the table, 0 pocketed or never racked
///   on        1 when the cue ball may contact it first (LegalActions::on)
///   value     9-/10-ball: the number / 15; 8-ball: +1 solids, -1 stripes,
///             0 the 8 and the cue ball; snooker: points / 7 (0 the cue
///             ball); three-cushion: +1 the player's cue ball, -1 the
///             opponent's, 0 the red
/// then the game fields, kEnvGameFields numbers (env_observation_names()):
///   player (0/1), phase break/play/decision (one-hot), ball_in_hand,
///   region anywhere/kitchen/D (one-hot), cue_must_leave_kitchen,
///   call_required, nominate_required, push_out_available, free_ball,
///   score and opponent_score (/ 147 snooker, / race_to three-cushion, 0
///   pool), fouls and opponent_fouls in a row (/ 3), group (8-ball: +1
///   solids, -1 stripes, 0 open), the open decisions (7 flags, Decision
///   order), shots / max_shots, and the episode's noise (speed, aim,
///   elevation, side, height sigmas over tournament_noise()'s).
inline constexpr int kEnvBallFeatures = 5;
inline constexpr int kEnvGameFields = 31;

/// Balls of a discipline's rack: 16 pool (10 for 9-ball, 11 for 10-ball),
/// 22 snooker, 3 three-cushion.
int env_ball_count(GameKind game);
/// env_ball_count(game) * kEnvBallFeatures + kEnvGameFields.
int env_observation_size(GameKind game);
/// A name for every entry ("ball3.x", ..., "phase.break", "noise.aim").
std::vector<std::string> env_observation_names(GameKind game);

/// Writes the observation of `state` from the point of view of `player`
/// (0 or 1: "score" is that player's, "opponent_score" the other's) into
/// `out` (env_observation_size() floats), with the episode's noise `noise`.
/// The balls on and the flags of the legal actions are those of the player
/// to act (LegalActions).
void write_observation(const GameState& state, int player, const CueStrikeNoise& noise, float* out);

/// The mirror image about the long string of an observation (y -> -y).
void mirror_observation(GameKind game, float* observation);

// ------------------------------------------------------------------ episodes

/// One table: its game, its seeds and the episode's counters.
struct EnvTable {
  std::uint64_t seed = 0;     ///< the table's seed (episodes drawn from it)
  std::uint64_t episode = 0;  ///< episodes started so far - 1
  std::uint64_t game_seed = 0;
  int learner = 0;            ///< the learner's seat this episode
  CueStrikeNoise noise;       ///< this episode's noise
  GameState state;
  std::vector<float> observation;
  int steps = 0;              ///< plays (both players') this episode: the seeds' counter
  /// Keep this episode's steps (start, history): what a viewer page draws.
  bool record_steps = false;
  GameState start;
  std::vector<GameStep> history;
  /// The observation's point of view: the learner, or in self-play the player to act.
  int viewer() const;
};

/// What one step did.
struct EnvStepResult {
  int player = 0;                      ///< who acted
  double reward = 0.0;                 ///< of the player who acted
  std::array<double, 2> rewards{};     ///< per player, from each one's point of view
  std::array<RewardTerms, 2> terms{};  ///< per player, unweighted
  bool terminated = false;             ///< the game ended with a result
  bool truncated = false;              ///< the game was cut short (max_shots, the simulator's bound)
  std::string illegal;                 ///< why the action was illegal (empty: legal)
  std::vector<Ruling> rulings;         ///< every play of the step, in order (the acting player's first)
  std::vector<int> players;            ///< who played each of them
};

/// A new episode on `table` (its seed and episode counter advance): the
/// game, the seat, the noise, the breaks and opponent moves up to the
/// learner's first turn, and the observation. `seed` given: the table is
/// reseeded (episode 0). A game that ends before the learner acts (the 9
/// on the recommended break, the opponent's run-out) is skipped: the next
/// episode is drawn (up to 100 in a row).
void env_reset(const EnvOptions& options, EnvTable& table, std::optional<std::uint64_t> seed = std::nullopt);

/// A new episode from `start` (a game of options.game, not over: a
/// drill, a layout to practise, a saved position): its balls, its player to
/// act and its rules' state, with the episode's noise; the learner's seat
/// is options.seat, or with -1 the player to act in `start`; the episode
/// lasts at most options.max_shots shots and decisions from `start`. Throws
/// InvalidArgument("state") for another discipline or a game that is over.
void env_reset_from(const EnvOptions& options, EnvTable& table, const GameState& start);

/// One action of the player to act on `table` (the learner, or in
/// self-play whoever acts), then the opponent's replies; updates the
/// observation. The table's game must not be over (InvalidArgument "step").
EnvStepResult env_step(const EnvOptions& options, EnvTable& table, const EnvAction& action);

/// True when options.opponent plays the player to act in `table` (the learner does not).
bool opponent_to_act(const EnvOptions& options, const EnvTable& table);

// ------------------------------------------------------------------ many tables

/// N tables stepped together on worker threads: table i seeded seed + i,
/// each stepped by its own action; a table whose game ends is reset at once
/// (auto-reset: its observation is the new episode's, the last one is kept
/// in final_observation). Results are identical whatever the thread count.
struct VectorEnvironment {
  EnvOptions options;
  std::vector<EnvTable> tables;
  int threads = 1;
  /// tables x observation size, row per table.
  std::vector<float> observations;
  std::vector<float> final_observations;  ///< rows valid where the last step ended the episode
  std::vector<EnvStepResult> results;
};

/// Throws InvalidArgument ("n" in [1, 65536], "threads" in [1, 256], options).
VectorEnvironment make_vector_environment(const EnvOptions& options, int n, int threads, std::uint64_t seed);
/// Resets every table (reseeded seed + i when `seed` is given).
void vector_reset(VectorEnvironment& env, std::optional<std::uint64_t> seed = std::nullopt);
/// Steps table i with actions[i] (actions.size() == tables).
void vector_step(VectorEnvironment& env, const std::vector<EnvAction>& actions);

}  // namespace cueball
