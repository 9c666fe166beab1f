#pragma once
// Moved to cueball/core/vec.hpp; this forwarding header is kept for one release.
#include "cueball/core/vec.hpp"  // IWYU pragma: export
