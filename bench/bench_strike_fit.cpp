// The per-shot strike fit (src/calibration/strike_fit.cpp): one fit of a
// synthetic three-cushion-table shot tracked at 50 Hz with a 1.5 cm dead band
// (the goal of issue 28: <= 0.2 s a shot on one core; 51-145 ms with 32 starts). The shot is made by
// the engine under the carom table's default constants, with either ball-ball model.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "cueball/io/scenario_json.hpp"
#include "cueball/calibration/calibrate.hpp"
#include "cueball/simulation/scenario.hpp"

namespace {

using namespace cueball;

struct Fixture {
  FitModel model;
  PreparedShot shot;
};

// The shot made and fitted under the ball-ball model `ball_collision`.
const Fixture& fixture(const ShotAction& action, const char* ball_collision) {
  static std::vector<std::unique_ptr<Fixture>> made;
  auto f = std::make_unique<Fixture>();
  Scenario s = scenario_from_json(std::string(R"({"table": "carom_10ft", "balls": [
      {"id": 0, "name": "white", "position": [0.7, 0.5]}, {"id": 1, "name": "yellow", "position": [2.1, 0.35]},
      {"id": 2, "name": "red", "position": [1.9, 1.05]}], "cue": {"ball": 0, "speed": 1},
      "ball_collision": {"model": ")") + ball_collision + R"("}})");
  f->model = {s.table, s.settings, s.cue_parameters};
  const SimulationResult r = simulate(s.table, balls_after_strike(s, to_strike(action, s.table.ball.radius)), s.settings);
  TrackedShot shot;
  shot.cue_ball = "white";
  const double strike = 0.011, rate = 50.0;
  const int n = static_cast<int>((r.end_time + strike + 0.5) * rate);
  for (std::size_t j = 0; j < s.balls.size(); ++j) {
    TrackedBall b;
    b.name = s.balls[j].name;
    Vec2 last{-1, -1};
    for (int k = 0; k <= n; ++k) {
      const double t = k / rate;
      const Vec2 p = r.state_at(j, std::max(t - strike, 0.0), s.settings.parameters).position;
      if (k != 0 && k != n && std::hypot(p.x - last.x, p.y - last.y) < 0.015) continue;
      last = p;
      b.t.push_back(t), b.x.push_back(p.x), b.y.push_back(p.y);
    }
    shot.balls.push_back(b);
  }
  f->shot = prepare_shot(shot, f->model.table, "shot");
  made.push_back(std::move(f));
  return *made.back();
}

void BM_FitStrike(benchmark::State& state) {
  const ShotAction actions[] = {{3.2, 25.0, 4.0, 0.2, 0.15}, {2.6, 4.0, 6.0, -0.25, -0.2}};
  const char* models[] = {"coulomb_impulse", "mathavan_2014"};
  const Fixture& f = fixture(actions[state.range(0)], models[state.range(1)]);
  state.SetLabel(models[state.range(1)]);
  double simulations = 0;
  for (auto _ : state) {
    const StrikeFit fit = fit_strike(f.shot, f.model);
    simulations += fit.simulations;
    benchmark::DoNotOptimize(fit.cost);
  }
  state.counters["simulations"] = benchmark::Counter(simulations, benchmark::Counter::kAvgIterations);
}
// Second argument: the ball-ball model (0 coulomb_impulse, 1 mathavan_2014,
// which fits the recorded match best: README "Validated against a real match").
BENCHMARK(BM_FitStrike)->ArgsProduct({{0, 1}, {0, 1}})->Unit(benchmark::kMillisecond);

}  // namespace
