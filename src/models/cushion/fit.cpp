// Fitting e_e and mu_w to measured rebounds: Mathavan, Jackson & Parkin
// (2010) section 3.5 (a 0.01 grid over (0, 1]^2 minimising the sum of squared
// errors), refined by Levenberg-Marquardt, with the Gauss-Newton covariance
// for the uncertainties (e.g. Press et al., "Numerical Recipes", 3rd ed.,
// section 15.5).
#include "cueball/models/cushion/fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string indexed(const char* list, std::size_t i, const std::string& field) {
  return std::string(list) + "[" + std::to_string(i) + "]." + field;
}

void require_positive(const std::string& field, double value, const char* meaning) {
  if (!(std::isfinite(value) && value > 0.0)) throw InvalidArgument(field, value, "(0, inf)", meaning);
}
void require_non_negative(const std::string& field, double value, const char* meaning) {
  if (!(std::isfinite(value) && value >= 0.0)) throw InvalidArgument(field, value, "[0, inf)", meaning);
}

// The prediction of every data point for one (e_e, mu_w), as residuals.
class Residuals {
 public:
  Residuals(const CushionFitData& data, const CushionImpactModel& base, const CushionFitOptions& options,
            double radius)
      : data_(data), base_(base), radius_(radius) {
    options_.solver = options.solver;
    options_.paper_steps = options.paper_steps;
    // Every evaluation has its own (e_e, mu_w), the Jacobian's 1e-6 apart: a
    // rolling-ball table per set would cost far more than the few impacts
    // solved with it (and fill the cache), so these are solved by the ODE.
    options_.rolling_table = false;
    for (const ObliqueRebound& o : data.oblique) balls_.push_back(incoming_ball(o.incidence));
  }

  std::size_t size() const { return data_.head_on.size() + 2 * data_.oblique.size(); }
  std::size_t solved() const { return solved_; }

  // Residual components into r (size()), returns their sum of squares.
  double evaluate(double e, double mu, std::vector<double>& r) {
    CushionImpactModel m = base_;
    m.restitution = e;
    m.cushion_friction = mu;
    std::size_t k = 0;
    if (!data_.head_on.empty()) {
      // Rate independence: one rolling head-on impact at V0 = 1 gives the ratio for all.
      IncomingBall unit_ball;
      unit_ball.velocity = {0.0, 1.0, 0.0};
      unit_ball.angular_velocity = {-1.0 / radius_, 0.0, 0.0};
      const double ratio = solve_cushion_impact(unit_ball, m, options_).rebound_speed;
      ++solved_;
      for (const HeadOnRebound& h : data_.head_on) r[k++] = ratio * h.incoming_speed - h.rebound_speed;
    }
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      const CushionImpactResult p = solve_cushion_impact(balls_[i], m, options_);
      ++solved_;
      const ObliqueRebound& o = data_.oblique[i];
      // Measured outgoing velocity from speed and beta = atan2(-yG', xG').
      r[k++] = p.velocity.x - o.rebound_speed * std::cos(o.rebound_angle);
      r[k++] = p.velocity.y + o.rebound_speed * std::sin(o.rebound_angle);
    }
    double sse = 0.0;
    for (const double x : r) sse += x * x;
    return sse;
  }

 private:
  const CushionFitData& data_;
  CushionImpactModel base_;
  CushionImpactOptions options_;
  double radius_;
  std::vector<IncomingBall> balls_;
  std::size_t solved_ = 0;
};

struct Box {
  double e_lo, e_hi, mu_lo, mu_hi;
  double clamp_e(double e) const { return std::clamp(e, e_lo, e_hi); }
  double clamp_mu(double mu) const { return std::clamp(mu, mu_lo, mu_hi); }
};

