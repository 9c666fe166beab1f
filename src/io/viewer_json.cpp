// What the HTML viewer draws, as JSON (io/viewer_json.hpp): the aim overlay
// of a planned shot, and the check that a result is one the page can draw.
#include "cueball/io/viewer_json.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "cueball/core/errors.hpp"
#include "io/json_input.hpp"

namespace cueball {

std::string aim_overlay_json(const SimulationResult& r, const Parameters& p, int cue_ball) {
  std::size_t cue = r.balls.size();
  for (std::size_t i = 0; i < r.balls.size(); ++i)
    if (r.balls[i].id == cue_ball) cue = i;
  if (cue == r.balls.size()) throw std::logic_error("aim_overlay_json: no ball has the cue ball's id");
  nlohmann::json line = nlohmann::json::array();
  const auto at = [&](double t) {
    const BallState s = r.state_at(cue, t, p);
    return nlohmann::json::array({s.position.x, s.position.y});
  };
  line.push_back(at(0.0));
  nlohmann::json ghost = nullptr;
  for (const Event& e : r.events) {
    if (e.type == EventType::ball_ball && (e.ball == cue_ball || e.other == cue_ball)) {
      ghost = at(e.time);
      break;
    }
    if ((e.type == EventType::ball_cushion || e.type == EventType::ball_jaw) && e.ball == cue_ball) line.push_back(at(e.time));
  }
  const BallTrajectory& b = r.balls[cue];
  line.push_back(ghost.is_null() ? at(b.pocketed ? b.pocket_time : r.end_time) : ghost);
  return nlohmann::json{{"aim_line", line}, {"ghost_ball", ghost}}.dump();
}

std::string with_overlay(std::string_view result_json, std::string_view overlay_json) {
  const std::size_t end = result_json.find_last_of('}');
  if (end == std::string_view::npos) throw std::logic_error("with_overlay: the result is not a JSON object");
  std::string out(result_json.substr(0, end));
  out += ",\"overlay\":";
  out += overlay_json;
  out += '}';
  return out;
}

namespace {

using Json = nlohmann::json;

// A value in the result document with its JSON path; each check returns the
// value or throws InvalidArgument naming the path.
class Node {
 public:
  Node(const Json& value, std::string path, const std::string& source)
      : value_(value), path_(std::move(path)), source_(source) {}

  Node operator[](const char* key) const {
    const std::string path = path_.empty() ? key : path_ + "." + key;
    if (!value_.is_object() || !value_.contains(key)) Node(value_, path, source_).fail("missing");
    return {value_.at(key), path, source_};
  }
  Node operator[](std::size_t i) const { return {value_.at(i), path_ + "[" + std::to_string(i) + "]", source_}; }
  bool has(const char* key) const { return value_.contains(key) && !value_.at(key).is_null(); }

  const Node& object() const { return expect(value_.is_object(), "expected an object"); }
  std::size_t array() const { return expect(value_.is_array(), "expected an array").value_.size(); }
  double number(double lo, double hi) const {
    expect(value_.is_number() && std::isfinite(value_.get<double>()), "expected a finite number");
    const double x = value_.get<double>();
    expect(x >= lo && x <= hi,
           format_number_beside(x, {lo, hi}) + " is outside [" + format_number(lo) + ", " + format_number(hi) + "]");
    return x;
  }
  void string() const { expect(value_.is_string(), "expected a string"); }
  void integer() const { expect(value_.is_number_integer(), "expected an integer"); }
  void integers() const {
    expect(value_.is_array(), "expected an array");
    for (const Json& x : value_) expect(x.is_number_integer(), "expected an array of ball ids");
  }
  void boolean() const { expect(value_.is_boolean(), "expected true or false"); }
  void vector(std::size_t size) const {
    const std::string what = "expected an array of " + std::to_string(size);
    expect(value_.is_array() && value_.size() == size, what + " numbers");
    for (const Json& x : value_) expect(x.is_number() && std::isfinite(x.get<double>()), what + " finite numbers");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InvalidArgument(source_, source_ + ": " + path_ + ": " + what + " (expected a result written by `cueball simulate -o`)");
  }

 private:
  const Node& expect(bool ok, const std::string& what) const {
    if (!ok) fail(what);
    return *this;
  }

  const Json& value_;
  std::string path_;
  const std::string& source_;
};

// Checks the keys and types the page reads.
void check_result(const Node& r) {
  constexpr double kBig = 1e6;
  const Node table = r["table"];
  table.object();
  table["name"].string();
  table["length"].number(1e-3, 100.0);
  table["width"].number(1e-3, 100.0);
  const Node cushions = table["cushions"];
  for (std::size_t i = 0, n = cushions.array(); i < n; ++i) {
    cushions[i]["start"].vector(2);
    cushions[i]["end"].vector(2);
  }
  const Node jaws = table["jaws"];
  for (std::size_t i = 0, n = jaws.array(); i < n; ++i) {
    jaws[i]["centre"].vector(2);
    jaws[i]["radius"].number(0.0, 10.0);
  }
  const Node pockets = table["pockets"];
  for (std::size_t i = 0, n = pockets.array(); i < n; ++i) {
    pockets[i]["centre"].vector(2);
    pockets[i]["radius"].number(0.0, 10.0);
    pockets[i]["name"].string();
  }
  const Node diamonds = table["diamonds"];
  for (std::size_t i = 0, n = diamonds.array(); i < n; ++i) diamonds[i].vector(2);
  const Node parameters = r["parameters"];
  parameters.object();
  parameters["radius"].number(1e-4, 1.0);
  for (const char* mu : {"mu_s", "mu_r", "mu_sp"}) parameters[mu].number(0.0, 10.0);
  parameters["g"].number(1e-3, 1e3);
  r["end_time"].number(0.0, kBig);
  const Node events = r["events"];
  for (std::size_t i = 0, n = events.array(); i < n; ++i) {
    events[i]["time"].number(0.0, kBig);
    events[i]["type"].string();
    events[i]["balls"].integers();
  }
  if (r.has("overlay")) {
    const Node overlay = r["overlay"];
    overlay.object();
    const Node line = overlay["aim_line"];
    const std::size_t points = line.array();
    if (points < 2) line.fail("expected at least two [x, y] points");
    for (std::size_t i = 0; i < points; ++i) line[i].vector(2);
    if (overlay.has("ghost_ball")) overlay["ghost_ball"].vector(2);
  }
  const Node balls = r["balls"];
  for (std::size_t i = 0, n = balls.array(); i < n; ++i) {
    const Node ball = balls[i];
    ball["id"].integer();
    ball["name"].string();
    ball["pocketed"].boolean();
    if (ball.has("pocket_time")) ball["pocket_time"].number(0.0, 1e9);
    const Node segments = ball["segments"];
    const std::size_t count = segments.array();
    if (count == 0) segments.fail("expected at least one segment");
    double previous = 0.0;
    for (std::size_t k = 0; k < count; ++k) {
      const Node segment = segments[k];
      previous = segment["t"].number(previous, kBig);
      segment["phase"].string();
      segment["position"].vector(2);
      segment["velocity"].vector(2);
      segment["angular_velocity"].vector(3);
    }
  }
}

}  // namespace

std::string checked_result_for_viewer(const std::string& source, std::string_view result_json) {
  Json r;
  try {
    r = detail::parse_json(result_json, "result");
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(source, source + ": " + e.what());
  }
  if (!r.is_object()) Node(r, "(document)", source).fail("expected a JSON object");
  check_result(Node(r, "", source));
  return r.dump();
}

}  // namespace cueball
