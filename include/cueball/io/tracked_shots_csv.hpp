// Tracked shots as CSV, one file a shot, for trackers that export tables
// rather than JSON (README "Tracked shots").
//
// A file is one shot: a header row naming the columns, then one row per
// sample of one ball, the balls' rows in any interleaving:
//   ball,t,x,y
//   yellow,0.000,2.12574,0.71327
//   red,0.000,1.90210,1.05003
//   yellow,0.020,2.12581,0.71410
// Columns `ball` (the ball's name), `t` (s, the record's clock), `x`, `y`
// (m, the table frame) are required, in any order; any other column is
// refused (naming it), so a typo is not silently dropped. Blank lines and
// lines starting with '#' are skipped; fields are trimmed of spaces and of
// one pair of double quotes; CRLF line ends are read. Each ball's rows must
// have increasing t. The shot's id is the file's name without its folder
// and ".csv"; the cue ball is the one named, or, when none is named, the
// ball that moves first (kMoveThreshold from its first sample).
// Every error names the file, the row (the line number, from 1, the header
// being row 1) and the column: "shot7.csv: row 12, column x: 4.2 is outside
// [-0.02, 2.86] m (position along the table)".
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cueball/calibration/tracked_shot.hpp"

namespace cueball {

/// One CSV file's name (as the user gave it) and text.
struct CsvShotFile {
  std::string name;
  std::string text;
};

/// Longest CSV file, bytes (64 MiB).
inline constexpr std::size_t kMaxTrackedShotCsvBytes = std::size_t{64} << 20;

/// One shot from one file; `cue_ball` empty: the ball that moves first.
/// Throws InvalidArgument (field: the file's name) as above; the shot is
/// validated (validate_tracked_shot) against `table`.
TrackedShot tracked_shot_from_csv(const CsvShotFile& file, const Table& table, const std::string& cue_ball);

/// The files as a tracked-shots set on the preset table `table_name`
/// (pool_9ft, snooker_12ft, carom_10ft); throws InvalidArgument ("table")
/// for another name, and for no files or more than kMaxTrackedShots.
TrackedShots tracked_shots_from_csv(const std::vector<CsvShotFile>& files, const std::string& table_name,
                                    const std::string& cue_ball);

}  // namespace cueball
