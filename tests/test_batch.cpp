// Tests of noisy batches (src/batch.cpp): determinism across thread counts,
// the reduction against a plain two-pass computation, errors from the
// workers, memory that does not grow with the number of shots, and the
// reflection of noisy strikes at their limits. (The first batch tests live in
// tests/test_simulator.cpp.)
#include "cueball/batch.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cueball/errors.hpp"
#include "cueball/scenario.hpp"

// ------------------------------------------------------------------ heap accounting
//
// The global operator new/delete of this test program count the bytes live
// on the heap and their peak, so that a test can see how much a batch holds
// at once.
namespace {
std::atomic<long long> g_live{0};
std::atomic<long long> g_peak{0};
constexpr std::size_t kHeader = 16;  // keeps the alignment of malloc

void* counted_new(std::size_t n) {
  void* block = std::malloc(n + kHeader);
  if (block == nullptr) throw std::bad_alloc();
  std::memcpy(block, &n, sizeof n);
  const long long live = g_live.fetch_add(static_cast<long long>(n)) + static_cast<long long>(n);
  long long peak = g_peak.load();
  while (live > peak && !g_peak.compare_exchange_weak(peak, live)) {
  }
  return static_cast<char*>(block) + kHeader;
}

void counted_delete(void* p) noexcept {
  if (p == nullptr) return;
  char* block = static_cast<char*>(p) - kHeader;
  std::size_t n = 0;
  std::memcpy(&n, block, sizeof n);
  g_live.fetch_sub(static_cast<long long>(n));
  std::free(block);
}
}  // namespace

void* operator new(std::size_t n) { return counted_new(n); }
void* operator new[](std::size_t n) { return counted_new(n); }
void operator delete(void* p) noexcept { counted_delete(p); }
void operator delete[](void* p) noexcept { counted_delete(p); }
void operator delete(void* p, std::size_t) noexcept { counted_delete(p); }
void operator delete[](void* p, std::size_t) noexcept { counted_delete(p); }

