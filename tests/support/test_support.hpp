// Helpers shared by cueball's tests.
#pragma once

#include <random>

#include "cueball/physics/cloth_motion.hpp"

namespace cueball::test {

/// A reproducible random initial state: velocity up to `max_speed` in any
/// direction, spins up to `max_spin` on each axis.
inline BallState random_state(std::mt19937_64& rng, double max_speed = 3.0, double max_spin = 150.0) {
  std::uniform_real_distribution<double> pos(-1.0, 1.0);
  std::uniform_real_distribution<double> speed(-max_speed, max_speed);
  std::uniform_real_distribution<double> spin(-max_spin, max_spin);
  return {{pos(rng), pos(rng)}, {speed(rng), speed(rng)}, {spin(rng), spin(rng), spin(rng)}};
}

}  // namespace cueball::test
