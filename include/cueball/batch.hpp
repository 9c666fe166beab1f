// Many noisy copies of one shot: what a robot or an AI planner asks in its
// inner loop ("if I play this, how often does the 9 drop, and where does the
// cue ball end up?").
//
// Shot k perturbs the scenario's cue strike with Gaussian execution noise
// (the scenario's CueStrikeNoise standard deviations) drawn from a generator
// seeded by (seed, k) alone. The shots are reduced in fixed blocks of
// kBatchBlockShots consecutive shots, each block in shot order, and the
// blocks are merged in block order, so the result is bit-identical for a
// given seed whatever the number of threads, and the memory a batch takes
// does not grow with the number of shots (a few blocks' partial sums per
// thread; no per-shot storage).
//
// Noisy values outside the strike's limits (cue_strike.hpp) are REFLECTED at
// the limit they cross, never dropped or clamped (reflect_into_limits()):
//   speed      in (0, kMaxCueSpeed]:  v > cap -> 2 cap - v,   v <= 0 -> -v
//   elevation  in [0, pi/2):          e < 0   -> -e,          e >= pi/2 -> pi - e
// (repeated until inside, for draws more than one range away). Why reflect:
// the noisy strike stays a continuous distribution whose density near the
// limit is that of the Gaussian folded back, so a break played at the cap or
// a level cue with elevation noise keeps every shot and a realistic spread.
// Clamping would instead pile a finite fraction of the shots onto exactly the
// limit (half of them for a strike at the limit): identical strikes that
// understate the spread of the outcomes. Reflection keeps the nominal strike
// as the mode, but it does shift the mean strike inwards (by about 0.8 sigma
// for a strike exactly at a limit); BatchResult counts the shots concerned
// (speed_reflected, elevation_reflected) so the caller can see it.
// A noisy tip offset beyond the miscue limit (sqrt(a^2 + b^2) >
// kMiscueOffsetFraction R) is a miscue, a real outcome of the stroke: it is
// counted in `miscues`, not simulated, and left out of the probabilities.
// Every other shot is simulated.
//
// Errors. Any exception a shot raises other than SimulationError (counted in
// `failures`) stops the batch: the workers finish the shots before it and
// stop, and simulate_batch rethrows, in the caller's thread, the very
// exception object of the lowest-numbered failing shot (e.g. an
// InvalidArgument naming the field, as a single run of that shot would
// throw), whatever the number of threads.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "cueball/scenario.hpp"

namespace cueball {

/// Largest number of shots in one batch. Memory does not grow with it; the
/// bound keeps the counts in an int and a batch's time sensible (10^8 breaks
/// at ~5000 shots/s per core are hours on two cores): split bigger studies
/// by seed.
inline constexpr int kMaxBatchShots = 100000000;
/// Largest number of worker threads.
inline constexpr int kMaxBatchThreads = 256;
/// Shots per reduction block (a fixed number: it must not depend on the
/// thread count, or the rounding of the sums would).
inline constexpr int kBatchBlockShots = 64;

struct BatchOptions {
  int shots = 1000;         ///< [1, kMaxBatchShots]
  int threads = 1;          ///< [1, kMaxBatchThreads]
  std::uint64_t seed = 0;
};

struct BallOutcome {
  int id = 0;
  double pocketed_probability = 0.0;  ///< over the simulated (non-miscue) shots
  Vec2 mean_position;                 ///< final position, over the shots where it stayed on the table
  Vec2 position_std;                  ///< standard deviation of the final position, per axis
};

struct BatchResult {
  int shots = 0;                ///< requested
  int simulated = 0;            ///< shots - miscues - failures
  int miscues = 0;              ///< noisy tip offsets beyond the miscue limit (not simulated)
  int failures = 0;             ///< shots that stopped with SimulationError (event limit)
  int speed_reflected = 0;      ///< shots whose noisy cue speed was reflected into (0, kMaxCueSpeed] (any outcome)
  int elevation_reflected = 0;  ///< shots whose noisy elevation was reflected into [0, pi/2) (any outcome)
  long long events = 0;         ///< events resolved over all simulated shots
  double seconds = 0.0;         ///< wall-clock time of the whole batch
  double shots_per_second = 0.0;
  std::vector<BallOutcome> balls;  ///< in the scenario's ball order
};

/// Throws InvalidArgument for bad options ("shots", "threads", with the
/// range), a scenario without a cue strike ("cue"), input the simulator
/// rejects, or a nominal strike that a single run would reject; rethrows a
/// shot's error as described above.
BatchResult simulate_batch(const Scenario& scenario, const BatchOptions& options);

/// A noisy strike brought within the limits by the reflection rule above.
struct LimitedStrike {
  CueStrike strike;
  bool speed_reflected = false;
  bool elevation_reflected = false;
};

/// The reflection rule of the header comment, applied to speed and
/// elevation; the other fields are returned unchanged. A value landing
/// exactly on an open end (speed 0, elevation pi/2) is moved inside by one
/// part in 2^52 of the range. Non-finite values are returned unchanged (the
/// strike's validation reports them).
LimitedStrike reflect_into_limits(const CueStrike& strike);

namespace detail {

/// One shot as the reducer sees it; the player fills it in.
struct ShotRecord {
  enum class Kind : char { simulated, miscue, failure };
  Kind kind = Kind::simulated;
  bool speed_reflected = false;
  bool elevation_reflected = false;
  int events = 0;
  std::vector<char> pocketed;        ///< per ball, sized by the reducer
  std::vector<Vec2> final_position;  ///< per ball, sized by the reducer
};

/// Plays shot `shot` into `record` (whose vectors have one entry per ball).
/// Called concurrently from the worker threads.
using PlayShot = std::function<void(int shot, ShotRecord& record)>;

/// The scheduler and reducer behind simulate_batch, for any player: blocks
/// of kBatchBlockShots shots taken by `threads` workers, reduced and merged
/// in block order (at most 4 x threads + 2 finished blocks wait to be merged),
/// errors rethrown by lowest shot. Fills every field of BatchResult but the
/// balls' ids, seconds and shots_per_second. Options are not validated.
BatchResult run_batch(int shots, int threads, std::size_t balls, const PlayShot& play);

}  // namespace detail

}  // namespace cueball
