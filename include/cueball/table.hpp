#pragma once
// Moved to cueball/table/table.hpp; this forwarding header is kept for one release.
#include "cueball/table/table.hpp"  // IWYU pragma: export
