// Batch simulation with execution noise; see batch.hpp.
//
// Sources: SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom
// number generators", OOPSLA 2014) for the per-shot seeds; Box-Muller for the
// normals; Welford's running mean and sum of squared deviations (Welford,
// Technometrics 4(3), 1962) within a block, and the pairwise merge of Chan,
// Golub & LeVeque ("Algorithms for computing the sample variance", The
// American Statistician 37(3), 1983) across blocks.
#include "cueball/batch.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <climits>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <numbers>
#include <random>
#include <thread>

#include "cueball/errors.hpp"

namespace cueball {

namespace {

// SplitMix64: decorrelates the per-shot seeds.
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

// Reflects x into [lo, hi] (batch.hpp); true in `reflected` when it was outside.
double reflect(double x, double lo, double hi, bool& reflected) {
  reflected = false;
  if (!std::isfinite(x) || (x >= lo && x <= hi)) return x;
  reflected = true;
  const double span = hi - lo;
  if (x < lo - 2.0 * span || x > hi + 2.0 * span) {
    // Far away: the reflections repeat with period 2 span.
    x = lo + std::fmod(x - lo, 2.0 * span);
    if (x < lo) x += 2.0 * span;
  }
  // Now within two spans of the range: at most three reflections.
  for (int i = 0; i < 4 && (x < lo || x > hi); ++i) x = x > hi ? 2.0 * hi - x : 2.0 * lo - x;
  return x;
}

// ------------------------------------------------------------------ reduction

using detail::ShotRecord;

struct BallSum {
  double pocketed = 0.0;
  double stayed = 0.0;  // shots where the ball stayed on the table
  Vec2 mean;
  Vec2 m2;              // sum of squared deviations from the mean, per axis
};

// The reduction of a run of consecutive shots.
struct Partial {
  int simulated = 0, miscues = 0, failures = 0, speed_reflected = 0, elevation_reflected = 0;
  long long events = 0;
  std::vector<BallSum> balls;

  explicit Partial(std::size_t n) : balls(n) {}

  void clear() {
    simulated = miscues = failures = speed_reflected = elevation_reflected = 0;
    events = 0;
    std::fill(balls.begin(), balls.end(), BallSum{});
  }

  // Welford's update, in shot order.
  void add(const ShotRecord& r) {
    speed_reflected += r.speed_reflected ? 1 : 0;
    elevation_reflected += r.elevation_reflected ? 1 : 0;
    if (r.kind == ShotRecord::Kind::miscue) ++miscues;
    if (r.kind == ShotRecord::Kind::failure) ++failures;
    if (r.kind != ShotRecord::Kind::simulated) return;
    ++simulated;
    events += r.events;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      BallSum& b = balls[i];
      if (r.pocketed[i]) {
        b.pocketed += 1.0;
        continue;
      }
      const Vec2 x = r.final_position[i];
      b.stayed += 1.0;
      const Vec2 before = x - b.mean;
      b.mean = b.mean + before / b.stayed;
      const Vec2 after = x - b.mean;
      b.m2 = b.m2 + Vec2{before.x * after.x, before.y * after.y};
    }
  }

  // Chan, Golub & LeVeque's merge of the shots that follow (o) into these.
  void merge(const Partial& o) {
    simulated += o.simulated;
    miscues += o.miscues;
    failures += o.failures;
    speed_reflected += o.speed_reflected;
    elevation_reflected += o.elevation_reflected;
    events += o.events;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      BallSum& a = balls[i];
      const BallSum& b = o.balls[i];
      a.pocketed += b.pocketed;
      if (b.stayed == 0.0) continue;
      if (a.stayed == 0.0) {
        a.stayed = b.stayed;
        a.mean = b.mean;
        a.m2 = b.m2;
        continue;
      }
      const double n = a.stayed + b.stayed;
      const Vec2 delta = b.mean - a.mean;
      a.mean = a.mean + delta * (b.stayed / n);
      const double w = a.stayed * b.stayed / n;
      a.m2 = a.m2 + b.m2 + Vec2{delta.x * delta.x * w, delta.y * delta.y * w};
      a.stayed = n;
    }
  }
};

