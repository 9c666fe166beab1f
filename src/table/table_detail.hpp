// What the table's JSON reader (src/io/table_json.cpp) needs of table.cpp:
// validation that names fields under a JSON path, and building a preset
// whose spec was validated under its own path.
#pragma once

#include <string>

#include "cueball/table/table.hpp"

namespace cueball::detail {

/// validate(table), every field named under `prefix` ("table.cushions[2]").
void validate_table_at(const Table& table, const std::string& prefix);
/// validate(spec), every field named under `prefix`.
void validate_spec_at(const TableSpec& spec, const std::string& prefix);
/// build_table() without validating the spec again.
Table build_table_unchecked(const TableSpec& spec);
/// prefix.field, or prefix[i] for a field "[i]", or field alone.
std::string join_path(const std::string& prefix, const std::string& field);

}  // namespace cueball::detail
