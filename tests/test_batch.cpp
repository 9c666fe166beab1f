// Tests of noisy batches (src/simulation/batch.cpp): determinism across thread counts,
// the reduction against a plain two-pass computation, errors from the
// workers, memory that does not grow with the number of shots, and the
// reflection of noisy strikes at their limits. (The first batch tests live in
// tests/test_simulator.cpp.)
#include "cueball/io/scenario_json.hpp"
#include "cueball/simulation/batch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <span>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cueball/core/errors.hpp"
#include "cueball/simulation/scenario.hpp"

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
  const int shots = 1000;  // 15 full blocks of 63 and one of 55
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

// A batch's blocks are what its threads share: a small batch is cut into
// kBatchBlocks of them (200 shots in 64-shot blocks left one of two threads
// 128 shots and the other 72), a large one into blocks of kBatchBlockShots,
// and a block never falls below kBatchMinBlockShots.
TEST(BatchReduction, ASmallBatchIsCutIntoBlocksForItsThreads) {
  EXPECT_EQ(batch_block_shots(1), kBatchMinBlockShots);
  EXPECT_EQ(batch_block_shots(64), 4);
  EXPECT_EQ(batch_block_shots(200), 13);  // 16 blocks, the last of 5
  EXPECT_EQ(batch_block_shots(1024), kBatchBlockShots);
  EXPECT_EQ(batch_block_shots(kMaxBatchShots), kBatchBlockShots);
  for (int shots = 1; shots <= 5000; ++shots) {
    const int block = batch_block_shots(shots);
    const int blocks = (shots + block - 1) / block;
    ASSERT_GE(block, kBatchMinBlockShots) << shots;
    ASSERT_LE(block, kBatchBlockShots) << shots;
    if (shots >= kBatchBlocks * kBatchMinBlockShots && shots <= kBatchBlocks * kBatchBlockShots) {
      ASSERT_LE(blocks, kBatchBlocks) << shots;
      ASSERT_GE(blocks, 13) << shots;  // ceil(65 / 5): the fewest
    } else if (shots > kBatchBlocks * kBatchBlockShots) {
      ASSERT_EQ(block, kBatchBlockShots) << shots;
    }
  }
}

TEST(BatchReduction, BitIdenticalForAnyNumberOfThreads) {
  for (int shots : {1, 5, 63, 64, 65, 200, 1000, 1025, 5000}) {
    const BatchResult one = detail::run_batch(shots, 1, kSyntheticBalls, synthetic_shot);
    for (int threads : {2, 3, 4, 8, 32}) {
      expect_identical(one, detail::run_batch(shots, threads, kSyntheticBalls, synthetic_shot),
                       std::to_string(shots) + " shots, " + std::to_string(threads) + " threads");
    }
  }
}

