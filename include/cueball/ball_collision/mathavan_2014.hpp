#pragma once
// Moved to cueball/models/ball_collision/mathavan_2014.hpp; this forwarding header is kept for one release.
#include "cueball/models/ball_collision/mathavan_2014.hpp"  // IWYU pragma: export
