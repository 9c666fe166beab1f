// A command's report as JSON or as an aligned table (io/report.hpp).
#include "cueball/io/report.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>

#include "io/json_output.hpp"

namespace cueball {

namespace {

std::string format_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", v == 0.0 ? 0.0 : v);  // no "-0"
  return buf;
}

}  // namespace

void Report::add(const std::string& key, double value, const std::string& unit, const std::string& meaning) {
  entries_.push_back({section_, key, value == 0.0 ? 0.0 : value, format_number(value), unit, meaning});
}

void Report::add(const std::string& key, const std::vector<double>& value, const std::string& unit,
                 const std::string& meaning) {
  std::string text = "[";
  std::vector<double> values;
  for (std::size_t i = 0; i < value.size(); ++i) {
    text += (i ? ", " : "") + format_number(value[i]);
    values.push_back(value[i] == 0.0 ? 0.0 : value[i]);
  }
  entries_.push_back({section_, key, std::move(values), text + "]", unit, meaning});
}

void Report::add_text(const std::string& key, const std::string& value, const std::string& meaning) {
  entries_.push_back({section_, key, value, value, "", meaning});
}

void Report::add_count(const std::string& key, long long value, const std::string& meaning) {
  entries_.push_back({section_, key, value, std::to_string(value), "", meaning});
}

void Report::begin_section(const std::string& name, const std::string& heading) {
  section_ = name;
  headings_.emplace_back(name, heading);
}

void Report::end_section() { section_.clear(); }

namespace io {

nlohmann::ordered_json report_json(const Report& report) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const Report::Entry& e : report.entries()) {
    nlohmann::ordered_json value;
    std::visit([&](const auto& v) { value = v; }, e.value);
    if (e.section.empty()) {
      j[e.key] = std::move(value);
    } else {
      j[e.section][e.key] = std::move(value);
    }
  }
  if (!report.warnings().empty()) j["warnings"] = report.warnings();
  return j;
}

}  // namespace io

std::string report_to_json(const Report& report, int indent) { return io::report_json(report).dump(indent); }

void Report::print(std::ostream& out, bool json) const {
  if (json) {
    out << report_to_json(*this) << '\n';
    return;
  }
  std::size_t key_width = 0;
  std::size_t value_width = 0;
  std::size_t unit_width = 0;
  for (const Entry& e : entries_) {
    key_width = std::max(key_width, e.key.size() + (e.section.empty() ? 0 : 2));
    value_width = std::max(value_width, e.text.size());
    unit_width = std::max(unit_width, e.unit.size());
  }
  out << title_ << '\n';
  std::string current;
  for (const Entry& e : entries_) {
    if (e.section != current) {
      current = e.section;
      for (const auto& [name, heading] : headings_) {
        if (name == current) out << "  " << heading << '\n';
      }
    }
    const std::string key = (e.section.empty() ? "" : "  ") + e.key;
    out << "  " << key << std::string(key_width - key.size() + 2, ' ')
        << std::string(value_width - e.text.size(), ' ') << e.text << "  " << e.unit;
    if (!e.meaning.empty()) out << std::string(unit_width - e.unit.size() + 2, ' ') << e.meaning;
    out << '\n';
  }
}

}  // namespace cueball
