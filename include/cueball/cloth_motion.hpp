#pragma once
// Moved to cueball/physics/cloth_motion.hpp; this forwarding header is kept for one release.
#include "cueball/physics/cloth_motion.hpp"  // IWYU pragma: export
