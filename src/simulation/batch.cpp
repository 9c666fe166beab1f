// Batch simulation with execution noise; see batch.hpp.
//
// Sources: SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom
// number generators", OOPSLA 2014) for the per-shot seeds; Box-Muller for the
// normals; Welford's running mean and sum of squared deviations (Welford,
// Technometrics 4(3), 1962) within a block, and the pairwise merge of Chan,
// Golub & LeVeque ("Algorithms for computing the sample variance", The
// American Statistician 37(3), 1983) across blocks.
#include "cueball/simulation/batch.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <climits>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <random>
#include <thread>

#include "cueball/core/errors.hpp"
#include "cueball/core/random.hpp"
#include "cueball/simulation/shot_facts.hpp"

namespace cueball {

namespace {

// Five standard normal draws (Box-Muller, RandomStream::normal_pair).
std::array<double, 5> standard_normals(std::uint64_t seed) {
  RandomStream rng(seed);
  const Vec2 a = rng.normal_pair(), b = rng.normal_pair(), c = rng.normal_pair();
  return {a.x, a.y, b.x, b.y, c.x};
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
  const CueStrike noisy = with_noise(s.cue->strike, s.noise, shot_normals(c.seed, static_cast<std::uint64_t>(shot)));
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
    outcome_from_result(r, s.cue->ball, out);
  } catch (const SimulationError&) {
    out.kind = ShotRecord::Kind::failure;
  }
}

}  // namespace

std::array<double, 5> shot_normals(std::uint64_t seed, std::uint64_t shot) {
  return standard_normals(splitmix64(seed ^ splitmix64(shot)));
}

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

