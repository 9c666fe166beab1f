// Cue obstruction (src/table/cue_obstruction.cpp): the rail test passes over
// the samples of the cue that provably stay clear of the rail; it must give
// the answer of testing every 2 mm sample, the model's definition (header
// comment of cue_obstruction.hpp), on strikes from all over pool, snooker
// and carom tables, level and raised, most of them reaching the rail.
// (The ball tests: test_shot_planner.cpp's CueObstructed.)
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "cueball/table/cue_obstruction.hpp"
#include "cueball/table/table.hpp"
#include "cue_rail_by_every_sample.hpp"

namespace cueball {
namespace {

using test::over_rail_low_by_every_sample;

TEST(CueObstruction, PassingOverClearSamplesGivesTheAnswerOfEverySample) {
  const Table tables[] = {build_table(pool_table_9ft_spec()), snooker_table_12ft(), carom_table_10ft()};
  std::mt19937_64 rng(2026);
  int obstructed = 0, clear = 0;
  for (const Table& t : tables) {
    const double R = t.ball.radius;
    std::uniform_real_distribution<double> x(0.0, t.length), y(0.0, t.width), angle(-3.14159, 3.14159),
        elevation(0.0, 0.6), offset(-0.5 * R, 0.5 * R);
    for (int i = 0; i < 4000; ++i) {
      const Vec2 p{x(rng), y(rng)};
      if (!ball_on_table(t, p, R)) continue;
      CueStrike strike;
      strike.aim = angle(rng);
      strike.elevation = i % 4 == 0 ? 0.0 : elevation(rng);
      strike.side_offset = offset(rng);
      strike.height_offset = offset(rng);
      const bool expected = over_rail_low_by_every_sample(t, p, strike, R);
      ASSERT_EQ(cue_obstructed(t, p, {}, strike, R), expected)
          << t.name << " at (" << p.x << ", " << p.y << "), aim " << strike.aim << ", elevation " << strike.elevation;
      (expected ? obstructed : clear) += 1;
    }
  }
  // Both answers occur often: the comparison tests each.
  EXPECT_GT(obstructed, 1000);
  EXPECT_GT(clear, 1000);
}

}  // namespace
}  // namespace cueball
