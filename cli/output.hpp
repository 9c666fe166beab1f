// The CLI's helpers for a command's Report (io/report.hpp: one JSON object
// with --json, else an aligned table with units).
#pragma once

#include "cueball/core/parameters.hpp"
#include "cueball/io/report.hpp"
#include "cueball/physics/cloth_motion.hpp"

namespace cueball::cli {

/// Adds a ball state (phase, position, velocity, angular velocity).
void add_state(Report& r, const BallState& s, const Parameters& p);
/// Adds the physical parameters in use.
void add_parameters(Report& r, const Parameters& p);

}  // namespace cueball::cli
