#include "output.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>

namespace cueball::cli {

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
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < value.size(); ++i) {
    text += (i ? ", " : "") + format_number(value[i]);
    array.push_back(value[i] == 0.0 ? 0.0 : value[i]);
  }
  entries_.push_back({section_, key, array, text + "]", unit, meaning});
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

nlohmann::ordered_json Report::to_json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const Entry& e : entries_) {
    if (e.section.empty()) {
      j[e.key] = e.value;
    } else {
      j[e.section][e.key] = e.value;
    }
  }
  if (!warnings_.empty()) j["warnings"] = warnings_;
  return j;
}

void Report::print(std::ostream& out, bool json) const {
  if (json) {
    out << to_json().dump(2) << '\n';
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

void add_state(Report& r, const BallState& s, const Parameters& p) {
  r.add_text("phase", to_string(motion_phase(s, p)), "motion phase");
  r.add("position", {s.position.x, s.position.y}, "m", "centre of the ball on the bed");
  r.add("velocity", {s.velocity.x, s.velocity.y}, "m/s");
  r.add("angular_velocity", {s.angular_velocity.x, s.angular_velocity.y, s.angular_velocity.z}, "rad/s");
  const Vec2 u = slip_velocity(s, p.ball.radius);
  r.add("slip_velocity", {u.x, u.y}, "m/s", "u = v + R z^ x w at the cloth");
}

void add_parameters(Report& r, const Parameters& p) {
  r.begin_section("parameters", "parameters:");
  r.add("mass", p.ball.mass, "kg");
  r.add("radius", p.ball.radius, "m");
  r.add("mu_s", p.cloth.sliding_friction, "", "sliding friction");
  r.add("mu_r", p.cloth.rolling_resistance, "", "rolling resistance, paper 001 convention");
  r.add("mu_sp", p.cloth.spin_friction, "", "vertical-spin friction");
  r.add("g", p.cloth.gravity, "m/s^2");
  r.end_section();
}

}  // namespace cueball::cli
