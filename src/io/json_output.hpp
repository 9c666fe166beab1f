// The library's JSON writers as nlohmann values, for writers that nest them
// (the result JSON nests the facts). Private: nlohmann stays out of the
// public headers.
#pragma once

#include <nlohmann/json.hpp>

#include "cueball/simulation/shot_facts.hpp"
#include "cueball/table/table.hpp"

namespace cueball::io {

/// shot_facts_to_json() as a value.
nlohmann::json shot_facts_json(const Table& table, const ShotFacts& facts);

}  // namespace cueball::io
