// Internal: a small bound-constrained Levenberg-Marquardt for the
// calibration's fits (at most a handful of parameters, residual vectors of a
// few hundred to a few thousand entries, each evaluation one simulation).
//
// Why our own: the problems are tiny (n <= 8, so the normal equations are
// solved directly), the Jacobian is by forward differences over the engine
// (the residuals are piecewise smooth: a contact that appears or vanishes is
// a jump), and bounds are handled by projection onto a box after each step.
// Ceres or Eigen would bring a dependency for a 6 x 6 solve. The method is
// Marquardt's (1963): (J^T J + lambda diag(J^T J)) d = -J^T r, lambda divided
// by 3 after an accepted step and multiplied by 4 after a rejected one
// (Nielsen's schedule simplified); a step is accepted only if it lowers the
// cost, so the cost never increases.
#pragma once

#include <functional>
#include <vector>

namespace cueball::detail {

struct LeastSquaresProblem {
  /// Fills r for the parameters q; returns false when the model cannot be
  /// evaluated there (the point is then treated as infinitely bad).
  std::function<bool(const std::vector<double>& q, std::vector<double>& r)> residuals;
  std::vector<double> lower, upper;  ///< box bounds
  std::vector<double> step;          ///< forward-difference step per parameter
  /// Optional projection after the box (e.g. the miscue circle of the tip offsets).
  std::function<void(std::vector<double>& q)> project;
};

struct LeastSquaresResult {
  std::vector<double> q;
  double cost = 0.0;  ///< sum of squared residuals at q
  int evaluations = 0;
};

/// At most `iterations` Jacobian updates from q0 (projected onto the bounds).
LeastSquaresResult levenberg_marquardt(const LeastSquaresProblem& problem, std::vector<double> q0, int iterations);

/// Solves the symmetric positive (semi-)definite system A x = b (n x n,
/// row-major) by Gaussian elimination with partial pivoting; false when singular.
bool solve_linear(std::vector<double> a, std::vector<double> b, std::vector<double>& x);

}  // namespace cueball::detail
