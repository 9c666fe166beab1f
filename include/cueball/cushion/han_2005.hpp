#pragma once
// Moved to cueball/models/cushion/han_2005.hpp; this forwarding header is kept for one release.
#include "cueball/models/cushion/han_2005.hpp"  // IWYU pragma: export
