#pragma once
// Moved to cueball/simulation/simulator.hpp; this forwarding header is kept for one release.
#include "cueball/simulation/simulator.hpp"  // IWYU pragma: export
