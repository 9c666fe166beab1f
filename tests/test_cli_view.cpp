// `cueball view` and `cueball simulate --html` (cli/command_view.cpp,
// cli/viewer_page.cpp): the page is the embedded template with the result in
// place of its token, '<' escaped so no string can end the <script>; bad
// result files get one line naming the JSON path. The page itself is tested
// in a real browser by viewer/test (ctest viewer_e2e).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "temp_dir.hpp"
#include "cueball/io/viewer_page.hpp"

namespace cueball {
namespace {

using namespace test;  // the CLI tests' helpers (tests/support/)
using Json = nlohmann::json;

constexpr std::string_view kOpen = R"(<script type="application/json" id="cueball-result">)";

// The JSON the page carries: the text of its cueball-result element.
Json embedded_result(const std::string& page) {
  const std::size_t begin = page.find(kOpen);
  EXPECT_NE(begin, std::string::npos);
  const std::size_t from = begin + kOpen.size();
  const std::size_t end = page.find("</script>", from);
  EXPECT_NE(end, std::string::npos);
  return Json::parse(page.substr(from, end - from));
}

std::size_t occurrences(std::string_view text, std::string_view what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string_view::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ViewerTemplate, HoldsTheTokenOnceInsideTheResultScript) {
  const std::string_view page = viewer_template();
  ASSERT_GT(page.size(), 100u);
  EXPECT_EQ(occurrences(page, kViewerResultToken), 1u);
  EXPECT_EQ(occurrences(page, std::string(kOpen) + std::string(kViewerResultToken) + "</script>"), 1u);
}

TEST(ViewerTemplate, FetchesNothing) {
  // Self-contained: no external scripts, styles, fonts or images.
  // Every src= and href= is inline (data:) or in-page (#).
  const std::string_view page = viewer_template();
  EXPECT_EQ(page.find("http://"), std::string_view::npos);
  EXPECT_EQ(page.find("https://"), std::string_view::npos);
  EXPECT_EQ(page.find("@import"), std::string_view::npos);
  for (const std::string_view attribute : {"src=\"", "href=\"", "src='", "href='"}) {
    for (std::size_t at = page.find(attribute); at != std::string_view::npos; at = page.find(attribute, at + 1)) {
      const std::string_view value = page.substr(at + attribute.size(), 5);
      EXPECT_TRUE(value == "data:" || value.front() == '#') << page.substr(at, 60);
    }
  }
}

TEST(ViewerPage, ReplacesTheTokenAndEscapesEveryLessThan) {
  const std::string json = R"({"name":"</script><script>alert(1)</script>","x":"a<b"})";
  const std::string page = viewer_page("<p>__CUEBALL_RESULT__</p>", json);
  EXPECT_EQ(page, R"(<p>{"name":"\u003c/script>\u003cscript>alert(1)\u003c/script>","x":"a\u003cb"}</p>)");
  EXPECT_EQ(Json::parse(page.substr(3, page.size() - 7)), Json::parse(json));  // the same document
}

TEST(ViewerPage, RefusesATemplateWithoutExactlyOneToken) {
  EXPECT_THROW((void)viewer_page("<p></p>", "{}"), std::logic_error);
  EXPECT_THROW((void)viewer_page("__CUEBALL_RESULT__ __CUEBALL_RESULT__", "{}"), std::logic_error);
}

TEST(CliView, WritesThePageWithTheResult) {
  const TempDir dir;
  const std::string result = dir.path("r.json"), page = dir.path("shot.html");
  ASSERT_EQ(run_cli({"simulate", "-o", result}).status, 0);
  const CliRun r = run_cli({"view", result, "-o", page});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(page), std::string::npos);
  const std::string html = read_text(page);
  EXPECT_EQ(html.find(kViewerResultToken), std::string::npos);
  EXPECT_EQ(embedded_result(html), Json::parse(read_text(result)));
  // Everything around the result is the template, byte for byte.
  const std::string_view tpl = viewer_template();
  const std::size_t at = tpl.find(kViewerResultToken);
  EXPECT_EQ(html.substr(0, at), tpl.substr(0, at));
  const std::string_view tail = tpl.substr(at + kViewerResultToken.size());
  EXPECT_EQ(html.substr(html.size() - tail.size()), tail);
}

TEST(CliView, SimulateHtmlWritesTheSamePageAsView) {
  const TempDir dir;
  const std::string result = dir.path("r.json"), direct = dir.path("direct.html"), viewed = dir.path("viewed.html");
  const CliRun sim = run_cli({"simulate", "-o", result, "--html", direct});
  ASSERT_EQ(sim.status, 0) << sim.err;
  EXPECT_NE(sim.out.find("viewer written to " + direct), std::string::npos);
  ASSERT_EQ(run_cli({"view", result, "-o", viewed}).status, 0);
  EXPECT_EQ(read_text(direct), read_text(viewed));
}

TEST(CliView, BadResultFilesNameThePath) {
  const TempDir dir;
  const std::string out = dir.path("x.html");
  expect_usage_error({"view", dir.path("missing.json"), "-o", out}, "cannot open the result file");
  expect_usage_error({"view", dir.write("a.json", R"({"table": )"), "-o", out}, "malformed JSON");
  expect_usage_error({"view", dir.write("b.json", "[1, 2]"), "-o", out}, "expected a JSON object");
  expect_usage_error({"view", dir.write("c.json", R"({"table": 1})"), "-o", out}, "table: expected an object");

  // A real result with one field broken at a time.
  const std::string good = dir.path("r.json");
  ASSERT_EQ(run_cli({"simulate", "-o", good}).status, 0);
  const Json result = Json::parse(read_text(good));
  const auto broken = [&](const char* name, auto&& edit) {
    Json j = result;
    edit(j);
    return dir.write(name, j.dump());
  };
  expect_usage_error({"view", broken("d.json", [](Json& j) { j.erase("events"); }), "-o", out}, "events: missing");
  expect_usage_error({"view", broken("e.json", [](Json& j) { j["balls"][2]["segments"][0]["t"] = "soon"; }), "-o", out},
                     "balls[2].segments[0].t: expected a finite number");
  expect_usage_error(
      {"view", broken("f.json", [](Json& j) { j["balls"][0]["segments"][1]["position"] = Json::array({1.0}); }), "-o",
       out},
      "balls[0].segments[1].position: expected an array of 2 numbers");
  expect_usage_error({"view", broken("g.json", [](Json& j) { j["table"]["length"] = -2.0; }), "-o", out},
                     "table.length: -2 is outside");
  expect_usage_error({"view", broken("h.json", [](Json& j) { j["balls"][1]["segments"] = Json::array(); }), "-o", out},
                     "balls[1].segments: expected at least one segment");
  expect_usage_error({"view", dir.write("i.json", R"({"table": {"length": 1e999}})"), "-o", out}, "table.length");
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(CliView, UnwritablePageIsAUsageError) {
  const TempDir dir;
  const std::string result = dir.path("r.json");
  ASSERT_EQ(run_cli({"simulate", "-o", result}).status, 0);
  expect_usage_error({"view", result, "-o", dir.path("no/such/dir/x.html")}, "cannot write the viewer page");
  expect_usage_error({"simulate", "--html", dir.path("no/such/dir/x.html")}, "--html");
}

TEST(CliView, RequiresItsArguments) {
  const CliRun r = run_cli({"view"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("result"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace cueball
