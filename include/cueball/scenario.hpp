#pragma once
// Moved to cueball/simulation/scenario.hpp; this forwarding header is kept for one release.
#include "cueball/simulation/scenario.hpp"  // IWYU pragma: export
#include "cueball/io/result_json.hpp"    // IWYU pragma: export (result_to_json)
#include "cueball/io/scenario_json.hpp"  // IWYU pragma: export (scenario_from_json, scenario_to_json, ...)
