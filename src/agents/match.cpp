// A whole game between two agents (agents/match.hpp).
#include "cueball/agents/match.hpp"

#include <utility>

#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"

namespace cueball {

namespace {

constexpr std::uint64_t u64(int v) { return static_cast<std::uint64_t>(v); }

std::size_t slot(int player) { return static_cast<std::size_t>(player); }

}  // namespace

std::uint64_t agent_seed(std::uint64_t game_seed, int step) { return stream_seed(game_seed, 2 * u64(step)); }
std::uint64_t shot_seed(std::uint64_t game_seed, int step) { return stream_seed(game_seed, 2 * u64(step) + 1); }

GameRecord play_game(const GameConfig& config, const std::array<AgentOptions, 2>& players, std::uint64_t seed) {
  for (std::size_t p = 0; p < 2; ++p) {
    try {
      validate(players[p]);
    } catch (const InvalidArgument& e) {
      const std::string field = "players[" + std::to_string(p) + "]." + e.field();
      throw InvalidArgument(field, field + ": " + e.what());
    }
  }
  GameRecord record;
  record.players = {to_string(players[0].kind), to_string(players[1].kind)};
  record.seed = seed;
  record.start = new_game(config, seed);
  GameState state = record.start;
  for (int k = 0; !state.over; ++k) {
    AgentChoice choice = choose(players[slot(state.to_shoot)], state, agent_seed(seed, k));
    GameStep step = play(state, choice.action, shot_seed(seed, k));
    state = step.next;
    record.steps.push_back(RecordedStep{choice.action, shot_seed(seed, k), std::move(step.ruling), std::move(step.next),
                                        std::move(choice.reasoning)});
  }
  return record;
}

GameTally tally(const GameRecord& record) {
  GameTally t;
  const GameState* before = &record.start;
  for (const RecordedStep& s : record.steps) {
    const std::size_t p = slot(before->to_shoot);
    const int cue = before->cue_ball();
    t.shots[p] += 1;
    if (s.ruling.foul) t.fouls[p] += 1;
    for (const int id : s.ruling.pocketed) t.pots[p] += id != cue && !(before->config.kind == GameKind::three_cushion) ? 1 : 0;
    before = &s.state;
  }
  return t;
}

}  // namespace cueball
