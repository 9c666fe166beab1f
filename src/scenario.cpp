// Scenario JSON in, simulation result JSON out; see scenario.hpp for the
// schema. nlohmann-json stays inside this file.
#include "cueball/scenario.hpp"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <numbers>
#include <set>

#include <nlohmann/json.hpp>

#include "cueball/errors.hpp"
#include "cueball/rack.hpp"
#include "json_input.hpp"

namespace cueball {

namespace {

using Json = nlohmann::json;
constexpr double kDegree = std::numbers::pi / 180.0;

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
        throw InvalidArgument(field(item.key()), field(item.key()) + " is not a known key; allowed: " + list);
      }
    }
  }

  bool has(const char* key) const { return j_.contains(key); }
  std::string field(const std::string& key) const { return path_ + "." + key; }
  const Json& at(const char* key) const { return j_.at(key); }

  double number(const char* key, double fallback, double lo, double hi, const char* meaning) const {
    if (!has(key)) return fallback;
    return number_at(j_.at(key), field(key), lo, hi, meaning);
  }

  static double number_at(const Json& v, const std::string& f, double lo, double hi, const char* meaning) {
    if (!v.is_number()) throw InvalidArgument(f, f + " must be a number (" + meaning + ")");
    const double x = v.get<double>();
    require_in_range(f.c_str(), x, lo, hi, meaning);
    return x;
  }

  int integer(const char* key, int fallback, int lo, int hi, const char* meaning) const {
    if (!has(key)) return fallback;
    const Json& v = j_.at(key);
    if (!v.is_number_integer()) throw InvalidArgument(field(key), field(key) + " must be an integer (" + meaning + ")");
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
    if (!j_.at(key).is_string()) throw InvalidArgument(field(key), field(key) + " must be a string");
    return j_.at(key).get<std::string>();
  }

  // A fixed-length array of numbers.
  template <std::size_t N>
  std::array<double, N> vector(const char* key, std::array<double, N> fallback, double bound, const char* meaning) const {
    if (!has(key)) return fallback;
    const Json& v = j_.at(key);
    if (!v.is_array() || v.size() != N)
      throw InvalidArgument(field(key), field(key) + " must be an array of " + std::to_string(N) + " numbers (" +
                                            meaning + ")");
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
  const std::string default_preset = table.name.find("snooker") != std::string::npos ? "snooker" : "pool";
  Parameters p = preset_parameters(r.text("preset", default_preset));
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

std::vector<SimulationBall> read_rack(const Reader& r, const Table& table) {
  r.allow_only({"type", "gap_sigma", "seed"});
  RackOptions options;
  options.gap_sigma = r.number("gap_sigma", 0.0, 0.0, kMaxGapSigma, "random gap scale, m");
  options.seed = static_cast<std::uint64_t>(r.integer("seed", 0, 0, 2147483647, "random seed"));
  const std::string type = r.text("type", "nine_ball");
  std::vector<PlacedBall> placed;
  if (type == "nine_ball") {
    placed = rack_nine_ball(table, options);
  } else if (type == "eight_ball") {
    placed = rack_eight_ball(table, options);
  } else if (type == "snooker") {
    placed = rack_snooker(table, options);
  } else {
    throw InvalidArgument(r.field("type"), r.field("type") + " = '" + type +
                                               "' is not known; allowed: nine_ball, eight_ball, snooker");
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
  if (!r.has("position")) throw InvalidArgument(r.field("position"), r.field("position") + " is required ([x, y], m)");
  const auto pos = r.vector<2>("position", {}, 100.0, "centre on the bed, m");
  const auto vel = r.vector<2>("velocity", {}, kMaxSpeed, "m/s");
  const auto spin = r.vector<3>("angular_velocity", {}, kMaxAngularSpeed, "rad/s");
  b.state = {{pos[0], pos[1]}, {vel[0], vel[1]}, {spin[0], spin[1], spin[2]}};
  return b;
}

ShotStrike read_cue(const Reader& r, CueParameters& cue, double radius) {
  r.allow_only({"ball", "speed", "aim_deg", "target", "elevation_deg", "side", "height", "mass", "tip_restitution"});
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
  cue.mass = r.number("mass", cue.mass, 0.1, 2.0, "cue mass, kg");
  cue.tip_restitution = r.number("tip_restitution", cue.tip_restitution, 0.0, 1.0, "cue tip restitution");
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

const SimulationBall* find_ball(const std::vector<SimulationBall>& balls, int id) {
  for (const SimulationBall& b : balls)
    if (b.id == id) return &b;
  return nullptr;
}

Json vec(Vec2 v) { return Json::array({v.x, v.y}); }
Json vec(Vec3 v) { return Json::array({v.x, v.y, v.z}); }

Json state_json(const BallState& s) {
  return {{"position", vec(s.position)}, {"velocity", vec(s.velocity)}, {"angular_velocity", vec(s.angular_velocity)}};
}

}  // namespace

Scenario scenario_from_json(std::string_view json_text) {
  const Json j = detail::parse_json(json_text, "scenario");
  const Reader r(j, "scenario");
  r.allow_only({"table", "parameters", "cushion", "ball_collision", "rack", "balls", "cue", "noise", "max_events"});
  Scenario s;
  if (r.has("table")) {
    const Json& t = r.at("table");
    if (t.is_string()) {
      try {
        s.table = preset_table(t.get<std::string>());
      } catch (const InvalidArgument& e) {
        throw InvalidArgument("scenario.table", std::string("scenario.table: ") + e.what());
      }
    } else {
      s.table = table_from_json(t.dump(), "scenario.table");
    }
  } else {
    s.table = pool_table_9ft();
  }
  const Json empty = Json::object();
  s.settings.parameters = read_parameters(Reader(r.has("parameters") ? r.at("parameters") : empty, "scenario.parameters"), s.table);
  if (r.has("parameters")) {
    Reader(r.at("parameters"), "scenario.parameters").allow_only({"preset", "mass", "radius", "mu_s", "mu_r", "mu_sp", "g"});
  }
  if (r.has("cushion")) {
    const Reader c(r.at("cushion"), "scenario.cushion");
    c.allow_only({"restitution", "friction"});
    s.settings.cushion_restitution = c.number("restitution", s.settings.cushion_restitution, 1e-9, 1.0, "Mathavan e_e");
    s.settings.cushion_friction = c.number("friction", s.settings.cushion_friction, 0.0, 0.43, "Mathavan mu_w, at most tan(theta)");
  }
  if (r.has("ball_collision")) {
    const Reader c(r.at("ball_collision"), "scenario.ball_collision");
    c.allow_only({"restitution", "friction", "friction_excess", "friction_decay"});
    BallCollisionParameters& b = s.settings.ball_collision;
    b.restitution = c.number("restitution", b.restitution, 0.0, 1.0, "ball-ball restitution");
    b.friction = c.number("friction", b.friction, 0.0, 1.0, "ball-ball friction at high slip speed");
    b.friction_excess = c.number("friction_excess", b.friction_excess, 0.0, 1.0, "extra friction at zero slip speed");
    b.friction_decay = c.number("friction_decay", b.friction_decay, 0.0, 100.0, "decay of the extra friction, s/m");
  }
  s.settings.max_events = r.integer("max_events", s.settings.max_events, 1, 100000000, "event limit");
  if (r.has("rack")) s.balls = read_rack(Reader(r.at("rack"), "scenario.rack"), s.table);
  if (r.has("balls")) {
    const Json& list = r.at("balls");
    if (!list.is_array()) throw InvalidArgument("scenario.balls", "scenario.balls must be an array of balls");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const SimulationBall b = read_ball(Reader(list[i], "scenario.balls[" + std::to_string(i) + "]"));
      bool replaced = false;
      for (SimulationBall& existing : s.balls) {
        if (existing.id == b.id && r.has("rack")) {
          existing = b;
          replaced = true;
        }
      }
      if (!replaced) s.balls.push_back(b);
    }
  }
  if (s.balls.empty()) s.balls = read_rack(Reader(empty, "scenario.rack"), s.table);
  const double radius = s.settings.parameters.ball.radius;
  if (r.has("cue")) s.cue = read_cue(Reader(r.at("cue"), "scenario.cue"), s.cue_parameters, radius);
  if (r.has("noise")) s.noise = read_noise(Reader(r.at("noise"), "scenario.noise"), radius);

  // Everything that can be checked before running: balls, table, constants.
  try {
    validate_simulation_input(s.table, s.balls, s.settings);
  } catch (const InvalidArgument& e) {
    const std::string f = e.field();
    const bool pathed = f.rfind("scenario", 0) == 0 || f.rfind("table", 0) == 0;
    throw InvalidArgument(pathed ? f : "scenario." + f, pathed ? e.what() : std::string("scenario.") + e.what());
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

CueStrike resolved_strike(const Scenario& s, const CueStrike& strike) {
  CueStrike out = strike;
  if (s.cue && s.cue->target) {
    const SimulationBall* from = find_ball(s.balls, s.cue->ball);
    const SimulationBall* to = find_ball(s.balls, *s.cue->target);
    if (from && to) {
      const Vec2 d = to->state.position - from->state.position;
      out.aim = std::atan2(d.y, d.x) + (strike.aim - s.cue->strike.aim);  // noise on the aim survives
    }
  }
  return out;
}

std::vector<SimulationBall> balls_after_strike(const Scenario& s, const std::optional<CueStrike>& strike) {
  std::vector<SimulationBall> balls = s.balls;
  if (!s.cue) return balls;
  const CueStrike chosen = resolved_strike(s, strike ? *strike : s.cue->strike);
  for (SimulationBall& b : balls) {
    if (b.id == s.cue->ball) b.state = strike_ball(chosen, b.state.position, s.settings.parameters.ball, s.cue_parameters);
  }
  return balls;
}

SimulationResult run_scenario(const Scenario& s) {
  SimulationResult r = simulate(s.table, balls_after_strike(s), s.settings);
  if (s.cue) r.events.insert(r.events.begin(), Event{0.0, EventType::cue_strike, s.cue->ball, -1});
  return r;
}

std::string result_to_json(const Scenario& s, const SimulationResult& r, double sample_rate, int indent) {
  const Parameters& p = s.settings.parameters;
  Json out;
  out["table"] = Json::parse(table_to_json(s.table));
  out["parameters"] = {{"mass", p.ball.mass},
                       {"radius", p.ball.radius},
                       {"mu_s", p.cloth.sliding_friction},
                       {"mu_r", p.cloth.rolling_resistance},
                       {"mu_sp", p.cloth.spin_friction},
                       {"g", p.cloth.gravity},
                       {"cushion_restitution", s.settings.cushion_restitution},
                       {"cushion_friction", s.settings.cushion_friction}};
  out["end_time"] = r.end_time;
  Json events = Json::array();
  for (const Event& e : r.events) {
    Json ev{{"time", e.time}, {"type", to_string(e.type)}, {"balls", Json::array({e.ball})}};
    switch (e.type) {
      case EventType::ball_ball: ev["balls"].push_back(e.other); break;
      case EventType::ball_cushion: ev["cushion"] = e.other; break;
      case EventType::ball_jaw: ev["jaw"] = e.other; break;
      case EventType::ball_pocket: ev["pocket"] = s.table.pockets[static_cast<std::size_t>(e.other)].name; break;
      default: break;
    }
    events.push_back(ev);
  }
  out["events"] = events;
  Json balls = Json::array();
  for (const BallTrajectory& b : r.balls) {
    Json jb = state_json(b.final_state);
    jb["id"] = b.id;
    jb["name"] = b.name;
    jb["pocketed"] = b.pocketed;
    jb["pocket"] = b.pocketed ? Json(s.table.pockets[static_cast<std::size_t>(b.pocket)].name) : Json(nullptr);
    jb["pocket_time"] = b.pocketed ? Json(b.pocket_time) : Json(nullptr);
    Json segments = Json::array();
    for (const TrajectorySegment& seg : b.segments) {
      Json js = state_json(seg.state);
      js["t"] = seg.start_time;
      js["phase"] = to_string(motion_phase(seg.state, p));
      segments.push_back(js);
    }
    jb["segments"] = segments;
    balls.push_back(jb);
  }
  out["balls"] = balls;
  if (sample_rate > 0.0) {
    const auto count = static_cast<std::size_t>(std::floor(r.end_time * sample_rate)) + 1;
    Json times = Json::array();
    for (std::size_t k = 0; k < count; ++k) times.push_back(static_cast<double>(k) / sample_rate);
    Json per_ball = Json::array();
    for (std::size_t i = 0; i < r.balls.size(); ++i) {
      Json pos = Json::array(), vel = Json::array(), spin = Json::array();
      for (std::size_t k = 0; k < count; ++k) {
        const BallState st = r.state_at(i, static_cast<double>(k) / sample_rate, p);
        pos.push_back(vec(st.position));
        vel.push_back(vec(st.velocity));
        spin.push_back(vec(st.angular_velocity));
      }
      per_ball.push_back({{"id", r.balls[i].id}, {"position", pos}, {"velocity", vel}, {"angular_velocity", spin}});
    }
    out["samples"] = {{"rate_hz", sample_rate}, {"times", times}, {"balls", per_ball}};
  }
  return out.dump(indent);
}

}  // namespace cueball
