#pragma once
// Moved to cueball/models/cushion/fit.hpp; this forwarding header is kept for one release.
#include "cueball/models/cushion/fit.hpp"  // IWYU pragma: export
