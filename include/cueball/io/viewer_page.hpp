// The self-contained HTML viewer: the page built from viewer/ (checked in as
// viewer/dist/cueball-viewer.html and embedded into the library at build
// time) with a result or a game document filled in: the CLI's --html and
// `view`, Python's Result and cueball.rl's render().
#pragma once

#include <string>
#include <string_view>


namespace cueball {

/// The token the page template holds exactly once, inside
/// <script type="application/json" id="cueball-result">.
inline constexpr std::string_view kViewerResultToken = "__CUEBALL_RESULT__";

/// The embedded page template (with the token).
std::string_view viewer_template();

/// The template with `result_json` in place of the token. Every '<' in the
/// JSON is written as the JSON escape \u003c, so no string in the result can
/// close the <script> element that carries it.
std::string viewer_page(std::string_view template_text, std::string_view result_json);

// The overlay and the check of a result: io/viewer_json.hpp.

}  // namespace cueball
