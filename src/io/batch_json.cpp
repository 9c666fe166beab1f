// Noisy batches as reports and JSON (io/batch_json.hpp).
#include "cueball/io/batch_json.hpp"

#include "io/json_output.hpp"

namespace cueball {

Report batch_report(const BatchResult& r, const std::string& title) {
  Report report(title);
  report.add_count("shots", r.shots, "requested");
  report.add_count("simulated", r.simulated, "shots simulated");
  report.add_count("miscues", r.miscues, "noisy tip offsets beyond the miscue limit (not simulated)");
  report.add_count("failures", r.failures, "shots stopped at the event limit");
  report.add_count("speed_reflected", r.speed_reflected, "noisy cue speeds reflected into (0, 12] m/s (simulated)");
  report.add_count("elevation_reflected", r.elevation_reflected, "noisy elevations reflected into [0, 90) deg (simulated)");
  report.add("seconds", r.seconds, "s", "wall-clock time");
  report.add("shots_per_second", r.shots_per_second, "1/s");
  report.add("events_per_shot", r.simulated ? static_cast<double>(r.events) / r.simulated : 0.0, "");
  return report;
}

std::string batch_result_to_json(const Scenario& s, const BatchResult& r, int indent) {
  nlohmann::ordered_json j = io::report_json(batch_report(r));
  nlohmann::ordered_json probability = nlohmann::ordered_json::object();
  nlohmann::ordered_json balls = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.balls.size(); ++i) {
    const BallOutcome& b = r.balls[i];
    probability[std::to_string(b.id)] = b.pocketed_probability;
    balls.push_back({{"id", b.id},
                     {"name", s.balls[i].name},
                     {"pocketed_probability", b.pocketed_probability},
                     {"mean_position", {b.mean_position.x, b.mean_position.y}},
                     {"position_std", {b.position_std.x, b.position_std.y}}});
  }
  j["pocketed_probability"] = probability;
  j["balls"] = balls;
  return j.dump(indent);
}

namespace {

struct ManyTotals {
  int miscues = 0, failures = 0, simulated = 0;
  long long events = 0;
};

ManyTotals many_totals(const ManyResult& r) {
  ManyTotals t;
  for (int k = 0; k < r.shots; ++k) {
    const auto i = static_cast<std::size_t>(k);
    t.miscues += r.miscue[i];
    t.failures += r.failure[i];
    t.events += r.events[i];
  }
  t.simulated = r.shots - t.miscues - t.failures;
  return t;
}

}  // namespace

Report many_report(const ManyResult& r, const std::string& title) {
  const ManyTotals t = many_totals(r);
  Report report(title);
  report.add_count("shots", r.shots, "actions played");
  report.add_count("simulated", t.simulated, "shots simulated");
  report.add_count("miscues", t.miscues, "tip offsets struck beyond the miscue limit (not simulated)");
  report.add_count("failures", t.failures, "shots stopped at the event limit");
  report.add("seconds", r.seconds, "s", "wall-clock time");
  report.add("shots_per_second", r.shots_per_second, "1/s");
  report.add("events_per_shot", t.simulated ? static_cast<double>(t.events) / t.simulated : 0.0, "");
  return report;
}

std::string many_result_to_json(const ManyResult& r, const std::string& outcomes, int indent) {
  nlohmann::ordered_json j = io::report_json(many_report(r));
  nlohmann::ordered_json pocketed = nlohmann::ordered_json::object();
  const auto balls = static_cast<std::size_t>(r.balls);
  for (std::size_t i = 0; i < balls; ++i) {
    int potted = 0;
    for (std::size_t k = 0; k < static_cast<std::size_t>(r.shots); ++k) potted += r.pocketed[k * balls + i];
    pocketed[std::to_string(r.ids[i])] = potted;
  }
  j["pocketed"] = pocketed;
  if (!outcomes.empty()) j["outcomes"] = outcomes;
  return j.dump(indent);
}

}  // namespace cueball
