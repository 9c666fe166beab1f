#pragma once
// Moved to cueball/planning/ball_in_hand.hpp; this forwarding header is kept for one release.
#include "cueball/planning/ball_in_hand.hpp"  // IWYU pragma: export
