// Fitting the cushion's constants e_e and mu_w to measured rebounds, as in
// section 3.5 of Mathavan, Jackson & Parkin (2010): the sum of squared
// errors of the predicted rebounds is minimised over the paper's 0.01 grid of
// (e_e, mu_w), then refined locally (Levenberg-Marquardt), and how well each
// constant is determined is estimated from the curvature of the residual
// (the Gauss-Newton covariance s^2 (J^T J)^-1, s^2 = SSE / (n - 2)).
//
// Head-on rolling impacts alone cannot separate the two constants: the model
// has no speed scale (the rebound is proportional to V0, see the tests of
// cushion_impact), so every head-on rolling point predicts the same ratio
// V_out / V0 = g(e_e, mu_w), and the data fix only the one combination
// g(e_e, mu_w) = mean ratio, a curve in the (e_e, mu_w) plane. The fit flags
// that (`poorly_separated`); oblique impacts, or spin, separate them.
#pragma once

#include <cstddef>
#include <vector>

#include "cueball/models/cushion/impact.hpp"
#include "cueball/core/parameters.hpp"

namespace cueball {

/// A head-on impact of a rolling ball without sidespin (the paper's Fig 7).
struct HeadOnRebound {
  double incoming_speed = 0.0;  ///< V0, m/s
  double rebound_speed = 0.0;   ///< measured, m/s
};

/// Any impact: its incidence and the measured rebound (speed and angle beta
/// from the cushion line, as in CushionImpactResult).
struct ObliqueRebound {
  PaperIncidence incidence;
  double rebound_speed = 0.0;  ///< m/s
  double rebound_angle = 0.0;  ///< beta, rad
};

struct CushionFitData {
  std::vector<HeadOnRebound> head_on;
  std::vector<ObliqueRebound> oblique;
};

struct CushionFitOptions {
  CushionSolver solver = CushionSolver::exact;  ///< the constants belong to the solver they were fitted with
  int paper_steps = 5000;                       ///< N, for CushionSolver::paper
  double grid_step = 0.01;                      ///< the paper's grid over (0, 1]^2, in (0, 0.5]
  double contact_height = 0.0;                  ///< h, m; 0 means 7R/5
};

struct CushionFit {
  double restitution = 0.0;  ///< e_e at the minimum
  double friction = 0.0;     ///< mu_w at the minimum
  /// Sum of squared errors at the minimum, m^2/s^2: (V_pred - V_meas)^2 per
  /// head-on point, |v_pred - v_meas|^2 (the outgoing velocity vectors) per oblique one.
  double residual = 0.0;
  double grid_restitution = 0.0;  ///< the best point of the grid, before refinement
  double grid_friction = 0.0;
  double grid_residual = 0.0;
  /// Standard errors from the curvature of the residual; +infinity for a
  /// direction the data do not determine.
  double restitution_sigma = 0.0;
  double friction_sigma = 0.0;
  double correlation = 0.0;        ///< of the two estimates, in [-1, 1]
  double condition_number = 0.0;   ///< of J^T J scaled to unit diagonal; large: nearly one combination only
  bool poorly_separated = false;   ///< |correlation| > 0.98 or condition number > 1e6
  double friction_upper_bound = 0.0;  ///< mu_w <= tan(theta): the model's range (larger lifts the ball)
  std::size_t residuals = 0;          ///< number of residual components
  std::size_t impacts_solved = 0;
  std::size_t beyond_rigid_cushion_limit = 0;  ///< data points with a normal speed above 2.5 m/s
};

/// Fits e_e and mu_w to `data` with the ball and cloth of `table`. Throws
/// InvalidArgument (naming e.g. "head_on[2].rebound_speed") on bad data or
/// options, or when there is no data.
CushionFit fit_cushion(const CushionFitData& data, const Parameters& table, const CushionFitOptions& options = {});

}  // namespace cueball