// ------------------------------------------------------------------ one shot

struct BatchContext {
  const Scenario& scenario;
  std::uint64_t seed;
};

void play_shot(const BatchContext& c, int shot, ShotRecord& out) {
  const Scenario& s = c.scenario;
  const CueStrike noisy = with_noise(
      s.cue->strike, s.noise, standard_normals(splitmix64(c.seed ^ splitmix64(static_cast<std::uint64_t>(shot)))));
  const LimitedStrike limited = reflect_into_limits(noisy);
  out.speed_reflected = limited.speed_reflected;
  out.elevation_reflected = limited.elevation_reflected;
  if (!cue_tip_offset_ok(limited.strike, s.settings.parameters.ball)) {
    out.kind = ShotRecord::Kind::miscue;
    return;
  }
  // Anything balls_after_strike throws now is a real error, not a miscue:
  // it propagates (simulate_batch rethrows it).
  const std::vector<SimulationBall> balls = balls_after_strike(s, limited.strike);
  try {
    // The scenario was validated once in simulate_batch.
    const SimulationResult r = simulate_unchecked(s.table, balls, s.settings);
    out.kind = ShotRecord::Kind::simulated;
    out.events = static_cast<int>(r.events.size());
    for (std::size_t i = 0; i < r.balls.size() && i < out.pocketed.size(); ++i) {
      out.pocketed[i] = r.balls[i].pocketed ? 1 : 0;
      out.final_position[i] = r.balls[i].final_state.position;
    }
  } catch (const SimulationError&) {
    out.kind = ShotRecord::Kind::failure;
  }
}

}  // namespace

LimitedStrike reflect_into_limits(const CueStrike& strike) {
  LimitedStrike out{strike, false, false};
  const double half_pi = 0.5 * std::numbers::pi;
  out.strike.speed = reflect(strike.speed, 0.0, kMaxCueSpeed, out.speed_reflected);
  if (out.strike.speed == 0.0) {  // (0, cap] is open at 0
    out.strike.speed = kMaxCueSpeed * 0x1.0p-52;
    out.speed_reflected = true;
  }
  out.strike.elevation = reflect(strike.elevation, 0.0, half_pi, out.elevation_reflected);
  if (out.strike.elevation == half_pi) {  // [0, pi/2) is open at pi/2
    out.strike.elevation = half_pi - half_pi * 0x1.0p-52;
    out.elevation_reflected = true;
  }
  return out;
}

