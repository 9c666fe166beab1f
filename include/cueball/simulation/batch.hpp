// Many noisy copies of one shot: what a robot or an AI planner asks in its
// inner loop ("if I play this, how often does the 9 drop, and where does the
// cue ball end up?").
//
// Shot k perturbs the scenario's cue strike with Gaussian execution noise
// (the scenario's CueStrikeNoise standard deviations) drawn from a generator
// seeded by (seed, k) alone. The shots are reduced in blocks of
// batch_block_shots(N) consecutive shots (a function of the batch size N
// alone), each block in shot order, and the
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

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "cueball/simulation/scenario.hpp"

namespace cueball {

/// Largest number of shots in one batch. Memory does not grow with it; the
/// bound keeps the counts in an int and a batch's time sensible (10^8 breaks
/// at ~5000 shots/s per core are hours on two cores): split bigger studies
/// by seed.
inline constexpr int kMaxBatchShots = 100000000;
/// Largest number of worker threads.
inline constexpr int kMaxBatchThreads = 256;
/// Most shots in one reduction block.
inline constexpr int kBatchBlockShots = 64;
/// Blocks a batch is cut into, where its blocks can be that small ...
inline constexpr int kBatchBlocks = 16;
/// ... and the fewest shots in a block.
inline constexpr int kBatchMinBlockShots = 4;
/// Shots per reduction block in a batch of `shots`: enough blocks to share
/// among the threads (kBatchBlocks of them up to 1,024 shots; a batch of
/// 200 in 64-shot blocks left one of two threads 128 shots and the other
/// 72) without a block's bookkeeping weighing on cheap shots. A function
/// of the batch size alone: never of the thread count, or the rounding of
/// the sums would be.
constexpr int batch_block_shots(int shots) {
  return std::clamp((shots + kBatchBlocks - 1) / kBatchBlocks, kBatchMinBlockShots, kBatchBlockShots);
}

/// What one shot did, derived from its SimulationResult's events
/// (outcome_from_result). The vectors have one entry per ball, in the
/// scenario's ball order.
struct ShotOutcome {
  enum class Kind : char { simulated, miscue, failure };
  Kind kind = Kind::simulated;     ///< miscue: not simulated; failure: SimulationError (event limit)
  bool speed_reflected = false;    ///< the noisy cue speed was reflected into the limits (noisy shots only)
  bool elevation_reflected = false;
  /// Events the simulator resolved, the cue strike not counted (run_scenario's
  /// events.size() - 1); 0 when not simulated.
  int events = 0;
  /// Id of the first ball the cue ball touches (the first ball_ball event
  /// involving it), -1 when it touches none or the shot was not simulated.
  int first_contact = -1;
  std::vector<char> pocketed;                ///< 1 when pocketed
  std::vector<int> pocket;                   ///< index into Table::pockets, -1 when not pocketed
  std::vector<Vec2> final_position;          ///< at the end (a pocketed ball: where it was captured); NaN when not simulated
  /// ball_cushion events of each ball before the cue ball's first contact
  /// with another ball (in event order; all of them when there is none).
  /// Jaw contacts (ball_jaw) are not counted.
  std::vector<int> cushions_before_contact;
  std::vector<int> cushions;                 ///< ball_cushion events of each ball in the whole shot

