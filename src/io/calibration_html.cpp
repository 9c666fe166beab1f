// The calibration report as a self-contained HTML page (io/calibration_html.hpp).
#include "cueball/io/calibration_html.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string_view>

#include "cueball/models/cushion/model.hpp"

namespace cueball {

namespace {

// Colours of the balls in layout order (the cue ball first).
constexpr const char* kBallColours[] = {"#1f5fbf", "#c0392b", "#c79a00", "#2e8b57", "#8e44ad", "#d35400"};
// Pixels per metre of the shot drawings and the margin around the table.
constexpr double kScale = 150.0;
constexpr double kMargin = 8.0;

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

std::string centimetres(double metres) { return std::isfinite(metres) ? fixed(100.0 * metres, 1) + " cm" : "-"; }

std::string escape(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out.push_back(c);
    }
  }
  return out;
}

const char* colour(std::size_t ball) { return kBallColours[ball % std::size(kBallColours)]; }

constexpr std::string_view kStyle = R"(<style>
body{font:14px/1.4 system-ui,sans-serif;margin:1.5em auto;max-width:1100px;color:#222;padding:0 1em}
h1{font-size:1.4em}h2{font-size:1.15em;margin-top:1.6em}
table.t{border-collapse:collapse;margin:.5em 0}table.t td,table.t th{padding:2px 10px;border-bottom:1px solid #ddd;text-align:right}
table.t th:first-child,table.t td:first-child{text-align:left}
.shots{display:flex;flex-wrap:wrap;gap:14px}
figure.shot{margin:0;border:1px solid #ccc;border-radius:4px;padding:6px}
figure.shot.mismatch{border-color:#c0392b}
figcaption{font-size:12px}
.legend span{margin-right:1em}
.note{color:#666;font-size:12px}
</style>
)";

void constants_section(std::string& h, const CalibrationReport& r) {
  const Parameters& p = r.model.settings.parameters;
  const CushionSettings& c = r.model.settings.cushion;
  const std::pair<const char*, double> values[] = {{"mu_s", p.cloth.sliding_friction},
                                                  {"mu_r", p.cloth.rolling_resistance},
                                                  {"mu_sp", p.cloth.spin_friction},
                                                  {"cushion_restitution", c.restitution},
                                                  {"cushion_friction", c.friction}};
  h += "<h2>Constants</h2>\n<p>cushion model <b>" + escape(to_string(c.model)) + "</b>";
  if (r.bootstrap_replicates > 0)
    h += "; spread over " + std::to_string(r.bootstrap_replicates) + " bootstrap replicates of the training shots";
  h += "</p>\n<table class=\"t\" id=\"constants\"><tr><th>constant</th><th>value</th>";
  if (!r.spread.empty()) h += "<th>std. dev.</th><th>5 %</th><th>95 %</th>";
  h += "</tr>\n";
  for (const auto& [name, value] : values) {
    h += "<tr><td>" + std::string(name) + "</td><td>" + fixed(value, 5) + "</td>";
    for (const ConstantSpread& s : r.spread)
      if (s.name == name) h += "<td>" + fixed(s.std_dev, 5) + "</td><td>" + fixed(s.p05, 5) + "</td><td>" + fixed(s.p95, 5) + "</td>";
    h += "</tr>\n";
  }
  h += "</table>\n";
}

void summary_section(std::string& h, const CalibrationReport& r) {
  h += "<h2>Summary</h2>\n<table class=\"t\" id=\"summary\"><tr><th></th><th>shots</th><th>cue RMSE median</th><th>cue p90</th>"
       "<th>cue mean</th><th>object balls median</th><th>object p90</th><th>contact mismatches</th></tr>\n";
  const std::pair<const char*, const FitSummary*> rows[] = {{"training", &r.training}, {"held out", &r.held_out}};
  for (const auto& [name, s] : rows) {
    if (s->shots == 0) continue;
    h += "<tr><td>" + std::string(name) + "</td><td>" + std::to_string(s->shots) + "</td><td>" + centimetres(s->cue_rmse_median) +
         "</td><td>" + centimetres(s->cue_rmse_p90) + "</td><td>" + centimetres(s->cue_rmse_mean) + "</td><td>" +
         centimetres(s->object_rmse_median) + "</td><td>" + centimetres(s->object_rmse_p90) + "</td><td>" +
         std::to_string(s->contact_mismatches) + "</td></tr>\n";
  }
  h += "</table>\n";
}

// A histogram of the shots' cue-ball RMSEs, 1 cm bins (2 cm or more when the
// largest error is far out), training and held-out bars side by side.
void distribution_section(std::string& h, const CalibrationReport& r) {
  double largest = 0.0;
  for (const ShotReport& s : r.shots)
    if (std::isfinite(s.fit.cue_rmse)) largest = std::max(largest, s.fit.cue_rmse);
  const double bin = largest <= 0.4 ? 0.01 : largest <= 0.8 ? 0.02 : 0.05;
  const auto bins = static_cast<std::size_t>(std::floor(largest / bin)) + 1;
  std::vector<int> training(bins, 0), held(bins, 0);
  for (const ShotReport& s : r.shots) {
    if (!std::isfinite(s.fit.cue_rmse)) continue;
    const auto k = std::min(static_cast<std::size_t>(std::floor(s.fit.cue_rmse / bin)), bins - 1);
    ++(s.held_out ? held : training)[k];
  }
  int tallest = 1;
  for (std::size_t k = 0; k < bins; ++k) tallest = std::max({tallest, training[k], held[k]});
  const double width = 900.0, height = 180.0, left = 30.0, bottom = 32.0;
  const double bar = (width - left) / static_cast<double>(bins);
  h += "<h2>Distribution of the cue-ball RMSE</h2>\n<svg id=\"distribution\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
       fixed(width, 0) + "\" height=\"" + fixed(height + bottom, 0) + "\" font-size=\"10\">\n";
  for (std::size_t k = 0; k < bins; ++k) {
    const double x = left + bar * static_cast<double>(k);
    const std::pair<int, const char*> series[] = {{training[k], "#7f8c8d"}, {held[k], "#1f5fbf"}};
    for (std::size_t s = 0; s < 2; ++s) {
      const int n = series[s].first;
      if (n == 0) continue;
      const double bh = (height - 10.0) * n / tallest;
      h += "<rect class=\"" + std::string(s == 0 ? "training" : "held-out") + "\" data-count=\"" + std::to_string(n) +
           "\" x=\"" + fixed(x + 1 + static_cast<double>(s) * bar / 2, 1) + "\" y=\"" + fixed(height - bh, 1) + "\" width=\"" +
           fixed(std::max(bar / 2 - 1, 1.0), 1) + "\" height=\"" + fixed(bh, 1) + "\" fill=\"" + series[s].second +
           "\"><title>" + std::to_string(n) + " shots</title></rect>\n";
    }
    const std::size_t label_every = std::max<std::size_t>(1, bins / 15);
    if (k % label_every == 0)
      h += "<text x=\"" + fixed(x, 1) + "\" y=\"" + fixed(height + 14, 0) + "\">" + fixed(100 * bin * static_cast<double>(k), 0) +
           "</text>\n";
  }
  h += "<text x=\"" + fixed(width - 4, 0) + "\" y=\"" + fixed(height + 28, 0) + "\" text-anchor=\"end\">cue-ball RMSE, cm</text>\n";
  h += "<text x=\"0\" y=\"10\">" + std::to_string(tallest) + "</text><line x1=\"" + fixed(left, 0) + "\" y1=\"" +
       fixed(height, 0) + "\" x2=\"" + fixed(width, 0) + "\" y2=\"" + fixed(height, 0) + "\" stroke=\"#444\"/>\n</svg>\n";
  h += "<p class=\"legend\"><span style=\"color:#7f8c8d\">&#9632; training shots</span><span style=\"color:#1f5fbf\">&#9632; "
       "held-out shots</span> (bins of " + fixed(100 * bin, 0) + " cm)</p>\n";
}

std::string points(const std::vector<Vec2>& path, double width) {
  std::string out;
  for (const Vec2& q : path) {
    out += fixed(kMargin + q.x * kScale, 1) + "," + fixed(kMargin + (width - q.y) * kScale, 1) + " ";
  }
  return out;
}

void shot_figure(std::string& h, const ShotDrawing& d, const Table& table) {
  const double w = table.length * kScale + 2 * kMargin, hgt = table.width * kScale + 2 * kMargin;
  h += "<figure class=\"shot" + std::string(d.contact_mismatch ? " mismatch" : "") + "\" id=\"shot-" + escape(d.id) + "\">\n";
  h += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + fixed(w, 0) + "\" height=\"" + fixed(hgt, 0) + "\">\n";
  h += "<rect x=\"" + fixed(kMargin, 0) + "\" y=\"" + fixed(kMargin, 0) + "\" width=\"" + fixed(table.length * kScale, 1) +
       "\" height=\"" + fixed(table.width * kScale, 1) + "\" fill=\"#e8f1ea\" stroke=\"#345\"/>\n";
  for (std::size_t j = 0; j < d.names.size(); ++j) {
    if (j < d.simulated.size() && d.simulated[j].size() > 1)
      h += "<polyline class=\"simulated\" points=\"" + points(d.simulated[j], table.width) + "\" fill=\"none\" stroke=\"" +
           colour(j) + "\" stroke-width=\"1.5\"/>\n";
    if (j < d.measured.size() && !d.measured[j].empty())
      h += "<polyline class=\"measured\" points=\"" + points(d.measured[j], table.width) + "\" fill=\"none\" stroke=\"" +
           colour(j) + "\" stroke-width=\"1.5\" stroke-dasharray=\"2 3\" stroke-linecap=\"round\" opacity=\"0.9\"/>\n";
    if (j < d.measured.size() && !d.measured[j].empty())
      h += "<circle cx=\"" + fixed(kMargin + d.measured[j].front().x * kScale, 1) + "\" cy=\"" +
           fixed(kMargin + (table.width - d.measured[j].front().y) * kScale, 1) + "\" r=\"" +
           fixed(table.ball.radius * kScale, 1) + "\" fill=\"none\" stroke=\"" + colour(j) + "\"/>\n";
  }
  h += "</svg>\n<figcaption><b>" + escape(d.id) + "</b>" + (d.held_out ? " (held out)" : " (training)") + ", cue ball " +
       centimetres(d.cue_rmse) + (d.contact_mismatch ? ", <b>contact mismatch</b>" : "") + "<br>";
  for (std::size_t j = 0; j < d.names.size(); ++j)
    h += "<span style=\"color:" + std::string(colour(j)) + "\">" + escape(d.names[j]) + " " +
         centimetres(j < d.ball_rmse.size() ? d.ball_rmse[j] : std::numeric_limits<double>::quiet_NaN()) + "</span> ";
  if (d.simulated.empty()) h += "<br>the simulation of the fitted strike failed";
  h += "</figcaption>\n</figure>\n";
}

}  // namespace

std::string calibration_report_html(const CalibrationReport& report, const Table& table,
                                    const std::vector<ShotDrawing>& drawings) {
  std::string h = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>cueball calibration: " +
                  escape(report.table_name) + "</title>\n";
  h += kStyle;
  h += "</head><body>\n<h1>Calibration on " + std::to_string(report.shots.size()) + " tracked shots (" +
       escape(report.table_name) + ")</h1>\n";
  constants_section(h, report);
  summary_section(h, report);
  distribution_section(h, report);
  std::vector<const ShotDrawing*> order;
  for (const ShotDrawing& d : drawings) order.push_back(&d);
  std::stable_sort(order.begin(), order.end(), [](const ShotDrawing* a, const ShotDrawing* b) {
    const double ea = std::isfinite(a->cue_rmse) ? a->cue_rmse : -1.0, eb = std::isfinite(b->cue_rmse) ? b->cue_rmse : -1.0;
    return ea > eb;
  });
  h += "<h2>Shots, worst cue-ball RMSE first</h2>\n<p class=\"note\">dotted: the tracked samples; solid: the simulation of "
       "the fitted strike under the constants above; circle: the layout. A red frame: the fit made or missed a contact the "
       "real balls did not.</p>\n<div class=\"shots\">\n";
  for (const ShotDrawing* d : order) shot_figure(h, *d, table);
  h += "</div>\n</body></html>\n";
  return h;
}

}  // namespace cueball
