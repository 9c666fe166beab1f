// One result of a command (the CLI's roll, plan, cushion, fit-cushion, batch,
// many, calibrate): named numbers with their SI units, counts, text, nested
// sections and warnings, written either as one JSON object (report_to_json,
// what --json prints) or as an aligned table with units and meanings.
// The commands whose JSON goes beyond these entries extend it in io/
// (batch_json.hpp, cushion_json.hpp), so that the CLI and Python write the
// same JSON from one writer.
#pragma once

#include <iosfwd>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace cueball {

class Report {
 public:
  explicit Report(std::string title = {}) : title_(std::move(title)) {}

  /// A number with its SI unit ("" when dimensionless) and a short meaning
  /// (-0 is written as 0).
  void add(const std::string& key, double value, const std::string& unit, const std::string& meaning = {});
  void add(const std::string& key, const std::vector<double>& value, const std::string& unit,
           const std::string& meaning = {});
  void add_text(const std::string& key, const std::string& value, const std::string& meaning = {});
  /// A count: printed and written as an integer.
  void add_count(const std::string& key, long long value, const std::string& meaning = {});
  /// Subsequent entries go into a nested JSON object (and an indented block).
  void begin_section(const std::string& name, const std::string& heading);
  void end_section();
  void warn(const std::string& message) { warnings_.push_back(message); }

  /// The JSON (report_to_json) when `json`, else the aligned table.
  void print(std::ostream& out, bool json) const;
  const std::vector<std::string>& warnings() const { return warnings_; }

  struct Entry {
    std::string section;  ///< "" at the top level
    std::string key;
    std::variant<double, std::vector<double>, std::string, long long> value;
    std::string text;  ///< as shown in the table
    std::string unit;
    std::string meaning;
  };
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::string title_;
  std::string section_;
  std::vector<std::pair<std::string, std::string>> headings_;
  std::vector<Entry> entries_;
  std::vector<std::string> warnings_;
};

/// The report as one JSON object: each entry by its key (a section's entries
/// in an object named by the section), then "warnings" (an array of strings)
/// when there are any. `indent`: spaces per nesting level, or -1 for one line.
std::string report_to_json(const Report& report, int indent = 2);

}  // namespace cueball
