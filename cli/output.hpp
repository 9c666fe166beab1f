// One result of a CLI command, printed either as one JSON object (--json)
// or as an aligned table with units.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cueball/physics/cloth_motion.hpp"

namespace cueball::cli {

class Report {
 public:
  explicit Report(std::string title) : title_(std::move(title)) {}

  /// A number with its SI unit ("" when dimensionless) and a short meaning.
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

  void print(std::ostream& out, bool json) const;
  nlohmann::ordered_json to_json() const;
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  struct Entry {
    std::string section;
    std::string key;
    nlohmann::ordered_json value;
    std::string text;  // as shown in the table
    std::string unit;
    std::string meaning;
  };
  std::string title_;
  std::string section_;
  std::vector<std::pair<std::string, std::string>> headings_;
  std::vector<Entry> entries_;
  std::vector<std::string> warnings_;
};

/// Adds a ball state (phase, position, velocity, angular velocity).
void add_state(Report& r, const BallState& s, const Parameters& p);
/// Adds the physical parameters in use.
void add_parameters(Report& r, const Parameters& p);

}  // namespace cueball::cli
