// Tables as JSON (io/table_json.hpp): the preset form and the full
// geometry, read with every error named by its JSON path.
#include "cueball/io/table_json.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "cueball/core/errors.hpp"
#include "io/json_input.hpp"
#include "table/table_detail.hpp"

namespace cueball {

namespace {

[[noreturn]] void fail(const std::string& field, const std::string& message) { throw InvalidArgument(field, message); }
std::string join(const std::string& prefix, const std::string& field) { return detail::join_path(prefix, field); }

}  // namespace


namespace {

using nlohmann::json;
using nlohmann::ordered_json;

std::string type_of(const json& j) { return j.type_name(); }

double read_number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, path + " must be a number, got " + type_of(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, path + " = " + format_number(v) + " is not a finite number");
  return v;
}

std::string read_string(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, path + " must be a string, got " + type_of(j));
  return j.get<std::string>();
}

Vec2 read_point(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 2) {
    fail(path, path + " must be a point [x, y] (an array of 2 numbers), got " +
                   (j.is_array() ? "an array of " + std::to_string(j.size()) : type_of(j)));
  }
  return {read_number(j[0], path + "[0]"), read_number(j[1], path + "[1]")};
}

const json& read_array(const json& j, const std::string& path) {
  if (!j.is_array()) fail(path, path + " must be an array, got " + type_of(j));
  return j;
}

void require_object(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, path + " must be a JSON object, got " + type_of(j));
}

void check_keys(const json& j, const std::string& path, std::initializer_list<const char*> allowed,
                const char* context = "") {
  require_object(j, path);
  for (auto it = j.begin(); it != j.end(); ++it) {
    const bool known =
        std::any_of(allowed.begin(), allowed.end(), [&](const char* k) { return it.key() == k; });
    if (known) continue;
    std::string list;
    for (const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
    fail(join(path, it.key()), join(path, it.key()) + " is not a known key" + context + "; allowed: " + list);
  }
}

const json* find(const json& j, const char* key) {
  const auto it = j.find(key);
  return it == j.end() ? nullptr : &*it;
}

const json& require(const json& j, const std::string& path, const char* key) {
  const json* v = find(j, key);
  if (v == nullptr) fail(join(path, key), join(path, key) + " is required");
  return *v;
}

void read_ball_into(const json& j, const std::string& path, BallParameters& ball, bool all_required) {
  check_keys(j, path, {"mass", "radius"});
  if (all_required) {
    ball.mass = read_number(require(j, path, "mass"), join(path, "mass"));
    ball.radius = read_number(require(j, path, "radius"), join(path, "radius"));
    return;
  }
  if (const json* v = find(j, "mass")) ball.mass = read_number(*v, join(path, "mass"));
  if (const json* v = find(j, "radius")) ball.radius = read_number(*v, join(path, "radius"));
}

void read_pocket_spec_into(const json& j, const std::string& path, PocketSpec& p) {
  check_keys(j, path, {"mouth", "cut_angle_deg", "jaw_radius", "shelf"});
  if (const json* v = find(j, "mouth")) p.mouth = read_number(*v, join(path, "mouth"));
  if (const json* v = find(j, "cut_angle_deg")) p.cut_angle_deg = read_number(*v, join(path, "cut_angle_deg"));
  if (const json* v = find(j, "jaw_radius")) p.jaw_radius = read_number(*v, join(path, "jaw_radius"));
  if (const json* v = find(j, "shelf")) p.shelf = read_number(*v, join(path, "shelf"));
}

Table read_preset_form(const json& j, const std::string& path) {
  check_keys(j, path,
             {"preset", "name", "length", "width", "cushion_height", "ball", "corner_pockets", "side_pockets"},
             " with \"preset\" (give either a preset with overrides or the full geometry)");
  const std::string preset_path = join(path, "preset");
  const std::string preset = read_string(j["preset"], preset_path);
  TableSpec spec;
  try {
    spec = preset_table_spec(preset);
  } catch (const InvalidArgument& e) {
    fail(preset_path, preset_path + ": " + e.what());
  }
  const double old_radius = spec.ball.radius;
  if (const json* v = find(j, "name")) spec.name = read_string(*v, join(path, "name"));
  if (const json* v = find(j, "length")) spec.length = read_number(*v, join(path, "length"));
  if (const json* v = find(j, "width")) spec.width = read_number(*v, join(path, "width"));
  if (const json* v = find(j, "ball")) read_ball_into(*v, join(path, "ball"), spec.ball, false);
  if (const json* v = find(j, "cushion_height")) {
    spec.cushion_height = read_number(*v, join(path, "cushion_height"));
  } else if (spec.ball.radius != old_radius && std::isfinite(spec.ball.radius)) {
    spec.cushion_height *= spec.ball.radius / old_radius;  // keep its proportion to the ball
  }
  for (const char* key : {"corner_pockets", "side_pockets"}) {
    const json* v = find(j, key);
    if (v == nullptr) continue;
    if (!spec.has_pockets) {
      fail(join(path, key), join(path, key) + " is not allowed: the " + preset + " preset has no pockets");
    }
    read_pocket_spec_into(*v, join(path, key), std::string(key) == "corner_pockets" ? spec.corner_pockets
                                                                                    : spec.side_pockets);
  }
  detail::validate_spec_at(spec, path);
  return detail::build_table_unchecked(spec);
}

// A cushion's or jaw's optional "name": a non-empty string (the rest is
// checked by validate_part_names); absent, the default is filled in later.
std::string read_part_name(const json& part, const std::string& path) {
  const json* v = find(part, "name");
  if (v == nullptr) return {};
  std::string name = read_string(*v, path + ".name");
  if (name.empty()) fail(path + ".name", path + ".name must not be empty (omit it for the default name)");
  return name;
}

Table read_full_form(const json& j, const std::string& path) {
  check_keys(j, path, {"name", "length", "width", "ball", "cushions", "jaws", "pockets", "diamonds"});
  Table t;
  t.name = "custom";
  if (const json* v = find(j, "name")) t.name = read_string(*v, join(path, "name"));
  t.length = read_number(require(j, path, "length"), join(path, "length"));
  t.width = read_number(require(j, path, "width"), join(path, "width"));
  read_ball_into(require(j, path, "ball"), join(path, "ball"), t.ball, true);
  {
    const std::string base = join(path, "cushions");
    const json& a = read_array(require(j, path, "cushions"), base);
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = base + "[" + std::to_string(i) + "]";
      check_keys(a[i], p, {"name", "start", "end", "contact_height"});
      t.cushions.push_back({read_point(require(a[i], p, "start"), p + ".start"),
                            read_point(require(a[i], p, "end"), p + ".end"),
                            read_number(require(a[i], p, "contact_height"), p + ".contact_height"),
                            read_part_name(a[i], p)});
    }
  }
  if (const json* v = find(j, "jaws")) {
    const std::string base = join(path, "jaws");
    const json& a = read_array(*v, base);
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = base + "[" + std::to_string(i) + "]";
      check_keys(a[i], p, {"name", "centre", "radius", "contact_height"});
      t.jaws.push_back({read_point(require(a[i], p, "centre"), p + ".centre"),
                        read_number(require(a[i], p, "radius"), p + ".radius"),
                        read_number(require(a[i], p, "contact_height"), p + ".contact_height"),
                        read_part_name(a[i], p)});
    }
  }
  if (const json* v = find(j, "pockets")) {
    const std::string base = join(path, "pockets");
    const json& a = read_array(*v, base);
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = base + "[" + std::to_string(i) + "]";
      check_keys(a[i], p, {"name", "centre", "radius"});
      t.pockets.push_back({read_string(require(a[i], p, "name"), p + ".name"),
                           read_point(require(a[i], p, "centre"), p + ".centre"),
                           read_number(require(a[i], p, "radius"), p + ".radius")});
    }
  }
  if (const json* v = find(j, "diamonds")) {
    const std::string base = join(path, "diamonds");
    const json& a = read_array(*v, base);
    for (std::size_t i = 0; i < a.size(); ++i) {
      t.diamonds.push_back(read_point(a[i], base + "[" + std::to_string(i) + "]"));
    }
  }
  name_parts(t);  // the defaults "cushions[i]", "jaws[j]" for parts given no name
  return t;
}