TEST(Batch, ResultsAreBitIdenticalWithOneTwoAndFourThreads) {
  const Scenario s = default_scenario();
  const BatchResult one = simulate_batch(s, {150, 1, 11});  // 15 blocks of 10
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

// ------------------------------------------------------------------ per-shot outcomes

void expect_same_outcome(const ShotOutcome& a, const ShotOutcome& b, const std::string& what) {
  EXPECT_EQ(a.kind, b.kind) << what;
  EXPECT_EQ(a.speed_reflected, b.speed_reflected) << what;
  EXPECT_EQ(a.elevation_reflected, b.elevation_reflected) << what;
  EXPECT_EQ(a.events, b.events) << what;
  EXPECT_EQ(a.first_contact, b.first_contact) << what;
  EXPECT_EQ(a.pocketed, b.pocketed) << what;
  EXPECT_EQ(a.pocket, b.pocket) << what;
  EXPECT_EQ(a.cushions_before_contact, b.cushions_before_contact) << what;
  EXPECT_EQ(a.cushions, b.cushions) << what;
  ASSERT_EQ(a.final_position.size(), b.final_position.size()) << what;
  // Bit for bit (NaN for a shot not simulated).
  EXPECT_EQ(0, std::memcmp(a.final_position.data(), b.final_position.data(), a.final_position.size() * sizeof(Vec2)))
      << what;
}

// Every array of two results, bit for bit.
void expect_identical(const ManyResult& a, const ManyResult& b, const std::string& what) {
  EXPECT_EQ(a.shots, b.shots) << what;
  EXPECT_EQ(a.balls, b.balls) << what;
  EXPECT_EQ(a.ids, b.ids) << what;
  EXPECT_EQ(a.pocketed, b.pocketed) << what;
  EXPECT_EQ(a.pocket, b.pocket) << what;
  ASSERT_EQ(a.final_position.size(), b.final_position.size()) << what;
  EXPECT_EQ(0, std::memcmp(a.final_position.data(), b.final_position.data(), a.final_position.size() * sizeof(double)))
      << what;
  EXPECT_EQ(a.first_contact, b.first_contact) << what;
  EXPECT_EQ(a.cushions_before_contact, b.cushions_before_contact) << what;
  EXPECT_EQ(a.cushions, b.cushions) << what;
  EXPECT_EQ(a.events, b.events) << what;
  EXPECT_EQ(a.miscue, b.miscue) << what;
  EXPECT_EQ(a.failure, b.failure) << what;
  EXPECT_EQ(a.speed_reflected, b.speed_reflected) << what;
  EXPECT_EQ(a.elevation_reflected, b.elevation_reflected) << what;
}

// N varied actions around the break: speeds 2-10 m/s, aims across the rack,
// some elevation, side and height.
std::vector<ShotAction> varied_actions(int n) {
  std::vector<ShotAction> a;
  for (int k = 0; k < n; ++k) {
    const auto u = [&](int i) { return unit(static_cast<std::uint64_t>(16 * k + i)); };
    a.push_back({2.0 + 8.0 * u(0), -8.0 + 16.0 * u(1), 10.0 * u(2), -0.3 + 0.6 * u(3), -0.3 + 0.6 * u(4)});
  }
  return a;
}

// The scenario `s` with its strike replaced by `action` (aimed, not targeted).
Scenario with_action(Scenario s, const ShotAction& action) {
  s.cue->target.reset();
  s.cue->strike = to_strike(action, s.settings.parameters.ball.radius);
  return s;
}

TEST(ManyOutcomes, EachShotIsTheSingleRunOfItsAction) {
  const Scenario s = default_scenario();
  const std::vector<ShotAction> actions = varied_actions(12);
  const ManyResult many = simulate_many(s, actions, {}, {});
  ASSERT_EQ(many.shots, 12);
  ASSERT_EQ(many.balls, 10);
  for (std::size_t j = 0; j < s.balls.size(); ++j) EXPECT_EQ(many.ids[j], s.balls[j].id) << j;  // the scenario's order
  int contacts = 0, pocketed = 0;
  for (int k = 0; k < many.shots; ++k) {
    const SimulationResult r = run_scenario(with_action(s, actions[static_cast<std::size_t>(k)]));
    ShotOutcome single;
    outcome_from_result(r, 0, single);
    EXPECT_EQ(single.events, static_cast<int>(r.events.size()) - 1);  // the cue strike not counted
    expect_same_outcome(many.outcome(k), single, "shot " + std::to_string(k));
    contacts += single.first_contact >= 0 ? 1 : 0;
    for (char p : single.pocketed) pocketed += p;
  }
  // The actions are varied enough to exercise the fields.
  EXPECT_GT(contacts, 3);
  EXPECT_GT(pocketed, 0);
}

TEST(ManyOutcomes, BitIdenticalWithOneTwoAndFourThreads) {
  Scenario s = default_scenario();
  s.noise.height_offset = 0.3 * s.settings.parameters.ball.radius;  // some miscues
  s.noise.elevation = 0.02;                                         // some reflected elevations
  const std::vector<ShotAction> actions = varied_actions(150);      // two full blocks and a partial one
  for (bool noise : {false, true}) {
    const ManyResult one = simulate_many(s, actions, {}, {1, 9, noise});
    if (noise) {
      EXPECT_GT(std::count(one.miscue.begin(), one.miscue.end(), 1), 0);
      EXPECT_GT(std::count(one.elevation_reflected.begin(), one.elevation_reflected.end(), 1), 0);
    } else {
      EXPECT_EQ(std::count(one.miscue.begin(), one.miscue.end(), 1), 0);
    }
    for (int threads : {2, 4})
      expect_identical(one, simulate_many(s, actions, {}, {threads, 9, noise}),
                       std::to_string(threads) + " threads, noise " + std::to_string(noise));
  }
}

// Cue ball 0 and object ball 5 on the pool table (2.54 x 1.27 m).
Scenario two_balls() {
  return scenario_from_json(R"({"table": "pool_9ft",
      "balls": [{"id": 0, "position": [0.5, 0.5]}, {"id": 5, "position": [2.0, 0.5]}],
      "cue": {"ball": 0, "aim_deg": 0, "speed": 2.0}})");
}

