// Benchmarks of the learning environment (src/rl/): what the rules, the
// observations and the actions cost beside the physics they drive.
//
//   BM_EnvWorkload         a fixed workload: 16 9-ball tables in self-play, 40
//                          steps each of random actions (the discrete parts
//                          within the masks), from reset, on one thread;
//   BM_WorkloadShotsOnly   the same shots simulated alone (run_scenario of
//                          every shot the workload played, the recommended
//                          breaks included; foul strokes move nothing and
//                          are left out): the physics' share;
//   BM_VectorStep/T        VectorEnvironment::step of 64 tables on T threads,
//                          random actions: env steps a second.
// The ratio BM_WorkloadShotsOnly / BM_EnvWorkload (times) is the share of an
// env step that is physics (issue 26's goal: >= 0.5). docs/rl.md has the
// figures.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "cueball/core/random.hpp"
#include "cueball/rl/environment.hpp"
#include "cueball/simulation/scenario.hpp"

namespace {

using namespace cueball;

constexpr int kTables = 16;
constexpr int kStepsPerTable = 40;

EnvOptions self_play() {
  EnvOptions o;
  o.opponent.kind.reset();
  return o;
}

EnvAction random_action(const GameState& s, RandomStream& rng) {
  EnvAction a;
  for (double& x : a.strike) x = rng.uniform(-1.0, 1.0);
  for (double& x : a.place) x = rng.uniform(-1.0, 1.0);
  const ActionMasks m = action_masks(s);
  std::vector<int> allowed;
  for (std::size_t d = 0; d < m.decision.size(); ++d)
    if (m.decision[d]) allowed.push_back(static_cast<int>(d));
  a.decision = allowed.empty() ? 0 : allowed[static_cast<std::size_t>(rng.integer(0, static_cast<int>(allowed.size()) - 1))];
  for (std::size_t id = 0; id < m.ball.size(); ++id)
    if (m.ball[id]) a.ball = static_cast<int>(id);
  a.pocket = rng.integer(0, 5);
  return a;
}

// The workload; with `shots`, every shot it simulates is kept.
long long run_workload(std::vector<Scenario>* shots) {
  const EnvOptions o = self_play();
  long long steps = 0;
  for (int i = 0; i < kTables; ++i) {
    EnvTable t;
    t.record_steps = shots != nullptr;
    RandomStream rng(stream_seed(99, static_cast<std::uint64_t>(i)));
    auto harvest = [&] {
      if (!shots) return;
      for (const GameStep& g : t.history)
        if (g.shot.cue) shots->push_back(g.shot);
      t.history.clear();
    };
    env_reset(o, t, static_cast<std::uint64_t>(i));
    for (int k = 0; k < kStepsPerTable; ++k) {
      env_step(o, t, random_action(t.state, rng));
      ++steps;
      harvest();
      if (t.state.over) {
        env_reset(o, t);
        harvest();
      }
    }
  }
  return steps;
}

void BM_EnvWorkload(benchmark::State& st) {
  long long steps = 0;
  for (auto _ : st) steps += run_workload(nullptr);
  st.counters["env_steps_per_s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EnvWorkload)->Unit(benchmark::kMillisecond);

void BM_WorkloadShotsOnly(benchmark::State& st) {
  std::vector<Scenario> shots;
  run_workload(&shots);
  long long n = 0;
  for (auto _ : st) {
    for (const Scenario& s : shots) {
      SimulationResult r = run_scenario(s);
      benchmark::DoNotOptimize(r.end_time);
    }
    n += static_cast<long long>(shots.size());
  }
  st.counters["shots_per_s"] = benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsRate);
  st.counters["shots"] = static_cast<double>(shots.size());
}
BENCHMARK(BM_WorkloadShotsOnly)->Unit(benchmark::kMillisecond);

void BM_VectorStep(benchmark::State& st) {
  const int threads = static_cast<int>(st.range(0));
  VectorEnvironment env = make_vector_environment(self_play(), 64, threads, 5);
  RandomStream rng(8);
  std::vector<EnvAction> actions(env.tables.size());
  long long steps = 0;
  for (auto _ : st) {
    st.PauseTiming();
    for (std::size_t i = 0; i < actions.size(); ++i) actions[i] = random_action(env.tables[i].state, rng);
    st.ResumeTiming();
    vector_step(env, actions);
    steps += static_cast<long long>(actions.size());
  }
  st.counters["env_steps_per_s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_VectorStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace


namespace {

// One reset: a new 9-ball game and the recommended break played (self-play).
void BM_EnvReset(benchmark::State& st) {
  const EnvOptions o = self_play();
  EnvTable t;
  env_reset(o, t, 1);
  for (auto _ : st) {
    env_reset(o, t);
    benchmark::DoNotOptimize(t.observation.data());
  }
}
BENCHMARK(BM_EnvReset)->Unit(benchmark::kMicrosecond);

}  // namespace