namespace detail {

BatchResult run_batch(int shots, int threads, std::size_t n, const PlayShot& play) {
  const int block_count = (shots + kBatchBlockShots - 1) / kBatchBlockShots;
  // Finished blocks wait here until every block before them is merged; a
  // worker that runs ahead by more than `window` blocks waits for the merge.
  const int window = 4 * threads + 2;
  std::atomic<int> next_block{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable merged_more;
  int merged = 0;                    // blocks merged into `total` (under mutex)
  std::map<int, Partial> finished;   // blocks done, not yet merged (under mutex)
  Partial total(n);
  int error_shot = INT_MAX;          // lowest failing shot (under mutex)
  std::exception_ptr error;

  const auto work = [&] {
    ShotRecord record;
    record.pocketed.assign(n, 0);
    record.final_position.assign(n, Vec2{});
    Partial part(n);
    while (!stop.load()) {
      // Blocks are taken in increasing order, so when shot k fails every
      // block before k's has been taken and will be finished: the lowest
      // failing shot is found whatever the threads do.
      const int b = next_block.fetch_add(1);
      if (b >= block_count) return;
      const int first = b * kBatchBlockShots, last = std::min(shots, first + kBatchBlockShots);
      {
        std::unique_lock<std::mutex> lock(mutex);
        merged_more.wait(lock, [&] { return b < merged + window || stop.load(); });
        if (stop.load() && first >= error_shot) return;  // only earlier shots can matter now
      }
      part.clear();
      for (int k = first; k < last; ++k) {
        record.kind = ShotRecord::Kind::simulated;
        record.speed_reflected = record.elevation_reflected = false;
        record.events = 0;
        try {
          play(k, record);
        } catch (...) {
          const std::lock_guard<std::mutex> lock(mutex);
          if (k < error_shot) {
            error_shot = k;
            error = std::current_exception();
          }
          stop.store(true);
          merged_more.notify_all();
          return;
        }
        part.add(record);
      }
      const std::lock_guard<std::mutex> lock(mutex);
      if (stop.load()) continue;  // the result is not needed any more
      finished.emplace(b, part);
      bool advanced = false;
      for (auto it = finished.begin(); it != finished.end() && it->first == merged; it = finished.erase(it)) {
        total.merge(it->second);
        ++merged;
        advanced = true;
      }
      if (advanced) merged_more.notify_all();
    }
  };

  // Anything else going wrong in a worker (bad_alloc) is reported too,
  // before any shot's error.
  const auto guarded = [&] {
    try {
      work();
    } catch (...) {
      {
        const std::lock_guard<std::mutex> lock(mutex);
        stop.store(true);
        error_shot = -1;
        error = std::current_exception();
      }
      merged_more.notify_all();
    }
  };
  if (threads <= 1) {
    guarded();
  } else {
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(threads));
    try {
      for (int w = 0; w < threads; ++w) pool.emplace_back(guarded);
    } catch (...) {  // could not start a thread: stop the others, then report
      {
        const std::lock_guard<std::mutex> lock(mutex);
        stop.store(true);
        error_shot = -1;
        error = std::current_exception();
      }
      merged_more.notify_all();
    }
    for (std::thread& t : pool) t.join();
  }
  if (error) std::rethrow_exception(error);

  BatchResult r;
  r.shots = shots;
  r.simulated = total.simulated;
  r.miscues = total.miscues;
  r.failures = total.failures;
  r.speed_reflected = total.speed_reflected;
  r.elevation_reflected = total.elevation_reflected;
  r.events = total.events;
  for (const BallSum& b : total.balls) {
    BallOutcome o;
    o.pocketed_probability = r.simulated > 0 ? b.pocketed / r.simulated : 0.0;
    if (b.stayed > 0.0) {
      o.mean_position = b.mean;
      o.position_std = {std::sqrt(b.m2.x / b.stayed), std::sqrt(b.m2.y / b.stayed)};
    }
    r.balls.push_back(o);
  }
  return r;
}

}  // namespace detail

BatchResult simulate_batch(const Scenario& s, const BatchOptions& options) {
  if (options.shots < 1 || options.shots > kMaxBatchShots)
    throw InvalidArgument("shots", static_cast<double>(options.shots), "[1, " + format_number(kMaxBatchShots) + "]",
                          "number of shots");
  if (options.threads < 1 || options.threads > kMaxBatchThreads)
    throw InvalidArgument("threads", static_cast<double>(options.threads),
                          "[1, " + std::to_string(kMaxBatchThreads) + "]", "worker threads");
  if (!s.cue) throw InvalidArgument("cue", "the scenario has no cue strike to repeat");
  validate_simulation_input(s.table, s.balls, s.settings);  // once; each shot then runs unchecked
  validate(s.noise);
  // The nominal strike must be one a single run accepts.
  validate(resolved_strike(s, s.cue->strike), s.settings.parameters.ball, s.cue_parameters);

  const auto start = std::chrono::steady_clock::now();
  const BatchContext context{s, options.seed};
  BatchResult r = detail::run_batch(options.shots, options.threads, s.balls.size(),
                                    [&](int shot, ShotRecord& record) { play_shot(context, shot, record); });
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.shots_per_second = r.seconds > 0.0 ? options.shots / r.seconds : 0.0;
  for (std::size_t i = 0; i < r.balls.size(); ++i) r.balls[i].id = s.balls[i].id;
  return r;
}

}  // namespace cueball