ordered_json point_json(Vec2 p) { return ordered_json::array({p.x, p.y}); }

}  // namespace

Table table_from_json(std::string_view json_text, std::string_view path_view) {
  const std::string path(path_view);
  const json j = detail::parse_json(json_text, path);
  require_object(j, path);
  Table t = j.contains("preset") ? read_preset_form(j, path) : read_full_form(j, path);
  detail::validate_table_at(t, path);
  return t;
}

std::string table_to_json(const Table& t) {
  ordered_json j;
  j["name"] = t.name;
  j["length"] = t.length;
  j["width"] = t.width;
  j["ball"] = ordered_json{{"mass", t.ball.mass}, {"radius", t.ball.radius}};
  ordered_json cushions = ordered_json::array();
  for (const CushionSegment& s : t.cushions) {
    ordered_json c;
    c["name"] = cushion_name(t, static_cast<std::size_t>(&s - t.cushions.data()));
    c["start"] = point_json(s.start);
    c["end"] = point_json(s.end);
    c["contact_height"] = s.contact_height;
    cushions.push_back(std::move(c));
  }
  j["cushions"] = std::move(cushions);
  ordered_json jaws = ordered_json::array();
  for (const JawArc& a : t.jaws) {
    ordered_json c;
    c["name"] = jaw_name(t, static_cast<std::size_t>(&a - t.jaws.data()));
    c["centre"] = point_json(a.centre);
    c["radius"] = a.radius;
    c["contact_height"] = a.contact_height;
    jaws.push_back(std::move(c));
  }
  j["jaws"] = std::move(jaws);
  ordered_json pockets = ordered_json::array();
  for (const Pocket& p : t.pockets) {
    ordered_json c;
    c["name"] = p.name;
    c["centre"] = point_json(p.centre);
    c["radius"] = p.radius;
    pockets.push_back(std::move(c));
  }
  j["pockets"] = std::move(pockets);
  ordered_json diamonds = ordered_json::array();
  for (Vec2 d : t.diamonds) diamonds.push_back(point_json(d));
  j["diamonds"] = std::move(diamonds);
  return j.dump(2);
}

}  // namespace cueball
