#pragma once
// Moved to cueball/models/cushion/stronge_compliant.hpp; this forwarding header is kept for one release.
#include "cueball/models/cushion/stronge_compliant.hpp"  // IWYU pragma: export
