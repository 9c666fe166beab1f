// The whole calibration: tracked shots in, constants and a report out
// (README "Calibrating from tracked shots").
//
// Steps (calibrate()): prepare every shot (tracked_shot.hpp); draw the
// held-out shots (a seeded shuffle: round(held_out x N) of them, at least
// one training shot kept); fit every training shot's strike under the start
// constants (strike_fit.hpp); fit the constants (constants_fit.hpp) unless
// only evaluating, and their bootstrap spread when asked; then fit every shot's strike afresh, multi-start, under
// the final constants (the held-out shots only here: they never touch the
// constants) and report.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cueball/calibration/constants_fit.hpp"
#include "cueball/calibration/report.hpp"
#include "cueball/calibration/tracked_shot.hpp"

namespace cueball {

struct CalibrationOptions {
  double held_out = 0.25;          ///< fraction of the shots held out, [0, 0.9]
  std::uint64_t seed = 0;          ///< of the held-out draw
  bool evaluate_only = false;      ///< fit strikes only, under the start constants
  int threads = 1;                 ///< [1, 256]
  StrikeFitOptions strike;
  ConstantsFitOptions constants;   ///< its threads are set from `threads`
  BootstrapOptions bootstrap;      ///< the constants' uncertainties (its threads too)
};

struct CalibrationReport {
  FitModel model;                  ///< the fitted (or, evaluating, the given) constants
  FitModel start;                  ///< the constants the fit started from
  std::string table_name;
  std::vector<ShotReport> shots;   ///< in the file's order
  FitSummary training, held_out;
  int constant_evaluations = 0;   ///< the constants fit's stage 1 (simplex)
  int constant_iterations = 0;    ///< its stage 2 (joint LM)
  int constant_restarts = 0;      ///< 1 when the mu_sp profile or a restart of stage 1 won (ConstantsFit::restarts_taken)
  /// The constants' spread over bootstrap replicates of the training shots
  /// (empty when not asked for, or when only evaluating).
  std::vector<ConstantSpread> spread;
  int bootstrap_replicates = 0;
  double seconds = 0.0;
};

/// Which of `n` shots calibrate() holds out for `held_out` and `seed`: a
/// seeded Fisher-Yates shuffle, the first round(held_out n) of it, at least
/// one shot kept for training; true for a held-out shot. A function of these
/// three only, so the held-out shots of a calibration can be evaluated again
/// under given constants (evaluate_only holds none out).
std::vector<bool> held_out_shots(int n, double held_out, std::uint64_t seed);

/// Calibrates `start` (table, settings, cue) on the shots. Throws
/// InvalidArgument naming "shots[i]..." for a shot that cannot be prepared,
/// "held_out" or "threads" for bad options.
CalibrationReport calibrate(const TrackedShots& shots, const FitModel& start, const CalibrationOptions& options);

/// One shot drawn for the HTML report: per ball (layout order) the tracked
/// samples (all of them, the layout's too) and the path simulated with the
/// fitted strike under the report's constants (simulated_paths).
struct ShotDrawing {
  std::string id;
  bool held_out = false;
  bool contact_mismatch = false;
  double cue_rmse = 0.0;                     ///< m
  std::vector<std::string> names;            ///< layout order, the cue ball first
  std::vector<double> ball_rmse;             ///< m, NaN without samples after the strike
  std::vector<std::vector<Vec2>> measured;   ///< per ball
  std::vector<std::vector<Vec2>> simulated;  ///< per ball; empty when the simulation fails
};

/// The drawings of the report's shots (the same `shots` it was made from,
/// in its order). Throws InvalidArgument when the shots do not match the
/// report (count or ids).
std::vector<ShotDrawing> shot_drawings(const TrackedShots& shots, const CalibrationReport& report);

/// The start model of a tracked-shots file: its table with the settings a
/// scenario on that table gets by default.
FitModel default_fit_model(const TrackedShots& shots);

}  // namespace cueball
