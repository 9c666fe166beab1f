// Benchmark of the cue-obstruction test (src/table/cue_obstruction.cpp),
// which the planner calls for every candidate strike: its rail test, which
// passes over the 2 mm samples that provably stay clear, against testing
// every sample (the model's definition, as tests/test_cue_obstruction.cpp
// checks them equal), alternately in each iteration over the same batch of
// random strikes from all over a 9-ft pool table (no other balls: the rail
// alone). Counters: microseconds a strike each way and their ratio.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "cueball/table/cue_obstruction.hpp"
#include "cueball/table/table.hpp"
#include "cue_rail_by_every_sample.hpp"  // tests/support/

namespace {

using namespace cueball;

struct Case {
  Vec2 cue_ball;
  CueStrike strike;
};

void BM_CueObstructionRail(benchmark::State& st) {
  const Table table = build_table(pool_table_9ft_spec());
  const double R = table.ball.radius;
  std::vector<Case> cases;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(0.0, table.length), y(0.0, table.width), aim(-3.14159, 3.14159),
      elevation(0.0, 0.3);
  while (cases.size() < 512) {
    const Vec2 p{x(rng), y(rng)};
    if (!ball_on_table(table, p, R)) continue;
    CueStrike s;
    s.aim = aim(rng);
    s.elevation = elevation(rng);
    cases.push_back({p, s});
  }
  double fast_s = 0.0, sampled_s = 0.0;
  int agree = 0;
  for (auto _ : st) {
    const auto t0 = std::chrono::steady_clock::now();
    for (const Case& c : cases) agree += cue_obstructed(table, c.cue_ball, {}, c.strike, R) ? 1 : 0;
    const auto t1 = std::chrono::steady_clock::now();
    for (const Case& c : cases) agree -= test::over_rail_low_by_every_sample(table, c.cue_ball, c.strike, R) ? 1 : 0;
    const auto t2 = std::chrono::steady_clock::now();
    fast_s += std::chrono::duration<double>(t1 - t0).count();
    sampled_s += std::chrono::duration<double>(t2 - t1).count();
  }
  if (agree != 0) st.SkipWithError("the two rail tests disagree");
  const double n = static_cast<double>(st.iterations()) * static_cast<double>(cases.size());
  st.counters["pass_over_us"] = 1e6 * fast_s / n;
  st.counters["every_sample_us"] = 1e6 * sampled_s / n;
  st.counters["every_sample_over_pass_over"] = sampled_s / fast_s;
}
BENCHMARK(BM_CueObstructionRail)->Unit(benchmark::kMillisecond);

}  // namespace
