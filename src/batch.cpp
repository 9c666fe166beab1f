// Batch simulation with execution noise; see batch.hpp.
#include "cueball/batch.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>

#include "cueball/errors.hpp"

namespace cueball {

namespace {

// SplitMix64 (Steele, Lea & Flood 2014): decorrelates the per-shot seeds.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// Five standard normal draws by Box-Muller on mt19937_64 output, so the
// numbers do not depend on the standard library's distributions.
std::array<double, 5> standard_normals(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto uniform = [&] { return (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53; };
  std::array<double, 6> z{};
  for (std::size_t i = 0; i < 6; i += 2) {
    const double radius = std::sqrt(-2.0 * std::log(uniform()));
    const double angle = 2.0 * std::numbers::pi * uniform();
    z[i] = radius * std::cos(angle);
    z[i + 1] = radius * std::sin(angle);
  }
  return {z[0], z[1], z[2], z[3], z[4]};
}

enum class Outcome : char { simulated, miscue, failure };

struct ShotOutcome {
  Outcome outcome = Outcome::miscue;
  int events = 0;
  std::vector<char> pocketed;
  std::vector<Vec2> final_position;
};

ShotOutcome play(const Scenario& s, std::uint64_t seed, int shot) {
  ShotOutcome o;
  const CueStrike noisy =
      with_noise(s.cue->strike, s.noise, standard_normals(splitmix64(seed ^ splitmix64(static_cast<std::uint64_t>(shot)))));
  std::vector<SimulationBall> balls;
  try {
    balls = balls_after_strike(s, noisy);
  } catch (const InvalidArgument&) {
    return o;  // a miscue or an out-of-range strike
  }
  try {
    // The scenario was validated once in simulate_batch; the strike is checked
    // by balls_after_strike (miscues are caught above).
    const SimulationResult r = simulate_unchecked(s.table, balls, s.settings);
    o.outcome = Outcome::simulated;
    o.events = static_cast<int>(r.events.size());
    for (const BallTrajectory& b : r.balls) {
      o.pocketed.push_back(b.pocketed ? 1 : 0);
      o.final_position.push_back(b.final_state.position);
    }
  } catch (const SimulationError&) {
    o.outcome = Outcome::failure;
  }
  return o;
}

}  // namespace

BatchResult simulate_batch(const Scenario& s, const BatchOptions& options) {
  if (options.shots < 1 || options.shots > 100000000)
    throw InvalidArgument("shots", static_cast<double>(options.shots), "[1, 1e8]", "number of shots");
  if (options.threads < 1 || options.threads > 256)
    throw InvalidArgument("threads", static_cast<double>(options.threads), "[1, 256]", "worker threads");
  if (!s.cue) throw InvalidArgument("cue", "the scenario has no cue strike to repeat");
  validate_simulation_input(s.table, s.balls, s.settings);  // once; each shot then runs unchecked
  validate(s.noise);

  const auto start = std::chrono::steady_clock::now();
  std::vector<ShotOutcome> outcomes(static_cast<std::size_t>(options.shots));
  // Each worker takes the next shot not yet taken, so a worker whose core is
  // slower (or whose shots are longer) does fewer of them and no worker waits
  // at the end. Each shot's outcome depends on its index only: the numbers
  // are the same whichever worker played it.
  std::atomic<int> next_shot{0};
  const auto work = [&] {
    for (int k = next_shot.fetch_add(1, std::memory_order_relaxed); k < options.shots;
         k = next_shot.fetch_add(1, std::memory_order_relaxed))
      outcomes[static_cast<std::size_t>(k)] = play(s, options.seed, k);
  };
  if (options.threads == 1) {
    work();
  } else {
    std::vector<std::thread> pool;
    for (int w = 0; w < options.threads; ++w) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Reduce in shot order: the same numbers whatever the threads did.
  BatchResult r;
  r.shots = options.shots;
  r.seconds = seconds;
  r.shots_per_second = seconds > 0.0 ? options.shots / seconds : 0.0;
  const std::size_t n = s.balls.size();
  std::vector<double> pocketed(n, 0.0), count(n, 0.0);
  std::vector<Vec2> sum(n);
  for (const ShotOutcome& o : outcomes) {
    if (o.outcome == Outcome::miscue) ++r.miscues;
    if (o.outcome == Outcome::failure) ++r.failures;
    if (o.outcome != Outcome::simulated) continue;
    ++r.simulated;
    r.events += o.events;
    for (std::size_t i = 0; i < n; ++i) {
      if (o.pocketed[i]) {
        pocketed[i] += 1.0;
        continue;
      }
      count[i] += 1.0;
      sum[i] = sum[i] + o.final_position[i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    BallOutcome b;
    b.id = s.balls[i].id;
    b.pocketed_probability = r.simulated > 0 ? pocketed[i] / r.simulated : 0.0;
    if (count[i] > 0.0) {
      b.mean_position = sum[i] / count[i];
      // Second pass for the spread: no cancellation between large squares.
      Vec2 squares;
      for (const ShotOutcome& o : outcomes) {
        if (o.outcome != Outcome::simulated || o.pocketed[i]) continue;
        const Vec2 d = o.final_position[i] - b.mean_position;
        squares = squares + Vec2{d.x * d.x, d.y * d.y};
      }
      b.position_std = {std::sqrt(squares.x / count[i]), std::sqrt(squares.y / count[i])};
    }
    r.balls.push_back(b);
  }
  return r;
}

}  // namespace cueball
