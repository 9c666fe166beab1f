#pragma once
// Moved to cueball/planning/position_play.hpp; this forwarding header is kept for one release.
#include "cueball/planning/position_play.hpp"  // IWYU pragma: export
