// The whole calibration (calibration/calibrate.cpp) on the recorded
// three-cushion match (README "Calibrating from tracked shots"), read from
// $CUEBALL_SHARED_DIR/data/measured-three-cushion/shots.json when the
// checkout has it beside it (it has no licence: never copied into the
// repository); skipped, saying so, when it is not there. The synthetic
// tests of the fits are in test_strike_fit.cpp and test_constants_fit.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "cueball/calibration/calibrate.hpp"
#include "cueball/io/tracked_shots_json.hpp"
#include "cueball/models/ball_collision/model.hpp"
#include "cueball/models/cushion/model.hpp"

namespace cueball {
namespace {

// The match's first `n` shots, or nothing when the file is not there.
std::optional<TrackedShots> match_shots(std::size_t n) {
  const char* dir = std::getenv("CUEBALL_SHARED_DIR");
  if (!dir) return std::nullopt;
  const std::filesystem::path file = std::filesystem::path(dir) / "data" / "measured-three-cushion" / "shots.json";
  std::ifstream in(file);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  TrackedShots shots = tracked_shots_from_json(text.str());
  if (shots.shots.size() > n) shots.shots.resize(n);
  return shots;
}

// The han_2005 cushion fitted on the match (README's table), and the table's
// default cloth.
FitModel han_model(const TrackedShots& shots) {
  FitModel m = default_fit_model(shots);
  m.settings.cushion = default_cushion_settings(CushionModel::han_2005);
  m.settings.cushion.restitution = 0.837;
  m.settings.cushion.friction = 0.256;
  return m;
}

// Strikes only, under `m`.
CalibrationReport evaluate(const TrackedShots& shots, const FitModel& m) {
  CalibrationOptions o;
  o.evaluate_only = true;
  o.strike.starts = 16;
  return calibrate(shots, m, o);
}

// The cloth fitted on the match (han_2005; README's table before the
// restarts) reproduces its shots better than the pool cloth (mu_r 0.014,
// twice this heated cloth's, carom_10ft's default before the carom preset);
// on the first 12 shots the cue-ball RMSE median stays under 12 cm (8.7 cm
// on the 91 held-out shots).
TEST(CalibrateOnTheRecordedMatch, FittedConstantsBeatTheDefaults) {
  const auto shots = match_shots(12);
  if (!shots) GTEST_SKIP() << "the recorded match (../shared/data/measured-three-cushion/shots.json) is not here";
  ASSERT_EQ(shots->table_name, "carom_10ft");
  FitModel defaults_model = han_model(*shots);
  FitModel fitted_model = defaults_model;
  ClothParameters& c = fitted_model.settings.parameters.cloth;
  c.sliding_friction = 0.246, c.rolling_resistance = 0.0061, c.spin_friction = 0.012;
  defaults_model.settings.parameters.cloth = pool_parameters().cloth;
  const CalibrationReport fitted = evaluate(*shots, fitted_model);
  const CalibrationReport defaults = evaluate(*shots, defaults_model);
  RecordProperty("fitted_cue_median_cm", std::to_string(100 * fitted.training.cue_rmse_median));
  RecordProperty("defaults_cue_median_cm", std::to_string(100 * defaults.training.cue_rmse_median));
  EXPECT_EQ(fitted.training.shots, 12);
  EXPECT_LT(fitted.training.cue_rmse_median, 0.12);
  EXPECT_LT(fitted.training.cue_rmse_median, defaults.training.cue_rmse_median);
  EXPECT_LT(fitted.training.all_rmse_median, defaults.training.all_rmse_median);
}

// The ball-ball contact with the cloth's friction at the table (mathavan_2014)
// against coulomb_impulse, each with the constants fitted under it on the 30
// training shots of README's split before the mu_sp profile (held-out
// cue-ball RMSE median 5.7 cm against 7.9): on the first 12 shots the
// former fits better too.
TEST(CalibrateOnTheRecordedMatch, MathavanBallBallContactFitsBetter) {
  const auto shots = match_shots(12);
  if (!shots) GTEST_SKIP() << "the recorded match (../shared/data/measured-three-cushion/shots.json) is not here";
  FitModel coulomb = han_model(*shots);
  coulomb.settings.parameters.cloth = {0.2164, 0.00582, 0.00995, coulomb.settings.parameters.cloth.gravity};
  coulomb.settings.cushion.restitution = 0.840, coulomb.settings.cushion.friction = 0.259;
  FitModel mathavan = han_model(*shots);
  mathavan.settings.parameters.cloth = {0.2271, 0.00578, 0.00815, mathavan.settings.parameters.cloth.gravity};
  mathavan.settings.cushion.restitution = 0.847, mathavan.settings.cushion.friction = 0.269;
  mathavan.settings.ball_collision_model = BallCollisionModel::mathavan_2014;
  mathavan.settings.ball_collision = default_ball_collision(BallCollisionModel::mathavan_2014);
  const CalibrationReport a = evaluate(*shots, coulomb);
  const CalibrationReport b = evaluate(*shots, mathavan);
  RecordProperty("coulomb_cue_median_cm", std::to_string(100 * a.training.cue_rmse_median));
  RecordProperty("mathavan_cue_median_cm", std::to_string(100 * b.training.cue_rmse_median));
  EXPECT_LT(b.training.cue_rmse_median, a.training.cue_rmse_median);
  EXPECT_LT(b.training.all_rmse_median, a.training.all_rmse_median);
}

// The held-out draw: round(F n) shots, at least one kept for training, the
// same for the same seed and another for another.
TEST(Calibrate, HeldOutShotsAreASeededFraction) {
  const auto count = [](const std::vector<bool>& v) { return std::count(v.begin(), v.end(), true); };
  EXPECT_EQ(count(held_out_shots(121, 0.75, 1)), 91);
  EXPECT_EQ(count(held_out_shots(10, 0.3, 4)), 3);
  EXPECT_EQ(count(held_out_shots(1, 0.9, 0)), 0);
  EXPECT_EQ(count(held_out_shots(2, 0.9, 0)), 1);
  EXPECT_EQ(held_out_shots(121, 0.75, 1), held_out_shots(121, 0.75, 1));
  EXPECT_NE(held_out_shots(121, 0.75, 1), held_out_shots(121, 0.75, 2));
}

// The goal (README "Validated against a real match"): the constants
// that `cueball calibrate match.json --cushion-model han_2005
// --ball-collision-model mathavan_2014 --held-out 0.75 --seed 1` fits on its
// 30 training shots reproduce the 91 shots it holds out to a cue-ball RMSE
// median <= 6 cm and a p90 <= 20 cm, every strike fitted afresh (32 starts,
// as calibrate fits the held-out shots); the constants to 5 digits, from
// that run's --json. README: 4.9 / 13.2 cm. The whole calibration takes
// 70-80 s of CPU (300 s on two loaded cores), too long for the suite; the
// figure's script (tools/calibration_figure.py) runs it on seeds 1-3.
TEST(CalibrateOnTheRecordedMatch, FittedConstantsMeetTheGoalOnTheHeldOutShots) {
  auto shots = match_shots(121);
  if (!shots) GTEST_SKIP() << "the recorded match (../shared/data/measured-three-cushion/shots.json) is not here";
  ASSERT_EQ(shots->shots.size(), 121u);
  const std::vector<bool> held = held_out_shots(121, 0.75, 1);
  std::vector<TrackedShot> held_shots;
  for (std::size_t i = 0; i < held.size(); ++i)
    if (held[i]) held_shots.push_back(shots->shots[i]);
  shots->shots = held_shots;
  FitModel m = han_model(*shots);
  m.settings.parameters.cloth = {0.22949, 0.0059220, 0.0052096, m.settings.parameters.cloth.gravity};
  m.settings.cushion.restitution = 0.84707, m.settings.cushion.friction = 0.27074;
  m.settings.ball_collision_model = BallCollisionModel::mathavan_2014;
  m.settings.ball_collision = default_ball_collision(BallCollisionModel::mathavan_2014);
  CalibrationOptions o;
  o.evaluate_only = true;
  o.threads = 2;
  const CalibrationReport r = calibrate(*shots, m, o);
  RecordProperty("held_out_cue_median_cm", std::to_string(100 * r.training.cue_rmse_median));
  RecordProperty("held_out_cue_p90_cm", std::to_string(100 * r.training.cue_rmse_p90));
  ASSERT_EQ(r.training.shots, 91);
  EXPECT_LE(r.training.cue_rmse_median, 0.06);
  EXPECT_LE(r.training.cue_rmse_p90, 0.20);
}

}  // namespace
}  // namespace cueball
