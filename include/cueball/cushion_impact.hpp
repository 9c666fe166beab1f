#pragma once
// Moved to cueball/models/cushion/impact.hpp; this forwarding header is kept for one release.
#include "cueball/models/cushion/impact.hpp"  // IWYU pragma: export
