// Episodes of the learning environment (rl/environment.hpp): reset, one
// step (the learner's action, then the automatic plays: the recommended
// break, the opponent's replies), the reward, the observation.
#include "cueball/rl/environment.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "cueball/agents/match.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"

namespace cueball {

namespace {

// An opponent plays (not self-play).
bool has_opponent(const EnvOptions& options) {
  return options.opponent.agent.has_value() || options.opponent.kind.has_value();
}

std::string num(double v) { return std::to_string(v); }

// The stream of a game's seed that draws the episode's seat and noise
// (far from the plays' streams agent_seed / shot_seed, match.hpp).
constexpr std::uint64_t kEpisodeStream = std::uint64_t{1} << 62;

std::size_t at(int player) { return static_cast<std::size_t>(player); }

// Everything one step touches, filled by the named steps below.
struct StepRun {
  const EnvOptions& options;
  EnvTable& table;
  EnvStepResult& result;
};

// The reward's terms of one play for both players.
void count_play(StepRun& run, int player, int cue_ball, const Ruling& ruling, bool illegal) {
  RewardTerms& mine = run.result.terms[at(player)];
  RewardTerms& theirs = run.result.terms[at(1 - player)];
  mine.points += ruling.points[at(player)] - ruling.points[at(1 - player)];
  theirs.points += ruling.points[at(1 - player)] - ruling.points[at(player)];
  if (ruling.foul) mine.fouls += 1.0;
  else
    for (const int id : ruling.pocketed)
      if (id != cue_ball) mine.pots += 1.0;
  if (illegal) mine.illegal += 1.0;
  if (ruling.game_over && ruling.winner) {
    run.result.terms[at(*ruling.winner)].win += 1.0;
    run.result.terms[at(1 - *ruling.winner)].win -= 1.0;
  }
}

// Applies one GameStep to the table and the step's result.
void apply(StepRun& run, GameStep&& step, bool illegal) {
  const int player = run.table.state.to_shoot;
  const int cue_ball = run.table.state.cue_ball();
  count_play(run, player, cue_ball, step.ruling, illegal);
  run.result.rulings.push_back(step.ruling);
  run.result.players.push_back(player);
  run.table.state = step.next;
  run.table.steps += 1;
  if (run.table.record_steps) run.table.history.push_back(std::move(step));
}

// True when the engine plays the player to act: the recommended break, or
// the opponent.
bool automatic(const EnvOptions& options, const EnvTable& table) {
  if (table.state.over) return false;
  if (table.state.phase == GamePhase::break_shot && options.break_policy == BreakPolicy::recommended) return true;
  return opponent_to_act(options, table);
}

// One automatic play: the recommended break, else the opponent's choice.
void play_automatic(StepRun& run) {
  EnvTable& t = run.table;
  Action action;
  if (t.state.phase == GamePhase::break_shot && run.options.break_policy == BreakPolicy::recommended) {
    action = break_action(t.state);
  } else {
    action = choose_action(*opponent_agent(run.options.opponent), t.state, agent_seed(t.game_seed, t.steps));
  }
  apply(run, play(t.state, action, shot_seed(t.game_seed, t.steps)), false);
}

// The automatic plays up to the next decision of a player the caller acts for.
void advance(StepRun& run) {
  while (automatic(run.options, run.table)) play_automatic(run);
}

// The learner's (or the acting player's) own action.
void play_action(StepRun& run, const EnvAction& a) {
  EnvTable& t = run.table;
  DecodedAction decoded = decode_action(run.options, t.state, a);
  const std::uint64_t seed = shot_seed(t.game_seed, t.steps);
  run.result.illegal = decoded.illegal;
  const bool illegal = !decoded.illegal.empty();
  if (illegal && !decoded.action.decision) {
    apply(run, play_foul_stroke(t.state, decoded.action.place, seed, "illegal action (" + decoded.illegal + ")"), true);
    return;
  }
  apply(run, play(t.state, decoded.action, seed), illegal);
}

// The rewards, the end flags and the observation after the step.
void finish(StepRun& run) {
  EnvTable& t = run.table;
  for (int p = 0; p < 2; ++p) run.result.rewards[at(p)] = weighted(run.options.reward, run.result.terms[at(p)]);
  run.result.reward = run.result.rewards[at(run.result.player)];
  run.result.terminated = t.state.over && !t.state.truncated;
  run.result.truncated = t.state.over && t.state.truncated;
  t.observation.resize(static_cast<std::size_t>(env_observation_size(t.state.config.kind)));
  write_observation(t.state, t.viewer(), t.noise, t.observation.data());
}

CueStrikeNoise scaled(const CueStrikeNoise& n, double k) {
  return {n.speed * k, n.aim * k, n.elevation * k, n.side_offset * k, n.height_offset * k};
}

// Step 1 of env_reset and env_reset_from: the episode's seat and noise, and
// its game: a new one, or `start` bounded to max_shots from where it stands.
void start_episode(const EnvOptions& options, EnvTable& table, const GameState* start = nullptr) {
  table.game_seed = stream_seed(table.seed, table.episode);
  RandomStream rng(stream_seed(table.game_seed, kEpisodeStream));
  const int seat = options.seat >= 0 ? options.seat : (rng.chance(0.5) ? 1 : 0);
  table.learner = has_opponent(options) ? seat : -1;
  table.noise = scaled(options.noise.base, rng.uniform(options.noise.scale_min, options.noise.scale_max));
  if (start) {
    table.state = *start;
    table.state.config.noise = table.noise;
    table.state.config.max_shots = start->shots + options.max_shots;
    if (has_opponent(options) && options.seat < 0) table.learner = start->to_shoot;
  } else {
    GameConfig config = env_game_config(options);
    config.noise = table.noise;
    table.state = new_game(config, table.game_seed);
  }
  table.steps = 0;
  table.history.clear();
  if (table.record_steps) table.start = table.state;
}

// Episodes env_reset skips in a row at most (each ended before the learner
// acted); the last is kept, over, so that a caller's step reports it.
constexpr int kMaxSkippedEpisodes = 100;

}  // namespace

double weighted(const RewardTerms& w, const RewardTerms& t) {
  return w.win * t.win + w.points * t.points + w.pots * t.pots + w.fouls * t.fouls + w.illegal * t.illegal;
}

int EnvTable::viewer() const { return learner >= 0 ? learner : state.to_shoot; }

void validate(const EnvOptions& options) {
  if (options.max_shots < 1 || options.max_shots > 100000)
    throw InvalidArgument("max_shots", options.max_shots, "[1, 100000]", "shots and decisions a game may last");
  if (!(options.max_speed > kEnvMinSpeed && options.max_speed <= 12.0))
    throw InvalidArgument("max_speed", options.max_speed, "(0.2, 12]", "m/s, the cue speed of strike[0] = 1");
  if (options.seat < -1 || options.seat > 1)
    throw InvalidArgument("seat", options.seat, "0, 1 or -1", "the learner's seat; -1: drawn per episode");
  validate(options.noise.base);
  const NoiseRange& n = options.noise;
  if (!(n.scale_min >= 0.0 && n.scale_max >= n.scale_min && n.scale_max <= 100.0))
    throw InvalidArgument("noise.scale", "noise.scale = [" + num(n.scale_min) + ", " + num(n.scale_max) +
                                             "] is not a range within [0, 100]");
  if (options.opponent.agent) {
    try {
      validate(*options.opponent.agent);
    } catch (const InvalidArgument& e) {
      const std::string field = "opponent." + e.field();
      throw InvalidArgument(field, field + ": " + e.what());
    }
  } else if (options.opponent.kind && (options.opponent.simulations < 1 || options.opponent.simulations > 1000000)) {
    throw InvalidArgument("opponent.simulations", options.opponent.simulations, "[1, 1000000]",
                          "engine runs of an opponent's decision");
  }
  const RewardTerms& w = options.reward;
  for (const double v : {w.win, w.points, w.pots, w.fouls, w.illegal})
    if (!std::isfinite(v)) throw InvalidArgument("reward", "reward: every weight must be finite");
}

GameConfig env_game_config(const EnvOptions& options) {
  GameConfig c = default_config(options.game);
  c.max_shots = options.max_shots;
  return c;
}

std::optional<AgentOptions> opponent_agent(const EnvOpponent& opponent) {
  if (opponent.agent) return opponent.agent;
  if (!opponent.kind) return std::nullopt;
  AgentOptions agent;
  agent.kind = *opponent.kind;
  agent.simulations = opponent.simulations;
  return agent;
}

bool opponent_to_act(const EnvOptions& options, const EnvTable& table) {
  return has_opponent(options) && !table.state.over && table.state.to_shoot != table.learner;
}

void env_reset(const EnvOptions& options, EnvTable& table, std::optional<std::uint64_t> seed) {
  if (seed) {
    table.seed = *seed;
    table.episode = 0;
  } else {
    table.episode += 1;
  }
  // A game that ends before the learner acts (the 9 on the recommended
  // break) gives it nothing to learn: the next episode is drawn instead.
  for (int tries = 0;; ++tries, ++table.episode) {
    start_episode(options, table);
    EnvStepResult ignored;
    StepRun run{options, table, ignored};
    advance(run);
    if (!table.state.over || tries == kMaxSkippedEpisodes) {
      finish(run);
      return;
    }
  }
}

void env_reset_from(const EnvOptions& options, EnvTable& table, const GameState& start) {
  if (start.config.kind != options.game)
    throw InvalidArgument("state", std::string("state: a ") + to_string(start.config.kind) + " state for a " +
                                       to_string(options.game) + " environment");
  if (start.over) throw InvalidArgument("state", "state: the game is over (" + start.end_reason + ")");
  table.episode += 1;
  start_episode(options, table, &start);
  EnvStepResult ignored;
  StepRun run{options, table, ignored};
  advance(run);
  finish(run);
}

EnvStepResult env_step(const EnvOptions& options, EnvTable& table, const EnvAction& action) {
  if (table.state.over) throw InvalidArgument("step", "step: the episode is over; reset the table first");
  EnvStepResult result;
  result.player = table.state.to_shoot;
  StepRun run{options, table, result};
  play_action(run, action);
  advance(run);
  finish(run);
  return result;
}

}  // namespace cueball
