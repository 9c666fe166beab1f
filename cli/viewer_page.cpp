// cueball simulate --html, cueball view: the result drawn by the embedded
// HTML viewer (viewer/README.md describes the page and its build).
#include "viewer_page.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "common.hpp"
#include "json_input.hpp"  // src/: the library's JSON reader (depth limit, 1e999 by path)

namespace cueball::cli {

// Defined in the source that cmake/EmbedFile.cmake generates from
// viewer/dist/cueball-viewer.html.
extern const unsigned char kViewerTemplate[];
extern const std::size_t kViewerTemplate_size;

std::string_view viewer_template() {
  return {reinterpret_cast<const char*>(kViewerTemplate), kViewerTemplate_size};
}

std::string viewer_page(std::string_view template_text, std::string_view result_json) {
  const std::size_t at = template_text.find(kViewerResultToken);
  if (at == std::string_view::npos || template_text.find(kViewerResultToken, at + 1) != std::string_view::npos)
    throw std::logic_error("the viewer template must hold the result token exactly once");
  std::string page;
  page.reserve(template_text.size() + result_json.size() + result_json.size() / 16);
  page.append(template_text.substr(0, at));
  for (const char c : result_json) {
    if (c == '<')
      page.append("\\u003c");
    else
      page.push_back(c);
  }
  page.append(template_text.substr(at + kViewerResultToken.size()));
  return page;
}

namespace {

using Json = nlohmann::json;

// Walks a result document, checking what the page reads; errors name the
// JSON path.
class ResultChecker {
 public:
  explicit ResultChecker(std::string source) : source_(std::move(source)) {}

  const Json& member(const Json& object, const std::string& path, const char* key) const {
    if (!object.contains(key)) fail(path.empty() ? key : path + "." + key, "missing");
    return object.at(key);
  }
  const Json& object(const Json& parent, const std::string& path, const char* key) const {
    const Json& v = member(parent, path, key);
    if (!v.is_object()) fail(join(path, key), "expected an object");
    return v;
  }
  const Json& array(const Json& parent, const std::string& path, const char* key) const {
    const Json& v = member(parent, path, key);
    if (!v.is_array()) fail(join(path, key), "expected an array");
    return v;
  }
  void number(const Json& parent, const std::string& path, const char* key, double lo, double hi) const {
    const Json& v = member(parent, path, key);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      fail(join(path, key), "expected a finite number");
    const double x = v.get<double>();
    if (x < lo || x > hi)
      fail(join(path, key), format_number(x) + " is outside [" + format_number(lo) + ", " + format_number(hi) + "]");
  }
  void optional_number(const Json& parent, const std::string& path, const char* key) const {
    if (parent.contains(key) && !parent.at(key).is_null()) number(parent, path, key, 0.0, 1e9);
  }
  void string(const Json& parent, const std::string& path, const char* key) const {
    if (!member(parent, path, key).is_string()) fail(join(path, key), "expected a string");
  }
  void vector(const Json& parent, const std::string& path, const char* key, std::size_t size) const {
    const Json& v = member(parent, path, key);
    if (!v.is_array() || v.size() != size) fail(join(path, key), "expected an array of " + std::to_string(size) + " numbers");
    for (const Json& x : v)
      if (!x.is_number() || !std::isfinite(x.get<double>()))
        fail(join(path, key), "expected an array of " + std::to_string(size) + " finite numbers");
  }
  static std::string join(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }
  static std::string item(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw UsageError(source_ + ": " + path + ": " + what + " (expected a result written by `cueball simulate -o`)");
  }

 private:
  std::string source_;
};

void check_result(const Json& r, const ResultChecker& c) {
  if (!r.is_object()) c.fail("(document)", "expected a JSON object");
  constexpr double kBig = 1e6;
  const Json& table = c.object(r, "", "table");
  c.string(table, "table", "name");
  c.number(table, "table", "length", 1e-3, 100.0);
  c.number(table, "table", "width", 1e-3, 100.0);
  const Json& cushions = c.array(table, "table", "cushions");
  for (std::size_t i = 0; i < cushions.size(); ++i) {
    const std::string p = ResultChecker::item("table.cushions", i);
    c.vector(cushions[i], p, "start", 2);
    c.vector(cushions[i], p, "end", 2);
  }
  const Json& jaws = c.array(table, "table", "jaws");
  for (std::size_t i = 0; i < jaws.size(); ++i) {
    const std::string p = ResultChecker::item("table.jaws", i);
    c.vector(jaws[i], p, "centre", 2);
    c.number(jaws[i], p, "radius", 0.0, 10.0);
  }
  const Json& pockets = c.array(table, "table", "pockets");
  for (std::size_t i = 0; i < pockets.size(); ++i) {
    const std::string p = ResultChecker::item("table.pockets", i);
    c.vector(pockets[i], p, "centre", 2);
    c.number(pockets[i], p, "radius", 0.0, 10.0);
    c.string(pockets[i], p, "name");
  }
  const Json& diamonds = c.array(table, "table", "diamonds");
  for (std::size_t i = 0; i < diamonds.size(); ++i) {
    const Json holder{{"d", diamonds[i]}};
    c.vector(holder, ResultChecker::item("table.diamonds", i), "d", 2);
  }
  const Json& parameters = c.object(r, "", "parameters");
  c.number(parameters, "parameters", "radius", 1e-4, 1.0);
  c.number(parameters, "parameters", "mu_s", 0.0, 10.0);
  c.number(parameters, "parameters", "mu_r", 0.0, 10.0);
  c.number(parameters, "parameters", "mu_sp", 0.0, 10.0);
  c.number(parameters, "parameters", "g", 1e-3, 1e3);
  c.number(r, "", "end_time", 0.0, kBig);
  const Json& events = c.array(r, "", "events");
  for (std::size_t i = 0; i < events.size(); ++i) {
    const std::string p = ResultChecker::item("events", i);
    c.number(events[i], p, "time", 0.0, kBig);
    c.string(events[i], p, "type");
    for (const Json& id : c.array(events[i], p, "balls"))
      if (!id.is_number_integer()) c.fail(p + ".balls", "expected an array of ball ids");
  }
  const Json& balls = c.array(r, "", "balls");
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const std::string p = ResultChecker::item("balls", i);
    if (!c.member(balls[i], p, "id").is_number_integer()) c.fail(p + ".id", "expected an integer");
    c.string(balls[i], p, "name");
    if (!c.member(balls[i], p, "pocketed").is_boolean()) c.fail(p + ".pocketed", "expected true or false");
    c.optional_number(balls[i], p, "pocket_time");
    const Json& segments = c.array(balls[i], p, "segments");
    if (segments.empty()) c.fail(p + ".segments", "expected at least one segment");
    double previous = 0.0;
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const std::string q = ResultChecker::item(p + ".segments", k);
      c.number(segments[k], q, "t", previous, kBig);
      previous = segments[k].at("t").get<double>();
      c.string(segments[k], q, "phase");
      c.vector(segments[k], q, "position", 2);
      c.vector(segments[k], q, "velocity", 2);
      c.vector(segments[k], q, "angular_velocity", 3);
    }
  }
}

}  // namespace

std::string checked_result_for_viewer(const std::string& source, std::string_view result_json) {
  Json r;
  try {
    r = detail::parse_json(result_json, "result");
  } catch (const InvalidArgument& e) {
    throw UsageError(source + ": " + e.what());
  }
  check_result(r, ResultChecker(source));
  return r.dump();
}

}  // namespace cueball::cli