namespace cueball {
namespace {

using detail::ShotRecord;

// Peak heap growth, in bytes, while f runs.
template <class F>
long long peak_growth(F f) {
  const long long before = g_live.load();
  g_peak.store(before);
  f();
  return g_peak.load() - before;
}

void expect_identical(const BatchResult& a, const BatchResult& b, const std::string& what) {
  EXPECT_EQ(a.shots, b.shots) << what;
  EXPECT_EQ(a.simulated, b.simulated) << what;
  EXPECT_EQ(a.miscues, b.miscues) << what;
  EXPECT_EQ(a.failures, b.failures) << what;
  EXPECT_EQ(a.speed_reflected, b.speed_reflected) << what;
  EXPECT_EQ(a.elevation_reflected, b.elevation_reflected) << what;
  EXPECT_EQ(a.events, b.events) << what;
  ASSERT_EQ(a.balls.size(), b.balls.size()) << what;
  for (std::size_t i = 0; i < a.balls.size(); ++i) {
    // Bit for bit.
    EXPECT_EQ(a.balls[i].id, b.balls[i].id) << what;
    EXPECT_EQ(a.balls[i].pocketed_probability, b.balls[i].pocketed_probability) << what << " ball " << i;
    EXPECT_EQ(a.balls[i].mean_position, b.balls[i].mean_position) << what << " ball " << i;
    EXPECT_EQ(a.balls[i].position_std, b.balls[i].position_std) << what << " ball " << i;
  }
}

// A cheap, reproducible player: shot k's outcome depends on k alone.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}
double unit(std::uint64_t x) { return static_cast<double>(mix(x) >> 11) * 0x1.0p-53; }

constexpr std::size_t kSyntheticBalls = 3;

void synthetic_shot(int shot, ShotRecord& r) {
  const auto k = static_cast<std::uint64_t>(shot);
  r.kind = shot % 11 == 3 ? ShotRecord::Kind::miscue
           : shot % 13 == 5 ? ShotRecord::Kind::failure
                            : ShotRecord::Kind::simulated;
  r.speed_reflected = shot % 3 == 0;
  r.elevation_reflected = shot % 5 == 0;
  r.events = 10 + shot % 7;
  for (std::size_t i = 0; i < kSyntheticBalls; ++i) {
    r.pocketed[i] = unit(4 * k + i) < 0.25 * static_cast<double>(i) ? 1 : 0;
    // Positions far from the origin: a naive sum of squares would lose digits.
    r.final_position[i] = {1000.0 + unit(8 * k + i), 2000.0 + 0.5 * unit(8 * k + 4 + i)};
  }
}

// ------------------------------------------------------------------ reduction

TEST(BatchReduction, MatchesAPlainTwoPassComputation) {
  const int shots = 1000;  // 15 full blocks and a partial one
  const BatchResult r = detail::run_batch(shots, 3, kSyntheticBalls, synthetic_shot);
  // Recompute in the most obvious way.
  ShotRecord rec;
  rec.pocketed.assign(kSyntheticBalls, 0);
  rec.final_position.assign(kSyntheticBalls, Vec2{});
  int simulated = 0, miscues = 0, failures = 0, speed = 0, elevation = 0;
  long long events = 0;
  std::vector<std::vector<Vec2>> stayed(kSyntheticBalls);
  std::vector<int> pocketed(kSyntheticBalls, 0);
  for (int k = 0; k < shots; ++k) {
    synthetic_shot(k, rec);
    speed += rec.speed_reflected;
    elevation += rec.elevation_reflected;
    if (rec.kind == ShotRecord::Kind::miscue) ++miscues;
    if (rec.kind == ShotRecord::Kind::failure) ++failures;
    if (rec.kind != ShotRecord::Kind::simulated) continue;
    ++simulated;
    events += rec.events;
    for (std::size_t i = 0; i < kSyntheticBalls; ++i) {
      if (rec.pocketed[i]) {
        ++pocketed[i];
      } else {
        stayed[i].push_back(rec.final_position[i]);
      }
    }
  }
  EXPECT_EQ(r.shots, shots);
  EXPECT_EQ(r.simulated, simulated);
  EXPECT_EQ(r.miscues, miscues);
  EXPECT_EQ(r.failures, failures);
  EXPECT_EQ(r.speed_reflected, speed);
  EXPECT_EQ(r.elevation_reflected, elevation);
  EXPECT_EQ(r.events, events);
  EXPECT_GT(miscues, 0);
  EXPECT_GT(failures, 0);
  ASSERT_EQ(r.balls.size(), kSyntheticBalls);
  for (std::size_t i = 0; i < kSyntheticBalls; ++i) {
    EXPECT_DOUBLE_EQ(r.balls[i].pocketed_probability, static_cast<double>(pocketed[i]) / simulated);
    Vec2 sum;
    for (Vec2 p : stayed[i]) sum = sum + p;
    const double n = static_cast<double>(stayed[i].size());
    const Vec2 mean = sum / n;
    Vec2 squares;
    for (Vec2 p : stayed[i]) squares = squares + Vec2{(p.x - mean.x) * (p.x - mean.x), (p.y - mean.y) * (p.y - mean.y)};
    EXPECT_NEAR(r.balls[i].mean_position.x, mean.x, 1e-12 * mean.x) << i;
    EXPECT_NEAR(r.balls[i].mean_position.y, mean.y, 1e-12 * mean.y) << i;
    // Uniform on [0, 1) and [0, 0.5): std 0.289 and 0.144.
    EXPECT_NEAR(r.balls[i].position_std.x, std::sqrt(squares.x / n), 1e-9) << i;
    EXPECT_NEAR(r.balls[i].position_std.y, std::sqrt(squares.y / n), 1e-9) << i;
    EXPECT_NEAR(r.balls[i].position_std.x, 1.0 / std::sqrt(12.0), 0.03) << i;
  }
}

TEST(BatchReduction, BitIdenticalForAnyNumberOfThreads) {
  for (int shots : {1, 63, 64, 65, 1000, 5000}) {
    const BatchResult one = detail::run_batch(shots, 1, kSyntheticBalls, synthetic_shot);
    for (int threads : {2, 3, 4, 8, 32}) {
      expect_identical(one, detail::run_batch(shots, threads, kSyntheticBalls, synthetic_shot),
                       std::to_string(shots) + " shots, " + std::to_string(threads) + " threads");
    }
  }
}

TEST(Batch, ResultsAreBitIdenticalWithOneTwoAndFourThreads) {
  const Scenario s = default_scenario();
  const BatchResult one = simulate_batch(s, {150, 1, 11});  // two full blocks and a partial one
  EXPECT_EQ(one.simulated + one.miscues + one.failures, 150);
  EXPECT_GT(one.simulated, 140);
  for (int threads : {2, 4}) expect_identical(one, simulate_batch(s, {150, threads, 11}), std::to_string(threads));
}

// ------------------------------------------------------------------ errors

// Throws for shots 7, 150 and 400; shot 7 is slow, so that with several
// threads the later errors happen first.
void failing_shot(int shot, ShotRecord& r) {
  if (shot == 7) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    throw InvalidArgument("cushions[7].end", "shot 7's error");
  }
  if (shot == 150 || shot == 400) throw InvalidArgument("jaws[0]", "a later shot's error");
  synthetic_shot(shot, r);
}

TEST(BatchErrors, TheLowestShotsErrorWinsWhateverTheThreads) {
  for (int threads : {1, 2, 4}) {
    try {
      detail::run_batch(2000, threads, kSyntheticBalls, failing_shot);
      ADD_FAILURE() << threads << " threads: expected InvalidArgument";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field(), "cushions[7].end") << threads << " threads";
      EXPECT_STREQ(e.what(), "shot 7's error") << threads << " threads";
    }
  }
  // Other exception types come through as they are.
  for (int threads : {1, 2, 4}) {
    EXPECT_THROW(detail::run_batch(500, threads, kSyntheticBalls,
                                   [](int shot, ShotRecord& r) {
                                     if (shot == 321) throw std::out_of_range("shot 321");
                                     synthetic_shot(shot, r);
                                   }),
                 std::out_of_range)
        << threads << " threads";
  }
}