// A mask of the default rack (10 balls, the cue ball first) for each of
// `shots` shots: about a third of the object balls absent, the cue ball
// always present.
std::vector<std::uint8_t> varied_mask(std::size_t shots, std::size_t balls) {
  std::vector<std::uint8_t> present(shots * balls, 1);
  for (std::size_t k = 0; k < shots; ++k)
    for (std::size_t j = 1; j < balls; ++j) present[k * balls + j] = unit(1000 + k * balls + j) < 0.35 ? 0 : 1;
  return present;
}

TEST(ManyOutcomes, MaskedLayoutsAreBitIdenticalWithOneTwoAndFourThreads) {
  Scenario s = default_scenario();
  s.noise.height_offset = 0.3 * s.settings.parameters.ball.radius;  // some miscues
  const std::vector<ShotAction> actions = varied_actions(150);
  const std::vector<std::uint8_t> present = varied_mask(actions.size(), s.balls.size());
  // The rack's positions in every row, NaN where the ball is absent (ignored there).
  std::vector<double> layouts;
  for (std::size_t k = 0; k < actions.size(); ++k)
    for (std::size_t j = 0; j < s.balls.size(); ++j) {
      const bool on = present[k * s.balls.size() + j] != 0;
      layouts.push_back(on ? s.balls[j].state.position.x : std::nan(""));
      layouts.push_back(on ? s.balls[j].state.position.y : std::nan(""));
    }
  for (bool noise : {false, true}) {
    const ManyResult one = simulate_many(s, actions, layouts, {1, 9, noise}, present);
    EXPECT_EQ(one.present, present);
    for (int threads : {2, 4})
      expect_identical(one, simulate_many(s, actions, layouts, {threads, 9, noise}, present),
                       std::to_string(threads) + " threads, noise " + std::to_string(noise));
  }
}

