#pragma once
// Moved to cueball/models/ball_collision/coulomb_impulse.hpp; this forwarding header is kept for one release.
#include "cueball/models/ball_collision/coulomb_impulse.hpp"  // IWYU pragma: export
