#pragma once
// Moved to cueball/simulation/scenario.hpp; this forwarding header is kept for one release.
#include "cueball/simulation/scenario.hpp"  // IWYU pragma: export