TEST(ManyOutcomes, AnAbsentBallIsNotOnTheTable) {
  // Ball 9 sits between the cue ball and ball 5: present, the cue ball hits
  // it first; absent, the shot is that of the table without it.
  const Scenario three = scenario_from_json(R"({"table": "pool_9ft",
      "balls": [{"id": 0, "position": [0.5, 0.5]}, {"id": 9, "position": [1.2, 0.5]}, {"id": 5, "position": [2.0, 0.5]}],
      "cue": {"ball": 0, "aim_deg": 0, "speed": 2.0}})");
  const std::vector<ShotAction> actions(3, ShotAction{2.0, 0.0, 0.0, 0.1, -0.2});
  const std::vector<std::uint8_t> present{1, 1, 1,  1, 0, 1,  1, 0, 0};
  const ManyResult r = simulate_many(three, actions, {}, {}, present);
  EXPECT_EQ(r.present, present);
  EXPECT_EQ(r.first_contact[0], 9);
  EXPECT_EQ(r.first_contact[1], 5);
  EXPECT_EQ(r.first_contact[2], -1);
  // Shot 1 is the single run of the table without ball 9, column for column.
  Scenario without = with_action(three, actions[1]);
  without.balls.erase(without.balls.begin() + 1);
  ShotOutcome single;
  outcome_from_result(run_scenario(without), 0, single);
  const ShotOutcome masked = r.outcome(1);
  EXPECT_EQ(masked.kind, ShotOutcome::Kind::simulated);
  EXPECT_EQ(masked.events, single.events);
  EXPECT_EQ(masked.first_contact, single.first_contact);
  for (const auto& [column, i] : std::vector<std::pair<std::size_t, std::size_t>>{{0, 0}, {2, 1}}) {
    EXPECT_EQ(masked.pocketed[column], single.pocketed[i]) << column;
    EXPECT_EQ(masked.pocket[column], single.pocket[i]) << column;
    EXPECT_EQ(masked.final_position[column], single.final_position[i]) << column;
    EXPECT_EQ(masked.cushions[column], single.cushions[i]) << column;
    EXPECT_EQ(masked.cushions_before_contact[column], single.cushions_before_contact[i]) << column;
  }
  // The absent ball's columns: not on the table.
  for (int k : {1, 2}) {
    const ShotOutcome o = r.outcome(k);
    EXPECT_EQ(o.pocketed[1], 0) << k;
    EXPECT_EQ(o.pocket[1], -1) << k;
    EXPECT_TRUE(std::isnan(o.final_position[1].x) && std::isnan(o.final_position[1].y)) << k;
    EXPECT_EQ(o.cushions[1], 0) << k;
  }
  // A full mask is the same as no mask, bit for bit.
  const std::vector<std::uint8_t> all(9, 1);
  expect_identical(simulate_many(three, actions, {}, {}), simulate_many(three, actions, {}, {}, all), "all present");
  // An absent ball's layout position is ignored: NaN, or on top of another ball.
  const std::vector<double> layouts{0.5, 0.5, 1.2, 0.5, 2.0, 0.5,
                                    0.5, 0.5, std::nan(""), 0.0, 2.0, 0.5,
                                    0.5, 0.5, 0.5, 0.5, 9.0, 9.0};
  expect_identical(r, simulate_many(three, actions, layouts, {}, present), "ignored positions");
}

TEST(ManyOutcomes, ANominalMiscueIsThatShotsOutcome) {
  const Scenario s = two_balls();
  // Shot 1 asks for side 0.4 and height 0.4: 0.57 R, beyond the 0.5 R limit.
  const std::vector<ShotAction> actions{{2.0, 0.0, 0.0, 0.0, 0.0}, {2.0, 0.0, 0.0, 0.4, 0.4}, {2.0, 0.0, 0.0, 0.3, 0.4}};
  const ManyResult r = simulate_many(s, actions, {}, {});
  EXPECT_EQ(r.miscue, (std::vector<std::uint8_t>{0, 1, 0}));  // (0.3, 0.4) is exactly on the limit: a stroke
  const ShotOutcome miscue = r.outcome(1);
  EXPECT_EQ(miscue.kind, ShotOutcome::Kind::miscue);
  EXPECT_EQ(miscue.events, 0);
  EXPECT_EQ(miscue.first_contact, -1);
  EXPECT_TRUE(std::isnan(miscue.final_position[0].x));
  EXPECT_EQ(r.present, (std::vector<std::uint8_t>(6, 1)));  // the balls are still there
  // The other shots are their single runs, as without the miscue beside them.
  for (std::size_t k : {0u, 2u}) {
    ShotOutcome single;
    outcome_from_result(run_scenario(with_action(s, actions[k])), 0, single);
    expect_same_outcome(r.outcome(static_cast<int>(k)), single, std::to_string(k));
  }
  // With noise the offset actually struck decides: copies of a nominal just
  // beyond the limit are some miscues, some strokes.
  Scenario noisy = s;
  noisy.noise.side_offset = 0.05 * s.settings.parameters.ball.radius;
  noisy.noise.height_offset = 0.05 * s.settings.parameters.ball.radius;
  const std::vector<ShotAction> beyond(200, ShotAction{2.0, 0.0, 0.0, 0.36, 0.36});  // 0.509 R
  const ManyResult n = simulate_many(noisy, beyond, {}, {2, 3, true});
  const auto miscues = std::count(n.miscue.begin(), n.miscue.end(), 1);
  EXPECT_GT(miscues, 0);
  EXPECT_LT(miscues, 200);
  // A miscue row is the noisy offset beyond the limit, the others within it.
  const BallParameters& ball = s.settings.parameters.ball;
  for (std::size_t k = 0; k < beyond.size(); ++k) {
    const CueStrike played = with_noise(to_strike(beyond[k], ball.radius), noisy.noise, shot_normals(3, k));
    EXPECT_EQ(n.miscue[k] != 0, !cue_tip_offset_ok(played, ball)) << k;
  }
}

