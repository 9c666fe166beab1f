// What the self-contained HTML viewer (viewer/, the CLI's --html and `view`)
// reads beside a result: the aim overlay of a planned shot, and the check that
// a result JSON is one the page can draw.
#pragma once

#include <string>
#include <string_view>

#include "cueball/core/parameters.hpp"
#include "cueball/simulation/simulator.hpp"

namespace cueball {

/// The aim overlay the page draws over the table (viewer/src/overlay.js), as
/// JSON: {"aim_line": [[x, y], ...], "ghost_ball": [x, y] or null}, metres.
/// aim_line is the path of ball `cue_ball`'s centre in `r` from its start
/// to its first ball-ball contact, through its cushion and jaw contacts
/// before it (a kick's path); ghost_ball is its centre at that contact, the
/// ghost-ball position. A cue ball that touches no ball gives the path to
/// where it stops (or is pocketed) and a null ghost_ball.
std::string aim_overlay_json(const SimulationResult& r, const Parameters& p, int cue_ball);

/// The result JSON (one object) with "overlay": overlay_json as its last key.
std::string with_overlay(std::string_view result_json, std::string_view overlay_json);

/// Checks that `result_json` is a cueball result the viewer can draw (the
/// keys and types the page reads) and returns it re-serialised compactly;
/// throws InvalidArgument (field: `source`) naming the first bad JSON path, e.g.
/// "RESULT.json: balls[2].segments[0].t: expected a number". An "overlay"
/// (optional) must be as aim_overlay_json() writes it.
std::string checked_result_for_viewer(const std::string& source, std::string_view result_json);

}  // namespace cueball
