// Scenarios as JSON (io/scenario_json.hpp): the reader, which names every
// error by its JSON path, and the writer, whose output reads back to the same
// simulation bit for bit.
#include "cueball/io/scenario_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "cueball/core/errors.hpp"
#include "cueball/io/table_json.hpp"
#include "cueball/models/cushion/impact.hpp"
#include "cueball/table/rack.hpp"
#include "io/json_input.hpp"
#include "io/json_output.hpp"
#include "core/angles.hpp"

namespace cueball {

namespace {

using Json = nlohmann::json;

// Reads one JSON object, tracking its path for error messages.
class Reader {
 public:
  Reader(const Json& j, std::string path) : j_(j), path_(std::move(path)) {
    if (!j_.is_object()) throw InvalidArgument(path_, path_ + " must be a JSON object");
  }

  void allow_only(std::initializer_list<const char*> keys) const {
    for (const auto& item : j_.items()) {
      bool known = false;
      for (const char* k : keys) known = known || item.key() == k;
      if (!known) {
        std::string list;
        for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
        const std::string f = field(detail::path_key(item.key()));
        throw InvalidArgument(f, f + " is not a known key; allowed: " + list);
      }
    }
  }

  bool has(const char* key) const { return j_.contains(key); }
  const std::string& path() const { return path_; }
  std::string field(const std::string& key) const { return path_ + "." + key; }
  const Json& at(const char* key) const { return j_.at(key); }

  double number(const char* key, double fallback, double lo, double hi, const char* meaning) const {
    if (!has(key)) return fallback;
    return number_at(j_.at(key), field(key), lo, hi, meaning);
  }

  static double number_at(const Json& v, const std::string& f, double lo, double hi, const char* meaning) {
    if (!v.is_number())
      throw InvalidArgument(f, f + " must be a number, got " + std::string(v.type_name()) + " (" + meaning + ")");
    const double x = v.get<double>();
    require_in_range(f.c_str(), x, lo, hi, meaning);
    return x;
  }

  int integer(const char* key, int fallback, int lo, int hi, const char* meaning) const {
    if (!has(key)) return fallback;
    const Json& v = j_.at(key);
    if (!v.is_number_integer())
      throw InvalidArgument(field(key), field(key) + " must be an integer, got " +
                                            (v.is_number() ? std::string("a fraction") : std::string(v.type_name())) +
                                            " (" + meaning + "; allowed [" + std::to_string(lo) + ", " +
                                            std::to_string(hi) + "])");
    // Unsigned values beyond long long (e.g. 2^64 - 1) are out of range, not negative.
    const long long x = v.is_number_unsigned() && v.get<unsigned long long>() > 9000000000000000000ULL
                            ? 9000000000000000000LL
                            : v.get<long long>();
    if (x < lo || x > hi)
      throw InvalidArgument(field(key), static_cast<double>(x), "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                            meaning);
    return static_cast<int>(x);
  }

  std::string text(const char* key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    if (!j_.at(key).is_string())
      throw InvalidArgument(field(key), field(key) + " must be a string, got " + std::string(j_.at(key).type_name()));
    return j_.at(key).get<std::string>();
  }

  // A fixed-length array of numbers.
  template <std::size_t N>
  std::array<double, N> vector(const char* key, std::array<double, N> fallback, double bound, const char* meaning) const {
    if (!has(key)) return fallback;
    const Json& v = j_.at(key);
    if (!v.is_array() || v.size() != N)
      throw InvalidArgument(field(key), field(key) + " must be an array of " + std::to_string(N) + " numbers, got " +
                                            (v.is_array() ? std::to_string(v.size()) + " elements"
                                                          : std::string(v.type_name())) +
                                            " (" + meaning + ")");
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i)
      out[i] = number_at(v[i], field(key) + "[" + std::to_string(i) + "]", -bound, bound, meaning);
    return out;
  }

