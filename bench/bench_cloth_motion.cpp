// Benchmarks of the closed-form cloth-motion kernels, which the table
// simulator calls for every ball at every event. Each benchmark runs over the
// same batch of random states so branch prediction cannot memorise one path.
// BM_StepwiseReference integrates the same motion with 1 ms explicit steps,
// the way a time-stepping simulator would, as the yardstick for the ratio.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "cueball/physics/cloth_motion.hpp"

namespace {

using namespace cueball;

struct Batch {
  std::vector<BallState> states;
  std::vector<double> times;
};

const Batch& batch() {
  static const Batch b = [] {
    Batch out;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> speed(-3.0, 3.0), spin(-150.0, 150.0), time(0.0, 3.0);
    for (int i = 0; i < 4096; ++i) {
      out.states.push_back({{0.0, 0.0}, {speed(rng), speed(rng)}, {spin(rng), spin(rng), spin(rng)}});
      out.times.push_back(time(rng));
    }
    return out;
  }();
  return b;
}

const Parameters kParams = pool_parameters();

void BM_MotionPhase(benchmark::State& st) {
  const Batch& b = batch();
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(motion_phase(b.states[i], kParams));
    i = (i + 1) & 4095;
  }
}
BENCHMARK(BM_MotionPhase);

void BM_NextTransition(benchmark::State& st) {
  const Batch& b = batch();
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(next_transition(b.states[i], kParams));
    i = (i + 1) & 4095;
  }
}
BENCHMARK(BM_NextTransition);

void BM_EvolveInPhase(benchmark::State& st) {
  const Batch& b = batch();
  std::vector<double> dt(4096);
  std::vector<MotionPhase> phase(4096);
  for (std::size_t k = 0; k < 4096; ++k) {
    dt[k] = 0.5 * next_transition(b.states[k], kParams).time;
    phase[k] = motion_phase(b.states[k], kParams);
  }
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(evolve_in_phase(b.states[i], phase[i], dt[i], kParams));
    i = (i + 1) & 4095;
  }
}
BENCHMARK(BM_EvolveInPhase);

// State at a time 0-3 s ahead, crossing however many transitions lie between.
void BM_StateAtTime(benchmark::State& st) {
  const Batch& b = batch();
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(evolve(b.states[i], b.times[i], kParams));
    i = (i + 1) & 4095;
  }
}
BENCHMARK(BM_StateAtTime);

// The yardstick: the same state-at-time by explicit 1 ms steps of the
// equations of motion (semi-implicit Euler, friction direction re-evaluated
// each step, which is what a time-stepping game engine does).
BallState stepwise(BallState s, double duration, const Parameters& p) {
  const double h = 1e-3;
  const double r = p.ball.radius, g = p.cloth.gravity;
  for (double t = 0.0; t < duration; t += h) {
    const Vec2 u = slip_velocity(s, r);
    const double slip = norm(u);
    Vec2 a{};
    Vec2 dw{};
    if (slip > 1e-3) {
      a = -(p.cloth.sliding_friction * g / slip) * u;
      dw = (2.5 * p.cloth.sliding_friction * g / (r * slip)) * perp(u);
    } else if (norm(s.velocity) > 1e-3) {
      a = -(5.0 / 7.0 * p.cloth.rolling_resistance * g / norm(s.velocity)) * s.velocity;
      dw = perp(a) / r;
    } else {
      s.velocity = {};
      s.angular_velocity.x = s.angular_velocity.y = 0.0;
    }
    s.velocity = s.velocity + h * a;
    s.angular_velocity.x += h * dw.x;
    s.angular_velocity.y += h * dw.y;
    s.position = s.position + h * s.velocity;
  }
  return s;
}

void BM_StepwiseReference(benchmark::State& st) {
  const Batch& b = batch();
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(stepwise(b.states[i], b.times[i], kParams));
    i = (i + 1) & 4095;
  }
}
BENCHMARK(BM_StepwiseReference);

}  // namespace
