#pragma once
// Moved to cueball/models/ball_collision/model.hpp; this forwarding header is kept for one release.
#include "cueball/models/ball_collision/model.hpp"  // IWYU pragma: export
