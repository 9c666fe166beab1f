// Many noisy copies of one shot: what a robot or an AI planner asks in its
// inner loop ("if I play this, how often does the 9 drop, and where does the
// cue ball end up?").
//
// Shot k perturbs the scenario's cue strike with Gaussian execution noise
// (the scenario's CueStrikeNoise standard deviations) drawn from a generator
// seeded by (seed, k) alone, and the outcomes are reduced in shot order, so
// the result is identical for a given seed whatever the number of threads.
// A noisy strike beyond the miscue limit counts as a miscue: it is not
// simulated and is left out of the probabilities.
#pragma once

#include <cstdint>
#include <vector>

#include "cueball/scenario.hpp"

namespace cueball {

struct BatchOptions {
  int shots = 1000;         ///< [1, 10^8]
  int threads = 1;          ///< [1, 256]
  std::uint64_t seed = 0;
};

struct BallOutcome {
  int id = 0;
  double pocketed_probability = 0.0;  ///< over the simulated (non-miscue) shots
  Vec2 mean_position;                 ///< final position, over the shots where it stayed on the table
  Vec2 position_std;                  ///< standard deviation of the final position, per axis
};

struct BatchResult {
  int shots = 0;        ///< requested
  int simulated = 0;    ///< shots - miscues - failures
  int miscues = 0;      ///< noisy strikes beyond the miscue limit or out of range
  int failures = 0;     ///< shots that stopped with SimulationError (event limit)
  long long events = 0; ///< events resolved over all shots
  double seconds = 0.0; ///< wall-clock time of the whole batch
  double shots_per_second = 0.0;
  std::vector<BallOutcome> balls;  ///< in the scenario's ball order
};

/// Throws InvalidArgument for bad options or a scenario without a cue strike.
BatchResult simulate_batch(const Scenario& scenario, const BatchOptions& options);

}  // namespace cueball
