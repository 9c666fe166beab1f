// The constants fit (calibration/constants_fit.cpp) and the whole calibration
// (calibrate.cpp) on synthetic tracked shots made by the engine under known
// constants (mu_r 0.008 and cushion friction 0.20, where the carom table's
// defaults are 0.0077, the carom cloth, and 0.14), tracked at 50 Hz with a
// 1.5 cm dead band and 0.34 mm noise. Stated tolerances: mu_r within 15 %,
// the cushion restitution within 0.03 and friction within 0.05, the
// training cue-ball RMSE median below 2 cm. mu_s and mu_sp are reported but
// not asserted: these shots (mostly rolling balls) barely see them. What the
// fit reaches today (README, "Calibrating from tracked shots"): mu_r 0.0080,
// e 0.950, friction 0.200, cue RMSE median 1.6 mm (0.6 mm when the exact
// cushion's steps were loosened at most 3x, not 10x). Its path along the
// valley where restitution and friction trade was fragile: before the
// restarts, one simplex stopped at friction 0.127, 15 mm, when those steps
// were first loosened 10x (issue 29), which perturbs each cushion impact by
// 1e-8 to 1e-7 of the speed; the restarts of the simplex are tested from a
// start on the far side of that valley below.
#include <gtest/gtest.h>

#include <cmath>

#include "cueball/calibration/calibrate.hpp"
#include "cueball/core/errors.hpp"
#include "test_scale.hpp"
#include "synthetic_tracks.hpp"