  /// Sizes every vector for `balls` balls and sets the fields to "not
  /// simulated" (kind simulated, 0 / -1 / NaN).
  void reset(std::size_t balls);
};

/// Fills `out` (every field but speed_reflected and elevation_reflected,
/// which it leaves alone) from a simulated shot: kind simulated, pocketing,
/// pockets and final positions from r.balls, counts from r.events. `cue_ball`
/// is the struck ball's id. r.balls must be in the order `out` is to report.
void outcome_from_result(const SimulationResult& r, int cue_ball, ShotOutcome& out);

/// Receives the outcome of every shot of a batch, in shot order, from one
/// thread at a time (the worker that merges the shot's block).
using OutcomeSink = std::function<void(int shot, const ShotOutcome& outcome)>;

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
///
/// `on_outcome`, when set, is called with each shot's outcome in shot order
/// 0, 1, 2, ... as the blocks are merged, under the batch's lock (at most
/// 4 x threads + 2 blocks of outcomes are held at once, so memory still does
/// not grow with the shots). An exception it throws stops the batch and is
/// rethrown by simulate_batch.
BatchResult simulate_batch(const Scenario& scenario, const BatchOptions& options, const OutcomeSink& on_outcome = {});

/// The five standard normals that perturb shot `shot` of a batch seeded
/// `seed` (speed, aim, elevation, side, height; with_noise(), cue_strike.hpp):
/// the same draws for simulate_batch, simulate_many and a game's shot.
std::array<double, 5> shot_normals(std::uint64_t seed, std::uint64_t shot);

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

// ------------------------------------------------------------------ many different shots
//
// simulate_many plays N different cue actions (optionally each from its own
// layout of the balls, some of them absent, optionally with the scenario's
// execution noise) and returns every shot's outcome, struct-of-arrays: flat
// row-major vectors that a binding can hand out as NumPy arrays of shape
// (N,), (N, balls) or (N, balls, 2) without touching the elements. Shots are
// scheduled exactly as simulate_batch's (blocks of batch_block_shots(N), work
// stealing) and each writes only its own rows, so the arrays are
// bit-identical whatever the number of threads; a shot's error other than
// SimulationError is rethrown in the caller, the lowest shot's winning, as
// simulate_batch does.
//
// What is an outcome and what is an error. A tip offset beyond the miscue
// limit (sqrt(side^2 + height^2) > kMiscueOffsetFraction ball radii) is a
// real stroke's outcome, whether the action asks for it or the noise puts
// it there: the offset actually struck decides (the action's without noise,
// the noisy one with it), and the shot is a miscue (row marked, not
// simulated, as in simulate_batch). A field outside its own range (speed
// 0 or above the cap, side 0.6, NaN, ...) is a programming error: an
// InvalidArgument naming it ("actions[17].speed") before any shot runs.
//
// Absent balls. `present`, when given, marks for each shot which of the
// scenario's balls are on the table (1) and which are not (0: e.g. pocketed
// by an earlier shot). An absent ball is left out of that shot's simulation;
// its layout position is ignored (any value, NaN included); its row reports
// present 0, pocketed 0, pocket -1, final position NaN and no cushions. The
// struck (cue) ball must be present in every shot.

/// One cue action, in the units of the scenario JSON's "cue" (so that an
/// (N, 5) float64 array of rows speed, aim_deg, elevation_deg, side, height
/// IS a span of ShotAction).
struct ShotAction {
  double speed = 3.0;          ///< cue speed, m/s, [1e-6, 12]
  double aim_deg = 0.0;        ///< the cue's direction in the bed's plane, degrees anticlockwise from +x, [-360, 360]
  double elevation_deg = 0.0;  ///< butt raised, degrees, [0, 89]
  double side = 0.0;           ///< tip offset to the right, ball radii, [-0.5, 0.5]
  double height = 0.0;         ///< tip offset above the centre, ball radii, [-0.5, 0.5]; sqrt(side^2 + height^2) > 0.5 is a miscue (an outcome)

