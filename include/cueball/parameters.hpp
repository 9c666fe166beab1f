#pragma once
// Moved to cueball/core/parameters.hpp; this forwarding header is kept for one release.
#include "cueball/core/parameters.hpp"  // IWYU pragma: export
