// Pocket windows: for each pocket of a table, the lines along which a
// rolling ball drops into it, by the direction it comes from, measured on
// the engine (the table's own jaws, facings and capture circle, and its
// cloth). A ball coming straight into a 9-ft table's corner pocket drops on
// lines up to 35 mm either side of one through the pocket's centre; one
// coming 20 deg off the pocket's axis, on a band 62 mm wide centred 35 mm to
// the side (a ball sent at the pocket's centre barely drops); a side pocket
// closes from 42 mm either side head on to nothing beyond about 65 deg.
// This is the "effective target size" of a
// pocket by angle of approach (D. G. Alciatore, "The Illustrated Principles
// of Pool and Billiards", 2004, and his technical proofs TP 3.5-3.8 on
// billiards.colostate.edu, for corner and side pockets, slow and fast
// shots, from a straight-line model of the jaws), here read from the
// simulation for any table. The ghost-ball chance (ghost_ball.hpp) takes its
// aim tolerance from it.
//
// The measurement: a lone ball rolling at kPocketWindowSpeed, started
// kPocketWindowDistance from the pocket's centre on lines in every direction
// (kPocketWindowAngleStepDeg apart) and at offsets from the centre line
// kPocketWindowScanStep apart, out to the pocket's radius and a ball's
// diameter either side; the window runs from the first potting line to the
// last, each edge bisected outwards to kPocketWindowEdgeTolerance (a gap
// inside it, which the 9-ft table's pockets do not show at 1 mm, is not
// looked for). Lines whose start is not on the table a millimetre clear of
// every cushion are not tried, so a window whose lines run along a rail
// ends where they leave the table. Built on first use for a table and its
// settings (about 20,000 engine runs, 0.1 s) and cached.
#pragma once

#include <memory>
#include <vector>

#include "cueball/simulation/scenario.hpp"

namespace cueball {

inline constexpr double kPocketWindowSpeed = 1.0;          ///< m/s, the rolling ball's speed at its start
inline constexpr double kPocketWindowDistance = 0.45;      ///< m, its start from the pocket's centre
inline constexpr double kPocketWindowAngleStepDeg = 2.5;   ///< between directions of approach
inline constexpr double kPocketWindowScanStep = 0.004;     ///< m, between the lines first tried
inline constexpr double kPocketWindowEdgeTolerance = 5e-4; ///< m, an edge located to within this

/// One pocket's window by direction of approach: for the direction whose
/// angle (anticlockwise from +x, of the ball's travel) is k x
/// kPocketWindowAngleStepDeg, the lowest and highest offsets (m, to the left
/// of the travel) of lines that pot, the offset measured from the line
/// through the pocket's centre; low > high where no line pots.
struct PocketWindow {
  std::vector<double> low;
  std::vector<double> high;
};

/// Every pocket's window, in the table's order of pockets.
struct PocketWindows {
  std::vector<PocketWindow> pockets;
};

/// The windows of table.table's pockets under table.settings (the balls are
/// not used), built on first use and cached (the last few tables and
/// settings; safe from several threads). Throws what simulate() throws on
/// a table it refuses.
std::shared_ptr<const PocketWindows> pocket_windows(const Scenario& table);

/// Half the width (m) of `pocket`'s window for a ball travelling in
/// direction `direction` (not necessarily unit), linear in the angle between
/// the two nearest measured directions (a closed window's half-width 0):
/// 0 where both are closed, or for a pocket the table does not have.
double pocket_window_half_width(const PocketWindows& windows, std::size_t pocket, Vec2 direction);

/// The offset (m, to the left of the travel) from the pocket's centre of
/// the line through the middle of `pocket`'s window for a ball travelling in
/// direction `direction`: linear in the angle between the two nearest
/// measured directions where both are open, the open one's where one is
/// closed; 0 where both are closed, or for a pocket the table does not have.
/// A ball sent on this line has the most room for error either side.
double pocket_window_middle(const PocketWindows& windows, std::size_t pocket, Vec2 direction);

}  // namespace cueball