namespace cueball {
namespace {

FitModel truth_model() {
  FitModel m = test::carom_model();
  m.settings.parameters.cloth.rolling_resistance = 0.008;
  m.settings.cushion.friction = 0.20;
  m.settings.cushion.restitution = 0.95;
  return m;
}

// One synthetic shot: the layout (white the cue ball) and the strike.
struct SyntheticCase {
  Vec2 white, yellow, red;
  ShotAction action;
};

TrackedShots synthetic_shots(const FitModel& truth, const std::vector<SyntheticCase>& cases, std::uint64_t seed) {
  TrackedShots shots;
  shots.table_name = "carom_10ft";
  shots.table = truth.table;
  for (const SyntheticCase& c : cases)
    shots.shots.push_back(test::synthetic_shot(truth, test::carom_layout(c.white, c.yellow, c.red), c.action, 0.011, seed++));
  return shots;
}

TrackedShots synthetic_match(const FitModel& truth) {
  return synthetic_shots(truth,
                         {
                             {{0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05}, {3.2, 25.0, 4.0, 0.2, 0.15}},
                             {{0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05}, {2.6, 4.0, 6.0, -0.25, -0.2}},
                             {{1.4, 0.7}, {0.4, 0.3}, {2.5, 1.1}, {3.5, 100.0, 3.0, 0.3, 0.1}},
                             {{2.0, 0.3}, {0.6, 1.0}, {1.2, 0.5}, {2.8, 160.0, 5.0, -0.3, 0.2}},
                             {{0.5, 1.0}, {2.4, 0.8}, {1.5, 0.2}, {3.0, -15.0, 2.0, 0.25, 0.25}},
                             {{1.0, 0.4}, {1.8, 1.2}, {2.6, 0.3}, {2.4, 60.0, 4.0, -0.2, 0.0}},
                         },
                         11);
}

TEST(ConstantsFit, RecoversTheCushionAndRollingConstants) {
  const FitModel truth = truth_model();
  const TrackedShots shots = synthetic_match(truth);
  CalibrationOptions o;
  o.held_out = 0.0;
  const CalibrationReport r = calibrate(shots, test::carom_model(), o);
  const auto& fitted = r.model.settings;
  RecordProperty("mu_s", std::to_string(fitted.parameters.cloth.sliding_friction));
  RecordProperty("mu_sp", std::to_string(fitted.parameters.cloth.spin_friction));
  RecordProperty("mu_r", std::to_string(fitted.parameters.cloth.rolling_resistance));
  RecordProperty("restitution", std::to_string(fitted.cushion.restitution));
  RecordProperty("friction", std::to_string(fitted.cushion.friction));
  RecordProperty("cue_rmse_median", std::to_string(r.training.cue_rmse_median));
  EXPECT_NEAR(fitted.parameters.cloth.rolling_resistance, 0.008, 0.15 * 0.008);
  EXPECT_NEAR(fitted.cushion.friction, 0.20, 0.05);
  EXPECT_NEAR(fitted.cushion.restitution, 0.95, 0.03);
  EXPECT_LT(r.training.cue_rmse_median, 0.02);
  EXPECT_EQ(r.training.shots, 6);
  EXPECT_EQ(r.held_out.shots, 0);
  EXPECT_GT(r.constant_evaluations, 10);
}

// The restarts of the simplex (constants_fit.cpp, restart_stage): from a
// start on the far side of the valley where restitution and friction trade
// (e 0.90, friction 0.10, the pool cloth's mu_r 0.014), one simplex stops
// at friction 0.105, e 0.979, a cue RMSE median of 20 mm (measured with
// restarts = 0); the restarts, their strikes fitted afresh, reach friction
// 0.185, e 0.939, mu_r 0.0081, 4.1 mm after the profile over mu_sp (0.193,
// 0.938, 0.0079, 5.2 mm before it; 0.191, 0.943, 2.6 mm with the exact
// cushion's steps loosened at most 3x, not 10x). (From the carom cloth's
// mu_r 0.0077 with the same cushion start they did not before the profile,
// e 0.903, 15 mm; with it they do: e 0.950, friction 0.200, 0.5 mm.)
TEST(ConstantsFit, RestartsRecoverFromTheFarSideOfTheValley) {
  const FitModel truth = truth_model();
  const TrackedShots shots = synthetic_match(truth);
  FitModel start = test::carom_model();
  start.settings.parameters.cloth = pool_parameters().cloth;
  start.settings.cushion.restitution = 0.90;
  start.settings.cushion.friction = 0.10;
  CalibrationOptions o;
  o.held_out = 0.0;
  o.constants.restarts = 2;
  const CalibrationReport r = calibrate(shots, start, o);
  const auto& fitted = r.model.settings;
  RecordProperty("mu_r", std::to_string(fitted.parameters.cloth.rolling_resistance));
  RecordProperty("restitution", std::to_string(fitted.cushion.restitution));
  RecordProperty("friction", std::to_string(fitted.cushion.friction));
  RecordProperty("cue_rmse_median", std::to_string(r.training.cue_rmse_median));
  EXPECT_NEAR(fitted.parameters.cloth.rolling_resistance, 0.008, 0.15 * 0.008);
  EXPECT_NEAR(fitted.cushion.friction, 0.20, 0.05);
  EXPECT_NEAR(fitted.cushion.restitution, 0.95, 0.03);
  EXPECT_LT(r.training.cue_rmse_median, 0.01);
  EXPECT_EQ(r.constant_restarts, 1);
}

// The profile over mu_sp (constants_fit.cpp, spin_profile_stage): three
// shots with side spin made with mu_sp 0.0085 (a vertical-spin deceleration
// of 6.7 rad/s^2, between the profile's points), the fit started from the
// carom defaults (test::carom_model(): the carom cloth, cushion e 0.98,
// friction 0.14) with mu_sp 0.0045 and 0.020, on opposite sides of the
// truth; 60 simplex evaluations and the fit's default restarts (2). Both
// must end within 10 % of the truth and within 2 % of each other. Measured:
// 0.00850 and 0.00856 (cue RMSE median 0.5 and 1.2 mm). Without the
// restarts (as this test was until issue 29) the fit from below stopped in
// the valley where the cushion's friction and restitution trade, wherever
// the cushion solver's last digits left it: 0.00851 (0.6 mm), then
// 0.00902 at cushion friction 0.185 (2.9 mm) after a change of the exact
// cushion's step control that moved those digits, and with the solver's
// local tolerance scaled by 0.999999, 1.000001 and 1.01 0.00844 (5.9 mm),
// 0.00865 and 0.0100 (friction 0.161, 8.2 mm); a user's fit has the
// restarts, which are for that valley (restart_stage): with them the fit
// from below ends at 0.00850, 0.00850, 0.00850 and 0.00857 under the same
// four. (Without the profile, spin_profile 0, and without the restarts:
// 0.0105, friction 0.158, 9.7 mm, and 0.00846.)
FitModel spin_truth() {
  FitModel m = truth_model();
  m.settings.parameters.cloth.spin_friction = 0.0085;
  return m;
}

TrackedShots spin_shots(const FitModel& truth) {
  return synthetic_shots(truth,
                         {
                             {{0.6, 0.4}, {2.5, 1.2}, {2.7, 0.3}, {2.8, 40.0, 3.0, 0.4, 0.1}},
                             {{2.2, 0.5}, {0.4, 1.1}, {0.3, 0.3}, {3.0, 150.0, 3.0, -0.4, 0.2}},
                             {{1.4, 1.1}, {0.3, 0.2}, {2.6, 0.2}, {2.6, -80.0, 4.0, 0.35, -0.1}},
                         },
                         31);
}

CalibrationReport spin_fit_from(const TrackedShots& shots, double start_spin_friction) {
  FitModel start = test::carom_model();
  start.settings.parameters.cloth.spin_friction = start_spin_friction;
  CalibrationOptions o;
  o.held_out = 0.0;
  o.strike.starts = 8;
  o.constants.max_evaluations = 60;
  o.constants.max_iterations = 4;
  return calibrate(shots, start, o);
}

// Under the sanitizers from below only (the start the simplex alone misses by more).
TEST(ConstantsFit, SpinProfileRecoversMuSpFromEitherSide) {
  const TrackedShots shots = spin_shots(spin_truth());
  std::vector<double> fitted;
  for (const double start : {0.0045, 0.020}) {
    if (test::sanitized() && start > 0.0085) continue;
    const CalibrationReport r = spin_fit_from(shots, start);
    fitted.push_back(r.model.settings.parameters.cloth.spin_friction);
    RecordProperty("mu_sp_from_" + std::to_string(start), std::to_string(fitted.back()));
    EXPECT_NEAR(fitted.back(), 0.0085, 0.10 * 0.0085) << "from mu_sp " << start;
    EXPECT_LT(r.training.cue_rmse_median, 0.01) << "from mu_sp " << start;
  }
  if (fitted.size() == 2) {
    EXPECT_NEAR(fitted[0], fitted[1], 0.02 * fitted[0]);
  }
}

TEST(Calibrate, HeldOutShotsAreDrawnBySeedAndOnlyEvaluated) {
  const FitModel truth = truth_model();
  const TrackedShots shots = synthetic_match(truth);
  CalibrationOptions o;
  o.held_out = 0.5;
  o.seed = 3;
  // Under the sanitizers 8 starts of each strike fit, not 32 (the same paths:
  // test_scale.hpp; at 32 this test took 145 s of the asan run).
  o.strike.starts = test::scaled(o.strike.starts, 8);
  o.evaluate_only = true;  // strikes only, under the true constants
  const CalibrationReport a = calibrate(shots, truth, o);
  // Evaluating holds nothing out: every shot is fitted under the given constants.
  EXPECT_EQ(a.training.shots, 6);
  EXPECT_EQ(a.constant_iterations, 0);
  EXPECT_LT(a.training.cue_rmse_median, 0.01);
  EXPECT_EQ(a.model.settings.parameters.cloth.rolling_resistance, 0.008);
  o.evaluate_only = false;
  o.constants.max_evaluations = 5;
  o.constants.max_iterations = 1;
  const CalibrationReport b = calibrate(shots, truth, o);
  const CalibrationReport c = calibrate(shots, truth, o);
  EXPECT_EQ(b.held_out.shots, 3);
  EXPECT_EQ(b.training.shots, 3);
  for (std::size_t i = 0; i < b.shots.size(); ++i) EXPECT_EQ(b.shots[i].held_out, c.shots[i].held_out);
}

// The bootstrap over shots: seeded (the same seed, the same spread), the
// fitted value inside the replicates' 5-95 % band widened by one standard
// deviation, and narrow on shots made without model error (mu_r within
// 10 %, restitution within 0.02). Its start is the truth, so the spread is
// that of the shots' noise and of the fits' local minima.
TEST(ConstantsFit, BootstrapSpreadIsSeededAndNarrowOnConsistentShots) {
  const FitModel truth = truth_model();
  const TrackedShots shots = synthetic_match(truth);
  std::vector<PreparedShot> prepared;
  std::vector<StrikeFit> strikes;
  for (std::size_t i = 0; i < shots.shots.size(); ++i) {
    prepared.push_back(prepare_shot(shots.shots[i], shots.table, "shots"));
    StrikeFitOptions so;
    so.starts = 8;
    strikes.push_back(fit_strike(prepared.back(), truth, so));
  }
  ConstantsFit fit;
  fit.model = truth;
  fit.strikes = strikes;
  BootstrapOptions o;
  o.replicates = 4;
  o.max_evaluations = 12;
  o.seed = 7;
  const std::vector<ConstantSpread> a = bootstrap_constants(prepared, fit, o);
  const std::vector<ConstantSpread> b = bootstrap_constants(prepared, fit, o);
  ASSERT_EQ(a.size(), 5u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].std_dev, b[k].std_dev) << a[k].name;
    EXPECT_EQ(a[k].p05, b[k].p05) << a[k].name;
    EXPECT_LE(a[k].p05, a[k].p95) << a[k].name;
    EXPECT_GE(a[k].value, a[k].p05 - a[k].std_dev - 1e-12) << a[k].name;
    EXPECT_LE(a[k].value, a[k].p95 + a[k].std_dev + 1e-12) << a[k].name;
  }
  EXPECT_EQ(a[1].name, "mu_r");
  EXPECT_DOUBLE_EQ(a[1].value, 0.008);
  EXPECT_LT(a[1].std_dev, 0.1 * 0.008);
  EXPECT_EQ(a[3].name, "cushion_restitution");
  EXPECT_LT(a[3].std_dev, 0.02);
  o.replicates = 0;
  EXPECT_TRUE(bootstrap_constants(prepared, fit, o).empty());
  o.replicates = 1001;
  EXPECT_THROW(bootstrap_constants(prepared, fit, o), InvalidArgument);
}

