// Tracked shots and calibration reports as JSON (io/tracked_shots_json.hpp).
#include "cueball/io/tracked_shots_json.hpp"

#include <cmath>
#include <limits>

#include "cueball/core/errors.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/models/cushion/model.hpp"
#include "cueball/simulation/scenario.hpp"
#include "io/json_input.hpp"
#include "io/json_output.hpp"

namespace cueball {

namespace {

using json = nlohmann::json;
using ordered_json = nlohmann::ordered_json;

std::string type_of(const json& j) { return j.type_name(); }

[[noreturn]] void wrong_type(const json& j, const std::string& path, const std::string& wanted) {
  const std::string shown = j.is_string() ? quote_input(j.get<std::string>()) : one_line(j.dump()).substr(0, 60);
  throw InvalidArgument(path, path + " = " + shown + " is a " + type_of(j) + "; allowed: " + wanted);
}

std::vector<double> numbers(const json& j, const std::string& path) {
  if (!j.is_array()) wrong_type(j, path, "an array of numbers");
  if (j.size() > kMaxTrackedSamples)
    throw InvalidArgument(path, path + " has " + std::to_string(j.size()) + " values; allowed: at most " +
                                    std::to_string(kMaxTrackedSamples));
  std::vector<double> out;
  out.reserve(j.size());
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_number()) wrong_type(j[i], path + "[" + std::to_string(i) + "]", "a number");
    out.push_back(j[i].get<double>());
  }
  return out;
}

void allow_only(const json& j, const std::string& path, std::initializer_list<const char*> keys) {
  for (const auto& [k, v] : j.items()) {
    bool known = false;
    for (const char* key : keys) known = known || k == key;
    if (!known) {
      std::string list;
      for (const char* key : keys) list += (list.empty() ? "" : ", ") + std::string(key);
      throw InvalidArgument(path + "." + detail::path_key(k),
                            path + "." + detail::path_key(k) + " is not a known key; allowed: " + list);
    }
  }
}

TrackedBall read_ball(const std::string& name, const json& j, const std::string& path) {
  if (!j.is_object()) wrong_type(j, path, "an object {\"t\": [...], \"x\": [...], \"y\": [...]}");
  allow_only(j, path, {"t", "x", "y"});
  TrackedBall b;
  b.name = name;
  for (const char* key : {"t", "x", "y"})
    if (!j.contains(key)) throw InvalidArgument(path + "." + key, path + "." + key + " is missing (each ball needs t, x and y)");
  b.t = numbers(j["t"], path + ".t");
  b.x = numbers(j["x"], path + ".x");
  b.y = numbers(j["y"], path + ".y");
  return b;
}

std::string id_text(const json& j, const std::string& path) {
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number_integer()) return std::to_string(j.get<long long>());
  if (j.is_number_unsigned()) return std::to_string(j.get<unsigned long long>());
  wrong_type(j, path, "an integer or a string");
}

TrackedShot read_shot(const json& j, const std::string& path, std::size_t position) {
  if (!j.is_object()) wrong_type(j, path, "an object");
  allow_only(j, path, {"cue_ball", "balls", "shot_id", "id", "index"});
  TrackedShot s;
  s.id = std::to_string(position);
  for (const char* key : {"index", "id", "shot_id"})  // the last one given wins
    if (j.contains(key)) s.id = id_text(j[key], path + "." + key);
  if (!j.contains("cue_ball")) throw InvalidArgument(path + ".cue_ball", path + ".cue_ball is missing (the struck ball's name)");
  if (!j["cue_ball"].is_string()) wrong_type(j["cue_ball"], path + ".cue_ball", "a ball's name");
  s.cue_ball = j["cue_ball"].get<std::string>();
  if (!j.contains("balls")) throw InvalidArgument(path + ".balls", path + ".balls is missing");
  const json& balls = j["balls"];
  if (!balls.is_object()) wrong_type(balls, path + ".balls", "an object of balls by name");
  for (const auto& [name, b] : balls.items()) s.balls.push_back(read_ball(name, b, path + ".balls." + detail::path_key(name)));
  return s;
}

