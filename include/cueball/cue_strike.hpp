#pragma once
// Moved to cueball/physics/cue_strike.hpp; this forwarding header is kept for one release.
#include "cueball/physics/cue_strike.hpp"  // IWYU pragma: export
