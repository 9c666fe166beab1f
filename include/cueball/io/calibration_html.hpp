// The calibration report as one self-contained HTML page (`cueball
// calibrate --html REPORT.html`): the constants (with their bootstrap spread
// when there is one), the summary on training and held-out shots, the
// distribution of the shots' cue-ball RMSEs, and per shot the tracked
// samples and the simulated paths over the table, so a user sees where the
// model and the table part. Inline SVG and CSS only: no script, no network
// resource.
#pragma once

#include <string>
#include <vector>

#include "cueball/calibration/calibrate.hpp"

namespace cueball {

/// The page. `drawings` from shot_drawings(shots, report) (any subset, any
/// order: the page lists them worst cue-ball RMSE first).
std::string calibration_report_html(const CalibrationReport& report, const Table& table,
                                    const std::vector<ShotDrawing>& drawings);

}  // namespace cueball