  friend bool operator==(const ShotAction&, const ShotAction&) = default;
};
static_assert(sizeof(ShotAction) == 5 * sizeof(double), "ShotAction must be five packed doubles");

/// The CueStrike (radians, metres) of an action for balls of radius `radius`.
CueStrike to_strike(const ShotAction& action, double radius);

/// Most shots in one simulate_many call. The result holds 12 bytes per shot
/// and 30 per shot and ball (1 + 1 + 4 + 16 + 4 + 4): 1e6 shots of a 10-ball
/// 9-ball rack are 312 MB, of a 22-ball snooker frame 672 MB. Split bigger
/// studies into chunks, each with its ManyOptions::first_shot: the rows are
/// those of one run of the whole study.
inline constexpr int kMaxManyShots = 1'000'000;

/// Largest ManyOptions::first_shot (2^53: every index is exact as a double).
inline constexpr std::uint64_t kMaxFirstShot = std::uint64_t{1} << 53;

struct ManyOptions {
  int threads = 1;          ///< [1, kMaxBatchThreads]
  std::uint64_t seed = 0;   ///< noise of shot k drawn from (seed, first_shot + k) as in simulate_batch
  /// Perturb each action with the scenario's execution noise (reflected into
  /// the limits), exactly as simulate_batch perturbs its one strike.
  bool noise = false;
  /// Where actions[0] stands in a study split into chunks, [0, kMaxFirstShot]:
  /// shot k is shot first_shot + k of the study, for its noise and in error
  /// messages ("actions[first_shot + k].speed"). A chunk run with its offset
  /// gives exactly the rows the whole study run at once would.
  std::uint64_t first_shot = 0;
};

/// Every shot's outcome; `shots` = N rows, `balls` = the scenario's balls,
/// in its order (ids[j] is ball j's id). Row-major: element (k, j) of a
/// shots x balls array is at k * balls + j; final_position (k, j, axis) at
/// (k * balls + j) * 2 + axis.
struct ManyResult {
  int shots = 0;
  int balls = 0;
  std::vector<int> ids;                                 ///< (balls)
  std::vector<std::uint8_t> present;                    ///< (shots, balls) 1 on the table at the start, 0 absent
  std::vector<std::uint8_t> pocketed;                   ///< (shots, balls) 0 / 1 (0 when absent)
  std::vector<std::int32_t> pocket;                     ///< (shots, balls) pocket index, -1 not pocketed
  std::vector<double> final_position;                   ///< (shots, balls, 2) m; NaN when not simulated or absent
  std::vector<std::int32_t> first_contact;              ///< (shots) id of the cue ball's first ball, -1 none
  std::vector<std::int32_t> cushions_before_contact;    ///< (shots, balls)
  std::vector<std::int32_t> cushions;                   ///< (shots, balls)
  std::vector<std::int32_t> events;                     ///< (shots) cue strike not counted; 0 when not simulated
  std::vector<std::uint8_t> miscue;                     ///< (shots) 0 / 1: tip offset struck beyond the miscue limit
  std::vector<std::uint8_t> failure;                    ///< (shots) 0 / 1: SimulationError (event limit)
  std::vector<std::uint8_t> speed_reflected;            ///< (shots) 0 / 1 (noise only)
  std::vector<std::uint8_t> elevation_reflected;        ///< (shots) 0 / 1 (noise only)
  double seconds = 0.0;                                 ///< wall-clock time, validation included
  double shots_per_second = 0.0;

  /// Row k gathered into a ShotOutcome (for tests and small callers).
  ShotOutcome outcome(int shot) const;
};

/// Plays actions[k] for k = 0 .. N-1, struck on the scenario's cue ball
/// (cue.ball; ball 0 without "cue"): the action's aim is absolute, the
/// scenario's cue "target" and strike are not used (its cue mass and tip
/// restitution are). `layouts`, when not empty, holds N x balls x 2 doubles:
/// shot k starts with ball j at (layouts[(k balls + j) 2], ... + 1), the
/// balls' velocities and spins being the scenario's. `present`, when not
/// empty, holds N x balls flags: ball j is on the table in shot k when
/// present[k balls + j] != 0 (header comment, "Absent balls"). Everything is
/// checked before any shot runs, each error an InvalidArgument naming the
/// first bad item: "actions" (N in [1, kMaxManyShots]), "threads",
/// "actions[17].speed" (or .aim_deg, .elevation_deg, .side, .height, each
/// against its own range; a tip offset beyond the miscue limit is not an
/// error but the shot's outcome), "layouts" (the size), "layouts[3][2]"
/// (present ball 2 of layout 3: not finite, off the table or inside a
/// cushion, or overlapping an earlier present ball of that layout),
/// "present" (the size), "present[3][0]" (the cue ball absent), the scenario
/// as the simulator checks it, the noise ("sigma ...") when used.
ManyResult simulate_many(const Scenario& scenario, std::span<const ShotAction> actions,
                         std::span<const double> layouts, const ManyOptions& options,
                         std::span<const std::uint8_t> present = {});

namespace detail {

/// One shot as the reducer sees it; the player fills it in.
using ShotRecord = ShotOutcome;

/// Plays shot `shot` into `record` (reset for the batch's balls before each
/// shot). Called concurrently from the worker threads.
using PlayShot = std::function<void(int shot, ShotRecord& record)>;

/// The scheduler and reducer behind simulate_batch and simulate_many, for
/// any player: blocks of batch_block_shots(shots) shots taken by `threads` workers,
/// reduced and merged in block order (at most 4 x threads + 2 finished
/// blocks wait to be merged), errors rethrown by lowest shot; `sink`, when
/// set, receives every outcome in shot order as its block is merged. Fills
/// every field of BatchResult but the balls' ids, seconds and
/// shots_per_second. Options are not validated.
BatchResult run_batch(int shots, int threads, std::size_t balls, const PlayShot& play, const OutcomeSink& sink = {});

}  // namespace detail

}  // namespace cueball
