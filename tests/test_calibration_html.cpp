// The calibration's HTML report (io/calibration_html.cpp) and the drawings
// behind it (calibrate.cpp's shot_drawings, strike_fit.cpp's
// simulated_paths), on synthetic tracked shots evaluated under the true
// constants: the page is self-contained, holds every shot and a histogram
// whose bars count every shot, and each drawn simulated path ends where the
// tracker last saw the ball (within 2 cm: the fit reproduces the shot).
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "cueball/core/errors.hpp"
#include "cueball/io/calibration_html.hpp"
#include "synthetic_tracks.hpp"

namespace cueball {
namespace {

TrackedShots two_shots(const FitModel& m) {
  TrackedShots shots;
  shots.table_name = "carom_10ft";
  shots.table = m.table;
  shots.shots.push_back(
      test::synthetic_shot(m, test::carom_layout({0.7, 0.5}, {2.1, 0.35}, {1.9, 1.05}), {3.2, 25.0, 4.0, 0.2, 0.15}, 0.01, 5));
  shots.shots.push_back(
      test::synthetic_shot(m, test::carom_layout({1.4, 0.7}, {0.4, 0.3}, {2.5, 1.1}), {3.0, 100.0, 3.0, 0.3, 0.1}, 0.01, 6));
  shots.shots[1].id = "<b>&'\"";  // escaped on the page
  return shots;
}

struct Evaluated {
  FitModel model = test::carom_model();
  TrackedShots shots = two_shots(model);
  CalibrationReport report;
  Evaluated() {
    CalibrationOptions o;
    o.evaluate_only = true;
    o.strike.starts = 8;
    report = calibrate(shots, model, o);
  }
};

const Evaluated& evaluated() {
  static const Evaluated e;
  return e;
}

TEST(CalibrationDrawings, SimulatedPathsEndAtTheLastTrackedSample) {
  const Evaluated& e = evaluated();
  const std::vector<ShotDrawing> d = shot_drawings(e.shots, e.report);
  ASSERT_EQ(d.size(), 2u);
  for (const ShotDrawing& s : d) {
    ASSERT_EQ(s.names.size(), 3u);
    ASSERT_EQ(s.simulated.size(), 3u) << s.id;
    for (std::size_t j = 0; j < 3; ++j) {
      ASSERT_FALSE(s.measured[j].empty());
      ASSERT_FALSE(s.simulated[j].empty());
      // The path starts at the layout and ends where the ball was last seen.
      EXPECT_LT(norm(s.simulated[j].front() - s.measured[j].front()), 0.005) << s.id << " " << s.names[j];
      EXPECT_LT(norm(s.simulated[j].back() - s.measured[j].back()), 0.02) << s.id << " " << s.names[j];
      // Points are at least 2 mm apart (but for the last).
      for (std::size_t k = 1; k + 1 < s.simulated[j].size(); ++k)
        EXPECT_GE(norm(s.simulated[j][k] - s.simulated[j][k - 1]), 0.002 - 1e-12);
    }
  }
}

TEST(CalibrationDrawings, RefuseShotsThatAreNotTheReports) {
  const Evaluated& e = evaluated();
  TrackedShots other = e.shots;
  other.shots.pop_back();
  EXPECT_THROW(shot_drawings(other, e.report), InvalidArgument);
  other = e.shots;
  other.shots[0].id = "another";
  EXPECT_THROW(shot_drawings(other, e.report), InvalidArgument);
}

TEST(CalibrationHtml, IsSelfContainedAndDrawsEveryShot) {
  const Evaluated& e = evaluated();
  const std::string page = calibration_report_html(e.report, e.shots.table, shot_drawings(e.shots, e.report));
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("</html>"), std::string::npos);
  // Nothing fetched: no script, no link, no src, no url().
  for (const char* fetch : {"<script", "<link", "src=", "url(", "@import", "href="}) EXPECT_EQ(page.find(fetch), std::string::npos) << fetch;
  // Every shot is a figure with three simulated and three measured paths.
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = page.find(what); at != std::string::npos; at = page.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("<figure"), 2u);
  EXPECT_EQ(count("class=\"simulated\""), 6u);
  EXPECT_EQ(count("class=\"measured\""), 6u);
  EXPECT_NE(page.find("id=\"shot-" + e.shots.shots[0].id + "\""), std::string::npos);
  // The odd id is escaped, never written raw.
  EXPECT_EQ(page.find("<b>&'\""), std::string::npos);
  EXPECT_NE(page.find("&lt;b&gt;&amp;&#39;&quot;"), std::string::npos);
  // The histogram's bars count every shot once.
  const std::regex bar("data-count=\"([0-9]+)\"");
  int shots = 0;
  for (auto it = std::sregex_iterator(page.begin(), page.end(), bar); it != std::sregex_iterator(); ++it) shots += std::stoi((*it)[1]);
  EXPECT_EQ(shots, 2);
  // The constants are shown as fitted.
  EXPECT_NE(page.find(std::to_string(e.report.model.settings.parameters.cloth.rolling_resistance).substr(0, 6)), std::string::npos);
}

TEST(CalibrationHtml, ShowsTheBootstrapSpreadWhenThereIsOne) {
  Evaluated e = evaluated();
  const std::vector<ShotDrawing> d = shot_drawings(e.shots, e.report);
  EXPECT_EQ(calibration_report_html(e.report, e.shots.table, d).find("std. dev."), std::string::npos);
  e.report.spread = {{"mu_r", 0.008, 0.0004, 0.0073, 0.0087}};
  e.report.bootstrap_replicates = 10;
  const std::string page = calibration_report_html(e.report, e.shots.table, d);
  EXPECT_NE(page.find("std. dev."), std::string::npos);
  EXPECT_NE(page.find("0.00040"), std::string::npos);
  EXPECT_NE(page.find("10 bootstrap replicates"), std::string::npos);
}

}  // namespace
}  // namespace cueball
