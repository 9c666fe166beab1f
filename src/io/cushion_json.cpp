// The cushion commands' JSON (io/cushion_json.hpp).
#include "cueball/io/cushion_json.hpp"


#include "io/json_output.hpp"
#include "core/angles.hpp"

namespace cueball {

namespace {

using Json = nlohmann::ordered_json;

Json sample_json(const CushionImpactSample& s) {
  return {{"P", s.normal_impulse},
          {"s", s.cushion_slip_speed},
          {"phi", s.cushion_slip_angle / kDegree},
          {"s_prime", s.bed_slip_speed},
          {"phi_prime", s.bed_slip_angle / kDegree},
          {"v", {s.velocity.x, s.velocity.y, s.velocity.z}},
          {"w", {s.angular_velocity.x, s.angular_velocity.y, s.angular_velocity.z}},
          {"work", s.work}};
}

Json history_json(const std::vector<CushionImpactSample>& history) {
  Json rows = Json::array();
  for (const CushionImpactSample& s : history) rows.push_back(sample_json(s));
  return rows;
}

// The CSV's columns as keys.
Json sweep_row_json(const CushionSweepRow& row, double radius) {
  const PaperIncidence& in = row.incoming;
  return {{"v0", in.speed},
          {"alpha_deg", in.angle / kDegree},
          {"topspin_k", in.topspin * radius / in.speed},
          {"sidespin_k", in.sidespin * radius / in.speed},
          {"speed", row.speed},
          {"angle_deg", row.angle / kDegree}};
}

Json sweep_head(const CushionSweepInfo& info) {
  Json j;
  j["family"] = info.family;
  j["model"] = info.model;
  if (!info.solver.empty()) j["solver"] = info.solver;
  j["preset"] = info.preset;
  return j;
}

}  // namespace

std::string cushion_report_to_json(const Report& report, const std::vector<CushionImpactSample>* history, int indent) {
  Json j = io::report_json(report);
  if (history) j["history"] = history_json(*history);
  return j.dump(indent);
}

std::string cushion_sweep_to_json(const CushionSweepInfo& info, const std::vector<CushionSweepRow>& rows, double radius,
                                  int indent) {
  Json j = sweep_head(info);
  Json array = Json::array();
  for (const CushionSweepRow& row : rows) array.push_back(sweep_row_json(row, radius));
  j["rows"] = array;
  return j.dump(indent);
}

std::string cushion_sweep_history_to_json(const CushionSweepInfo& info, const std::vector<CushionImpactSample>& history,
                                          int indent) {
  Json j = sweep_head(info);
  j["history"] = history_json(history);
  return j.dump(indent);
}

std::string figures_to_json(const std::string& out, const std::string& format, const std::vector<std::string>& files,
                            int indent) {
  return Json{{"out", out}, {"format", format}, {"files", files}}.dump(indent);
}

}  // namespace cueball