 private:
  const Json& j_;
  std::string path_;
};

Parameters read_parameters(const Reader& r, const Table& table) {
  const std::string default_preset = cloth_preset_for(table);
  const std::string preset = r.text("preset", default_preset);
  if (preset != "pool" && preset != "snooker" && preset != "carom")
    throw InvalidArgument(r.field("preset"),
                          r.field("preset") + " = " + quote_input(preset) + " is not known; allowed: pool, snooker, carom");
  Parameters p = preset_parameters(preset);
  p.ball = table.ball;
  p.ball.mass = r.number("mass", p.ball.mass, kMassRange.min, kMassRange.max, "ball mass, kg");
  p.ball.radius = r.number("radius", p.ball.radius, kRadiusRange.min, kRadiusRange.max, "ball radius, m");
  p.cloth.sliding_friction = r.number("mu_s", p.cloth.sliding_friction, kSlidingFrictionRange.min,
                                      kSlidingFrictionRange.max, "sliding friction");
  p.cloth.rolling_resistance = r.number("mu_r", p.cloth.rolling_resistance, kRollingResistanceRange.min,
                                        kRollingResistanceRange.max, "rolling resistance");
  p.cloth.spin_friction =
      r.number("mu_sp", p.cloth.spin_friction, kSpinFrictionRange.min, kSpinFrictionRange.max, "spin friction");
  p.cloth.gravity = r.number("g", p.cloth.gravity, kGravityRange.min, kGravityRange.max, "gravity, m/s^2");
  return p;
}

// "cushion": the model by name, then its constants (each model's own
// defaults, cushion_model.hpp).
CushionSettings read_cushion(const Reader& r) {
  r.allow_only({"model", "restitution", "friction", "solver", "paper_steps", "exact_tolerance", "frequency_ratio"});
  const std::string name = r.text("model", to_string(CushionModel::mathavan_2010));
  const std::optional<CushionModel> model = cushion_model_from_string(name);
  if (!model)
    throw InvalidArgument(r.field("model"), r.field("model") + " = " + quote_input(name) +
                                                " is not known; allowed: " + cushion_model_names(""));
  CushionSettings c = default_cushion_settings(*model);
  if (*model == CushionModel::mathavan_2010) {
    c.restitution = r.number("restitution", c.restitution, 1e-9, 1.0, "Mathavan e_e");
    c.friction = r.number("friction", c.friction, 0.0, 0.43, "Mathavan mu_w, at most tan(theta)");
    const std::string solver = r.text("solver", to_string(c.solver));
    const std::optional<CushionSolver> chosen = cushion_solver_from_string(solver);
    if (!chosen)
      throw InvalidArgument(r.field("solver"), r.field("solver") + " = " + quote_input(solver) +
                                                   " is not known; allowed: exact, paper");
    c.solver = *chosen;
    // Each solver's own key, refused with the other (it would be ignored).
    const auto only_with = [&](const char* key, CushionSolver owner) {
      if (c.solver != owner && r.has(key))
        throw InvalidArgument(r.field(key), r.field(key) + " applies to the solver \"" + to_string(owner) +
                                                "\" only, not to " + quote_input(solver));
    };
    only_with("paper_steps", CushionSolver::paper);
    only_with("exact_tolerance", CushionSolver::exact);
    c.paper_steps = r.integer("paper_steps", c.paper_steps, 1, kMaxCushionPaperSteps, "Euler steps per impact");
    c.exact_tolerance =
        r.number("exact_tolerance", c.exact_tolerance, kMinExactTolerance, kMaxExactTolerance, "the exact solver's local error per step");
  }
  const auto only_for = [&](const char* key, CushionModel owner) {
    if (*model != owner && r.has(key))
      throw InvalidArgument(r.field(key), r.field(key) + " applies to the model \"" + to_string(owner) +
                                              "\" only, not to " + quote_input(name));
  };
  only_for("solver", CushionModel::mathavan_2010);
  only_for("paper_steps", CushionModel::mathavan_2010);
  only_for("exact_tolerance", CushionModel::mathavan_2010);
  only_for("frequency_ratio", CushionModel::stronge_compliant);
  if (*model == CushionModel::han_2005) {
    c.restitution = r.number("restitution", c.restitution, 0.0, 1.0, "Han 2005 e");
    c.friction = r.number("friction", c.friction, 0.0, 1.0, "Han 2005 mu");
  } else if (*model == CushionModel::stronge_compliant) {
    c.restitution = r.number("restitution", c.restitution, 1e-9, 1.0, "Stronge's energetic e");
    c.friction = r.number("friction", c.friction, 0.0, 1.0, "mu");
    c.frequency_ratio = r.number("frequency_ratio", c.frequency_ratio, 1.0 + 1e-9, 1000.0,
                                 "Omega, tangential over normal natural frequency");
  }
  return c;
}

std::vector<SimulationBall> read_rack(const Reader& r, const Table& table) {
  r.allow_only({"type", "gap_sigma", "seed"});
  RackOptions options;
  options.gap_sigma = r.number("gap_sigma", 0.0, 0.0, kMaxGapSigma, "random gap scale, m");
  options.seed = static_cast<std::uint64_t>(r.integer("seed", 0, 0, 2147483647, "random seed"));
  const std::string type = r.text("type", "nine_ball");
  std::vector<PlacedBall> placed;
  try {
    if (type == "nine_ball") {
      placed = rack_nine_ball(table, options);
    } else if (type == "eight_ball") {
      placed = rack_eight_ball(table, options);
    } else if (type == "snooker") {
      placed = rack_snooker(table, options);
    } else {
      throw InvalidArgument(r.field("type"), r.field("type") + " = " + quote_input(type) +
                                                 " is not known; allowed: nine_ball, eight_ball, snooker");
    }
  } catch (const InvalidArgument& e) {
    // The rack's own errors name "rack" (or "rack.gap_sigma"): the JSON path is scenario.rack.
    if (e.field().rfind("rack", 0) != 0) throw;
    const std::string what = e.what();
    const std::string rest = what.rfind(e.field(), 0) == 0 ? what.substr(e.field().size()) : ": " + what;
    throw InvalidArgument("scenario." + e.field(), "scenario." + e.field() + rest);
  }
  std::vector<SimulationBall> balls;
  for (const PlacedBall& b : placed) balls.push_back({b.id, b.name, {b.position, {}, {}}});
  return balls;
}

SimulationBall read_ball(const Reader& r) {
  r.allow_only({"id", "name", "position", "velocity", "angular_velocity"});
  SimulationBall b;
  b.id = r.integer("id", 0, 0, 1000000, "ball id");
  b.name = r.text("name", std::to_string(b.id));
  bool printable = b.name.size() <= 32;
  for (char c : b.name) printable = printable && static_cast<unsigned char>(c) >= 0x20 && c != 0x7F;
  if (!printable)
    throw InvalidArgument(r.field("name"), r.field("name") + " = " + quote_input(b.name) +
                                               " must be at most 32 bytes without control characters");
  if (!r.has("position")) throw InvalidArgument(r.field("position"), r.field("position") + " is required ([x, y], m)");
  const auto pos = r.vector<2>("position", {}, 100.0, "centre on the bed, m");
  const auto vel = r.vector<2>("velocity", {}, kMaxSpeed, "m/s");
  const auto spin = r.vector<3>("angular_velocity", {}, kMaxAngularSpeed, "rad/s");
  b.state = {{pos[0], pos[1]}, {vel[0], vel[1]}, {spin[0], spin[1], spin[2]}};
  return b;
}

ShotStrike read_cue(const Reader& r, CueParameters& cue, double radius) {
  r.allow_only({"ball", "speed", "aim_deg", "target", "elevation_deg", "side", "height", "mass", "tip_restitution",
                "end_mass"});
  ShotStrike s;
  s.ball = r.integer("ball", 0, 0, 1000000, "id of the struck ball");
  if (r.has("target") && r.has("aim_deg"))
    throw InvalidArgument(r.field("target"), r.field("target") + ": give either target or aim_deg, not both");
  if (r.has("target")) s.target = r.integer("target", 0, 0, 1000000, "id of the ball to aim at");
  s.strike.speed = r.number("speed", 3.0, 1e-6, kMaxCueSpeed, "cue speed, m/s");
  s.strike.aim = r.number("aim_deg", 0.0, -360.0, 360.0, "aim direction from +x, degrees") * kDegree;
  s.strike.elevation = r.number("elevation_deg", 0.0, 0.0, 89.0, "cue elevation, degrees") * kDegree;
  s.strike.side_offset = r.number("side", 0.0, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset to the right, ball radii") * radius;
  s.strike.height_offset = r.number("height", 0.0, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset above the centre, ball radii") * radius;
  s.given = CueStrikeInUnits{r.number("aim_deg", 0.0, -360.0, 360.0, "aim direction from +x, degrees"),
                             r.number("elevation_deg", 0.0, 0.0, 89.0, "cue elevation, degrees"),
                             r.number("side", 0.0, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset to the right, ball radii"),
                             r.number("height", 0.0, -kMiscueOffsetFraction, kMiscueOffsetFraction, "tip offset above the centre, ball radii")};
  cue.mass = r.number("mass", cue.mass, 0.1, 2.0, "cue mass, kg");
  cue.tip_restitution = r.number("tip_restitution", cue.tip_restitution, 0.0, 1.0, "cue tip restitution");
  cue.end_mass = r.number("end_mass", cue.end_mass, 0.0, kMaxCueEndMass, "cue shaft end mass of squirt, kg; 0: no squirt");
  return s;
}

CueStrikeNoise read_noise(const Reader& r, double radius) {
  r.allow_only({"speed", "aim_deg", "elevation_deg", "side", "height"});
  CueStrikeNoise n;
  n.speed = r.number("speed", 0.0, 0.0, 5.0, "sigma of the cue speed, m/s");
  n.aim = r.number("aim_deg", 0.0, 0.0, 30.0, "sigma of the aim, degrees") * kDegree;
  n.elevation = r.number("elevation_deg", 0.0, 0.0, 30.0, "sigma of the elevation, degrees") * kDegree;
  n.side_offset = r.number("side", 0.0, 0.0, 0.5, "sigma of the side offset, ball radii") * radius;
  n.height_offset = r.number("height", 0.0, 0.0, 0.5, "sigma of the height offset, ball radii") * radius;
  return n;
}

// An error of validate_simulation_input() (or of a cushion or jaw's impact
// model), which names library fields (radius, mu_w, h, balls[3].speed), as
// the JSON path the user wrote: what to change to fix it.
InvalidArgument relabelled(const InvalidArgument& e, const Json& j, const std::vector<std::string>& origins) {
  const std::string& f = e.field();
  const std::string what = e.what();
  if (f.rfind("scenario", 0) == 0) return e;
  const auto given = [&](const char* object, const char* key) {
    return j.contains(object) && j.at(object).is_object() && j.at(object).contains(key);
  };
  const auto at = [&](const std::string& path) { return InvalidArgument(path, path + ": " + what); };
  const bool table_object = j.contains("table") && j.at("table").is_object();
  // The ball's radius and mass come from "parameters", else from the table.
  const auto ball_field = [&](const char* key) {
    if (given("parameters", key) || !table_object) return "scenario.parameters." + std::string(key);
    return std::string("scenario.table.ball");
  };
  for (const char* key : {"mass", "radius", "mu_s", "mu_r", "mu_sp", "g"}) {
    if (f == key) return at(std::string(key) == "mass" || std::string(key) == "radius" ? ball_field(key) : "scenario.parameters." + f);
  }
  if (f == "cushion_restitution" || f == "e_e") return at("scenario.cushion.restitution");
  if (f == "cushion_paper_steps") return at("scenario.cushion.paper_steps");
  if (f == "cushion_exact_tolerance") return at("scenario.cushion.exact_tolerance");
  if (f == "cushion_frequency_ratio") return at("scenario.cushion.frequency_ratio");
  if (f == "cushion_friction" || f == "mu_w") {
    // mu_w's bounds depend on the contact angle (radius, cushion height) and on mu_s.
    if (given("cushion", "friction")) return at("scenario.cushion.friction");
    if (given("parameters", "mu_s")) return at("scenario.parameters.mu_s");
    if (given("parameters", "radius")) return at("scenario.parameters.radius");
    return at(table_object ? "scenario.table" : "scenario.cushion.friction");
  }
  if (f == "h" || f == "sin_theta") {
    // A cushion or jaw contact height outside (R, 2R): the ball's radius or the table's heights.
    return at(given("parameters", "radius") ? "scenario.parameters.radius" : table_object ? "scenario.table" : ball_field("radius"));
  }
  for (const char* key : {"restitution", "friction", "friction_excess", "friction_decay"})
    if (f == key) return at("scenario.ball_collision." + f);
  if (f == "max_events") return at("scenario.max_events");
  if (f.rfind("balls[", 0) == 0) {
    const std::size_t close = f.find(']');
    const std::size_t i = close == std::string::npos ? origins.size() : std::stoul(f.substr(6, close - 6));
    const std::string origin = i < origins.size() ? origins[i] : "scenario.balls";
    std::string key = close == std::string::npos || close + 2 > f.size() ? "" : f.substr(close + 2);
    if (key == "speed") key = "velocity";
    if (key == "angular speed") key = "angular_velocity";
    const std::string path = origin == "scenario.rack" || key.empty() ? origin : origin + "." + key;
    // "balls[3].position = (...) is off the table" -> "scenario.balls[1].position = (...) ..."
    const std::string lib = f.substr(0, close + 1) + ".";
    std::string rest = what.rfind(lib, 0) == 0 ? what.substr(lib.size()) : what;
    if (rest.rfind(key, 0) == 0 && !key.empty() && path.size() > key.size() &&
        path.compare(path.size() - key.size(), key.size(), key) == 0)
      return InvalidArgument(path, path + rest.substr(key.size()));
    if (origin == "scenario.rack") rest = "a ball the rack placed: " + rest;
    return InvalidArgument(path, path + ": " + rest);
  }
  return at(table_object ? "scenario.table" : "scenario");
}

}  // namespace

namespace io {

Json vec(Vec2 v) { return Json::array({v.x, v.y}); }
Json vec(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

Json state_json(const BallState& s) {
  return {{"position", vec(s.position)}, {"velocity", vec(s.velocity)}, {"angular_velocity", vec(s.angular_velocity)}};
}

// A value u in the scenario's units whose conversion u * unit (what the
// reader computes) is x exactly: `given` when it is one, else the one nearest
// x / unit within 64 doubles of it, else x / unit itself.
double in_units(double x, double unit, std::optional<double> given) {
  if (given && *given * unit == x) return *given;
  const double u = x / unit;
  if (u * unit == x) return u;
  double up = u, down = u;
  for (int k = 0; k < 64; ++k) {
    up = std::nextafter(up, std::numeric_limits<double>::infinity());
    if (up * unit == x) return up;
    down = std::nextafter(down, -std::numeric_limits<double>::infinity());
    if (down * unit == x) return down;
  }
  return u;
}

std::optional<double> given_part(const std::optional<CueStrikeInUnits>& g, double CueStrikeInUnits::*field) {
  if (!g) return std::nullopt;
  return (*g).*field;
}

Json cue_json(const Scenario& s) {
  const ShotStrike& c = *s.cue;
  const double radius = s.settings.parameters.ball.radius;
  Json j;
  j["ball"] = c.ball;
  if (c.target) {
    j["target"] = *c.target;
  } else {
    j["aim_deg"] = in_units(c.strike.aim, kDegree, given_part(c.given, &CueStrikeInUnits::aim_deg));
  }
  j["speed"] = c.strike.speed;
  j["elevation_deg"] = in_units(c.strike.elevation, kDegree, given_part(c.given, &CueStrikeInUnits::elevation_deg));
  j["side"] = in_units(c.strike.side_offset, radius, given_part(c.given, &CueStrikeInUnits::side));
  j["height"] = in_units(c.strike.height_offset, radius, given_part(c.given, &CueStrikeInUnits::height));
  j["mass"] = s.cue_parameters.mass;
  j["tip_restitution"] = s.cue_parameters.tip_restitution;
  j["end_mass"] = s.cue_parameters.end_mass;
  return j;
}

// The ball and cloth as the "parameters" object of a scenario (and of a result).
Json parameters_json(const Parameters& p) {
  return {{"mass", p.ball.mass},
          {"radius", p.ball.radius},
          {"mu_s", p.cloth.sliding_friction},
          {"mu_r", p.cloth.rolling_resistance},
          {"mu_sp", p.cloth.spin_friction},
          {"g", p.cloth.gravity}};
}

Json scenario_json(const Scenario& s) {
  const Parameters& p = s.settings.parameters;
  const double radius = p.ball.radius;
  Json j;
  j["table"] = Json::parse(table_to_json(s.table));
  j["parameters"] = parameters_json(p);
  const CushionSettings& cushion = s.settings.cushion;
  j["cushion"] = {{"model", to_string(cushion.model)}, {"restitution", cushion.restitution}, {"friction", cushion.friction}};
  if (cushion.model == CushionModel::mathavan_2010) {
    j["cushion"]["solver"] = to_string(cushion.solver);
    if (cushion.solver == CushionSolver::paper) j["cushion"]["paper_steps"] = cushion.paper_steps;
    if (cushion.solver == CushionSolver::exact && cushion.exact_tolerance != CushionSettings{}.exact_tolerance) {
      j["cushion"]["exact_tolerance"] = cushion.exact_tolerance;
    }
  }
  if (cushion.model == CushionModel::stronge_compliant) j["cushion"]["frequency_ratio"] = cushion.frequency_ratio;
  j["ball_collision"] = ball_collision_json<Json>(s.settings);
  j["max_events"] = s.settings.max_events;
  Json balls = Json::array();
  for (const SimulationBall& ball : s.balls) {
    Json jb = state_json(ball.state);
    jb["id"] = ball.id;
    jb["name"] = ball.name;
    balls.push_back(jb);
  }
  j["balls"] = balls;
  if (s.cue) j["cue"] = cue_json(s);
  j["noise"] = {{"speed", s.noise.speed},
                {"aim_deg", in_units(s.noise.aim, kDegree, std::nullopt)},
                {"elevation_deg", in_units(s.noise.elevation, kDegree, std::nullopt)},
                {"side", in_units(s.noise.side_offset, radius, std::nullopt)},
                {"height", in_units(s.noise.height_offset, radius, std::nullopt)}};
  return j;
}

}  // namespace io

using io::scenario_json;

std::string scenario_to_json(const Scenario& s, int indent) { return scenario_json(s).dump(indent); }

Scenario scenario_from_document(std::string_view json_text) {
  if (json_text.size() > kMaxScenarioBytes) return scenario_from_json(json_text);  // its size error
  const Json j = detail::parse_json(json_text, "scenario");
  if (j.is_object() && j.contains("events") && j.contains("scenario")) {
    if (!j.at("scenario").is_object())
      throw InvalidArgument("scenario", "scenario: the result's \"scenario\" must be a scenario object, got " +
                                            std::string(j.at("scenario").type_name()));
    return scenario_from_json(j.at("scenario").dump());
  }
  return scenario_from_json(json_text);
}

Scenario scenario_from_json(std::string_view json_text) {
  if (json_text.size() > kMaxScenarioBytes)
    throw InvalidArgument("scenario", "scenario: " + std::to_string(json_text.size()) + " bytes of JSON is more than the " +
                                          std::to_string(kMaxScenarioBytes) + " allowed (16 MiB)");
  const Json j = detail::parse_json(json_text, "scenario");
  const Reader r(j, "scenario");
  r.allow_only({"table", "parameters", "cushion", "ball_collision", "rack", "balls", "cue", "noise", "max_events"});
  Scenario s;
  if (r.has("table")) {
    const Json& t = r.at("table");
    if (t.is_string()) {
      const std::string name = t.get<std::string>();
      if (name != "pool_9ft" && name != "snooker_12ft" && name != "carom_10ft")
        throw InvalidArgument("scenario.table", "scenario.table = " + quote_input(name) +
                                                    " is not a known table; allowed: pool_9ft, snooker_12ft, carom_10ft, "
                                                    "or a table object");
      s.table = preset_table(name);
    } else if (t.is_object()) {
      s.table = table_from_json(t.dump(), "scenario.table");
    } else {
      throw InvalidArgument("scenario.table", "scenario.table must be a table name or a table object, got " +
                                                  std::string(t.type_name()));
    }
  } else {
    s.table = pool_table_9ft();
  }
  const Json empty = Json::object();
  if (r.has("parameters")) {
    Reader(r.at("parameters"), "scenario.parameters").allow_only({"preset", "mass", "radius", "mu_s", "mu_r", "mu_sp", "g"});
  }
  s.settings.parameters = read_parameters(Reader(r.has("parameters") ? r.at("parameters") : empty, "scenario.parameters"), s.table);
  if (r.has("cushion")) s.settings.cushion = read_cushion(Reader(r.at("cushion"), "scenario.cushion"));
  if (r.has("ball_collision")) {
    const Reader c(r.at("ball_collision"), "scenario.ball_collision");
    c.allow_only({"model", "restitution", "friction", "friction_excess", "friction_decay"});
    const std::string name = c.text("model", to_string(BallCollisionModel::coulomb_impulse));
    const std::optional<BallCollisionModel> model = ball_collision_model_from_string(name);
    if (!model)
      throw InvalidArgument(c.field("model"), c.field("model") + " = " + quote_input(name) +
                                                  " is not known; allowed: " + ball_collision_model_names(""));
    // coulomb_impulse's speed-dependent friction: mathavan_2014's is constant.
    // A 0 changes nothing and is accepted: results written before this check
    // carry both keys at 0 under every model, and replay.
    for (const char* key : {"friction_excess", "friction_decay"})
      if (*model != BallCollisionModel::coulomb_impulse && c.has(key) &&
          c.number(key, 0.0, 0.0, 100.0, "coulomb_impulse's speed-dependent friction") != 0.0)
        throw InvalidArgument(c.field(key), c.field(key) + " applies to the model \"" +
                                                to_string(BallCollisionModel::coulomb_impulse) + "\" only, not to " +
                                                quote_input(name));
    s.settings.ball_collision_model = *model;
    s.settings.ball_collision = default_ball_collision(*model);  // the model's own constants unless given
    BallCollisionParameters& b = s.settings.ball_collision;
    b.restitution = c.number("restitution", b.restitution, 0.0, 1.0, "ball-ball restitution");
    b.friction = c.number("friction", b.friction, 0.0, 1.0, "ball-ball friction at high slip speed");
    b.friction_excess = c.number("friction_excess", b.friction_excess, 0.0, 1.0, "extra friction at zero slip speed");
    b.friction_decay = c.number("friction_decay", b.friction_decay, 0.0, 100.0, "decay of the extra friction, s/m");
  }
  s.settings.max_events = r.integer("max_events", s.settings.max_events, 1, kMaxEvents, "event limit");
  // Where each ball of s.balls came from, as the user wrote it: "scenario.rack"
  // or "scenario.balls[k]" (with a rack, s.balls is not the "balls" list).
  std::vector<std::string> origins;
  if (r.has("rack")) {
    s.balls = read_rack(Reader(r.at("rack"), "scenario.rack"), s.table);
    origins.assign(s.balls.size(), "scenario.rack");
  }
  if (r.has("balls")) {
    const Json& list = r.at("balls");
    if (!list.is_array())
      throw InvalidArgument("scenario.balls", "scenario.balls must be an array of balls, got " + std::string(list.type_name()));
    if (list.size() > kMaxBalls)
      throw InvalidArgument("scenario.balls", "scenario.balls has " + std::to_string(list.size()) +
                                                  " balls; allowed: at most " + std::to_string(kMaxBalls));
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string path = "scenario.balls[" + std::to_string(i) + "]";
      const SimulationBall b = read_ball(Reader(list[i], path));
      bool replaced = false;
      for (std::size_t k = 0; k < s.balls.size(); ++k) {
        if (s.balls[k].id == b.id && origins[k] == "scenario.rack") {
          s.balls[k] = b;
          origins[k] = path;
          replaced = true;
        }
      }
      if (!replaced) {
        s.balls.push_back(b);
        origins.push_back(path);
      }
    }
  }
  if (s.balls.size() > kMaxBalls)
    throw InvalidArgument("scenario.balls", "scenario.rack and scenario.balls place " + std::to_string(s.balls.size()) +
                                                " balls; allowed: at most " + std::to_string(kMaxBalls));
  if (s.balls.empty()) {
    s.balls = read_rack(Reader(empty, "scenario.rack"), s.table);
    origins.assign(s.balls.size(), "scenario.rack");
  }
  const double radius = s.settings.parameters.ball.radius;
  if (r.has("cue")) s.cue = read_cue(Reader(r.at("cue"), "scenario.cue"), s.cue_parameters, radius);
  if (r.has("noise")) s.noise = read_noise(Reader(r.at("noise"), "scenario.noise"), radius);

  // Everything that can be checked before running: balls, table, constants,
  // and the impact model of every cushion and jaw
  // (validate_simulation_input). Library fields become the JSON paths the user wrote.
  try {
    validate_simulation_input(s.table, s.balls, s.settings);
  } catch (const InvalidArgument& e) {
    throw relabelled(e, j, origins);
  }
  if (s.cue) {
    if (!find_ball(s.balls, s.cue->ball))
      throw InvalidArgument("scenario.cue.ball", "scenario.cue.ball = " + std::to_string(s.cue->ball) + " is not a ball on the table");
    if (s.cue->target && (!find_ball(s.balls, *s.cue->target) || *s.cue->target == s.cue->ball))
      throw InvalidArgument("scenario.cue.target", "scenario.cue.target = " + std::to_string(*s.cue->target) +
                                                       " is not another ball on the table");
    try {
      validate(resolved_strike(s, s.cue->strike), s.settings.parameters.ball, s.cue_parameters);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument("scenario.cue." + e.field(), std::string("scenario.cue: ") + e.what());
    }
  }
  return s;
}

Scenario default_scenario() {
  return scenario_from_json(R"({
    "table": "pool_9ft",
    "rack": { "type": "nine_ball" },
    "cue": { "ball": 0, "target": 1, "speed": 7.0 },
    "noise": { "speed": 0.1, "aim_deg": 0.2, "side": 0.02, "height": 0.02 }
  })");
}

CueStrikeNoise noise_from_json(std::string_view json_text, double radius, const std::string& path) {
  const Json j = detail::parse_json(json_text, path);
  return read_noise(Reader(j, path), radius);
}

}  // namespace cueball
