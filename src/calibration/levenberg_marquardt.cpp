#include "calibration/levenberg_marquardt.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cueball::detail {

namespace {

double sum_squares(const std::vector<double>& r) {
  double s = 0.0;
  for (double v : r) s += v * v;
  return s;
}

void project(const LeastSquaresProblem& p, std::vector<double>& q) {
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = std::clamp(q[i], p.lower[i], p.upper[i]);
  if (p.project) p.project(q);
}

// Evaluates the cost at q; +inf when the model fails.
double evaluate(const LeastSquaresProblem& p, const std::vector<double>& q, std::vector<double>& r, int& evaluations) {
  ++evaluations;
  if (!p.residuals(q, r)) return std::numeric_limits<double>::infinity();
  const double c = sum_squares(r);
  return std::isfinite(c) ? c : std::numeric_limits<double>::infinity();
}

// Forward differences, stepping inwards at an upper bound. False when a
// column cannot be evaluated.
bool jacobian(const LeastSquaresProblem& p, const std::vector<double>& q, const std::vector<double>& r,
              std::vector<double>& jac, int& evaluations) {
  const std::size_t n = q.size(), m = r.size();
  jac.assign(m * n, 0.0);
  std::vector<double> qs = q, rs;
  for (std::size_t i = 0; i < n; ++i) {
    double h = p.step[i];
    if (q[i] + h > p.upper[i]) h = -h;
    qs[i] = q[i] + h;
    ++evaluations;
    if (!p.residuals(qs, rs) || rs.size() != m) return false;
    for (std::size_t k = 0; k < m; ++k) jac[k * n + i] = (rs[k] - r[k]) / h;
    qs[i] = q[i];
  }
  return true;
}

}  // namespace

bool solve_linear(std::vector<double> a, std::vector<double> b, std::vector<double>& x) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r * n + c]) > std::abs(a[piv * n + c])) piv = r;
    if (!(std::abs(a[piv * n + c]) > 1e-300)) return false;
    if (piv != c) {
      for (std::size_t k = 0; k < n; ++k) std::swap(a[c * n + k], a[piv * n + k]);
      std::swap(b[c], b[piv]);
    }
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r * n + c] / a[c * n + c];
      for (std::size_t k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
      b[r] -= f * b[c];
    }
  }
  x.assign(n, 0.0);
  for (std::size_t c = n; c-- > 0;) {
    double s = b[c];
    for (std::size_t k = c + 1; k < n; ++k) s -= a[c * n + k] * x[k];
    x[c] = s / a[c * n + c];
  }
  return true;
}

LeastSquaresResult levenberg_marquardt(const LeastSquaresProblem& p, std::vector<double> q0, int iterations) {
  LeastSquaresResult out;
  project(p, q0);
  out.q = q0;
  std::vector<double> r, rt, jac, trial;
  out.cost = evaluate(p, out.q, r, out.evaluations);
  if (!std::isfinite(out.cost)) return out;
  const std::size_t n = out.q.size();
  double lambda = 1e-3;
  for (int it = 0; it < iterations; ++it) {
    if (!jacobian(p, out.q, r, jac, out.evaluations)) break;
    const std::size_t m = r.size();
    std::vector<double> jtj(n * n, 0.0), g(n, 0.0);
    for (std::size_t k = 0; k < m; ++k)
      for (std::size_t i = 0; i < n; ++i) {
        const double ji = jac[k * n + i];
        g[i] -= ji * r[k];
        for (std::size_t j = 0; j < n; ++j) jtj[i * n + j] += ji * jac[k * n + j];
      }
    bool accepted = false;
    for (int attempt = 0; attempt < 6 && !accepted; ++attempt) {
      std::vector<double> a = jtj, d;
      for (std::size_t i = 0; i < n; ++i) a[i * n + i] += lambda * std::max(jtj[i * n + i], 1e-12);
      if (!solve_linear(a, g, d)) {
        lambda *= 4;
        continue;
      }
      trial = out.q;
      for (std::size_t i = 0; i < n; ++i) trial[i] += d[i];
      project(p, trial);
      const double c = evaluate(p, trial, rt, out.evaluations);
      if (c < out.cost) {
        accepted = true;
        const double gain = (out.cost - c) / out.cost;
        out.q = trial, out.cost = c, r.swap(rt);
        lambda = std::max(lambda / 3, 1e-7);
        if (gain < 1e-6) return out;
      } else {
        lambda *= 4;
      }
    }
    if (!accepted) break;
  }
  return out;
}

}  // namespace cueball::detail