TEST(ManyOutcomes, BadMasksAreNamed) {
  const Scenario s = two_balls();
  const std::vector<ShotAction> actions(4, ShotAction{2.0, 0.0, 0.0, 0.0, 0.0});
  const auto error = [&](std::vector<std::uint8_t> present, std::vector<double> layouts = {}, std::uint64_t first = 0) {
    ManyOptions o;
    o.first_shot = first;
    try {
      simulate_many(s, actions, layouts, o, present);
    } catch (const InvalidArgument& e) {
      return std::string(e.field()) + " | " + e.what();
    }
    return std::string("accepted");
  };
  std::vector<std::uint8_t> ok(8, 1);
  EXPECT_EQ(error(ok), "accepted");
  const std::string size = error(std::vector<std::uint8_t>(7, 1));
  EXPECT_EQ(size.rfind("present | ", 0), 0u) << size;
  EXPECT_NE(size.find("8 (shots 4 x balls 2)"), std::string::npos) << size;
  std::vector<std::uint8_t> no_cue = ok;
  no_cue[2 * 2] = 0;  // shot 2's cue ball
  const std::string cue = error(no_cue, {}, 100);
  EXPECT_EQ(cue.rfind("present[102][0] | present[102][0] is false: the cue ball (id 0) must be on the table", 0), 0u)
      << cue;
  // A present ball's layout is still checked.
  std::vector<double> layouts{0.5, 0.5, 2.0, 0.5, 0.5, 0.5, 2.0, 0.5, 0.5, 0.5, 2.0, 0.5, 0.5, 0.5, 2.7, 0.5};
  EXPECT_EQ(error(ok, layouts).rfind("layouts[3][1] | ", 0), 0u);
  std::vector<std::uint8_t> without_5 = ok;
  without_5[3 * 2 + 1] = 0;
  EXPECT_EQ(error(without_5, layouts), "accepted");
}

TEST(ManyOutcomes, ChunksWithTheirFirstShotAreTheWholeStudy) {
  Scenario s = default_scenario();
  s.noise.height_offset = 0.3 * s.settings.parameters.ball.radius;  // some miscues
  const std::vector<ShotAction> actions = varied_actions(130);
  const ManyResult whole = simulate_many(s, actions, {}, {2, 4, true});
  // Rows 0-49, 50-76 and 77-129 run apart, each told where it starts.
  const std::vector<std::pair<std::size_t, std::size_t>> chunks{{0, 50}, {50, 77}, {77, 130}};
  for (const auto& [first, last] : chunks) {
    const std::span<const ShotAction> part(actions.data() + first, last - first);
    ManyOptions o{1, 4, true};
    o.first_shot = first;
    const ManyResult chunk = simulate_many(s, part, {}, o);
    for (std::size_t k = first; k < last; ++k)
      expect_same_outcome(chunk.outcome(static_cast<int>(k - first)), whole.outcome(static_cast<int>(k)), std::to_string(k));
  }
  // Without its offset, a later chunk draws the first chunk's noise: not the same shots.
  const ManyResult unshifted = simulate_many(s, std::span<const ShotAction>(actions.data() + 77, 53), {}, {1, 4, true});
  const auto row = static_cast<std::size_t>(whole.balls) * 2;  // the cue ball's x in row k is at k * row
  int differ = 0;
  for (std::size_t k = 0; k < 53; ++k) differ += unshifted.final_position[k * row] != whole.final_position[(77 + k) * row];
  EXPECT_GT(differ, 0);
  // Errors name the row of the whole study.
  std::vector<ShotAction> bad(actions.begin() + 50, actions.begin() + 77);
  bad[3].speed = 0.0;
  ManyOptions o{1, 4, true};
  o.first_shot = 50;
  try {
    simulate_many(s, bad, {}, o);
    ADD_FAILURE() << "accepted a zero speed";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.field()), "actions[53].speed");
  }
  o.first_shot = kMaxFirstShot + 1;
  EXPECT_THROW(simulate_many(s, actions, {}, o), InvalidArgument);
}

