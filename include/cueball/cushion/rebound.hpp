#pragma once
// Moved to cueball/models/cushion/rebound.hpp; this forwarding header is kept for one release.
#include "cueball/models/cushion/rebound.hpp"  // IWYU pragma: export
