// Benchmarks of whole games (src/games/, src/agents/): games per second of
// every discipline between two random agents (each iteration a whole game
// from its own seed: the break, every shot simulated and judged; the
// discipline's default config), the pocket games between two ghost-ball
// agents with tournament noise, and the cost of one agent
// decision on a mid-rack table: the ghost-ball agent's, the planner agent's
// at its default budget and with position play, and its ball in hand;
// the planner's and the safety planner's on a table with no clear pot.
// Counters: games per second and shots per game, or engine runs per
// decision. docs/planner-benchmark.md ("Games") has the figures.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "cueball/agents/agent.hpp"
#include "cueball/core/random.hpp"
#include "cueball/games/game.hpp"

namespace {

using namespace cueball;

void play_games(benchmark::State& st, GameKind game_kind, AgentKind kind, bool noise) {
  AgentOptions agent;
  agent.kind = kind;
  GameConfig config = default_config(game_kind);
  if (noise) config.noise = tournament_noise();
  std::uint64_t game = 0;
  long long shots = 0;
  for (auto _ : st) {
    GameState s = new_game(config, game);
    while (!s.over) {
      const std::uint64_t seed = stream_seed(game, static_cast<std::uint64_t>(s.shots));
      s = play(s, choose_action(agent, s, seed), seed).next;
    }
    shots += s.shots;
    ++game;
    benchmark::DoNotOptimize(s.winner);
  }
  st.counters["games_per_s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
  st.counters["shots_per_game"] = static_cast<double>(shots) / static_cast<double>(st.iterations());
}

void BM_RandomVsRandom(benchmark::State& st) {
  play_games(st, static_cast<GameKind>(st.range(0)), AgentKind::random, false);
  st.SetLabel(to_string(static_cast<GameKind>(st.range(0))));
}
BENCHMARK(BM_RandomVsRandom)->DenseRange(0, 4)->Unit(benchmark::kMillisecond);

void BM_GhostBallVsGhostBall(benchmark::State& st) {
  play_games(st, static_cast<GameKind>(st.range(0)), AgentKind::ghost_ball, true);
  st.SetLabel(to_string(static_cast<GameKind>(st.range(0))));
}
BENCHMARK(BM_GhostBallVsGhostBall)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

// A 9-ball table in play with these balls (the cue ball, id 0, left out
// when in hand anywhere), tournament noise, `on` the ball on.
GameState nine_ball_table(const std::vector<std::pair<int, Vec2>>& balls, int on, bool in_hand) {
  GameConfig config = default_config(GameKind::nine_ball);
  config.noise = tournament_noise();
  GameState s = new_game(config);
  s.phase = GamePhase::play;
  s.ball_in_hand.reset();
  s.table.balls.clear();
  for (const auto& [id, p] : balls) {
    if (in_hand && id == 0) continue;
    SimulationBall b;
    b.id = id;
    b.name = id == 0 ? "cue" : std::to_string(id);
    b.state.position = p;
    s.table.balls.push_back(b);
  }
  s.on = {on};
  if (in_hand) s.ball_in_hand = PlacementRegion{};
  return s;
}

// A mid-rack 9-ball table: the 3 to play, five balls left, the cue ball in
// the middle (or in hand anywhere).
GameState mid_rack(bool in_hand) {
  return nine_ball_table({{0, {1.1, 0.6}}, {3, {1.7, 0.35}}, {4, {2.2, 1.0}}, {6, {0.6, 0.9}}, {7, {1.4, 1.1}}, {9, {2.3, 0.4}}},
                         3, in_hand);
}

// A 9-ball table where the 1 has no clear direct pot (tests/test_safety.cpp's
// first hidden layout): the planner finds a bank of 0.4, the safety planner
// searches a safety and plays it.
GameState hidden() {
  return nine_ball_table({{0, {1.403, 1.063}}, {1, {1.923, 0.503}}, {2, {2.441, 0.128}}, {3, {0.513, 0.972}},
                          {4, {1.138, 0.953}}, {9, {1.692, 0.080}}},
                         1, false);
}

void decide_on(benchmark::State& st, const AgentOptions& agent, const GameState& s) {
  long long runs = 0;
  std::uint64_t seed = 0;
  for (auto _ : st) {
    if (agent.kind == AgentKind::planner || agent.kind == AgentKind::safety_planner) {
      const PlannerChoice c = agent.kind == AgentKind::planner ? planner_choice(agent, s, seed++)
                                                                : safety_planner_choice(agent, s, seed++);
      runs += c.simulations;
      benchmark::DoNotOptimize(c.action.strike);
    } else {
      benchmark::DoNotOptimize(choose_action(agent, s, seed++).strike);
    }
  }
  st.counters["runs_per_decision"] = static_cast<double>(runs) / static_cast<double>(st.iterations());
}

void decide(benchmark::State& st, const AgentOptions& agent, bool in_hand) { decide_on(st, agent, mid_rack(in_hand)); }

void BM_GhostBallDecision(benchmark::State& st) {
  AgentOptions a;
  a.kind = AgentKind::ghost_ball;
  decide(st, a, false);
}
BENCHMARK(BM_GhostBallDecision)->Unit(benchmark::kMicrosecond);

void BM_PlannerDecision(benchmark::State& st) {
  AgentOptions a;  // the planner at its defaults: 2,000 runs, no position play
  decide(st, a, false);
}
BENCHMARK(BM_PlannerDecision)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_PlannerDecisionWithPosition(benchmark::State& st) {
  AgentOptions a;
  a.position_simulations = 1000;
  decide(st, a, false);
}
BENCHMARK(BM_PlannerDecisionWithPosition)->Unit(benchmark::kMillisecond)->Iterations(5);

void BM_PlannerBallInHand(benchmark::State& st) {
  AgentOptions a;
  a.position_simulations = 1000;
  decide(st, a, true);
}
BENCHMARK(BM_PlannerBallInHand)->Unit(benchmark::kMillisecond)->Iterations(3);

// Side by side on the hidden table: the planner's decision (a bank) and the
// safety planner's (the same plan, then its safety search).
void BM_PlannerDecisionHidden(benchmark::State& st) {
  AgentOptions a;
  decide_on(st, a, hidden());
}
BENCHMARK(BM_PlannerDecisionHidden)->Unit(benchmark::kMillisecond)->Iterations(10);

void BM_SafetyPlannerDecisionHidden(benchmark::State& st) {
  AgentOptions a;
  a.kind = AgentKind::safety_planner;
  decide_on(st, a, hidden());
}
BENCHMARK(BM_SafetyPlannerDecisionHidden)->Unit(benchmark::kMillisecond)->Iterations(10);

}  // namespace