// Jacobian of the residuals by central differences (one-sided at the box).
void jacobian(Residuals& res, const Box& box, double e, double mu, std::vector<double>& je,
              std::vector<double>& jmu) {
  constexpr double step = 1e-6;
  std::vector<double> a(res.size());
  std::vector<double> b(res.size());
  const double e1 = box.clamp_e(e + step);
  const double e0 = box.clamp_e(e - step);
  res.evaluate(e1, mu, a);
  res.evaluate(e0, mu, b);
  for (std::size_t i = 0; i < a.size(); ++i) je[i] = (a[i] - b[i]) / (e1 - e0);
  const double m1 = box.clamp_mu(mu + step);
  const double m0 = box.clamp_mu(mu - step);
  res.evaluate(e, m1, a);
  res.evaluate(e, m0, b);
  for (std::size_t i = 0; i < a.size(); ++i) jmu[i] = (a[i] - b[i]) / (m1 - m0);
}

}  // namespace

CushionFit fit_cushion(const CushionFitData& data, const Parameters& table, const CushionFitOptions& options) {
  validate(table);
  const double radius = table.ball.radius;
  if (data.head_on.empty() && data.oblique.empty()) {
    throw InvalidArgument("data", "data = no measurements; at least one head-on or oblique rebound is needed");
  }
  for (std::size_t i = 0; i < data.head_on.size(); ++i) {
    require_positive(indexed("head_on", i, "incoming_speed"), data.head_on[i].incoming_speed, "V0, m/s");
    require_non_negative(indexed("head_on", i, "rebound_speed"), data.head_on[i].rebound_speed, "m/s");
  }
  for (std::size_t i = 0; i < data.oblique.size(); ++i) {
    const ObliqueRebound& o = data.oblique[i];
    try {
      incoming_ball(o.incidence);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(indexed("oblique", i, "incidence." + e.field()), e.what());
    }
    require_non_negative(indexed("oblique", i, "rebound_speed"), o.rebound_speed, "m/s");
    require_finite(indexed("oblique", i, "rebound_angle").c_str(), o.rebound_angle);
  }
  if (!(std::isfinite(options.grid_step) && options.grid_step > 0.0 && options.grid_step <= 0.5)) {
    throw InvalidArgument("grid_step", options.grid_step, "(0, 0.5]", "spacing of the (e_e, mu_w) grid");
  }
  const double height = options.contact_height == 0.0 ? default_cushion_height(table.ball) : options.contact_height;

  // The base model validates the table, the height and the options' solver.
  const CushionImpactModel base = cushion_impact_model(table, {0.5, 0.0, height});
  {
    CushionImpactOptions o;
    o.solver = options.solver;
    o.paper_steps = options.paper_steps;
    IncomingBall b;
    b.velocity = {0.0, 1.0, 0.0};
    solve_cushion_impact(b, base, o);  // throws on a bad solver or paper_steps
  }
  const double s = base.sin_theta;
  const double c = std::sqrt((1.0 - s) * (1.0 + s));
  double mu_max = s / c;  // tan(theta): validate(CushionImpactModel)
  const double wedge = c / (1.0 + s);
  if (base.cloth_friction >= wedge) mu_max = std::min(mu_max, wedge * (1.0 - 1e-12));

  CushionFit fit;
  fit.friction_upper_bound = mu_max;
  Residuals res(data, base, options, radius);
  fit.residuals = res.size();
  for (const HeadOnRebound& h : data.head_on) {
    if (h.incoming_speed > kRigidCushionSpeedLimit) ++fit.beyond_rigid_cushion_limit;
  }
  for (const ObliqueRebound& o : data.oblique) {
    if (o.incidence.speed * std::sin(o.incidence.angle) > kRigidCushionSpeedLimit) ++fit.beyond_rigid_cushion_limit;
  }

  // The paper's grid: e_e, mu_w = step, 2 step, ... up to 1 (mu_w up to its bound).
  const double step = options.grid_step;
  const int ne = static_cast<int>(std::floor(1.0 / step + 1e-9));
  const int nmu = static_cast<int>(std::floor(std::min(1.0, mu_max) / step + 1e-9));
  std::vector<double> r(res.size());
  fit.grid_residual = kInfinity;
  for (int i = 1; i <= ne; ++i) {
    for (int j = 1; j <= std::max(nmu, 1); ++j) {
      const double e = i * step;
      const double mu = nmu >= 1 ? j * step : mu_max;
      const double sse = res.evaluate(e, mu, r);
      if (sse < fit.grid_residual) {
        fit.grid_residual = sse;
        fit.grid_restitution = e;
        fit.grid_friction = mu;
      }
    }
  }

  // Levenberg-Marquardt from the best grid point, inside the model's box.
  const Box box{1e-6, 1.0, 0.0, mu_max};
  double e = fit.grid_restitution;
  double mu = fit.grid_friction;
  double sse = fit.grid_residual;
  std::vector<double> je(res.size());
  std::vector<double> jmu(res.size());
  std::vector<double> trial(res.size());
  double lambda = 1e-3;
  for (int it = 0; it < 100 && lambda < 1e12; ++it) {
    res.evaluate(e, mu, r);
    jacobian(res, box, e, mu, je, jmu);
    double a11 = 0.0, a12 = 0.0, a22 = 0.0, g1 = 0.0, g2 = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      a11 += je[i] * je[i];
      a12 += je[i] * jmu[i];
      a22 += jmu[i] * jmu[i];
      g1 += je[i] * r[i];
      g2 += jmu[i] * r[i];
    }
    bool improved = false;
    while (lambda < 1e12) {
      const double b11 = a11 * (1.0 + lambda) + 1e-300;
      const double b22 = a22 * (1.0 + lambda) + 1e-300;
      const double det = b11 * b22 - a12 * a12;
      const double de = -(b22 * g1 - a12 * g2) / det;
      const double dmu = -(b11 * g2 - a12 * g1) / det;
      const double e_new = box.clamp_e(e + de);
      const double mu_new = box.clamp_mu(mu + dmu);
      const double sse_new = res.evaluate(e_new, mu_new, trial);
      if (sse_new < sse) {
        const double moved = std::abs(e_new - e) + std::abs(mu_new - mu);
        e = e_new;
        mu = mu_new;
        sse = sse_new;
        lambda = std::max(lambda / 3.0, 1e-12);
        improved = moved > 1e-12;
        break;
      }
      lambda *= 4.0;
    }
    if (!improved) break;
  }
  fit.restitution = e;
  fit.friction = mu;
  fit.residual = sse;

  // Uncertainty from the curvature: C = s^2 (J^T J)^-1, s^2 = SSE / (n - 2).
  res.evaluate(e, mu, r);
  jacobian(res, box, e, mu, je, jmu);
  double a11 = 0.0, a12 = 0.0, a22 = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    a11 += je[i] * je[i];
    a12 += je[i] * jmu[i];
    a22 += jmu[i] * jmu[i];
  }
  const double n = static_cast<double>(r.size());
  const double s2 = n > 2.0 ? sse / (n - 2.0) : sse;
  const double rho = a11 > 0.0 && a22 > 0.0 ? a12 / std::sqrt(a11 * a22) : 1.0;  // correlation of J's columns
  fit.condition_number = std::abs(rho) < 1.0 ? (1.0 + std::abs(rho)) / (1.0 - std::abs(rho)) : kInfinity;
  fit.correlation = -rho;
  if (fit.condition_number < 1e12) {
    const double det = a11 * a22 - a12 * a12;
    fit.restitution_sigma = std::sqrt(s2 * a22 / det);
    fit.friction_sigma = std::sqrt(s2 * a11 / det);
  } else {
    fit.restitution_sigma = kInfinity;
    fit.friction_sigma = kInfinity;
  }
  fit.poorly_separated = std::abs(fit.correlation) > 0.98 || fit.condition_number > 1e6;
  fit.impacts_solved = res.solved();
  return fit;
}

}  // namespace cueball