TEST(ManyOutcomes, NoisyCopiesOfOneActionAreTheBatchsShots) {
  // An aimed (not targeted) strike: the action is exactly the scenario's.
  const Scenario s = scenario_from_json(R"({"table": "pool_9ft",
      "balls": [{"id": 0, "position": [1.1, 0.7]}, {"id": 1, "position": [2.05, 0.95]}, {"id": 9, "position": [0.8, 1.0]}],
      "cue": {"ball": 0, "aim_deg": 13.587, "speed": 2.5, "height": -0.2},
      "noise": {"speed": 0.05, "aim_deg": 0.25, "side": 0.02, "height": 0.3}})");
  const int shots = 200;
  std::vector<ShotOutcome> streamed;
  const BatchResult batch = simulate_batch(s, {shots, 2, 5}, [&](int shot, const ShotOutcome& outcome) {
    EXPECT_EQ(shot, static_cast<int>(streamed.size()));  // in shot order
    streamed.push_back(outcome);
  });
  ASSERT_EQ(static_cast<int>(streamed.size()), shots);
  const std::vector<ShotAction> same(shots, ShotAction{2.5, 13.587, 0.0, 0.0, -0.2});
  const ManyResult many = simulate_many(s, same, {}, {2, 5, true});
  for (int k = 0; k < shots; ++k) expect_same_outcome(many.outcome(k), streamed[static_cast<std::size_t>(k)], std::to_string(k));
  // And the batch's aggregates are those of the streamed outcomes.
  int simulated = 0, miscues = 0, potted = 0;
  long long events = 0;
  for (const ShotOutcome& x : streamed) {
    miscues += x.kind == ShotOutcome::Kind::miscue ? 1 : 0;
    if (x.kind != ShotOutcome::Kind::simulated) continue;
    ++simulated;
    events += x.events;
    potted += x.pocketed[1];
  }
  EXPECT_GT(miscues, 0);
  EXPECT_EQ(batch.miscues, miscues);
  EXPECT_EQ(batch.simulated, simulated);
  EXPECT_EQ(batch.events, events);
  EXPECT_DOUBLE_EQ(batch.balls[1].pocketed_probability, static_cast<double>(potted) / simulated);
}

