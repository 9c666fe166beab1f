#pragma once
// Moved to cueball/models/cushion/model.hpp; this forwarding header is kept for one release.
#include "cueball/models/cushion/model.hpp"  // IWYU pragma: export
