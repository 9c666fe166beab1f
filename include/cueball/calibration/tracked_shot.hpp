// Tracked shots: ball positions sampled by a camera tracker, the data a
// calibration fits the engine to (README "Tracked shots").
//
// A tracked shot holds, for every ball, its samples (t, x, y) on the record's
// clock (seconds) in the table frame (metres, origin at a corner of the
// playing surface, x along the length). What trackers do to such records,
// and what prepare_shot() makes of it:
//   - sampling gaps: samples need not be regular; the fit compares the
//     simulation with the measurement at the sample times only, so a gap is
//     simply a stretch without residuals;
//   - dead bands: a tracker that writes a sample only after the ball moved
//     1.5-2 cm leaves slow balls sparse and a resting ball with its first
//     and last sample only; nothing is interpolated, but what the dead band
//     says of a ball that never moves is used: it stayed where it was, so
//     held samples (FitSample::held) every kHoldStep say so to the fit;
//   - a record that starts before the strike (by up to seconds): the strike
//     is placed after the cue ball's last sample before it first moves
//     (kMoveThreshold from its first sample); the samples before are the
//     layout, not residuals, and the fit's strike time is searched between
//     that sample and the first moving one;
//   - balls that never move: kept; their samples (at least the first) say
//     the simulated ball must stay where it is, which is what tells a fit
//     that a contact the real balls never made is wrong.
// The layout handed to the simulator is the balls' positions at the strike,
// each moved onto the table's legal area (at most kMaxLayoutNudge: tracker
// noise near a cushion) and pairs closer than two radii pushed apart.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cueball/simulation/simulator.hpp"
#include "cueball/table/table.hpp"

namespace cueball {

/// One ball's samples: t strictly increasing (s), x and y (m), same length >= 1.
struct TrackedBall {
  std::string name;
  std::vector<double> t, x, y;
};

struct TrackedShot {
  std::string id;                 ///< the shot's name in reports ("545600", or its index)
  std::string cue_ball;           ///< name of the struck ball (one of balls[].name)
  std::vector<TrackedBall> balls; ///< as recorded
};

/// A file of tracked shots on one table.
struct TrackedShots {
  std::string table_name;         ///< the preset name when given by name, else the table's name
  Table table;
  std::vector<TrackedShot> shots;
};

/// Displacement from the first sample (m) from which a ball counts as moved.
inline constexpr double kMoveThreshold = 0.005;
/// Largest distance (m) a layout position is moved to be legal (on the
/// table, clear of the other balls); beyond it the shot is refused.
inline constexpr double kMaxLayoutNudge = 0.02;
/// Most balls in one tracked shot, most samples of one ball, longest record (s).
inline constexpr std::size_t kMaxTrackedBalls = 22;
inline constexpr std::size_t kMaxTrackedSamples = 100000;
inline constexpr double kMaxRecordSeconds = 600.0;
/// Most shots in one file.
inline constexpr std::size_t kMaxTrackedShots = 100000;

/// Checks one shot; throws InvalidArgument naming the path below `path`
/// ("shots[3].balls.red.t[5] = 1.2 is not after the previous sample 1.3"):
/// at least one ball, the cue ball among them, names unique and non-empty,
/// t, x, y of equal length >= 1, every value finite, t strictly increasing
/// within [-kMaxRecordSeconds, kMaxRecordSeconds], positions within the
/// playing surface widened by kMaxLayoutNudge, the cue ball moving.
void validate_tracked_shot(const TrackedShot& shot, const Table& table, const std::string& path);

/// A sample as the fit uses it: ball index in PreparedShot::layout, time
/// after the estimated strike (s), position (m).
struct FitSample {
  int ball = 0;
  double t = 0.0;
  double x = 0.0, y = 0.0;
  /// Not written by the tracker: the dead band says a ball stayed within it
  /// of its last written sample until the next one, so for a ball that
  /// never moves prepare_shot adds one every kHoldStep from the strike to
  /// its last sample, at its position. They weigh in the fit (without them
  /// a resting ball has one residual, its last sample, and a fit that hits
  /// it pays little) but not in the reported RMSEs. Filling the gaps of
  /// moving balls too was tried on the match and made the fits worse (cue
  /// RMSE median 9.1 cm against 7.5 under the same constants): seconds of
  /// held samples at a stopping ball's last position outweigh its path.
  bool held = false;
};

/// Spacing of the held samples, s.
inline constexpr double kHoldStep = 0.1;
/// Least gap (s) between the first two object balls' departures for the
/// record to say which one the cue ball struck first (at 50 Hz and a 1.5-2 cm
/// dead band a slow ball's first sample may come a few samples late).
inline constexpr double kContactOrderGap = 0.1;

/// A shot made ready for fitting (prepare_shot).
struct PreparedShot {
  std::string id;
  /// Names in layout order: the cue ball first (id 0), then the others in
  /// the record's order (ids 1, 2, ...).
  std::vector<std::string> names;
  std::vector<SimulationBall> layout;   ///< at the strike, made legal
  double origin = 0.0;                  ///< record time of the estimated strike: FitSample::t = record t - origin
  double strike_min = 0.0;              ///< bounds of the fitted strike time, on the samples' clock
  double strike_max = 0.0;
  std::vector<FitSample> samples;       ///< after the strike, ordered by ball then time (held ones included)
  std::vector<int> samples_per_ball;    ///< tracked samples after the strike (held ones not counted)
  std::vector<char> moved;              ///< the ball moved kMoveThreshold or more in the record
  /// Per ball: the time (samples' clock) of its first sample kMoveThreshold
  /// from its first one; +infinity for a ball that never moves.
  std::vector<double> departure;
  /// The object ball (layout index) the cue ball struck first as the record
  /// tells it: the first object ball to depart, when the next one departs
  /// kContactOrderGap or more later (or never); -1 when no object ball
  /// moved or two departed too close together to tell.
  int first_object_ball = -1;
  double aim_estimate_deg = 0.0;        ///< direction of the cue ball's first movement
  double speed_estimate = 0.0;          ///< its speed over the first moving samples, m/s
  double duration = 0.0;                ///< last sample time (samples' clock)
  std::vector<std::string> notes;       ///< what preparation did (dropped samples, nudges)
};

/// Prepares a validated shot (validate_tracked_shot first). Throws
/// InvalidArgument naming `path` when the layout cannot be made legal.
PreparedShot prepare_shot(const TrackedShot& shot, const Table& table, const std::string& path);

}  // namespace cueball