TEST(ManyOutcomes, FirstContactAndCushionsOnHandMadeShots) {
  const Scenario s = two_balls();
  const std::vector<ShotAction> actions{
      {2.0, 0.0, 0.0, 0.0, 0.0},     // 0: straight at ball 5 (scenario layout)
      {2.0, -90.0, 0.0, 0.0, 0.0},   // 1: down into the near rail, back up into ball 5 above it
      {1.0, 90.0, 0.0, 0.0, 0.0},    // 2: up into the far rail, no ball in the way
  };
  const std::vector<double> layouts{
      0.5, 0.5, 2.0, 0.5,   // shot 0: as the scenario
      1.0, 0.3, 1.0, 0.9,   // shot 1: ball 5 straight above the cue ball
      0.5, 0.5, 2.0, 0.5,   // shot 2
  };
  const ManyResult r = simulate_many(s, actions, layouts, {});
  const ShotOutcome straight = r.outcome(0), rail_first = r.outcome(1), none = r.outcome(2);
  EXPECT_EQ(straight.first_contact, 5);
  EXPECT_EQ(straight.cushions_before_contact, (std::vector<int>{0, 0}));
  EXPECT_GE(straight.cushions[1], 1);  // ball 5 goes on into the right-hand rail
  EXPECT_EQ(rail_first.first_contact, 5);
  EXPECT_EQ(rail_first.cushions_before_contact, (std::vector<int>{1, 0}));
  EXPECT_GE(rail_first.cushions[0], 1);
  EXPECT_GE(rail_first.cushions[1], 1);  // ball 5 driven into the far rail
  EXPECT_EQ(none.first_contact, -1);
  EXPECT_GE(none.cushions[0], 1);
  EXPECT_EQ(none.cushions_before_contact, none.cushions);  // no contact: every cushion is before it
  EXPECT_EQ(none.cushions[1], 0);
  // The layouts were applied: shot 1 is the single run from its layout.
  Scenario moved = with_action(s, actions[1]);
  moved.balls[0].state.position = {1.0, 0.3};
  moved.balls[1].state.position = {1.0, 0.9};
  ShotOutcome single;
  outcome_from_result(run_scenario(moved), 0, single);
  expect_same_outcome(rail_first, single, "layout 1");
  // Not the scenario's layout: there the same action misses ball 5.
  EXPECT_EQ(simulate_many(s, std::span(actions).subspan(1, 1), {}, {}).first_contact[0], -1);
  // Row-major positions: shot 2's ball 5 never moved.
  EXPECT_EQ(r.final_position[(2 * 2 + 1) * 2], 2.0);
  EXPECT_EQ(r.final_position[(2 * 2 + 1) * 2 + 1], 0.5);
}

