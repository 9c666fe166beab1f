#pragma once
// Moved to cueball/table/rack.hpp; this forwarding header is kept for one release.
#include "cueball/table/rack.hpp"  // IWYU pragma: export
