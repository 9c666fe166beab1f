// Tracked shots (calibration/tracked_shot.cpp): validation naming the path,
// and what preparation makes of tracker records (a record starting before
// the strike, dead bands, balls that never move, tracker noise near a
// cushion, touching balls).
#include <gtest/gtest.h>

#include <cmath>

#include "cueball/calibration/tracked_shot.hpp"
#include "expect_invalid.hpp"
#include "synthetic_tracks.hpp"

namespace cueball {
namespace {

using test::expect_invalid;

TrackedShot simple_shot() {
  TrackedShot s;
  s.id = "1";
  s.cue_ball = "white";
  s.balls = {{"white", {0.0, 0.02, 0.04, 1.0}, {0.5, 0.56, 0.62, 1.4}, {0.5, 0.5, 0.5, 0.5}},
             {"red", {0.0, 1.0}, {2.0, 2.0}, {0.7, 0.7}}};
  return s;
}

const Table& carom() {
  static const Table t = preset_table("carom_10ft");
  return t;
}

TEST(TrackedShot, ValidShotPasses) { EXPECT_NO_THROW(validate_tracked_shot(simple_shot(), carom(), "shots[0]")); }

TEST(TrackedShot, ErrorsNameThePath) {
  TrackedShot s = simple_shot();
  s.balls[0].t[2] = 0.01;
  expect_invalid("shots[0].balls.white.t[2]", [&] { validate_tracked_shot(s, carom(), "shots[0]"); });
  s = simple_shot();
  s.balls[1].x.pop_back();
  expect_invalid("shots[0].balls.red.x", [&] { validate_tracked_shot(s, carom(), "shots[0]"); });
  s = simple_shot();
  s.balls[1].y[0] = 5.0;
  expect_invalid("shots[0].balls.red.y[0]", [&] { validate_tracked_shot(s, carom(), "shots[0]"); });
  s = simple_shot();
  s.balls[1].x[1] = std::nan("");
  expect_invalid("shots[0].balls.red.x[1]", [&] { validate_tracked_shot(s, carom(), "shots[0]"); });
  s = simple_shot();
  s.cue_ball = "yellow";
  expect_invalid("shots[0].cue_ball", [&] { validate_tracked_shot(s, carom(), "shots[0]"); });
  s = simple_shot();
  s.balls[0].t.clear(), s.balls[0].x.clear(), s.balls[0].y.clear();
  expect_invalid("shots[0].balls.white.t", [&] { validate_tracked_shot(s, carom(), "shots[0]"); });
  s = simple_shot();
  s.cue_ball = "red";  // the red never moves
  expect_invalid("shots[0].balls.red", [&] { validate_tracked_shot(s, carom(), "shots[0]"); });
  s = simple_shot();
  s.balls[1].name = "white";
  expect_invalid("shots[0].balls.\"white\"", [&] { validate_tracked_shot(s, carom(), "shots[0]"); });
}

TEST(TrackedShot, PreparationPutsTheCueBallFirstAndKeepsBallsThatNeverMove) {
  TrackedShot s = simple_shot();
  std::swap(s.balls[0], s.balls[1]);
  const PreparedShot p = prepare_shot(s, carom(), "shots[0]");
  ASSERT_EQ(p.names.size(), 2u);
  EXPECT_EQ(p.names[0], "white");
  EXPECT_EQ(p.layout[0].id, 0);
  EXPECT_EQ(p.layout[1].id, 1);
  EXPECT_EQ(p.moved[0], 1);
  EXPECT_EQ(p.moved[1], 0);
  EXPECT_EQ(p.samples_per_ball[1], 1);  // its last sample: it must stay put
  // ... and held samples every 0.1 s before it (the dead band says it stayed); none for the moving ball.
  int held_red = 0, held_white = 0;
  for (const FitSample& q : p.samples) (q.ball == 1 ? held_red : held_white) += q.held ? 1 : 0;
  EXPECT_GE(held_red, 8);
  EXPECT_EQ(held_white, 0);
  // The strike: after the rest sample at 0, before the first moving one at 0.02.
  EXPECT_GE(p.origin, 0.0);
  EXPECT_LT(p.origin, 0.02);
  EXPECT_GT(p.speed_estimate, 2.5);
  EXPECT_NEAR(p.aim_estimate_deg, 0.0, 1e-9);
}

TEST(TrackedShot, TheFirstObjectBallToDepartIsTheCueBallsFirstContact) {
  // White moves at 0.02 s; yellow departs at 0.30 s, red at `red_departs`.
  const auto shot = [](double red_departs) {
    TrackedShot s;
    s.id = "1";
    s.cue_ball = "white";
    s.balls = {{"white", {0.0, 0.02, 0.04, 1.0}, {0.5, 0.56, 0.62, 1.4}, {0.5, 0.5, 0.5, 0.5}},
               {"red", {0.0, red_departs, 2.0}, {2.0, 2.02, 2.3}, {0.7, 0.7, 0.7}},
               {"yellow", {0.0, 0.30, 2.0}, {1.5, 1.52, 1.8}, {0.3, 0.3, 0.3}}};
    return s;
  };
  const PreparedShot apart = prepare_shot(shot(0.30 + kContactOrderGap + 0.05), carom(), "shots[0]");
  ASSERT_EQ(apart.names, (std::vector<std::string>{"white", "red", "yellow"}));
  EXPECT_EQ(apart.first_object_ball, 2);  // yellow
  EXPECT_NEAR(apart.departure[2] - apart.departure[1], -(kContactOrderGap + 0.05), 1e-12);
  // Departures closer than kContactOrderGap: the record cannot tell.
  EXPECT_EQ(prepare_shot(shot(0.30 + kContactOrderGap / 2), carom(), "shots[0]").first_object_ball, -1);
  // A ball that never moves departs never; then the other one is the first.
  const PreparedShot one = prepare_shot(simple_shot(), carom(), "shots[0]");
  EXPECT_TRUE(std::isinf(one.departure[1]));
  EXPECT_EQ(one.first_object_ball, -1);
  TrackedShot red_only = shot(0.4);
  red_only.balls.pop_back();
  EXPECT_EQ(prepare_shot(red_only, carom(), "shots[0]").first_object_ball, 1);
}

TEST(TrackedShot, RecordStartingBeforeTheStrike) {
  TrackedShot s = simple_shot();
  // The cue ball sits 5 s (within the noise) before it is struck.
  s.balls[0] = {"white", {0.0, 2.0, 5.0, 5.02, 5.04, 6.0}, {0.5, 0.5003, 0.4998, 0.56, 0.62, 1.4}, {0.5, 0.5, 0.5, 0.5, 0.5, 0.5}};
  s.balls[1] = {"red", {0.0, 6.0}, {2.0, 2.0}, {0.7, 0.7}};
  const PreparedShot p = prepare_shot(s, carom(), "shots[0]");
  EXPECT_GE(p.origin, 4.999);
  EXPECT_LT(p.origin, 5.02);
  EXPECT_EQ(p.samples_per_ball[0], 3);  // 5.02, 5.04, 6.0
  EXPECT_FALSE(p.notes.empty());
}

TEST(TrackedShot, LayoutNudgedOntoTheTableAndApart) {
  TrackedShot s = simple_shot();
  const double R = carom().ball.radius;
  s.balls[0].y = {R - 0.004, R - 0.004, R - 0.004, R - 0.004};  // tracker noise into the cushion
  s.balls[1] = {"red", {0.0, 1.0}, {0.5 + 2 * R - 0.003, 2.0}, {R + 0.01, 0.7}};  // touching, overlapped by 3 mm
  const PreparedShot p = prepare_shot(s, carom(), "shots[0]");
  EXPECT_GE(p.layout[0].state.position.y, R);
  const Vec2 d = p.layout[1].state.position - p.layout[0].state.position;
  EXPECT_GE(norm(d), 2 * R);
  EXPECT_NO_THROW(validate_simulation_input(carom(), p.layout, SimulationSettings{}));
  // Overlapping by far more than the nudge allowed: refused naming the ball.
  s.balls[1] = {"red", {0.0, 1.0}, {0.5 + 0.01, 2.0}, {R + 0.01, 0.7}};
  EXPECT_THROW(prepare_shot(s, carom(), "shots[0]"), InvalidArgument);
}

TEST(TrackedShot, SyntheticDeadBandLeavesRestingBallsSparse) {
  const FitModel model = test::carom_model();
  const auto layout = test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05});
  const TrackedShot shot = test::synthetic_shot(model, layout, {3.0, 10.0, 3.0, 0.0, 0.0}, 0.01, 7);
  ASSERT_NO_THROW(validate_tracked_shot(shot, model.table, "shot"));
  const PreparedShot p = prepare_shot(shot, model.table, "shot");
  EXPECT_GT(p.samples_per_ball[0], 20);
  // A ball at rest gets its first and last sample only (the tail).
  for (std::size_t j = 1; j < p.layout.size(); ++j)
    if (!p.moved[j]) {
      EXPECT_EQ(p.samples_per_ball[j], 1);
    }
}

}  // namespace
}  // namespace cueball
