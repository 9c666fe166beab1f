// cueball-stress --games N: whole games between random agents (agents/
// agent.hpp, AgentKind::random), every discipline, each step checked for the
// rules' invariants (issue 25, item 7). Game k of a run with --seed S plays
// new_game(default_config(kind), S + k), the shot n's agent seed and play
// seed both stream_seed(S + k, n), so any game is reproduced alone by
//     cueball-stress --games 1 --game KIND --seed S+k
//
// One shot in eight is played as a foul stroke (play_foul_stroke, as the
// learning environment plays an illegal action), the rest as the agent chose.
//
// The invariants (a game counts once per kind of violation):
//   illegal      play() refused the random agent's action (InvalidArgument):
//                legal_actions() and validate_action() disagree
//   crash        any other exception
//   unbounded    the game took more steps than config.max_shots
//   unfinished   it ended without a winner and without being truncated
//   balls        balls not conserved: after a shot, the object balls on the
//                table plus those pocketed and not respotted (the rulings'
//                pocketed and respotted lists) differ from the rack's
//                (decisions that re-rack or restore the balls reset the count)
//   table        a ball at rest where ball_on_table() refuses it, or two
//                balls overlapping by more than 1e-9 m
//   scores       the scores differ from the sum of the rulings' points (pool
//                games: 1 to the winner)
//   replay       playing the same actions with the same seeds again does not
//                give the same final state (every 10th game)
#include "game_stress.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "cueball/agents/agent.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"

namespace cueball {

namespace {

constexpr std::array kViolationNames{"illegal", "crash", "unbounded", "unfinished", "balls", "table", "scores", "replay"};
constexpr std::size_t kViolations = kViolationNames.size();

struct GameOutcome {
  int steps = 0;
  bool truncated = false;
  int winner = -1;
  std::map<std::string, int> fouls;
  std::array<std::string, kViolations> violation;  // empty: none
};

bool pool_game(GameKind k) {
  return k == GameKind::nine_ball || k == GameKind::eight_ball || k == GameKind::ten_ball;
}

// Every ball at rest on the bed and no two overlapping.
std::string table_problem(const GameState& s) {
  const Table& t = s.table.table;
  const double r = t.ball.radius;
  const auto& balls = s.table.balls;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!ball_on_table(t, balls[i].state.position, r)) return "ball " + std::to_string(balls[i].id) + " off the bed";
    for (std::size_t j = i + 1; j < balls.size(); ++j)
      if (norm(balls[i].state.position - balls[j].state.position) < 2.0 * r - 1e-9)
        return "balls " + std::to_string(balls[i].id) + " and " + std::to_string(balls[j].id) + " overlap";
  }
  return {};
}

std::vector<int> ids_on_table(const GameState& s) {
  std::vector<int> ids = object_balls(s);
  std::sort(ids.begin(), ids.end());
  return ids;
}

GameConfig config_for(GameKind kind, std::uint64_t seed) {
  GameConfig c = default_config(kind);
  if (seed % 2 == 1) c.fouls_to_lose = 0;
  if (kind == GameKind::three_cushion) c.race_to = 3;  // random play scores about once in 90 shots
  return c;
}

bool resets_balls(const std::optional<Decision>& d) {
  return d && (*d == Decision::rerack_and_break || *d == Decision::rerack_opponent_breaks || *d == Decision::rerack ||
               *d == Decision::restore);
}

// One game, checked step by step (header comment).
struct GameRun {
  GameKind kind;
  std::uint64_t seed = 0;
  GameState state;
  std::vector<Action> actions;
  std::vector<char> foul_strokes;  // actions[i] was played as a foul stroke
  std::vector<int> all;   // the rack's object balls
  std::vector<int> down;  // pocketed and not respotted
  std::array<int, 2> points{};
  GameOutcome out;
};

void note(GameRun& run, std::size_t kind, std::string what) {
  if (run.out.violation[kind].empty())
    run.out.violation[kind] = "shot " + std::to_string(run.state.shots) + ": " + std::move(what);
}

void check_balls(GameRun& run, const GameStep& step) {
  if (resets_balls(step.action.decision)) {
    run.down.clear();
    for (const int id : run.all)
      if (!on_table_id(step.next, id)) run.down.push_back(id);
    return;
  }
  for (const int id : step.ruling.pocketed)
    if (std::find(run.all.begin(), run.all.end(), id) != run.all.end()) run.down.push_back(id);
  for (const int id : step.ruling.respotted) {
    const auto it = std::find(run.down.begin(), run.down.end(), id);
    if (it == run.down.end()) {
      note(run, 4, "ball " + std::to_string(id) + " respotted but not down");
      return;
    }
    run.down.erase(it);
  }
  std::vector<int> seen = ids_on_table(step.next);
  seen.insert(seen.end(), run.down.begin(), run.down.end());
  std::sort(seen.begin(), seen.end());
  if (seen != run.all) note(run, 4, "the balls on the table and down are not the rack's");
}

// One shot in eight (where a shot is due) is a foul stroke instead, as a
// learner's illegal action plays it (play_foul_stroke, rl/environment.hpp),
// with the agent's spot when it has one.
bool foul_stroke_turn(const GameState& state, std::uint64_t shot_seed) {
  return state.phase != GamePhase::decision && (stream_seed(shot_seed, 1) & 7u) == 0;
}

GameStep play_step(const GameState& state, const Action& a, bool foul_stroke, std::uint64_t shot_seed) {
  return foul_stroke ? play_foul_stroke(state, a.place, shot_seed, "stress: a foul stroke") : play(state, a, shot_seed);
}