void read_table(const json& root, TrackedShots& out) {
  if (!root.contains("table")) throw InvalidArgument("table", "table is missing (a preset name or a table object)");
  const json& t = root["table"];
  if (t.is_string()) {
    out.table_name = t.get<std::string>();
    try {
      out.table = preset_table(out.table_name);
    } catch (const InvalidArgument&) {
      throw InvalidArgument("table", "table = " + quote_input(out.table_name) +
                                         " is not a preset; allowed: pool_9ft, snooker_12ft, carom_10ft or a table object");
    }
  } else if (t.is_object()) {
    out.table = table_from_json(t.dump(), "table");
    out.table_name = out.table.name;
  } else {
    wrong_type(t, "table", "a preset name or a table object");
  }
}

ordered_json constants_json(const FitModel& m, const std::string& table_name) {
  ordered_json j;
  if (table_name == "pool_9ft" || table_name == "snooker_12ft" || table_name == "carom_10ft")
    j["table"] = table_name;
  else
    j["table"] = ordered_json::parse(table_to_json(m.table));
  const Parameters& p = m.settings.parameters;
  j["parameters"] = {{"mass", p.ball.mass},
                     {"radius", p.ball.radius},
                     {"mu_s", p.cloth.sliding_friction},
                     {"mu_r", p.cloth.rolling_resistance},
                     {"mu_sp", p.cloth.spin_friction},
                     {"g", p.cloth.gravity}};
  const CushionSettings& c = m.settings.cushion;
  j["cushion"] = {{"model", to_string(c.model)}, {"restitution", c.restitution}, {"friction", c.friction}};
  if (c.model == CushionModel::stronge_compliant) j["cushion"]["frequency_ratio"] = c.frequency_ratio;
  // The ball-ball model the strikes were fitted under (not fitted itself),
  // with its constants, in the scenario's form.
  j["ball_collision"] = io::ball_collision_json<ordered_json>(m.settings);
  return j;
}

ordered_json number_or_null(double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr); }

ordered_json summary_json(const FitSummary& s) {
  return {{"shots", s.shots},
          {"cue_rmse_median", number_or_null(s.cue_rmse_median)},
          {"cue_rmse_p90", number_or_null(s.cue_rmse_p90)},
          {"cue_rmse_mean", number_or_null(s.cue_rmse_mean)},
          {"all_rmse_median", number_or_null(s.all_rmse_median)},
          {"all_rmse_p90", number_or_null(s.all_rmse_p90)},
          {"all_rmse_mean", number_or_null(s.all_rmse_mean)},
          {"object_rmse_median", number_or_null(s.object_rmse_median)},
          {"object_rmse_p90", number_or_null(s.object_rmse_p90)},
          {"contact_mismatches", s.contact_mismatches},
          {"seconds_per_shot", s.seconds_per_shot}};
}

ordered_json shot_json(const ShotReport& r) {
  ordered_json j;
  j["id"] = r.id;
  j["held_out"] = r.held_out;
  const StrikeFit& f = r.fit;
  j["strike"] = {{"speed", f.action.speed},   {"aim_deg", f.action.aim_deg}, {"elevation_deg", f.action.elevation_deg},
                 {"side", f.action.side},     {"height", f.action.height}, {"strike_time", f.strike_time}};
  j["cue_rmse"] = number_or_null(f.cue_rmse);
  j["all_rmse"] = number_or_null(f.all_rmse);
  ordered_json balls = ordered_json::object();
  for (std::size_t k = 0; k < r.balls.size(); ++k) {
    const bool have = k < f.ball_rmse.size();
    balls[r.balls[k]] = {{"rmse", number_or_null(have ? f.ball_rmse[k] : std::numeric_limits<double>::quiet_NaN())},
                         {"moved_simulated", have && f.moved_simulated[k] != 0}};
  }
  j["balls"] = std::move(balls);
  const auto first = static_cast<std::size_t>(f.first_contact);
  j["first_contact"] = f.first_contact >= 0 && first < r.balls.size() ? ordered_json(r.balls[first]) : ordered_json(nullptr);
  j["contact_mismatch"] = f.contact_mismatch;
  j["simulations"] = f.simulations;
  j["seconds"] = f.seconds;
  j["notes"] = r.notes;
  return j;
}

}  // namespace

