// The self-contained HTML viewer: the page built from viewer/ (checked in as
// viewer/dist/cueball-viewer.html and embedded into the binary at build time)
// with a simulation result filled in.
#pragma once

#include <string>
#include <string_view>

#include "cueball/simulation/simulator.hpp"

namespace cueball::cli {

/// The token the page template holds exactly once, inside
/// <script type="application/json" id="cueball-result">.
inline constexpr std::string_view kViewerResultToken = "__CUEBALL_RESULT__";

/// The embedded page template (with the token).
std::string_view viewer_template();

/// The template with `result_json` in place of the token. Every '<' in the
/// JSON is written as the JSON escape \u003c, so no string in the result can
/// close the <script> element that carries it.
std::string viewer_page(std::string_view template_text, std::string_view result_json);

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
/// throws UsageError naming the first bad JSON path, e.g.
/// "RESULT.json: balls[2].segments[0].t: expected a number". An "overlay"
/// (optional) must be as aim_overlay_json() writes it.
std::string checked_result_for_viewer(const std::string& source, std::string_view result_json);

}  // namespace cueball::cli