TEST(Calibrate, RejectsBadOptions) {
  const TrackedShots shots = synthetic_match(truth_model());
  CalibrationOptions o;
  o.held_out = 0.95;
  EXPECT_THROW(calibrate(shots, test::carom_model(), o), InvalidArgument);
  o = {};
  o.threads = 0;
  EXPECT_THROW(calibrate(shots, test::carom_model(), o), InvalidArgument);
  // The constants fit's options are checked by fit_constants, after the
  // training shots' strikes are fitted: under the sanitizers from 2 starts
  // each, not 32 (test_scale.hpp; 19 s of the asan run with 32).
  const auto constants_options = [] {
    CalibrationOptions fresh;
    fresh.strike.starts = test::scaled(fresh.strike.starts, 2);
    return fresh;
  };
  o = constants_options();
  o.constants.max_evaluations = 0;
  EXPECT_THROW(calibrate(shots, test::carom_model(), o), InvalidArgument);
  o = constants_options();
  o.constants.restarts = 17;
  EXPECT_THROW(calibrate(shots, test::carom_model(), o), InvalidArgument);
  o = constants_options();
  o.constants.spin_profile = 17;
  EXPECT_THROW(calibrate(shots, test::carom_model(), o), InvalidArgument);
  o = {};
  o.bootstrap.replicates = -1;
  EXPECT_THROW(calibrate(shots, test::carom_model(), o), InvalidArgument);
}

}  // namespace
}  // namespace cueball
