#pragma once
// Moved to cueball/table/table.hpp; this forwarding header is kept for one release.
#include "cueball/table/table.hpp"  // IWYU pragma: export
#include "cueball/io/table_json.hpp"  // IWYU pragma: export (table_from_json, table_to_json)
