#pragma once
// Moved to cueball/physics/straight_shot_inverse.hpp; this forwarding header is kept for one release.
#include "cueball/physics/straight_shot_inverse.hpp"  // IWYU pragma: export
