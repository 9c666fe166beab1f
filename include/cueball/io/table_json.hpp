// Tables as JSON: the preset form with overrides and the full geometry
// (table/table.hpp for the geometry itself).
#pragma once

#include <string>
#include <string_view>

#include "cueball/table/table.hpp"

namespace cueball {

/// Parses a table. The document is a JSON object in one of two forms.
///
/// Preset with overrides (the geometry is rebuilt from the overridden spec):
///   { "preset": "pool_9ft" | "snooker_12ft" | "carom_10ft",
///     "name": string, "length": m, "width": m, "cushion_height": m,
///     "ball": { "mass": kg, "radius": m },
///     "corner_pockets": { "mouth": m, "cut_angle_deg": deg, "jaw_radius": m, "shelf": m },
///     "side_pockets": { ...same keys... } }
///   Every key but "preset" is optional and partial objects override only
///   the keys given. When the ball's radius changes and "cushion_height" is
///   absent, the cushion height keeps its proportion to the ball.
///
/// Full geometry (what table_to_json() writes):
///   { "name": string, "length": m, "width": m,
///     "ball": { "mass": kg, "radius": m },
///     "cushions": [ { "name": string, "start": [x, y], "end": [x, y], "contact_height": m }, ... ],
///     "jaws":     [ { "name": string, "centre": [x, y], "radius": m, "contact_height": m }, ... ],
///     "pockets":  [ { "name": string, "centre": [x, y], "radius": m }, ... ],
///     "diamonds": [ [x, y], ... ] }
///   "name", "jaws", "pockets" and "diamonds" are optional (default "custom"
///   and empty); "ball" and the others are required. A cushion's or jaw's
///   "name" is optional (default "cushions[i]", "jaws[j]"; "Names" above) and,
///   when given, a non-empty string.
///
/// Unknown keys are rejected. Every error is an InvalidArgument whose field()
/// is the JSON path, with `path` naming the document itself, and whose message
/// gives the value and the allowed range, e.g.
///   "table.pockets[2].radius = -1 is outside (0, 0.2] m".
/// Malformed JSON is reported with nlohmann-json's byte position. The result
/// is validated (validate(const Table&)), with fields named by JSON path.
Table table_from_json(std::string_view json_text, std::string_view path = "table");

/// The full-geometry form, every cushion and jaw with its name in use;
/// table_from_json(table_to_json(t)) == t exactly when every part is named
/// (any table of build_table() or table_from_json()), else == t after
/// name_parts(t).
std::string table_to_json(const Table& table);

}  // namespace cueball