TEST(ManyOutcomes, BadActionsAndLayoutsAreNamed) {
  const Scenario s = two_balls();
  const auto error = [&](std::vector<ShotAction> actions, std::vector<double> layouts, ManyOptions o = {}) {
    try {
      simulate_many(s, actions, layouts, o);
    } catch (const InvalidArgument& e) {
      return std::string(e.field()) + " | " + e.what();
    }
    return std::string("accepted");
  };
  std::vector<ShotAction> ok(20, ShotAction{2.0, 0.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(error(ok, {}), "accepted");
  const auto bad = [&](std::size_t k, auto set) {
    std::vector<ShotAction> a = ok;
    set(a[k]);
    return error(a, {});
  };
  const std::string speed = bad(17, [](ShotAction& a) { a.speed = 0.0; });
  EXPECT_EQ(speed.rfind("actions[17].speed | ", 0), 0u) << speed;
  EXPECT_NE(speed.find("[1e-06, 12]"), std::string::npos) << speed;
  EXPECT_EQ(bad(3, [](ShotAction& a) { a.speed = 12.5; }).rfind("actions[3].speed | ", 0), 0u);
  EXPECT_EQ(bad(4, [](ShotAction& a) { a.aim_deg = std::nan(""); }).rfind("actions[4].aim_deg | ", 0), 0u);
  const std::string elevation = bad(5, [](ShotAction& a) { a.elevation_deg = 90.0; });
  EXPECT_EQ(elevation.rfind("actions[5].elevation_deg | ", 0), 0u) << elevation;
  EXPECT_NE(elevation.find("[0, 89]"), std::string::npos) << elevation;
  EXPECT_EQ(bad(6, [](ShotAction& a) { a.side = -0.6; }).rfind("actions[6].side | ", 0), 0u);
  EXPECT_EQ(bad(7, [](ShotAction& a) { a.height = 0.6; }).rfind("actions[7].height | ", 0), 0u);
  // Side and height each in range but beyond the miscue limit together: an outcome, not an error.
  EXPECT_EQ(bad(8, [](ShotAction& a) { a.side = a.height = 0.4; }), "accepted");
  EXPECT_EQ(error({}, {}).rfind("actions | ", 0), 0u);
  EXPECT_EQ(error(ok, {}, {0, 0, false}).rfind("threads | ", 0), 0u);
  // Layouts: 20 shots x 2 balls x 2.
  std::vector<double> layouts;
  for (int k = 0; k < 20; ++k) layouts.insert(layouts.end(), {0.5, 0.5, 2.0, 0.5});
  EXPECT_EQ(error(ok, layouts), "accepted");
  const std::string size = error(ok, std::vector<double>(layouts.begin(), layouts.end() - 1));
  EXPECT_EQ(size.rfind("layouts | ", 0), 0u) << size;
  EXPECT_NE(size.find("80"), std::string::npos) << size;
  std::vector<double> off = layouts;
  off[3 * 4 + 2] = 2.7;  // layouts[3][1] beyond the right-hand rail
  const std::string off_table = error(ok, off);
  EXPECT_EQ(off_table.rfind("layouts[3][1] | layouts[3][1] = (2.7, 0.5) m is off the playing surface", 0), 0u)
      << off_table;
  std::vector<double> overlap = layouts;
  overlap[9 * 4 + 2] = 0.55;  // layouts[9][1] 5 cm from ball 0 (2R = 5.715 cm)
  const std::string overlapping = error(ok, overlap);
  EXPECT_EQ(overlapping.rfind("layouts[9][1] | layouts[9][1] overlaps layouts[9][0]", 0), 0u) << overlapping;
  std::vector<double> nan = layouts;
  nan[11 * 4] = std::nan("");
  EXPECT_EQ(error(ok, nan).rfind("layouts[11][0] | ", 0), 0u);
  // Touching is allowed.
  std::vector<double> touching = layouts;
  touching[2] = 0.5 + 2 * s.settings.parameters.ball.radius;
  EXPECT_EQ(error(ok, touching), "accepted");
}

TEST(ManyOutcomes, ResultRowsAreChecked) {
  const ManyResult r = simulate_many(two_balls(), std::vector<ShotAction>{ShotAction{}}, {}, {});
  EXPECT_THROW((void)r.outcome(1), InvalidArgument);
  EXPECT_THROW((void)r.outcome(-1), InvalidArgument);
}

TEST(BatchOutcomes, StreamingDoesNotGrowWithTheShotsAndStopsOnTheSinksError) {
  const Scenario s = scenario_from_json(R"({"table": "pool_9ft", "balls": [{"id": 0, "position": [0.6, 0.6]}],
      "cue": {"ball": 0, "aim_deg": 30, "speed": 1.0}, "noise": {"speed": 0.05, "aim_deg": 1}})");
  long long rows = 0;
  const OutcomeSink count = [&](int, const ShotOutcome& x) { rows += static_cast<long long>(x.cushions.size()); };
  // Up to 4 x 2 + 2 = 10 blocks of 64 outcomes (~170 bytes each for one
  // ball) wait to be merged, ~110 kB, whether the window fills or not
  // depends on the scheduling; storing all 16384 outcomes would be 2.7 MB.
  const long long small = peak_growth([&] { simulate_batch(s, {2048, 2, 1}, count); });
  const long long large = peak_growth([&] { simulate_batch(s, {16384, 2, 1}, count); });
  EXPECT_EQ(rows, 2048 + 16384);
  EXPECT_LT(large, small + 128 * 1024) << small << " -> " << large << " bytes";
  EXPECT_LT(large, 384 * 1024) << large << " bytes";
  const OutcomeSink failing = [](int shot, const ShotOutcome&) {
    if (shot == 100) throw std::runtime_error("disk full");
  };
  for (int threads : {1, 2}) {
    try {
      simulate_batch(s, {1000, threads, 1}, failing);
      ADD_FAILURE() << "expected the sink's error";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "disk full");
    }
  }
}

}  // namespace
}  // namespace cueball
