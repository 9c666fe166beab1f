#pragma once
// Moved to cueball/planning/shot_planner.hpp; this forwarding header is kept for one release.
#include "cueball/planning/shot_planner.hpp"  // IWYU pragma: export
