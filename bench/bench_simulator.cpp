// Benchmarks of whole shots (src/simulator.cpp): the built-in 9-ball break,
// a one-ball shot with several cushion hits, and batch throughput on one and
// two threads (their ratio is the parallel speed-up). Counters report events
// and microseconds per shot.
#include <benchmark/benchmark.h>

#include "cueball/batch.hpp"
#include "cueball/scenario.hpp"

namespace {

using namespace cueball;

void run_shot(benchmark::State& st, const Scenario& s) {
  const std::vector<SimulationBall> balls = balls_after_strike(s);
  std::size_t events = 0;
  for (auto _ : st) {
    const SimulationResult r = simulate(s.table, balls, s.settings);
    events = r.events.size();
    benchmark::DoNotOptimize(r.end_time);
  }
  st.counters["events"] = static_cast<double>(events);
  st.counters["us_per_shot"] = benchmark::Counter(static_cast<double>(st.iterations()) * 1e-6,
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_NineBallBreak(benchmark::State& st) { run_shot(st, default_scenario()); }
BENCHMARK(BM_NineBallBreak)->Unit(benchmark::kMicrosecond);

// The same break without re-validating the table and balls: what a batch or
// a planner pays per shot once its scenario has been validated.
void BM_NineBallBreakUnchecked(benchmark::State& st) {
  const Scenario s = default_scenario();
  const std::vector<SimulationBall> balls = balls_after_strike(s);
  for (auto _ : st) benchmark::DoNotOptimize(simulate_unchecked(s.table, balls, s.settings).end_time);
  st.counters["us_per_shot"] = benchmark::Counter(static_cast<double>(st.iterations()) * 1e-6,
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_NineBallBreakUnchecked)->Unit(benchmark::kMicrosecond);

// One ball around the table: struck hard with running side, several rails.
void BM_OneBallCushions(benchmark::State& st) {
  static const Scenario s = scenario_from_json(R"({"table": "pool_9ft",
      "balls": [{"id": 0, "position": [0.6, 0.4]}],
      "cue": {"ball": 0, "aim_deg": 27, "speed": 6.0, "side": 0.3, "height": 0.2}})");
  run_shot(st, s);
}
BENCHMARK(BM_OneBallCushions)->Unit(benchmark::kMicrosecond);

void BM_BatchBreaks(benchmark::State& st) {
  static const Scenario s = default_scenario();
  const int threads = static_cast<int>(st.range(0));
  double shots = 0.0;
  for (auto _ : st) {
    const BatchResult r = simulate_batch(s, {200, threads, 1});
    shots += r.shots;
  }
  st.counters["shots_per_second"] = benchmark::Counter(shots, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BatchBreaks)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