void step_game(GameRun& run, const AgentOptions& agent) {
  const std::uint64_t shot_seed = stream_seed(run.seed, static_cast<std::uint64_t>(run.state.shots));
  const Action a = choose_action(agent, run.state, shot_seed);
  const bool foul_stroke = foul_stroke_turn(run.state, shot_seed);
  GameStep step;
  try {
    step = play_step(run.state, a, foul_stroke, shot_seed);
  } catch (const InvalidArgument& e) {
    note(run, 0, e.what());
    run.state.over = true;
    return;
  }
  run.actions.push_back(a);
  run.foul_strokes.push_back(foul_stroke ? 1 : 0);
  check_balls(run, step);
  const std::string problem = table_problem(step.next);
  if (!problem.empty()) note(run, 5, problem);
  if (step.ruling.foul) ++run.out.fouls[to_string(*step.ruling.foul)];
  run.points[0] += step.ruling.points[0];
  run.points[1] += step.ruling.points[1];
  run.state = std::move(step.next);
}

void finish(GameRun& run, bool replay) {
  const GameState& s = run.state;
  run.out.steps = s.shots;
  run.out.truncated = s.truncated;
  run.out.winner = s.winner ? *s.winner : -1;
  if (s.shots > s.config.max_shots) note(run, 2, "more steps than max_shots");
  if (run.out.violation[0].empty() && !s.winner && !s.truncated) note(run, 3, "over without a winner or a truncation");
  const std::array<int, 2> expected =
      pool_game(run.kind) ? std::array<int, 2>{s.winner == 0 ? 1 : 0, s.winner == 1 ? 1 : 0} : run.points;
  if (run.out.violation[0].empty() && s.scores != expected)
    note(run, 6, "scores " + std::to_string(s.scores[0]) + ":" + std::to_string(s.scores[1]) + ", expected " +
                     std::to_string(expected[0]) + ":" + std::to_string(expected[1]));
  if (replay && run.out.violation[0].empty()) {
    GameState r = new_game(config_for(run.kind, run.seed), run.seed);
    for (std::size_t i = 0; i < run.actions.size(); ++i)
      r = play_step(r, run.actions[i], run.foul_strokes[i] != 0, stream_seed(run.seed, static_cast<std::uint64_t>(r.shots)))
              .next;
    if (!(r == s)) note(run, 7, "the replay differs");
  }
}

GameOutcome run_game(GameKind kind, std::uint64_t seed) {
  GameRun run{kind, seed, {}, {}, {}, {}, {}, {}, {}};
  AgentOptions agent;
  agent.kind = AgentKind::random;
  try {
    run.state = new_game(config_for(kind, seed), seed);
    run.all = ids_on_table(run.state);
    const int bound = run.state.config.max_shots + 1;
    for (int n = 0; !run.state.over && n < bound; ++n) step_game(run, agent);
    if (!run.state.over) note(run, 2, "not over after max_shots + 1 steps");
    finish(run, seed % 10 == 0);
  } catch (const std::exception& e) {
    note(run, 1, e.what());
  }
  return run.out;
}

}  // namespace

bool on_table_id(const GameState& s, int id) { return find_ball(s.table.balls, id) != nullptr; }

int run_game_stress(const std::vector<GameKind>& kinds, long long games, std::uint64_t seed, int threads) {
  std::printf("cueball-stress --games: %lld random-agent games per discipline, seeds %llu..%llu, %d thread%s\n", games,
              static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed + static_cast<std::uint64_t>(games) - 1),
              threads, threads == 1 ? "" : "s");
  bool violated = false;
  for (const GameKind kind : kinds) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<GameOutcome> outcomes(static_cast<std::size_t>(games));
    std::atomic<long long> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back([&] {
        for (long long k; (k = next++) < games;)
          outcomes[static_cast<std::size_t>(k)] = run_game(kind, seed + static_cast<std::uint64_t>(k));
      });
    for (std::thread& t : pool) t.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    long long steps = 0, truncated = 0;
    std::array<long long, 2> wins{};
    std::map<std::string, long long> fouls;
    std::array<long long, kViolations> count{};
    std::array<long long, kViolations> first{};
    for (std::size_t k = 0; k < outcomes.size(); ++k) {
      const GameOutcome& o = outcomes[k];
      steps += o.steps;
      truncated += o.truncated ? 1 : 0;
      if (o.winner >= 0) ++wins[static_cast<std::size_t>(o.winner)];
      for (const auto& [name, n] : o.fouls) fouls[name] += n;
      for (std::size_t v = 0; v < kViolations; ++v)
        if (!o.violation[v].empty() && count[v]++ == 0) first[v] = static_cast<long long>(k);
    }
    std::printf("\n%s: %lld games, %lld shots and decisions (%.1f a game), %.2f s (%.0f games/s); wins %lld:%lld, truncated %lld\n",
                to_string(kind), games, steps, static_cast<double>(steps) / static_cast<double>(games), seconds,
                static_cast<double>(games) / seconds, wins[0], wins[1], truncated);
    std::string foul_line;
    for (const auto& [name, n] : fouls) foul_line += (foul_line.empty() ? "" : ", ") + name + " " + std::to_string(n);
    std::printf("  fouls: %s\n", foul_line.empty() ? "none" : foul_line.c_str());
    for (std::size_t v = 0; v < kViolations; ++v) {
      if (count[v] == 0) continue;
      violated = true;
      const auto k = static_cast<std::size_t>(first[v]);
      std::printf("  VIOLATION %-10s %lld games; first: seed %llu, %s\n", kViolationNames[v], count[v],
                  static_cast<unsigned long long>(seed + k), outcomes[k].violation[v].c_str());
    }
    if (std::all_of(count.begin(), count.end(), [](long long c) { return c == 0; })) std::printf("  no violation\n");
  }
  return violated ? 1 : 0;
}

}  // namespace cueball
