// Benchmarks of the cue strike (src/physics/cue_strike.cpp), which the batch
// simulator calls once per simulated shot, after with_noise(). Each benchmark
// runs over the same batch of random valid strikes so that branch prediction
// cannot memorise one path.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "cueball/physics/cue_strike.hpp"

namespace {

using namespace cueball;

const BallParameters kBall = pool_parameters().ball;
const CueParameters kCue;

const std::vector<CueStrike>& strikes() {
  static const std::vector<CueStrike> batch = [] {
    std::vector<CueStrike> out;
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> speed(0.5, 10.0), aim(-std::numbers::pi, std::numbers::pi),
        elev(0.0, 0.6), unit(0.0, 1.0);
    for (int i = 0; i < 4096; ++i) {
      const double rho = 0.45 * kBall.radius * std::sqrt(unit(rng));
      const double angle = 2 * std::numbers::pi * unit(rng);
      out.push_back({speed(rng), aim(rng), elev(rng), rho * std::cos(angle), rho * std::sin(angle)});
    }
    return out;
  }();
  return batch;
}

// The API entry point: validation (including the miscue check) + the kernel.
void BM_StrikeBall(benchmark::State& st) {
  const auto& b = strikes();
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(strike_ball(b[i], {0.5, 0.5}, kBall, kCue));
    i = (i + 1) & 4095;
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_StrikeBall);

// The kernel alone, for inputs validated beforehand.
void BM_StrikeBallUnchecked(benchmark::State& st) {
  const auto& b = strikes();
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(strike_ball_unchecked(b[i], {0.5, 0.5}, kBall, kCue));
    i = (i + 1) & 4095;
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_StrikeBallUnchecked);

// What one noisy shot of the batch simulator costs before the motion: five
// normal draws, with_noise(), the miscue check and the strike.
void BM_NoisyStrike(benchmark::State& st) {
  const auto& b = strikes();
  const CueStrikeNoise sigma{0.05, 0.003, 0.01, 0.0008, 0.0008};
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  std::size_t i = 0;
  for (auto _ : st) {
    const CueStrike played = with_noise(b[i], sigma, {normal(rng), normal(rng), normal(rng), normal(rng), normal(rng)});
    if (cue_tip_offset_ok(played, kBall) && played.elevation >= 0.0 && played.speed > 0.0) {
      benchmark::DoNotOptimize(strike_ball_unchecked(played, {0.5, 0.5}, kBall, kCue));
    }
    i = (i + 1) & 4095;
  }
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_NoisyStrike);

}  // namespace