BatchResult run_batch(int shots, int threads, std::size_t n, const PlayShot& play, const OutcomeSink& sink) {
  // A finished block: its reduction and, for the sink, its shots' outcomes.
  struct Finished {
    Partial part;
    std::vector<ShotOutcome> outcomes;
  };
  const int block = batch_block_shots(shots);
  const int block_count = (shots + block - 1) / block;
  // Finished blocks wait here until every block before them is merged; a
  // worker that runs ahead by more than `window` blocks waits for the merge.
  const int window = 4 * threads + 2;
  std::atomic<int> next_block{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::condition_variable merged_more;
  int merged = 0;                    // blocks merged into `total` (under mutex)
  std::map<int, Finished> finished;  // blocks done, not yet merged (under mutex)
  Partial total(n);
  int error_shot = INT_MAX;          // lowest failing shot (under mutex)
  std::exception_ptr error;

  // Block b into the total and its outcomes to the sink (under mutex, in block order).
  const auto merge_block = [&](int b, const Partial& part, const std::vector<ShotOutcome>& outcomes) {
    total.merge(part);
    if (sink)
      for (std::size_t i = 0; i < outcomes.size(); ++i) sink(b * block + static_cast<int>(i), outcomes[i]);
    ++merged;
  };

  const auto work = [&] {
    ShotRecord record;
    Partial part(n);
    std::vector<ShotOutcome> outcomes;  // the block's, when there is a sink
    while (!stop.load()) {
      // Blocks are taken in increasing order, so when shot k fails every
      // block before k's has been taken and will be finished: the lowest
      // failing shot is found whatever the threads do.
      const int b = next_block.fetch_add(1);
      if (b >= block_count) return;
      const int first = b * block, last = std::min(shots, first + block);
      {
        std::unique_lock<std::mutex> lock(mutex);
        merged_more.wait(lock, [&] { return b < merged + window || stop.load(); });
        if (stop.load() && first >= error_shot) return;  // only earlier shots can matter now
      }
      part.clear();
      if (sink) outcomes.resize(static_cast<std::size_t>(last - first));
      for (int k = first; k < last; ++k) {
        record.reset(n);
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
        if (sink) outcomes[static_cast<std::size_t>(k - first)] = record;
      }
      const std::lock_guard<std::mutex> lock(mutex);
      if (stop.load()) continue;  // the result is not needed any more
      bool advanced = false;
      if (b == merged) {  // next in order (always so on one thread): merged at once, nothing copied
        merge_block(b, part, outcomes);
        advanced = true;
      } else {
        finished.emplace(b, Finished{part, sink ? std::move(outcomes) : std::vector<ShotOutcome>{}});
        outcomes.clear();
      }
      for (auto it = finished.begin(); it != finished.end() && it->first == merged; it = finished.erase(it)) {
        merge_block(it->first, it->second.part, it->second.outcomes);
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

BatchResult simulate_batch(const Scenario& s, const BatchOptions& options, const OutcomeSink& on_outcome) {
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
                                    [&](int shot, ShotRecord& record) { play_shot(context, shot, record); },
                                    on_outcome);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.shots_per_second = r.seconds > 0.0 ? options.shots / r.seconds : 0.0;
  for (std::size_t i = 0; i < r.balls.size(); ++i) r.balls[i].id = s.balls[i].id;
  return r;
}

// ------------------------------------------------------------------ outcomes

void ShotOutcome::reset(std::size_t balls) {
  kind = Kind::simulated;
  speed_reflected = elevation_reflected = false;
  events = 0;
  first_contact = -1;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  pocketed.assign(balls, 0);
  pocket.assign(balls, -1);
  final_position.assign(balls, Vec2{nan, nan});
  cushions_before_contact.assign(balls, 0);
  cushions.assign(balls, 0);
}

void outcome_from_result(const SimulationResult& r, int cue_ball, ShotOutcome& out) {
  const std::size_t n = r.balls.size();
  out.kind = ShotOutcome::Kind::simulated;
  out.pocketed.assign(n, 0);
  out.pocket.assign(n, -1);
  out.final_position.resize(n);
  out.cushions_before_contact.assign(n, 0);
  out.cushions.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const BallTrajectory& b = r.balls[i];
    out.pocketed[i] = b.pocketed ? 1 : 0;
    out.pocket[i] = b.pocketed ? b.pocket : -1;
    out.final_position[i] = b.final_state.position;
  }
  thread_local ShotFacts facts;  // each worker's, its lists' storage reused shot after shot
  shot_facts_into(r, cue_ball, facts);
  out.first_contact = facts.first_contact;
  for (const CushionHit& c : facts.cushions) {
    const auto i = static_cast<std::size_t>(
        std::find_if(r.balls.begin(), r.balls.end(), [&](const BallTrajectory& b) { return b.id == c.ball; }) -
        r.balls.begin());
    if (i == n) continue;
    ++out.cushions[i];
    if (!c.after_first_contact) ++out.cushions_before_contact[i];
  }
  out.events = static_cast<int>(std::count_if(r.events.begin(), r.events.end(),
                                               [](const Event& e) { return e.type != EventType::cue_strike; }));
}

// ------------------------------------------------------------------ many different shots

CueStrike to_strike(const ShotAction& a, double radius) {
  constexpr double degree = std::numbers::pi / 180.0;
  return CueStrike{a.speed, a.aim_deg * degree, a.elevation_deg * degree, a.side * radius, a.height * radius};
}

ShotOutcome ManyResult::outcome(int shot) const {
  if (shot < 0 || shot >= shots)
    throw InvalidArgument("shot", static_cast<double>(shot), "[0, " + std::to_string(shots - 1) + "]", "row of the result");
  const auto n = static_cast<std::size_t>(balls);
  const auto k = static_cast<std::size_t>(shot);
  ShotOutcome o;
  o.reset(n);
  o.kind = failure[k] ? ShotOutcome::Kind::failure
           : miscue[k] ? ShotOutcome::Kind::miscue
                       : ShotOutcome::Kind::simulated;
  o.speed_reflected = speed_reflected[k] != 0;
  o.elevation_reflected = elevation_reflected[k] != 0;
  o.events = events[k];
  o.first_contact = first_contact[k];
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t e = k * n + j;
    o.pocketed[j] = static_cast<char>(pocketed[e]);
    o.pocket[j] = pocket[e];
    o.final_position[j] = {final_position[2 * e], final_position[2 * e + 1]};
    o.cushions_before_contact[j] = cushions_before_contact[e];
    o.cushions[j] = cushions[e];
  }
  return o;
}

namespace {

std::string action_field(std::uint64_t k, const char* what) { return "actions[" + std::to_string(k) + "]." + what; }

std::string row_field(const char* array, std::uint64_t k, std::size_t j) {
  return std::string(array) + "[" + std::to_string(k) + "][" + std::to_string(j) + "]";
}

// Each field against its own range; the tip offset as a whole is not
// checked: beyond the miscue limit it is the shot's outcome (batch.hpp).
void check_action(std::uint64_t k, const ShotAction& a) {
  const auto in = [&](const char* name, double v, double lo, double hi, const char* meaning) {
    if (!(std::isfinite(v) && v >= lo && v <= hi))
      throw InvalidArgument(action_field(k, name), v, "[" + format_number(lo) + ", " + format_number(hi) + "]", meaning);
  };
  // The scenario JSON's ranges for "cue" (scenario.cpp, read_cue).
  in("speed", a.speed, 1e-6, kMaxCueSpeed, "cue speed, m/s");
  in("aim_deg", a.aim_deg, -360.0, 360.0, "aim direction from +x, degrees");
  in("elevation_deg", a.elevation_deg, 0.0, 89.0, "cue elevation, degrees");
  in("side", a.side, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset to the right, ball radii");
  in("height", a.height, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset above the centre, ball radii");
}

// Shot k's starting layout: its present balls on the table, apart. `on`
// is the shot's row of `present`, or empty (every ball present).
void check_layout(const Table& table, std::span<const double> layout, std::span<const std::uint8_t> on,
                  std::uint64_t k, double radius) {
  const std::size_t n = layout.size() / 2;
  const auto present = [&](std::size_t j) { return on.empty() || on[j] != 0; };
  for (std::size_t j = 0; j < n; ++j) {
    if (!present(j)) continue;
    const Vec2 p{layout[2 * j], layout[2 * j + 1]};
    const std::string field = row_field("layouts", k, j);
    if (!(std::isfinite(p.x) && std::isfinite(p.y)) || !ball_on_table(table, p, radius))
      throw InvalidArgument(field, field + " = (" + format_number(p.x) + ", " + format_number(p.y) +
                                       ") m is off the playing surface or inside a cushion");
    for (std::size_t i = 0; i < j; ++i) {
      if (!present(i)) continue;
      const double d = norm(p - Vec2{layout[2 * i], layout[2 * i + 1]});
      if (d < 2 * radius - kPlacementTolerance)
        throw InvalidArgument(field, field + " overlaps " + row_field("layouts", k, i) + ": centres " +
                                         format_number(d) + " m apart, allowed >= 2R = " + format_number(2 * radius) +
                                         " m");
    }
  }
}

// One simulate_many call: its input, checked once, and the result its shots
// fill in, each shot its own rows.
struct ManyContext {
  const Scenario& scenario;
  std::span<const ShotAction> actions;
  std::span<const double> layouts;         // empty: the scenario's
  std::span<const std::uint8_t> present;   // empty: every ball
  const ManyOptions& options;
  std::size_t shots = 0;
  std::size_t balls = 0;
  std::size_t cue = 0;                     // the struck ball's index in the scenario
  int cue_id = 0;
  ManyResult& out;
};

// Step 1: everything a shot could reject, before any shot runs (batch.hpp's
// list of errors, in its order).
void check_many_input(ManyContext& c) {
  const Scenario& s = c.scenario;
  const ManyOptions& o = c.options;
  if (c.actions.empty() || c.actions.size() > static_cast<std::size_t>(kMaxManyShots))
    throw InvalidArgument("actions", static_cast<double>(c.actions.size()), "[1, " + format_number(kMaxManyShots) + "]",
                          "number of shots (rows of actions)");
  if (o.threads < 1 || o.threads > kMaxBatchThreads)
    throw InvalidArgument("threads", static_cast<double>(o.threads), "[1, " + std::to_string(kMaxBatchThreads) + "]",
                          "worker threads");
  if (o.first_shot > kMaxFirstShot)
    throw InvalidArgument("first_shot", static_cast<double>(o.first_shot), "[0, 2^53]",
                          "index of actions[0] in the whole study");
  validate_simulation_input(s.table, s.balls, s.settings);  // once; each shot then runs unchecked
  if (o.noise) validate(s.noise);
  c.shots = c.actions.size();
  c.balls = s.balls.size();
  c.cue_id = s.cue ? s.cue->ball : 0;
  c.cue = c.balls;
  for (std::size_t j = 0; j < c.balls; ++j)
    if (s.balls[j].id == c.cue_id) c.cue = j;
  if (c.cue == c.balls)
    throw InvalidArgument(s.cue ? "cue.ball" : "balls",
                          "the scenario has no ball with id " + std::to_string(c.cue_id) + " to strike");
  for (std::size_t k = 0; k < c.shots; ++k) check_action(o.first_shot + k, c.actions[k]);
  const std::size_t n = c.balls, shots = c.shots;
  const std::string sizes = " (shots " + std::to_string(shots) + " x balls " + std::to_string(n);
  if (!c.layouts.empty() && c.layouts.size() != shots * n * 2)
    throw InvalidArgument("layouts", static_cast<double>(c.layouts.size()),
                          std::to_string(shots * n * 2) + sizes + " x 2) or 0", "number of coordinates");
  if (!c.present.empty() && c.present.size() != shots * n)
    throw InvalidArgument("present", static_cast<double>(c.present.size()), std::to_string(shots * n) + sizes + ") or 0",
                          "number of on-table flags");
  for (std::size_t k = 0; k < shots && !c.present.empty(); ++k)
    if (c.present[k * n + c.cue] == 0) {
      const std::string field = row_field("present", o.first_shot + k, c.cue);
      throw InvalidArgument(field, field + " is false: the cue ball (id " + std::to_string(c.cue_id) +
                                       ") must be on the table in every shot");
    }
  const std::span<const std::uint8_t> all;
  for (std::size_t k = 0; k < shots && !c.layouts.empty(); ++k)
    check_layout(s.table, c.layouts.subspan(k * n * 2, n * 2), c.present.empty() ? all : c.present.subspan(k * n, n),
                 o.first_shot + k, s.settings.parameters.ball.radius);
}

// Step 2: the result's arrays, every row "not simulated" until its shot
// stores it; `present` copied from the input (all 1 without it).
void size_result(const ManyContext& c) {
  ManyResult& out = c.out;
  const std::size_t shots = c.shots, n = c.balls;
  out.shots = static_cast<int>(shots);
  out.balls = static_cast<int>(n);
  out.ids.clear();
  for (const SimulationBall& b : c.scenario.balls) out.ids.push_back(b.id);
  if (c.present.empty())
    out.present.assign(shots * n, 1);
  else
    out.present.assign(c.present.begin(), c.present.end());
  for (std::uint8_t& p : out.present) p = p != 0 ? 1 : 0;
  out.pocketed.assign(shots * n, 0);
  out.pocket.assign(shots * n, -1);
  out.final_position.assign(shots * n * 2, 0.0);
  out.first_contact.assign(shots, -1);
  out.cushions_before_contact.assign(shots * n, 0);
  out.cushions.assign(shots * n, 0);
  out.events.assign(shots, 0);
  out.miscue.assign(shots, 0);
  out.failure.assign(shots, 0);
  out.speed_reflected.assign(shots, 0);
  out.elevation_reflected.assign(shots, 0);
}

// Step 3 (each shot): its outcome into its rows. No two threads touch one element.
void store_outcome(const ManyContext& c, std::size_t k, const ShotOutcome& o) {
  ManyResult& out = c.out;
  out.miscue[k] = o.kind == ShotOutcome::Kind::miscue ? 1 : 0;
  out.failure[k] = o.kind == ShotOutcome::Kind::failure ? 1 : 0;
  out.speed_reflected[k] = o.speed_reflected ? 1 : 0;
  out.elevation_reflected[k] = o.elevation_reflected ? 1 : 0;
  out.events[k] = o.events;
  out.first_contact[k] = o.first_contact;
  for (std::size_t j = 0; j < c.balls; ++j) {
    const std::size_t e = k * c.balls + j;
    out.pocketed[e] = o.pocketed[j] ? 1 : 0;
    out.pocket[e] = o.pocket[j];
    out.final_position[2 * e] = o.final_position[j].x;
    out.final_position[2 * e + 1] = o.final_position[j].y;
    out.cushions_before_contact[e] = o.cushions_before_contact[j];
    out.cushions[e] = o.cushions[j];
  }
}

// The strike of shot k as struck: the action, with the noise when asked.
LimitedStrike struck(const ManyContext& c, std::size_t k) {
  const CueStrike nominal = to_strike(c.actions[k], c.scenario.settings.parameters.ball.radius);
  if (!c.options.noise) return {nominal, false, false};
  return reflect_into_limits(
      with_noise(nominal, c.scenario.noise, shot_normals(c.options.seed, c.options.first_shot + k)));
}

// Shot k's balls at the start: the scenario's, moved to its layout, its
// absent balls left out; `index[i]` is ball i's index in the scenario.
void starting_balls(const ManyContext& c, std::size_t k, std::vector<SimulationBall>& balls,
                    std::vector<std::size_t>& index) {
  const std::size_t n = c.balls;
  balls.clear();
  index.clear();
  for (std::size_t j = 0; j < n; ++j) {
    if (!c.present.empty() && c.present[k * n + j] == 0) continue;
    balls.push_back(c.scenario.balls[j]);
    index.push_back(j);
    if (!c.layouts.empty()) balls.back().state.position = {c.layouts[(k * n + j) * 2], c.layouts[(k * n + j) * 2 + 1]};
  }
}

// Step 3: plays shot k into `record` (reset for the scenario's balls) and stores it.
void play_many_shot(const ManyContext& c, std::size_t k, ShotRecord& record) {
  const Scenario& s = c.scenario;
  const BallParameters& ball = s.settings.parameters.ball;
  const LimitedStrike strike = struck(c, k);
  record.speed_reflected = strike.speed_reflected;
  record.elevation_reflected = strike.elevation_reflected;
  if (!cue_tip_offset_ok(strike.strike, ball)) {
    record.kind = ShotRecord::Kind::miscue;
    store_outcome(c, k, record);
    return;
  }
  if (c.present.empty()) {  // every ball: the outcome's columns are the scenario's
    std::vector<SimulationBall> balls = s.balls;
    if (!c.layouts.empty())
      for (std::size_t j = 0; j < c.balls; ++j)
        balls[j].state.position = {c.layouts[(k * c.balls + j) * 2], c.layouts[(k * c.balls + j) * 2 + 1]};
    balls[c.cue].state = strike_ball(strike.strike, balls[c.cue].state.position, ball, s.cue_parameters);
    try {
      outcome_from_result(simulate_unchecked(s.table, balls, s.settings), c.cue_id, record);
    } catch (const SimulationError&) {
      record.kind = ShotRecord::Kind::failure;
    }
    store_outcome(c, k, record);
    return;
  }
  // Some balls absent: simulate the present ones, then spread their outcome
  // over the scenario's columns (the absent ones keep reset()'s values).
  thread_local std::vector<SimulationBall> balls;
  thread_local std::vector<std::size_t> index;
  thread_local ShotOutcome on_table;
  starting_balls(c, k, balls, index);
  const auto cue = static_cast<std::size_t>(std::find(index.begin(), index.end(), c.cue) - index.begin());
  balls[cue].state = strike_ball(strike.strike, balls[cue].state.position, ball, s.cue_parameters);
  try {
    outcome_from_result(simulate_unchecked(s.table, balls, s.settings), c.cue_id, on_table);
    record.events = on_table.events;
    record.first_contact = on_table.first_contact;
    for (std::size_t i = 0; i < index.size(); ++i) {
      const std::size_t j = index[i];
      record.pocketed[j] = on_table.pocketed[i];
      record.pocket[j] = on_table.pocket[i];
      record.final_position[j] = on_table.final_position[i];
      record.cushions_before_contact[j] = on_table.cushions_before_contact[i];
      record.cushions[j] = on_table.cushions[i];
    }
  } catch (const SimulationError&) {
    record.kind = ShotRecord::Kind::failure;
  }
  store_outcome(c, k, record);
}

}  // namespace

ManyResult simulate_many(const Scenario& s, std::span<const ShotAction> actions, std::span<const double> layouts,
                         const ManyOptions& options, std::span<const std::uint8_t> present) {
  const auto start = std::chrono::steady_clock::now();
  ManyResult out;
  ManyContext c{s, actions, layouts, present, options, 0, 0, 0, 0, out};
  check_many_input(c);
  size_result(c);
  detail::run_batch(out.shots, options.threads, c.balls,
                    [&](int shot, ShotRecord& record) { play_many_shot(c, static_cast<std::size_t>(shot), record); });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.shots_per_second = out.seconds > 0.0 ? out.shots / out.seconds : 0.0;
  return out;
}

}  // namespace cueball
