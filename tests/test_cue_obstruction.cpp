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

namespace cueball {
namespace {

// The model by its definition: every 2 mm sample of the axis from the tip,
// the first one outside the playing area or within the cue's radius of a
// nose line decides (no balls: the rail alone).
bool over_rail_low_by_every_sample(const Table& table, Vec2 cue_ball, const CueStrike& strike, double R) {
  const CueAxis axis = cue_axis(cue_ball, strike, R);
  const double rail = rail_height(table);
  const double drop = kCueTipRadius / std::cos(strike.elevation);
  for (double s = 0.0; s <= kCueLength; s += 0.002) {
    const Vec3 x = axis.tip + s * axis.toward_butt;
    const Vec2 p{x.x, x.y};
    bool over = !inside_playing_area(table, p);
    for (const CushionSegment& k : table.cushions) over = over || distance_to_segment(k, p) < kCueTipRadius;
    if (over) return x.z - drop < rail;
  }
  return false;
}

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
