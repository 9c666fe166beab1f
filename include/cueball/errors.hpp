#pragma once
// Moved to cueball/core/errors.hpp; this forwarding header is kept for one release.
#include "cueball/core/errors.hpp"  // IWYU pragma: export
