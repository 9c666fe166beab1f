#pragma once
// Moved to cueball/simulation/batch.hpp; this forwarding header is kept for one release.
#include "cueball/simulation/batch.hpp"  // IWYU pragma: export
