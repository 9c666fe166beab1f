// A command's report (src/io/report.cpp): the JSON of its entries, sections
// and warnings, and the aligned table with units and meanings.
#include "cueball/io/report.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include <nlohmann/json.hpp>

namespace cueball {
namespace {

Report example() {
  Report r("example (SI units)");
  r.add("v0", 2.0, "m/s", "initial speed");
  r.add("w", {-0.0, 1.5}, "rad/s");
  r.add_count("shots", 3, "requested");
  r.begin_section("parameters", "parameters:");
  r.add_text("preset", "pool");
  r.add("mass", 0.17, "kg");
  r.end_section();
  r.add("t", -0.0, "s");
  return r;
}

TEST(Report, JsonHasEveryEntryInOrderWithSectionsNested) {
  Report r = example();
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(report_to_json(r));
  EXPECT_EQ(j.dump(), R"({"v0":2.0,"w":[0.0,1.5],"shots":3,"parameters":{"preset":"pool","mass":0.17},"t":0.0})");
  EXPECT_TRUE(j["shots"].is_number_integer());
  EXPECT_EQ(report_to_json(r, -1), j.dump());  // -1: one line
  r.warn("careful");
  EXPECT_EQ(nlohmann::ordered_json::parse(report_to_json(r))["warnings"], nlohmann::ordered_json::array({"careful"}));
}

TEST(Report, PrintsTheJsonOrAnAlignedTable) {
  const Report r = example();
  std::ostringstream json, table;
  r.print(json, true);
  EXPECT_EQ(json.str(), report_to_json(r) + "\n");
  r.print(table, false);
  EXPECT_EQ(table.str(),
            "example (SI units)\n"
            "  v0               2  m/s    initial speed\n"
            "  w         [0, 1.5]  rad/s\n"
            "  shots            3         requested\n"
            "  parameters:\n"
            "    preset      pool  \n"
            "    mass        0.17  kg\n"
            "  t                0  s\n");
}

}  // namespace
}  // namespace cueball
