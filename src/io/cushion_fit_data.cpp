// Measured cushion impacts as CSV (io/cushion_fit_data.hpp), for fitting e_e
// and mu_w (models/cushion/fit.hpp).
#include "cueball/io/cushion_fit_data.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cueball/core/errors.hpp"
#include "cueball/physics/cloth_motion.hpp"
#include "core/angles.hpp"

namespace cueball {

namespace {

// A cell's value in [lo, hi], or InvalidArgument naming the file, the line
// and the cell as the CLI names a flag ("data.csv:3: v0 = 40 is outside the
// allowed range [1e-06, 30] (incoming speed, m/s)").
void check_cell(const std::string& file, const std::string& cell, double value, double lo, double hi, const char* meaning) {
  if (std::isfinite(value) && value >= lo && value <= hi) return;
  char lo_text[32], hi_text[32];
  std::snprintf(lo_text, sizeof lo_text, "%.10g", lo);
  std::snprintf(hi_text, sizeof hi_text, "%.10g", hi);
  throw InvalidArgument(file, cell + " = " + format_number_beside(value, {lo, hi}) +
                                  (std::isfinite(value) ? " is outside the allowed range [" : " is not a finite number; allowed: [") +
                                  lo_text + ", " + hi_text + "] (" + meaning + ")");
}

}  // namespace

CushionFitData cushion_fit_data_from_csv(std::string_view csv, const std::string& file, double radius) {
  if (csv.substr(0, 3) == "\xEF\xBB\xBF") csv.remove_prefix(3);
  CushionFitData data;
  std::istringstream in{std::string(csv)};
  std::string line;
  const auto blank = [](const std::string& t, std::size_t from = 0) {
    return t.find_first_not_of(" \t\r", from) == std::string::npos;
  };
  for (int number = 1; std::getline(in, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    if (blank(line)) continue;
    const std::string where = file + ":" + std::to_string(number);
    std::vector<double> values;
    std::vector<std::string> cells;
    {
      std::size_t start = 0;
      for (;;) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
    }
    std::size_t numeric = 0;
    std::size_t bad = cells.size();  // the first cell that is not a number
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::string& cell = cells[i];
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(cell.c_str(), &end);
      const bool ok = !blank(cell) && end != cell.c_str() && blank(cell, static_cast<std::size_t>(end - cell.c_str()));
      if (ok) {
        ++numeric;
        values.push_back(v);
      } else if (bad == cells.size()) {
        bad = i;
      }
    }
    if (bad < cells.size()) {
      if (number == 1 && numeric == 0 && data.head_on.empty() && data.oblique.empty()) continue;  // a header
      throw InvalidArgument(file, where + ": cell " + std::to_string(bad + 1) + " = " + quote_input(cells[bad]) +
                       (blank(cells[bad]) ? " is empty" : " is not a number") +
                       "; expected v0,v_out or v0,alpha_deg,topspin_k,sidespin_k,v_out,beta_deg");
    }
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]))
        throw InvalidArgument(file, where + ": cell " + std::to_string(i + 1) + " = " + quote_input(cells[i]) +
                         " is not a finite number");
    if (values.size() == 2) {
      check_cell(file, (where + ": v0").c_str(), values[0], 1e-6, kMaxSpeed, "incoming speed, m/s");
      check_cell(file, (where + ": v_out").c_str(), values[1], 0.0, kMaxSpeed, "measured rebound speed, m/s");
      data.head_on.push_back({values[0], values[1]});
    } else if (values.size() == 6) {
      check_cell(file, (where + ": v0").c_str(), values[0], 1e-6, kMaxSpeed, "incoming speed, m/s");
      check_cell(file, (where + ": alpha_deg").c_str(), values[1], 1e-9, 90.0, "angle of incidence, degrees");
      check_cell(file, (where + ": topspin_k").c_str(), values[2], -20.0, 20.0, "topspin as K V0/R");
      check_cell(file, (where + ": sidespin_k").c_str(), values[3], -20.0, 20.0, "sidespin as K V0/R");
      check_cell(file, (where + ": v_out").c_str(), values[4], 0.0, kMaxSpeed, "measured rebound speed, m/s");
      check_cell(file, (where + ": beta_deg").c_str(), values[5], 0.0, 180.0, "measured rebound angle, degrees");
      ObliqueRebound o;
      o.incidence = {values[0], values[1] * kDegree, values[2] * values[0] / radius, values[3] * values[0] / radius};
      o.rebound_speed = values[4];
      o.rebound_angle = values[5] * kDegree;
      data.oblique.push_back(o);
    } else {
      throw InvalidArgument(file, where + ": expected 2 numbers (v0,v_out) or 6 (v0,alpha_deg,topspin_k,sidespin_k,v_out,beta_deg), got " +
                       std::to_string(values.size()));
    }
  }
  // Two constants and an error estimate: at least 3 residuals (an oblique
  // impact gives two, its rebound's two velocity components).
  const std::size_t residuals = data.head_on.size() + 2 * data.oblique.size();
  if (residuals < kMinFitResiduals)
    throw InvalidArgument(file, file + ": " + std::to_string(data.head_on.size()) + " head-on and " +
                     std::to_string(data.oblique.size()) + " oblique measurements are too few; allowed: at least " +
                     std::to_string(kMinFitResiduals) + " head-on, or 2 oblique, or 1 oblique and 1 head-on " +
                     "(e_e, mu_w and the error need 3 residuals)");
  return data;
}

}  // namespace cueball
