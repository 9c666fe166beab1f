// Synthetic tracked shots made by the engine itself: a known strike under
// known constants, sampled as a camera tracker samples (50 Hz, a sample
// written only after the ball moved a dead band since the last one written,
// the first and the last sample of every ball always written, Gaussian
// position noise), for the calibration's tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "cueball/calibration/calibrate.hpp"
#include "cueball/simulation/scenario.hpp"

namespace cueball::test {

struct TrackerModel {
  double rate = 50.0;          ///< Hz
  double dead_band = 0.015;    ///< m
  double noise = 0.34e-3;      ///< m, standard deviation per axis
  double record_start = 0.0;   ///< record time of the first sample; the strike is at strike_time
  double tail = 0.5;           ///< s recorded after the last ball stops
};

/// The carom table's start model (default constants of a carom_10ft scenario).
inline FitModel carom_model() {
  TrackedShots shots;
  shots.table_name = "carom_10ft";
  shots.table = preset_table("carom_10ft");
  return default_fit_model(shots);
}

/// Three carom balls: white (the cue ball), yellow, red.
inline std::vector<SimulationBall> carom_layout(Vec2 white, Vec2 yellow, Vec2 red) {
  std::vector<SimulationBall> b(3);
  b[0].id = 0, b[0].name = "white", b[0].state.position = white;
  b[1].id = 1, b[1].name = "yellow", b[1].state.position = yellow;
  b[2].id = 2, b[2].name = "red", b[2].state.position = red;
  return b;
}

inline TrackedShot synthetic_shot(const FitModel& model, const std::vector<SimulationBall>& layout, const ShotAction& action,
                                  double strike_time, std::uint64_t seed, const TrackerModel& tracker = {}) {
  Scenario s;
  s.table = model.table;
  s.settings = model.settings;
  s.balls = layout;
  s.cue = ShotStrike{};
  s.cue_parameters = model.cue;
  const SimulationResult r =
      simulate(s.table, balls_after_strike(s, to_strike(action, s.table.ball.radius)), s.settings);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, tracker.noise);
  const double end = strike_time + r.end_time + tracker.tail;
  const int samples = static_cast<int>(std::ceil((end - tracker.record_start) * tracker.rate));
  TrackedShot shot;
  shot.id = "synthetic-" + std::to_string(seed);
  shot.cue_ball = layout[0].name;
  for (std::size_t j = 0; j < layout.size(); ++j) {
    TrackedBall b;
    b.name = layout[j].name;
    Vec2 written{};
    for (int k = 0; k <= samples; ++k) {
      const double t = tracker.record_start + k / tracker.rate;
      const Vec2 p = r.state_at(j, std::max(t - strike_time, 0.0), s.settings.parameters).position;
      const bool first = k == 0, last = k == samples;
      if (!first && !last && std::hypot(p.x - written.x, p.y - written.y) < tracker.dead_band) continue;
      written = p;
      b.t.push_back(t);
      b.x.push_back(p.x + noise(random));
      b.y.push_back(p.y + noise(random));
    }
    shot.balls.push_back(b);
  }
  return shot;
}

/// The shared match's file, when the checkout has ../shared beside it
/// (the tests get the directory in CUEBALL_SHARED_DIR), else "".
inline std::string shared_match_path() {
  const char* dir = std::getenv("CUEBALL_SHARED_DIR");
  if (dir == nullptr) return {};
  const std::string path = std::string(dir) + "/data/measured-three-cushion/shots.json";
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return {};
  std::fclose(f);
  return path;
}

}  // namespace cueball::test
