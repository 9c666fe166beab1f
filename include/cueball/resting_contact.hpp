#pragma once
// Moved to cueball/physics/resting_contact.hpp; this forwarding header is kept for one release.
#include "cueball/physics/resting_contact.hpp"  // IWYU pragma: export