TrackedShots tracked_shots_from_json(std::string_view text) {
  if (text.size() > kMaxTrackedShotsBytes)
    throw InvalidArgument("shots", "the tracked shots are " + std::to_string(text.size()) + " bytes; allowed: at most " +
                                       std::to_string(kMaxTrackedShotsBytes));
  // The reader names paths from the document's root ("shots[0].balls.red.t[1]").
  const std::string root_name = "shots file";
  json root;
  try {
    root = detail::parse_json(text, root_name);
  } catch (const InvalidArgument& e) {
    const std::string prefix = root_name + ".";
    if (e.field().rfind(prefix, 0) != 0) throw;
    std::string message = e.what();
    if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
    throw InvalidArgument(e.field().substr(prefix.size()), message);
  }
  if (!root.is_object()) wrong_type(root, "shots file", "an object {\"table\": .., \"shots\": [..]}");
  for (const auto& [k, v] : root.items())
    if (k != "table" && k != "shots" && !v.is_string())
      throw InvalidArgument(detail::path_key(k), detail::path_key(k) +
                                                     " is not a known key; allowed: table, shots, and descriptions "
                                                     "(a key whose value is a string)");
  TrackedShots out;
  read_table(root, out);
  if (!root.contains("shots")) throw InvalidArgument("shots", "shots is missing (an array of tracked shots)");
  const json& shots = root["shots"];
  if (!shots.is_array()) wrong_type(shots, "shots", "an array of tracked shots");
  if (shots.empty()) throw InvalidArgument("shots", "shots is empty; allowed: 1 to " + std::to_string(kMaxTrackedShots) + " shots");
  if (shots.size() > kMaxTrackedShots)
    throw InvalidArgument("shots", "shots has " + std::to_string(shots.size()) + " shots; allowed: at most " +
                                       std::to_string(kMaxTrackedShots));
  for (std::size_t i = 0; i < shots.size(); ++i) {
    const std::string path = "shots[" + std::to_string(i) + "]";
    out.shots.push_back(read_shot(shots[i], path, i));
    validate_tracked_shot(out.shots.back(), out.table, path);
  }
  return out;
}

std::string constants_to_json(const FitModel& model, const std::string& table_name, int indent) {
  return constants_json(model, table_name).dump(indent);
}

FitModel fit_model_from_json(std::string_view json_text, const TrackedShots& shots) {
  const Scenario s = scenario_from_json(json_text);
  FitModel m;
  m.table = shots.table;
  m.settings = s.settings;
  m.cue = s.cue_parameters;
  if (std::abs(s.settings.parameters.ball.radius - shots.table.ball.radius) > 1e-12)
    throw InvalidArgument("scenario.parameters.radius",
                          "scenario.parameters.radius = " + format_number(s.settings.parameters.ball.radius) +
                              " differs from the tracked shots' table's ball radius " +
                              format_number(shots.table.ball.radius));
  return m;
}

std::string calibration_report_to_json(const CalibrationReport& r, int indent) {
  ordered_json j;
  j["table"] = r.table_name;
  j["constants"] = constants_json(r.model, r.table_name);
  j["start_constants"] = constants_json(r.start, r.table_name);
  j["summary"] = {{"training", summary_json(r.training)}, {"held_out", summary_json(r.held_out)}};
  j["constant_evaluations"] = r.constant_evaluations;
  j["constant_iterations"] = r.constant_iterations;
  j["constant_restarts"] = r.constant_restarts;
  ordered_json spread = ordered_json::object();
  for (const ConstantSpread& c : r.spread)
    spread[c.name] = {{"value", c.value}, {"std_dev", c.std_dev}, {"p05", c.p05}, {"p95", c.p95}};
  j["uncertainty"] = {{"method", r.spread.empty() ? "none" : "bootstrap over the training shots"},
                      {"replicates", r.bootstrap_replicates},
                      {"constants", std::move(spread)}};
  j["seconds"] = r.seconds;
  ordered_json shots = ordered_json::array();
  for (const ShotReport& s : r.shots) shots.push_back(shot_json(s));
  j["shots"] = std::move(shots);
  return j.dump(indent);
}

}  // namespace cueball
