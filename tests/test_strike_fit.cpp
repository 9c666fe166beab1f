// The strike fit (calibration/strike_fit.cpp) on synthetic tracked shots made
// by the engine: 50 Hz, a 1.5 cm dead band, 0.34 mm tracker noise. Stated
// tolerances: cue-ball RMSE within 3 mm of the truth's (noise level), speed
// within 1 %, aim within 0.2 deg, strike time within 5 ms; elevation and tip
// offsets within 3 deg and 0.06 ball radii (they are seen only through
// the curve and the cushions, so less sharply).
#include <gtest/gtest.h>

#include <cmath>

#include "cueball/calibration/strike_fit.hpp"
#include "cueball/core/errors.hpp"
#include "synthetic_tracks.hpp"

namespace cueball {
namespace {

struct Case {
  ShotAction action;
  double strike_time;
  double record_start;
};

void expect_recovered(const Case& c, std::uint64_t seed) {
  const FitModel model = test::carom_model();
  const auto layout = test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05});
  test::TrackerModel tracker;
  tracker.record_start = c.record_start;
  const TrackedShot shot = test::synthetic_shot(model, layout, c.action, c.strike_time, seed, tracker);
  validate_tracked_shot(shot, model.table, "shot");
  const PreparedShot p = prepare_shot(shot, model.table, "shot");
  const StrikeFit truth = evaluate_strike(p, model, c.action, c.strike_time - p.origin);
  const StrikeFit f = fit_strike(p, model);
  SCOPED_TRACE("seed " + std::to_string(seed));
  // The layout itself is read from noisy samples, so even the true strike
  // leaves more than the noise after a few contacts (three-cushion shots
  // amplify 0.34 mm); the fit must do at least about as well as the truth.
  EXPECT_LT(f.cue_rmse, truth.cue_rmse + 3e-3);
  EXPECT_LT(f.all_rmse, truth.all_rmse + 3e-3);
  EXPECT_NEAR(f.action.speed, c.action.speed, 0.01 * c.action.speed);
  EXPECT_NEAR(f.action.aim_deg, c.action.aim_deg, 0.2);
  EXPECT_NEAR(f.strike_time, c.strike_time, 5e-3);
  EXPECT_NEAR(f.action.elevation_deg, c.action.elevation_deg, 3.0);
  EXPECT_NEAR(f.action.side, c.action.side, 0.06);
  EXPECT_NEAR(f.action.height, c.action.height, 0.06);
  EXPECT_FALSE(f.contact_mismatch);
  EXPECT_GT(f.simulations, 100);
}

TEST(StrikeFit, RecoversAStrikeWithSideAndFollow) {
  expect_recovered({{3.2, 25.0, 4.0, 0.2, 0.15}, 0.013, 0.0}, 1);
}

TEST(StrikeFit, RecoversAStrikeWithDraw) {
  expect_recovered({{2.6, 4.0, 6.0, -0.25, -0.2}, 0.007, 0.0}, 2);
}

TEST(StrikeFit, RecordStartingSecondsBeforeTheStrike) {
  // The record starts 3 s before the strike: the samples before are the layout.
  expect_recovered({{3.0, -20.0, 3.0, 0.1, 0.0}, 3.011, 0.0}, 3);
}

TEST(StrikeFit, TheTrueStrikeOfANoiselessRecordCostsNothing) {
  const FitModel model = test::carom_model();
  const auto layout = test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05});
  const ShotAction a{3.2, 25.0, 4.0, 0.2, 0.15};
  test::TrackerModel tracker;
  tracker.noise = 0.0;
  const TrackedShot shot = test::synthetic_shot(model, layout, a, 0.013, 4, tracker);
  const PreparedShot p = prepare_shot(shot, model.table, "shot");
  const StrikeFit truth = evaluate_strike(p, model, a, 0.013 - p.origin);
  EXPECT_LT(truth.all_rmse, 1e-9);
  EXPECT_FALSE(truth.contact_mismatch);
  // A strike a degree off costs far more.
  const StrikeFit off = evaluate_strike(p, model, {3.2, 26.0, 4.0, 0.2, 0.15}, 0.013 - p.origin);
  EXPECT_GT(off.all_rmse, 10 * truth.all_rmse);
}

TEST(StrikeFit, AFirstContactOtherThanTheRecordsIsAMismatch) {
  // White straight at red (ball 2), yellow well out of the way: the record
  // says red departs first; the same shot aimed at yellow strikes ball 1
  // first, which evaluate_strike reports as a contact mismatch.
  const FitModel model = test::carom_model();
  const auto layout = test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05});
  const double at_red = std::atan2(1.05 - 0.5, 1.9 - 0.7) * 180.0 / 3.14159265358979323846;
  const double at_yellow = std::atan2(0.35 - 0.5, 2.1 - 0.7) * 180.0 / 3.14159265358979323846;
  const ShotAction red_first{2.0, at_red, 0.0, 0.0, 0.0};
  const TrackedShot shot = test::synthetic_shot(model, layout, red_first, 0.01, 7);
  const PreparedShot p = prepare_shot(shot, model.table, "shot");
  ASSERT_EQ(p.first_object_ball, 2);
  const StrikeFit truth = evaluate_strike(p, model, red_first, 0.01 - p.origin);
  EXPECT_EQ(truth.first_contact, 2);
  EXPECT_FALSE(truth.contact_mismatch);
  const StrikeFit other = evaluate_strike(p, model, {2.0, at_yellow, 0.0, 0.0, 0.0}, 0.01 - p.origin);
  EXPECT_EQ(other.first_contact, 1);
  EXPECT_TRUE(other.contact_mismatch);
}

TEST(StrikeFit, RejectsBadOptions) {
  const FitModel model = test::carom_model();
  const auto layout = test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05});
  const TrackedShot shot = test::synthetic_shot(model, layout, {3.0, 10.0, 3.0, 0.0, 0.0}, 0.01, 5);
  const PreparedShot p = prepare_shot(shot, model.table, "shot");
  StrikeFitOptions o;
  o.starts = 0;
  EXPECT_THROW(fit_strike(p, model, o), InvalidArgument);
}

}  // namespace
}  // namespace cueball