// A table whose first jaw is valid for the table's ball but too high for the
// ball the parameters give: found only when a shot is simulated.
Scenario scenario_with_a_jaw_too_high() {
  Scenario s = default_scenario();
  s.table.jaws[0].contact_height = 0.056;     // in (R, 2R) for the table's R = 0.028575
  s.settings.parameters.ball.radius = 0.0275;  // 2R = 0.055: the cushions' 0.0365 still fits
  return s;
}

TEST(BatchErrors, AWorkersErrorIsTheSingleShotsErrorForOneTwoAndFourThreads) {
  const Scenario s = scenario_with_a_jaw_too_high();
  std::string field, message;
  try {
    run_scenario(s);
    FAIL() << "the single shot should fail";
  } catch (const InvalidArgument& e) {
    field = e.field();
    message = e.what();
  }
  for (int threads : {1, 2, 4}) {
    try {
      simulate_batch(s, {200, threads, 3});
      ADD_FAILURE() << threads << " threads: expected InvalidArgument";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field(), field) << threads << " threads";
      EXPECT_EQ(e.what(), message) << threads << " threads";
    }
  }
}

TEST(BatchErrors, BadOptionsAndStrikesNameTheField) {
  const Scenario s = default_scenario();
  const auto field = [&](BatchOptions o, const Scenario& sc) {
    try {
      simulate_batch(sc, o);
    } catch (const InvalidArgument& e) {
      return std::string(e.field()) + ": " + e.what();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(field({0, 1, 0}, s).rfind("shots: ", 0), 0u);
  const std::string too_many = field({kMaxBatchShots + 1, 1, 0}, s);
  EXPECT_EQ(too_many.rfind("shots: ", 0), 0u) << too_many;
  EXPECT_NE(too_many.find("[1, 100000000]"), std::string::npos) << too_many;
  EXPECT_EQ(field({10, 0, 0}, s).rfind("threads: ", 0), 0u);
  EXPECT_EQ(field({10, kMaxBatchThreads + 1, 0}, s).rfind("threads: ", 0), 0u);
  // A nominal strike a single run would refuse.
  Scenario miscue = s;
  miscue.cue->strike.height_offset = 0.7 * s.settings.parameters.ball.radius;
  EXPECT_EQ(field({10, 1, 0}, miscue).rfind("tip offset: ", 0), 0u) << field({10, 1, 0}, miscue);
}

// ------------------------------------------------------------------ memory

TEST(BatchMemory, DoesNotGrowWithTheNumberOfShots) {
  // The reducer alone: 200 against 200000 shots.
  for (int threads : {1, 2}) {
    const long long small = peak_growth([&] { detail::run_batch(200, threads, kSyntheticBalls, synthetic_shot); });
    const long long large = peak_growth([&] { detail::run_batch(200000, threads, kSyntheticBalls, synthetic_shot); });
    // Storing 56 bytes per shot would be 11 MB.
    EXPECT_LT(large, small + 64 * 1024) << threads << " threads: " << small << " -> " << large << " bytes";
    EXPECT_LT(large, 256 * 1024) << threads << " threads";
  }
  // A whole simulated batch: one ball rolling into a cushion, 256 against
  // 16384 shots.
  const Scenario s = scenario_from_json(R"({"table": "pool_9ft", "balls": [{"id": 0, "position": [0.6, 0.6]}],
      "cue": {"ball": 0, "aim_deg": 30, "speed": 1.0}, "noise": {"speed": 0.05, "aim_deg": 1}})");
  const long long small = peak_growth([&] { simulate_batch(s, {256, 2, 1}); });
  const long long large = peak_growth([&] { simulate_batch(s, {16384, 2, 1}); });
  EXPECT_LT(large, small + 64 * 1024) << small << " -> " << large << " bytes";
}

// ------------------------------------------------------------------ noise at the limits

TEST(BatchNoise, ReflectIntoLimits) {
  const double half_pi = std::numbers::pi / 2;
  const auto speed = [](double v) { return reflect_into_limits(CueStrike{v, 0.0, 0.1, 0.0, 0.0}); };
  EXPECT_EQ(speed(12.5).strike.speed, 11.5);
  EXPECT_TRUE(speed(12.5).speed_reflected);
  EXPECT_EQ(speed(-0.25).strike.speed, 0.25);
  EXPECT_EQ(speed(30.0).strike.speed, 6.0);     // 2 cap - 30 = -6, then -(-6)
  EXPECT_EQ(speed(1000.5).strike.speed, 7.5);   // 1000.5 - 41 * 24 = 16.5, then 24 - 16.5
  EXPECT_EQ(speed(kMaxCueSpeed).strike.speed, kMaxCueSpeed);  // the cap itself is allowed
  EXPECT_FALSE(speed(kMaxCueSpeed).speed_reflected);
  EXPECT_FALSE(speed(7.0).speed_reflected);
  EXPECT_GT(speed(0.0).strike.speed, 0.0);  // (0, cap] is open at 0
  EXPECT_TRUE(speed(0.0).speed_reflected);
  EXPECT_FALSE(speed(12.5).elevation_reflected);
  EXPECT_EQ(speed(12.5).strike.elevation, 0.1);
  const auto elevation = [](double e) { return reflect_into_limits(CueStrike{5.0, 0.3, e, 0.001, -0.002}); };
  EXPECT_EQ(elevation(-0.125).strike.elevation, 0.125);
  EXPECT_TRUE(elevation(-0.125).elevation_reflected);
  EXPECT_FALSE(elevation(-0.125).speed_reflected);
  EXPECT_NEAR(elevation(half_pi + 0.1).strike.elevation, half_pi - 0.1, 1e-15);
  EXPECT_LT(elevation(half_pi).strike.elevation, half_pi);  // [0, pi/2) is open at pi/2
  EXPECT_EQ(elevation(0.0).strike.elevation, 0.0);
  EXPECT_FALSE(elevation(0.0).elevation_reflected);
  // The other fields are untouched.
  const CueStrike out = elevation(-0.125).strike;
  EXPECT_EQ(out.aim, 0.3);
  EXPECT_EQ(out.side_offset, 0.001);
  EXPECT_EQ(out.height_offset, -0.002);
  EXPECT_TRUE(std::isnan(speed(std::numeric_limits<double>::quiet_NaN()).strike.speed));
}

TEST(BatchNoise, ABreakAtTheSpeedCapSimulatesEveryShot) {
  Scenario s = default_scenario();
  s.cue->strike.speed = kMaxCueSpeed;
  s.noise.speed = 0.3;
  const BatchResult r = simulate_batch(s, {128, 2, 5});
  EXPECT_EQ(r.miscues, 0);
  EXPECT_EQ(r.simulated + r.failures, 128);
  EXPECT_EQ(r.failures, 0);
  // About half the draws land above the cap (binomial 128, 1/2: 64 +- 5.7).
  EXPECT_GT(r.speed_reflected, 40);
  EXPECT_LT(r.speed_reflected, 88);
  EXPECT_EQ(r.elevation_reflected, 0);
}

TEST(BatchNoise, ElevationNoiseAroundALevelCueSimulatesEveryShot) {
  Scenario s = default_scenario();
  s.cue->strike.elevation = 0.0;
  s.noise.elevation = 1.0 * std::numbers::pi / 180.0;
  const BatchResult r = simulate_batch(s, {128, 2, 6});
  EXPECT_EQ(r.miscues, 0);
  EXPECT_EQ(r.simulated + r.failures, 128);
  EXPECT_GT(r.elevation_reflected, 40);
  EXPECT_LT(r.elevation_reflected, 88);
  EXPECT_EQ(r.speed_reflected, 0);
}

TEST(BatchNoise, TipOffsetsBeyondTheMiscueLimitAreTheOnlyMiscues) {
  Scenario s = default_scenario();
  const double R = s.settings.parameters.ball.radius;
  s.noise.side_offset = 0.0;
  s.noise.height_offset = 0.5 * R;  // |b| > 0.5 R, a miscue, for |z| > 1: 31.7 % of the shots
  const BatchResult r = simulate_batch(s, {128, 2, 7});
  EXPECT_GT(r.miscues, 20);
  EXPECT_LT(r.miscues, 62);
  EXPECT_EQ(r.simulated + r.miscues + r.failures, 128);
  EXPECT_EQ(r.speed_reflected, 0);
  EXPECT_EQ(r.elevation_reflected, 0);
}

}  // namespace
}  // namespace cueball
