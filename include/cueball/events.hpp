#pragma once
// Moved to cueball/physics/contact_prediction.hpp; this forwarding header is kept for one release.
#include "cueball/physics/contact_prediction.hpp"  // IWYU pragma: export
