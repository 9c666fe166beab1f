// Games as JSON (io/game_json.hpp): the state file (a scenario plus its
// "game" object), actions, rulings, steps and records, and the replay
// check of a record. The scenario part is read and written by the
// scenario's own reader and writer (scenario_json.cpp).
#include "cueball/io/game_json.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <set>
#include <utility>

#include <nlohmann/json.hpp>

#include "cueball/agents/match.hpp"
#include "cueball/core/errors.hpp"
#include "cueball/io/scenario_json.hpp"
#include "io/json_input.hpp"
#include "io/json_output.hpp"
#include "core/angles.hpp"

namespace cueball {

namespace {

using Json = nlohmann::json;

constexpr std::array kKinds{GameKind::nine_ball, GameKind::eight_ball, GameKind::ten_ball, GameKind::snooker,
                            GameKind::three_cushion};
constexpr std::array kPhases{GamePhase::break_shot, GamePhase::play, GamePhase::decision, GamePhase::over};
constexpr std::array kGroups{Group::none, Group::solids, Group::stripes};
constexpr std::array kFouls{Foul::scratch,
                            Foul::wrong_ball_first,
                            Foul::no_contact,
                            Foul::no_rail_after_contact,
                            Foul::illegal_break,
                            Foul::ball_off_table,
                            Foul::wrong_pocket,
                            Foul::cue_ball_not_out_of_kitchen,
                            Foul::bad_cue_ball,
                            Foul::miscue};
constexpr std::array kDecisions{Decision::play,    Decision::pass,         Decision::rerack_and_break,
                                Decision::rerack_opponent_breaks, Decision::respot_eight, Decision::rerack,
                                Decision::restore};

template <class Value, std::size_t N>
std::optional<Value> named(const std::array<Value, N>& all, std::string_view name) {
  for (const Value v : all)
    if (name == to_string(v)) return v;
  return std::nullopt;
}
template <class Value, std::size_t N>
std::string names(const std::array<Value, N>& all) {
  std::string s;
  for (const Value v : all) s += (s.empty() ? "" : ", ") + std::string(to_string(v));
  return s;
}

bool on_table_id(const std::vector<SimulationBall>& balls, int id) { return find_ball(balls, id) != nullptr; }

// ------------------------------------------------------------------ reading

// One JSON object, with its path for the messages.
class Reader {
 public:
  Reader(const Json& j, std::string path) : j_(j), path_(std::move(path)) {
    if (!j_.is_object()) throw InvalidArgument(path_, path_ + " must be a JSON object, got " + std::string(j_.type_name()));
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
  const Json& at(const char* key) const { return j_.at(key); }
  std::string field(const std::string& key) const { return path_ + "." + key; }
  const std::string& path() const { return path_; }

  double number(const char* key, double fallback, double lo, double hi, const char* meaning) const {
    if (!has(key)) return fallback;
    return number_at(at(key), field(key), lo, hi, meaning);
  }
  static double number_at(const Json& v, const std::string& f, double lo, double hi, const char* meaning) {
    if (!v.is_number())
      throw InvalidArgument(f, f + " must be a number, got " + std::string(v.type_name()) + " (" + meaning + ")");
    const double x = v.get<double>();
    require_in_range(f.c_str(), x, lo, hi, meaning);
    return x;
  }
  static long long integer_at(const Json& v, const std::string& f, long long lo, long long hi, const char* meaning) {
    if (!v.is_number_integer())
      throw InvalidArgument(f, f + " must be an integer, got " +
                                   (v.is_number() ? std::string("a fraction") : std::string(v.type_name())) + " (" +
                                   meaning + "; allowed [" + std::to_string(lo) + ", " + std::to_string(hi) + "])");
    const long long x = v.is_number_unsigned() && v.get<unsigned long long>() > 9000000000000000000ULL
                            ? 9000000000000000000LL
                            : v.get<long long>();
    if (x < lo || x > hi)
      throw InvalidArgument(f, f + " = " + std::to_string(x) + " is out of range [" + std::to_string(lo) + ", " +
                                   std::to_string(hi) + "] (" + meaning + ")");
    return x;
  }
  int integer(const char* key, int fallback, int lo, int hi, const char* meaning) const {
    if (!has(key)) return fallback;
    return static_cast<int>(integer_at(at(key), field(key), lo, hi, meaning));
  }
  std::uint64_t seed(const char* key, std::uint64_t fallback) const {
    if (!has(key)) return fallback;
    const Json& v = at(key);
    if (!v.is_number_unsigned() && !(v.is_number_integer() && v.get<long long>() >= 0))
      throw InvalidArgument(field(key), field(key) + " must be an integer in [0, 2^64 - 1], got " +
                                            (v.is_number() ? v.dump() : std::string(v.type_name())) + " (a seed)");
    return v.get<std::uint64_t>();
  }
  bool flag(const char* key, bool fallback) const {
    if (!has(key)) return fallback;
    if (!at(key).is_boolean())
      throw InvalidArgument(field(key), field(key) + " must be true or false, got " + std::string(at(key).type_name()));
    return at(key).get<bool>();
  }
  std::string text(const char* key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    if (!at(key).is_string())
      throw InvalidArgument(field(key), field(key) + " must be a string, got " + std::string(at(key).type_name()));
    return at(key).get<std::string>();
  }
  const Json& array(const char* key, std::size_t max) const {
    const Json& v = at(key);
    if (!v.is_array())
      throw InvalidArgument(field(key), field(key) + " must be an array, got " + std::string(v.type_name()));
    if (v.size() > max)
      throw InvalidArgument(field(key), field(key) + " has " + std::to_string(v.size()) + " elements; allowed: at most " +
                                            std::to_string(max));
    return v;
  }
  template <class Value, std::size_t N>
  Value name(const char* key, Value fallback, const std::array<Value, N>& all, const char* meaning) const {
    if (!has(key)) return fallback;
    return name_at(at(key), field(key), all, meaning);
  }
  template <class Value, std::size_t N>
  static Value name_at(const Json& v, const std::string& f, const std::array<Value, N>& all, const char* meaning) {
    if (!v.is_string())
      throw InvalidArgument(f, f + " must be a string (" + meaning + "), got " + std::string(v.type_name()) +
                                   "; allowed: " + names(all));
    const std::optional<Value> x = named(all, v.get<std::string>());
    if (!x)
      throw InvalidArgument(f, f + " = " + quote_input(v.get<std::string>()) + " is not known (" + meaning +
                                   "); allowed: " + names(all));
    return *x;
  }
  // [a, b] of integers.
  std::array<int, 2> pair(const char* key, std::array<int, 2> fallback, int lo, int hi, const char* meaning) const {
    if (!has(key)) return fallback;
    const Json& v = at(key);
    if (!v.is_array() || v.size() != 2)
      throw InvalidArgument(field(key), field(key) + " must be an array of 2 integers [player 0, player 1] (" + meaning + ")");
    return {static_cast<int>(integer_at(v[0], field(key) + "[0]", lo, hi, meaning)),
            static_cast<int>(integer_at(v[1], field(key) + "[1]", lo, hi, meaning))};
  }
  std::vector<int> ids(const char* key, int hi, const char* meaning) const {
    std::vector<int> out;
    if (!has(key)) return out;
    const Json& v = array(key, 64);
    for (std::size_t i = 0; i < v.size(); ++i)
      out.push_back(static_cast<int>(integer_at(v[i], field(key) + "[" + std::to_string(i) + "]", 0, hi, meaning)));
    return out;
  }
  std::optional<int> player_or_null(const char* key) const {
    if (!has(key) || at(key).is_null()) return std::nullopt;
    return static_cast<int>(integer_at(at(key), field(key), 0, 1, "a player: 0 or 1, or null"));
  }

 private:
  const Json& j_;
  std::string path_;
};

// An error of a reader that names its own root ("scenario", "noise",
// "state") renamed to the path the JSON was at.
InvalidArgument renamed(const InvalidArgument& e, const std::string& from, const std::string& to) {
  const auto swap = [&](std::string s) {
    for (std::size_t at_ = s.find(from); at_ != std::string::npos; at_ = s.find(from, at_ + to.size())) {
      const std::size_t end = at_ + from.size();
      const bool word = (at_ == 0 || s[at_ - 1] == ' ' || s[at_ - 1] == '(') &&
                        (end == s.size() || s[end] == '.' || s[end] == ':' || s[end] == ' ' || s[end] == '[');
      if (word) {
        s.replace(at_, from.size(), to);
      } else {
        at_ += from.size() - std::min(from.size(), to.size());
      }
    }
    return s;
  };
  return InvalidArgument(swap(e.field()), swap(e.what()));
}

GameKind read_kind(const Reader& r) {
  if (!r.has("kind")) throw InvalidArgument(r.field("kind"), r.field("kind") + " is required; allowed: " + names(kKinds));
  return r.name("kind", GameKind::nine_ball, kKinds, "the game");
}

double ball_radius_of(const std::string& preset) {
  try {
    return preset_table(preset).ball.radius;
  } catch (const InvalidArgument&) {
    return pool_table_9ft().ball.radius;  // the name itself is refused by validate()
  }
}

GameConfig read_config(const Reader& r, GameKind kind) {
  r.allow_only({"kind", "table", "rack", "noise", "max_shots", "fouls_to_lose", "nine_on_break_wins", "push_out",
                "break_scratch_region", "reds", "miss_rule", "race_to"});
  GameConfig c = default_config(kind);
  if (r.has("kind") && r.name("kind", kind, kKinds, "the game") != kind)
    throw InvalidArgument(r.field("kind"), r.field("kind") + " = " + r.at("kind").dump() + " differs from the game's kind \"" +
                                               to_string(kind) + "\"");
  c.table = r.text("table", c.table);
  if (r.has("rack")) {
    const Reader rack(r.at("rack"), r.field("rack"));
    rack.allow_only({"gap_sigma", "seed"});
    c.rack.gap_sigma = rack.number("gap_sigma", c.rack.gap_sigma, 0.0, kMaxGapSigma, "random gap scale, m");
    c.rack.seed = rack.seed("seed", c.rack.seed);
  }
  if (r.has("noise")) {
    try {
      c.noise = noise_from_json(r.at("noise").dump(), ball_radius_of(c.table), r.field("noise"));
    } catch (const InvalidArgument& e) {
      if (e.field().rfind(r.field("noise"), 0) == 0) throw;
      throw InvalidArgument(r.field("noise"), r.field("noise") + ": " + e.what());
    }
  }
  c.max_shots = r.integer("max_shots", c.max_shots, 1, 100000, "shots after which the game is truncated");
  c.fouls_to_lose = r.integer("fouls_to_lose", c.fouls_to_lose, 0, 10, "consecutive fouls that lose; 0: off");
  c.nine_on_break_wins = r.flag("nine_on_break_wins", c.nine_on_break_wins);
  c.push_out = r.flag("push_out", c.push_out);
  if (r.has("break_scratch_region")) {
    const std::string name = r.text("break_scratch_region", "");
    const std::optional<PlacementRegion::Kind> k = placement_region_from_string(name);
    if (!k || (*k != PlacementRegion::Kind::behind_head_string && *k != PlacementRegion::Kind::anywhere))
      throw InvalidArgument(r.field("break_scratch_region"), r.field("break_scratch_region") + " = " + quote_input(name) +
                                                                 " is not known; allowed: behind_head_string, anywhere");
    c.break_scratch_region = *k;
  }
  c.reds = r.integer("reds", c.reds, 6, 15, "snooker reds: 6, 10 or 15");
  c.miss_rule = r.flag("miss_rule", c.miss_rule);
  c.race_to = r.integer("race_to", c.race_to, 1, 1000, "three-cushion points to win");
  try {
    validate(c);
  } catch (const InvalidArgument& e) {
    // validate() names the config's own fields ("reds", "preset" for the table).
    const std::string key = e.field() == "preset" ? "table" : e.field();
    const std::string f = r.field(key);
    throw InvalidArgument(f, f + ": " + e.what());
  }
  return c;
}

// The ball ids of a discipline.
bool id_in_set(const GameConfig& c, int id) {
  switch (c.kind) {
    case GameKind::nine_ball: return id >= 0 && id <= 9;
    case GameKind::ten_ball: return id >= 0 && id <= 10;
    case GameKind::eight_ball: return id >= 0 && id <= 15;
    case GameKind::snooker: return id == 0 || (id >= 1 && id <= c.reds) || (id >= 16 && id <= 21);
    case GameKind::three_cushion: return id >= 0 && id <= 2;
  }
  return false;
}
std::string id_set(const GameConfig& c) {
  switch (c.kind) {
    case GameKind::nine_ball: return "0 (the cue ball) to 9";
    case GameKind::ten_ball: return "0 (the cue ball) to 10";
    case GameKind::eight_ball: return "0 (the cue ball) to 15";
    case GameKind::snooker: return "0 (the cue ball), the reds 1 to " + std::to_string(c.reds) + ", the colours 16 to 21";
    case GameKind::three_cushion: return "0 (white), 1 (yellow), 2 (red)";
  }
  return "?";
}
void check_id(const GameConfig& c, int id, const std::string& f) {
  if (!id_in_set(c, id))
    throw InvalidArgument(f, f + " = " + std::to_string(id) + " is not a ball of " + to_string(c.kind) + "; allowed: " +
                                 id_set(c));
}

// A ball of "balls" or "before_miss" (the scenario's form), at rest.
SimulationBall read_ball_at_rest(const Json& v, const std::string& path, const GameConfig& c) {
  const Reader r(v, path);
  r.allow_only({"id", "name", "position", "velocity", "angular_velocity"});
  SimulationBall b;
  if (!r.has("id")) throw InvalidArgument(r.field("id"), r.field("id") + " is required");
  b.id = r.integer("id", 0, 0, 1000000, "ball id");
  check_id(c, b.id, r.field("id"));
  b.name = r.text("name", b.id == 0 ? "cue" : std::to_string(b.id));
  if (!r.has("position") || !r.at("position").is_array() || r.at("position").size() != 2)
    throw InvalidArgument(r.field("position"), r.field("position") + " must be [x, y], m");
  b.state.position = {Reader::number_at(r.at("position")[0], r.field("position") + "[0]", -100, 100, "m"),
                      Reader::number_at(r.at("position")[1], r.field("position") + "[1]", -100, 100, "m")};
  return b;
}

// The region a discipline's table has.
bool region_allowed(GameKind kind, PlacementRegion::Kind region) {
  switch (region) {
    case PlacementRegion::Kind::anywhere:
    case PlacementRegion::Kind::rectangle: return true;
    case PlacementRegion::Kind::behind_head_string:
      return kind == GameKind::nine_ball || kind == GameKind::eight_ball || kind == GameKind::ten_ball;
    case PlacementRegion::Kind::inside_d: return kind == GameKind::snooker;
  }
  return false;
}

std::optional<PlacementRegion> read_region(const Reader& game, const GameConfig& c, const Table& table) {
  if (!game.has("ball_in_hand") || game.at("ball_in_hand").is_null()) return std::nullopt;
  const std::string f = game.field("ball_in_hand");
  const Json& v = game.at("ball_in_hand");
  const std::string allowed = "null, anywhere, " +
                              std::string(c.kind == GameKind::snooker ? "inside_d, "
                                          : c.kind == GameKind::three_cushion ? ""
                                                                              : "behind_head_string, ") +
                              "or {\"kind\": \"rectangle\", \"x_min\", \"x_max\", \"y_min\", \"y_max\"}";
  PlacementRegion region;
  if (v.is_string()) {
    const std::optional<PlacementRegion::Kind> k = placement_region_from_string(v.get<std::string>());
    if (!k || *k == PlacementRegion::Kind::rectangle)
      throw InvalidArgument(f, f + " = " + quote_input(v.get<std::string>()) + " is not a region; allowed: " + allowed);
    region.kind = *k;
  } else if (v.is_object()) {
    const Reader r(v, f);
    r.allow_only({"kind", "x_min", "x_max", "y_min", "y_max"});
    if (r.text("kind", "rectangle") != "rectangle")
      throw InvalidArgument(r.field("kind"), r.field("kind") + " = " + r.at("kind").dump() +
                                                 ": an object is a rectangle; give the other regions by name");
    region.kind = PlacementRegion::Kind::rectangle;
    for (const char* key : {"x_min", "x_max", "y_min", "y_max"})
      if (!r.has(key)) throw InvalidArgument(r.field(key), r.field(key) + " is required (m)");
    region.x_min = r.number("x_min", 0, 0, table.length, "m, on the bed");
    region.x_max = r.number("x_max", 0, region.x_min, table.length, "m, on the bed, at least x_min");
    region.y_min = r.number("y_min", 0, 0, table.width, "m, on the bed");
    region.y_max = r.number("y_max", 0, region.y_min, table.width, "m, on the bed, at least y_min");
  } else {
    throw InvalidArgument(f, f + " must be null, a region's name or a rectangle object, got " +
                                 std::string(v.type_name()) + "; allowed: " + allowed);
  }
  if (!region_allowed(c.kind, region.kind))
    throw InvalidArgument(f, f + " = \"" + to_string(region.kind) + "\" is not a region of " + to_string(c.kind) +
                                 "'s table; allowed: " + allowed);
  return region;
}

// The scenario part: the scenario's own reader, its paths under `path`.
Scenario read_table(const Json& j, const std::string& path, const GameConfig& c) {
  Json scenario = j;
  scenario.erase("game");
  if (scenario.contains("cue"))
    throw InvalidArgument(path + ".cue", path + ".cue: a state holds no strike (give the shot to `game shoot --cue` or play())");
  if (!scenario.contains("balls"))
    throw InvalidArgument(path + ".balls", path + ".balls is required: the balls on the table");
  if (!scenario.contains("table")) scenario["table"] = c.table;
  const bool none = scenario.at("balls").is_array() && scenario.at("balls").empty() && !scenario.contains("rack");
  Scenario s;
  try {
    s = scenario_from_json(scenario.dump());
  } catch (const InvalidArgument& e) {
    throw renamed(e, "scenario", path);
  }
  if (none) s.balls.clear();
  return s;
}

void check_balls(const Json& j, const std::string& path, const Scenario& s, const GameConfig& c) {
  std::set<int> seen;
  const Json& list = j.at("balls");
  for (std::size_t i = 0; i < s.balls.size() && i < list.size(); ++i) {
    const std::string f = path + ".balls[" + std::to_string(i) + "]";
    const SimulationBall& b = s.balls[i];
    check_id(c, b.id, f + ".id");
    if (!seen.insert(b.id).second)
      throw InvalidArgument(f + ".id", f + ".id = " + std::to_string(b.id) + " is given twice (one ball per id)");
    const BallState& st = b.state;
    if (st.velocity.x != 0.0 || st.velocity.y != 0.0)
      throw InvalidArgument(f + ".velocity", f + ".velocity: the balls of a state are at rest; allowed: [0, 0]");
    if (st.angular_velocity.x != 0.0 || st.angular_velocity.y != 0.0 || st.angular_velocity.z != 0.0)
      throw InvalidArgument(f + ".angular_velocity",
                            f + ".angular_velocity: the balls of a state are at rest; allowed: [0, 0, 0]");
  }
}

GameState read_state(const Json& j, const std::string& path) {
  const Reader top(j, path);
  if (!top.has("game"))
    throw InvalidArgument(path + ".game", path + ".game is required: a state is a scenario with a \"game\" object");
  const Reader g(top.at("game"), path + ".game");
  g.allow_only({"kind", "config", "phase", "to_shoot", "breaker", "ball_in_hand", "cue_must_leave_kitchen", "scores",
                "fouls_in_a_row", "on", "groups", "decisions", "push_out_available", "free_ball", "misses_in_a_row",
                "colour_on", "before_miss", "shots", "inning_points", "over", "winner", "truncated", "end_reason"});
  GameState s;
  const GameKind kind = read_kind(g);
  const Json empty = Json::object();
  s.config = read_config(Reader(g.has("config") ? g.at("config") : empty, g.field("config")), kind);
  s.table = read_table(j, path, s.config);
  check_balls(j, path, s.table, s.config);
  const GameState fresh;  // defaults of the optional keys
  s.phase = g.name("phase", fresh.phase, kPhases, "where the game stands");
  s.to_shoot = g.integer("to_shoot", 0, 0, 1, "the player to act");
  s.breaker = g.integer("breaker", 0, 0, 1, "who broke this rack");
  s.ball_in_hand = read_region(g, s.config, s.table.table);
  s.cue_must_leave_kitchen = g.flag("cue_must_leave_kitchen", false);
  if (s.cue_must_leave_kitchen && s.config.kind != GameKind::eight_ball)
    throw InvalidArgument(g.field("cue_must_leave_kitchen"),
                          g.field("cue_must_leave_kitchen") + " = true applies to eight_ball only");
  s.scores = g.pair("scores", {0, 0}, 0, 1000000, "points");
  s.fouls_in_a_row = g.pair("fouls_in_a_row", {0, 0}, 0, 1000, "consecutive fouls");
  s.on = g.ids("on", 1000000, "a ball the cue ball may contact first");
  for (std::size_t i = 0; i < s.on.size(); ++i) check_id(s.config, s.on[i], g.field("on") + "[" + std::to_string(i) + "]");
  if (g.has("groups")) {
    const Json& v = g.at("groups");
    if (!v.is_array() || v.size() != 2)
      throw InvalidArgument(g.field("groups"), g.field("groups") + " must be [group of player 0, group of player 1]; allowed: " +
                                                   names(kGroups));
    s.groups = {Reader::name_at(v[0], g.field("groups") + "[0]", kGroups, "8-ball group"),
                Reader::name_at(v[1], g.field("groups") + "[1]", kGroups, "8-ball group")};
    const bool open = s.groups[0] == Group::none && s.groups[1] == Group::none;
    const bool set = s.groups[0] != Group::none && s.groups[1] != Group::none && s.groups[0] != s.groups[1];
    if (!open && (s.config.kind != GameKind::eight_ball || !set))
      throw InvalidArgument(g.field("groups"), g.field("groups") + " = " + v.dump() +
                                                   (s.config.kind == GameKind::eight_ball
                                                        ? " is neither an open table [\"none\", \"none\"] nor one solids and one stripes"
                                                        : " applies to eight_ball only; allowed: [\"none\", \"none\"]"));
  }
  if (g.has("decisions")) {
    const Json& v = g.array("decisions", kDecisions.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      s.decisions.push_back(Reader::name_at(v[i], g.field("decisions") + "[" + std::to_string(i) + "]", kDecisions, "a decision"));
  }
  s.push_out_available = g.flag("push_out_available", false);
  s.free_ball = g.flag("free_ball", false);
  s.misses_in_a_row = g.integer("misses_in_a_row", 0, 0, 1000, "consecutive misses");
  s.colour_on = g.integer("colour_on", 0, 0, 21, "snooker: the colour on in the clearance; 0: none");
  if (s.colour_on != 0) check_id(s.config, s.colour_on, g.field("colour_on"));
  if (g.has("before_miss")) {
    const Json& v = g.array("before_miss", kMaxBalls);
    for (std::size_t i = 0; i < v.size(); ++i)
      s.before_miss.push_back(read_ball_at_rest(v[i], g.field("before_miss") + "[" + std::to_string(i) + "]", s.config));
  }
  s.shots = g.integer("shots", 0, 0, s.config.max_shots, "shots and decisions played; at most config.max_shots");
  s.inning_points = g.integer("inning_points", 0, 0, 1000000, "points of the current inning");
  s.over = g.flag("over", false);
  s.winner = g.player_or_null("winner");
  s.truncated = g.flag("truncated", false);
  s.end_reason = g.text("end_reason", "");

  // The parts that must agree.
  if (s.over != (s.phase == GamePhase::over))
    throw InvalidArgument(g.field("phase"), g.field("phase") + " = \"" + to_string(s.phase) + "\" disagrees with " +
                                                g.field("over") + " = " + (s.over ? "true" : "false") +
                                                " (a game over is in phase \"over\", and only then)");
  if (s.phase == GamePhase::decision && s.decisions.empty())
    throw InvalidArgument(g.field("decisions"), g.field("decisions") + " is empty in phase \"decision\"; allowed: one or more of " +
                                                    names(kDecisions));
  if (s.phase != GamePhase::decision && !s.over && !s.decisions.empty())
    throw InvalidArgument(g.field("decisions"), g.field("decisions") + " are open only in phase \"decision\"");
  if (s.winner && !s.over)
    throw InvalidArgument(g.field("winner"), g.field("winner") + " = " + std::to_string(*s.winner) + " in a game that is not over");
  if (s.truncated && !s.over)
    throw InvalidArgument(g.field("truncated"), g.field("truncated") + " = true in a game that is not over");
  if (s.truncated && s.winner)
    throw InvalidArgument(g.field("winner"), g.field("winner") + ": a truncated game has no winner; allowed: null");
  const int cue = s.cue_ball();
  if (!s.over && !s.ball_in_hand && !on_table_id(s.table.balls, cue))
    throw InvalidArgument(path + ".balls", path + ".balls: the cue ball " + std::to_string(cue) +
                                              " is not on the table and not in hand (" + g.field("ball_in_hand") +
                                              " is null)");
  if (s.config.kind == GameKind::three_cushion)
    for (const int id : {0, 1, 2})
      if (!on_table_id(s.table.balls, id))
        throw InvalidArgument(path + ".balls", path + ".balls: three-cushion is played with balls 0, 1 and 2; " +
                                                  std::to_string(id) + " is missing");
  return s;
}

// ------------------------------------------------------------------ writing

Json noise_json(const CueStrikeNoise& n, double radius) {
  return {{"speed", n.speed},
          {"aim_deg", io::in_units(n.aim, kDegree, std::nullopt)},
          {"elevation_deg", io::in_units(n.elevation, kDegree, std::nullopt)},
          {"side", io::in_units(n.side_offset, radius, std::nullopt)},
          {"height", io::in_units(n.height_offset, radius, std::nullopt)}};
}

Json config_json(const GameConfig& c, bool with_kind) {
  Json j;
  if (with_kind) j["kind"] = to_string(c.kind);
  j["table"] = c.table;
  j["rack"] = {{"gap_sigma", c.rack.gap_sigma}, {"seed", c.rack.seed}};
  j["noise"] = noise_json(c.noise, ball_radius_of(c.table));
  j["max_shots"] = c.max_shots;
  j["fouls_to_lose"] = c.fouls_to_lose;
  j["nine_on_break_wins"] = c.nine_on_break_wins;
  j["push_out"] = c.push_out;
  j["break_scratch_region"] = to_string(c.break_scratch_region);
  j["reds"] = c.reds;
  j["miss_rule"] = c.miss_rule;
  j["race_to"] = c.race_to;
  return j;
}

Json pair_json(const std::array<int, 2>& a) { return Json::array({a[0], a[1]}); }
Json player_json(const std::optional<int>& p) { return p ? Json(*p) : Json(nullptr); }

Json region_json(const std::optional<PlacementRegion>& r) {
  if (!r) return nullptr;
  if (r->kind != PlacementRegion::Kind::rectangle) return to_string(r->kind);
  return {{"kind", "rectangle"}, {"x_min", r->x_min}, {"x_max", r->x_max}, {"y_min", r->y_min}, {"y_max", r->y_max}};
}

Json ball_json(const SimulationBall& b) {
  Json jb = io::state_json(b.state);
  jb["id"] = b.id;
  jb["name"] = b.name;
  return jb;
}

Json state_json(const GameState& s) {
  Scenario table = s.table;
  table.cue.reset();
  Json j = io::scenario_json(table);
  Json g;
  g["kind"] = to_string(s.config.kind);
  g["config"] = config_json(s.config, false);
  g["phase"] = to_string(s.phase);
  g["to_shoot"] = s.to_shoot;
  g["breaker"] = s.breaker;
  g["ball_in_hand"] = region_json(s.ball_in_hand);
  g["cue_must_leave_kitchen"] = s.cue_must_leave_kitchen;
  g["scores"] = pair_json(s.scores);
  g["fouls_in_a_row"] = pair_json(s.fouls_in_a_row);
  g["on"] = s.on;
  g["groups"] = Json::array({to_string(s.groups[0]), to_string(s.groups[1])});
  Json decisions = Json::array();
  for (const Decision d : s.decisions) decisions.push_back(to_string(d));
  g["decisions"] = decisions;
  g["push_out_available"] = s.push_out_available;
  g["free_ball"] = s.free_ball;
  g["misses_in_a_row"] = s.misses_in_a_row;
  g["colour_on"] = s.colour_on;
  Json before = Json::array();
  for (const SimulationBall& b : s.before_miss) before.push_back(ball_json(b));
  g["before_miss"] = before;
  g["shots"] = s.shots;
  g["inning_points"] = s.inning_points;
  g["over"] = s.over;
  g["winner"] = player_json(s.winner);
  g["truncated"] = s.truncated;
  g["end_reason"] = s.end_reason;
  j["game"] = g;
  return j;
}

// ------------------------------------------------------------------ actions and rulings

Json action_json(const Action& a) {
  Json j;
  if (a.decision) {
    j["decision"] = to_string(*a.decision);
    return j;
  }
  j["speed"] = a.strike.speed;
  if (a.aim_at) {
    j["target"] = *a.aim_at;
  } else {
    j["aim_deg"] = a.strike.aim_deg;
  }
  j["elevation_deg"] = a.strike.elevation_deg;
  j["side"] = a.strike.side;
  j["height"] = a.strike.height;
  if (a.place) j["place"] = io::vec(*a.place);
  if (a.called_ball || a.called_pocket) {
    Json call = Json::object();
    if (a.called_ball) call["ball"] = *a.called_ball;
    if (a.called_pocket) call["pocket"] = *a.called_pocket;
    j["call"] = call;
  }
  if (a.push_out) j["push_out"] = true;
  if (a.nominate) j["nominate"] = *a.nominate;
  return j;
}

Action read_action(const Json& j, const Table* table, const std::string& path) {
  const Reader r(j, path);
  Action a;
  if (r.has("decision")) {
    r.allow_only({"decision"});
    a.decision = r.name("decision", Decision::play, kDecisions, "a decision instead of a shot");
    return a;
  }
  r.allow_only({"speed", "aim_deg", "target", "elevation_deg", "side", "height", "place", "call", "push_out", "nominate",
                "decision"});
  if (r.has("target") && r.has("aim_deg"))
    throw InvalidArgument(r.field("target"), r.field("target") + ": give either target or aim_deg, not both");
  a.strike.speed = r.number("speed", a.strike.speed, 1e-6, 12.0, "cue speed, m/s");
  a.strike.aim_deg = r.number("aim_deg", 0.0, -360.0, 360.0, "aim direction from +x, degrees");
  if (r.has("target")) a.aim_at = r.integer("target", 0, 0, 1000000, "id of the ball to aim at");
  a.strike.elevation_deg = r.number("elevation_deg", 0.0, 0.0, 89.0, "cue elevation, degrees");
  a.strike.side = r.number("side", 0.0, -0.5, 0.5, "tip offset to the right, ball radii");
  a.strike.height = r.number("height", 0.0, -0.5, 0.5, "tip offset above the centre, ball radii");
  if (r.has("place")) {
    const Json& p = r.at("place");
    if (!p.is_array() || p.size() != 2)
      throw InvalidArgument(r.field("place"), r.field("place") + " must be [x, y], m (the cue ball's spot when in hand)");
    a.place = Vec2{Reader::number_at(p[0], r.field("place") + "[0]", -100, 100, "m"),
                   Reader::number_at(p[1], r.field("place") + "[1]", -100, 100, "m")};
  }
  if (r.has("call")) {
    const Reader c(r.at("call"), r.field("call"));
    c.allow_only({"ball", "pocket"});
    if (c.has("ball")) a.called_ball = c.integer("ball", 0, 0, 1000000, "the called ball");
    if (c.has("pocket")) {
      const Json& p = c.at("pocket");
      if (p.is_string() && table != nullptr) {
        std::string pockets;
        for (std::size_t k = 0; k < table->pockets.size(); ++k) {
          pockets += (pockets.empty() ? "" : ", ") + table->pockets[k].name;
          if (table->pockets[k].name == p.get<std::string>()) a.called_pocket = static_cast<int>(k);
        }
        if (!a.called_pocket)
          throw InvalidArgument(c.field("pocket"), c.field("pocket") + " = " + quote_input(p.get<std::string>()) +
                                                       " is not a pocket of the table; allowed: " + pockets +
                                                       " (or its index)");
      } else {
        a.called_pocket = c.integer("pocket", 0, 0, 1000, "the called pocket's index in the table's pockets");
      }
    }
  }
  a.push_out = r.flag("push_out", false);
  if (r.has("nominate")) a.nominate = r.integer("nominate", 0, 0, 1000000, "the nominated ball");
  return a;
}

Json ruling_json(const Ruling& r) {
  Json j;
  j["foul"] = r.foul ? Json(to_string(*r.foul)) : Json(nullptr);
  j["points"] = pair_json(r.points);
  j["turn_over"] = r.turn_over;
  j["game_over"] = r.game_over;
  j["winner"] = player_json(r.winner);
  j["respotted"] = r.respotted;
  j["pocketed"] = r.pocketed;
  j["push_out"] = r.push_out;
  j["miss"] = r.miss;
  j["truncated"] = r.truncated;
  j["reason"] = r.reason;
  return j;
}

Ruling read_ruling(const Json& j, const std::string& path) {
  const Reader r(j, path);
  r.allow_only({"foul", "points", "turn_over", "game_over", "winner", "respotted", "pocketed", "push_out", "miss",
                "truncated", "reason"});
  Ruling out;
  if (r.has("foul") && !r.at("foul").is_null()) out.foul = r.name("foul", Foul::scratch, kFouls, "the foul");
  out.points = r.pair("points", {0, 0}, -1000000, 1000000, "points scored");
  out.turn_over = r.flag("turn_over", false);
  out.game_over = r.flag("game_over", false);
  out.winner = r.player_or_null("winner");
  out.respotted = r.ids("respotted", 1000000, "a respotted ball");
  out.pocketed = r.ids("pocketed", 1000000, "a pocketed ball");
  out.push_out = r.flag("push_out", false);
  out.miss = r.flag("miss", false);
  out.truncated = r.flag("truncated", false);
  out.reason = r.text("reason", "");
  return out;
}

// ------------------------------------------------------------------ records

constexpr const char* kRecordFormat = "cueball-game-record";

Reasoning read_reasoning(const Json& j, const std::string& path) {
  const Reader r(j, path);
  r.allow_only({"summary", "considered"});
  Reasoning out;
  out.summary = r.text("summary", "");
  if (r.has("considered")) {
    const Json& list = r.array("considered", 1000);
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Reader c(list[i], r.field("considered") + "[" + std::to_string(i) + "]");
      c.allow_only({"what", "estimate", "next_estimate"});
      out.considered.push_back({c.text("what", ""), c.number("estimate", -1.0, 0.0, 1.0, "a probability"),
                                c.number("next_estimate", -1.0, 0.0, 1.0, "a probability")});
    }
  }
  return out;
}

Json record_json(const GameRecord& g) {
  Json j;
  j["players"] = Json::array({g.players[0], g.players[1]});
  j["seed"] = g.seed;
  j["start"] = state_json(g.start);
  Json steps = Json::array();
  for (const RecordedStep& s : g.steps) {
    Json step{{"action", action_json(s.action)}, {"seed", s.seed}, {"ruling", ruling_json(s.ruling)},
              {"state", state_json(s.state)}};
    if (io::has_reasoning(s.reasoning)) step["reasoning"] = io::reasoning_json(s.reasoning);
    steps.push_back(std::move(step));
  }
  j["steps"] = steps;
  return j;
}

GameRecord read_record(const Json& j, const std::string& path) {
  const Reader r(j, path);
  r.allow_only({"players", "seed", "start", "steps"});
  GameRecord g;
  if (r.has("players")) {
    const Json& p = r.at("players");
    if (!p.is_array() || p.size() != 2 || !p[0].is_string() || !p[1].is_string())
      throw InvalidArgument(r.field("players"), r.field("players") + " must be [name, name]");
    g.players = {p[0].get<std::string>(), p[1].get<std::string>()};
  }
  g.seed = r.seed("seed", 0);
  if (!r.has("start")) throw InvalidArgument(r.field("start"), r.field("start") + " is required: the state before the first step");
  g.start = read_state(r.at("start"), r.field("start"));
  if (r.has("steps")) {
    const Json& steps = r.array("steps", 1000000);
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const Reader s(steps[i], r.field("steps") + "[" + std::to_string(i) + "]");
      s.allow_only({"action", "seed", "ruling", "state", "reasoning"});
      for (const char* key : {"action", "ruling", "state"})
        if (!s.has(key)) throw InvalidArgument(s.field(key), s.field(key) + " is required");
      RecordedStep step;
      step.action = read_action(s.at("action"), &g.start.table.table, s.field("action"));
      step.seed = s.seed("seed", 0);
      step.ruling = read_ruling(s.at("ruling"), s.field("ruling"));
      step.state = read_state(s.at("state"), s.field("state"));
      if (s.has("reasoning")) step.reasoning = read_reasoning(s.at("reasoning"), s.field("reasoning"));
      g.steps.push_back(std::move(step));
    }
  }
  return g;
}

// The first place where two JSON values differ, depth first.
std::optional<std::string> first_difference(const Json& a, const Json& b, const std::string& path, Json& va, Json& vb) {
  if (a.is_object() && b.is_object()) {
    for (const auto& item : a.items()) {
      const std::string p = path + "." + detail::path_key(item.key());
      if (!b.contains(item.key())) {
        va = item.value();
        vb = "(missing)";
        return p;
      }
      if (auto d = first_difference(item.value(), b.at(item.key()), p, va, vb)) return d;
    }
    for (const auto& item : b.items())
      if (!a.contains(item.key())) {
        va = "(missing)";
        vb = item.value();
        return path + "." + detail::path_key(item.key());
      }
    return std::nullopt;
  }
  if (a.is_array() && b.is_array()) {
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
      if (auto d = first_difference(a[i], b[i], path + "[" + std::to_string(i) + "]", va, vb)) return d;
    if (a.size() != b.size()) {
      va = std::to_string(a.size()) + " elements";
      vb = std::to_string(b.size()) + " elements";
      return path;
    }
    return std::nullopt;
  }
  if (a.dump() != b.dump()) {
    va = a;
    vb = b;
    return path;
  }
  return std::nullopt;
}

}  // namespace

// ------------------------------------------------------------------ public

std::string game_state_to_json(const GameState& state, int indent) { return state_json(state).dump(indent); }

GameState game_state_from_json(std::string_view json_text) {
  if (json_text.size() > kMaxScenarioBytes)
    throw InvalidArgument("state", "state: " + std::to_string(json_text.size()) + " bytes of JSON is more than the " +
                                       std::to_string(kMaxScenarioBytes) + " allowed (16 MiB)");
  return read_state(detail::parse_json(json_text, "state"), "state");
}

std::string game_config_to_json(const GameConfig& config, int indent) { return config_json(config, true).dump(indent); }

GameConfig game_config_from_json(std::string_view json_text, const std::string& path) {
  const Json j = detail::parse_json(json_text, path);
  const Reader r(j, path);
  return read_config(r, read_kind(r));
}

std::string action_to_json(const Action& action, int indent) { return action_json(action).dump(indent); }

Action action_from_json(std::string_view json_text, const Table* table, const std::string& path) {
  return read_action(detail::parse_json(json_text, path), table, path);
}

std::string ruling_to_json(const Ruling& ruling, int indent) { return ruling_json(ruling).dump(indent); }

Ruling ruling_from_json(std::string_view json_text, const std::string& path) {
  return read_ruling(detail::parse_json(json_text, path), path);
}

std::string game_step_to_json(const GameStep& step, int indent) {
  Json j;
  j["action"] = action_json(step.action);
  j["ruling"] = ruling_json(step.ruling);
  j["facts"] = step.action.decision ? Json(nullptr) : io::shot_facts_json(step.shot.table, step.facts);
  j["state"] = state_json(step.next);
  return j.dump(indent);
}

std::string game_records_to_json(const std::vector<GameRecord>& records, int indent) {
  Json games = Json::array();
  for (const GameRecord& g : records) games.push_back(record_json(g));
  return Json{{"format", kRecordFormat}, {"version", 1}, {"games", games}}.dump(indent);
}

std::vector<GameRecord> game_records_from_json(std::string_view json_text) {
  if (json_text.size() > kMaxGameRecordBytes)
    throw InvalidArgument("record", "record: " + std::to_string(json_text.size()) + " bytes of JSON is more than the " +
                                        std::to_string(kMaxGameRecordBytes) + " allowed (256 MiB)");
  const Json j = detail::parse_json(json_text, "record");
  const Reader r(j, "record");
  r.allow_only({"format", "version", "games"});
  if (r.text("format", "") != kRecordFormat)
    throw InvalidArgument("record.format", "record.format must be \"" + std::string(kRecordFormat) + "\"" +
                                               (r.has("format") ? ", got " + r.at("format").dump() : " (missing)"));
  r.integer("version", 1, 1, 1, "the record format's version");
  if (!r.has("games")) throw InvalidArgument("record.games", "record.games is required: the games");
  const Json& games = r.array("games", 1000000);
  std::vector<GameRecord> out;
  for (std::size_t i = 0; i < games.size(); ++i) out.push_back(read_record(games[i], "record.games[" + std::to_string(i) + "]"));
  return out;
}

std::string game_summary_to_json(const std::vector<GameRecord>& records, int indent) {
  Json games = Json::array();
  std::array<int, 2> wins{}, fouls{}, pots{};
  int truncated = 0;
  std::size_t steps = 0;
  for (const GameRecord& g : records) {
    const GameState& end = g.steps.empty() ? g.start : g.steps.back().state;
    const GameTally t = tally(g);
    games.push_back({{"seed", g.seed},
                     {"players", Json::array({g.players[0], g.players[1]})},
                     {"scores", pair_json(end.scores)},
                     {"winner", player_json(end.winner)},
                     {"truncated", end.truncated},
                     {"end_reason", end.end_reason},
                     {"steps", g.steps.size()},
                     {"fouls", pair_json(t.fouls)},
                     {"pots", pair_json(t.pots)}});
    if (end.winner) wins[static_cast<std::size_t>(*end.winner)] += 1;
    truncated += end.truncated ? 1 : 0;
    for (std::size_t p = 0; p < 2; ++p) {
      fouls[p] += t.fouls[p];
      pots[p] += t.pots[p];
    }
    steps += g.steps.size();
  }
  const Json totals = {{"games", records.size()}, {"wins", pair_json(wins)}, {"truncated", truncated},
                       {"fouls", pair_json(fouls)}, {"pots", pair_json(pots)}, {"steps", steps}};
  return Json{{"games", games}, {"totals", totals}}.dump(indent);
}

std::optional<ReplayDifference> replay_difference(const GameRecord& record, int game) {
  GameState state = record.start;
  for (std::size_t i = 0; i < record.steps.size(); ++i) {
    const RecordedStep& recorded = record.steps[i];
    ReplayDifference d;
    d.game = game;
    d.step = static_cast<int>(i);
    const std::string at_step = "games[" + std::to_string(game) + "].steps[" + std::to_string(i) + "]";
    GameStep step;
    try {
      step = play(state, recorded.action, recorded.seed);
    } catch (const InvalidArgument& e) {
      d.path = at_step + ".action";
      d.recorded = action_json(recorded.action).dump();
      d.replayed = std::string("refused: ") + e.what();
      return d;
    }
    Json va, vb;
    const Json rec_ruling = ruling_json(recorded.ruling), new_ruling = ruling_json(step.ruling);
    if (auto p = first_difference(rec_ruling, new_ruling, at_step + ".ruling", va, vb)) {
      d.path = *p;
      d.recorded = va.is_string() ? va.get<std::string>() : va.dump();
      d.replayed = vb.is_string() ? vb.get<std::string>() : vb.dump();
      return d;
    }
    const Json rec_state = state_json(recorded.state), new_state = state_json(step.next);
    if (auto p = first_difference(rec_state, new_state, at_step + ".state", va, vb)) {
      d.path = *p;
      d.recorded = va.is_string() ? va.get<std::string>() : va.dump();
      d.replayed = vb.is_string() ? vb.get<std::string>() : vb.dump();
      return d;
    }
    state = std::move(step.next);
  }
  return std::nullopt;
}

namespace io {

nlohmann::json reasoning_json(const Reasoning& r) {
  nlohmann::json considered = nlohmann::json::array();
  for (const ConsideredOption& c : r.considered) {
    nlohmann::json o{{"what", c.what}};
    if (c.estimate >= 0.0) o["estimate"] = c.estimate;
    if (c.next_estimate >= 0.0) o["next_estimate"] = c.next_estimate;
    considered.push_back(std::move(o));
  }
  return {{"summary", r.summary}, {"considered", considered}};
}

bool has_reasoning(const Reasoning& r) { return !r.summary.empty() || !r.considered.empty(); }

}  // namespace io

}  // namespace cueball
