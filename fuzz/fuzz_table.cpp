// libFuzzer target: cueball::table_from_json on arbitrary bytes.
//
// Checked for every input: the reader returns or throws InvalidArgument
// (field and message non-empty); nothing else escapes, nothing crashes. For
// every accepted table: validate() agrees, table_to_json -> table_from_json
// gives the same table exactly, and ball_on_table answers for a few points.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>

#include "cueball/core/errors.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/table/table.hpp"
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    cueball::Table t;
    try {
      t = cueball::table_from_json(text, "table");
    } catch (const cueball::InvalidArgument& e) {
      cueball_fuzz::check_rejection(e, "table");
      return 0;
    }
    if (cueball_fuzz::verbose()) std::fprintf(stderr, "table: accepted %s\n", t.name.c_str());
    try {
      cueball::validate(t);
    } catch (const cueball::InvalidArgument& e) {
      cueball_fuzz::fail("table_from_json returned a table that validate() rejects", e.what());
    }
    const std::string written = cueball::table_to_json(t);
    cueball::Table back;
    try {
      back = cueball::table_from_json(written, "table");
    } catch (const cueball::InvalidArgument& e) {
      cueball_fuzz::fail("table_to_json wrote a table that table_from_json rejects", e.what() + ("\n" + written));
    }
    cueball_fuzz::check(back == t, "table_from_json(table_to_json(t)) != t", written);
    cueball_fuzz::check(cueball::table_to_json(back) == written, "table_to_json is not stable", written);
    const double l = t.length, w = t.width;
    for (const cueball::Vec2 p : {cueball::Vec2{l / 2, w / 2}, cueball::Vec2{l / 4, w / 3}, cueball::Vec2{0.0, 0.0},
                                  cueball::Vec2{l, w}, cueball::Vec2{-1.0, w / 2}})
      (void)cueball::ball_on_table(t, p);
  } catch (const std::exception& e) {
    cueball_fuzz::unexpected(e, "table_from_json/table_to_json");
  }
  return 0;
}
