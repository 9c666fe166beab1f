#pragma once
// Moved to cueball/physics/polynomial_roots.hpp; this forwarding header is kept for one release.
#include "cueball/physics/polynomial_roots.hpp"  // IWYU pragma: export
