#include "cueball/calibration/constants_fit.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <thread>

#include "cueball/core/errors.hpp"
#include "cueball/models/cushion/model.hpp"

namespace cueball {

namespace {

// The outer parameters: log mu_s, log mu_r, log mu_sp, cushion restitution, cushion friction.
constexpr int kConstants = 5;

std::vector<double> to_vector(const FitModel& m) {
  const ClothParameters& c = m.settings.parameters.cloth;
  return {std::log(c.sliding_friction), std::log(c.rolling_resistance), std::log(c.spin_friction),
          m.settings.cushion.restitution, m.settings.cushion.friction};
}

// The model of an outer point, or nothing outside the model's ranges
// (parameters, mu_r < mu_s, the cushion model's own bounds).
std::optional<FitModel> model_of(const FitModel& start, const std::vector<double>& u) {
  FitModel m = start;
  ClothParameters& c = m.settings.parameters.cloth;
  c.sliding_friction = std::exp(u[0]);
  c.rolling_resistance = std::exp(u[1]);
  c.spin_friction = std::exp(u[2]);
  m.settings.cushion.restitution = u[3];
  m.settings.cushion.friction = u[4];
  try {
    validate(m.settings.parameters);
    for (const CushionSegment& s : m.table.cushions)
      (void)cushion_contact(m.settings.parameters, m.settings.cushion, s.contact_height);
  } catch (const InvalidArgument&) {
    return std::nullopt;
  }
  return m;
}

struct OuterContext {
  const std::vector<PreparedShot>& shots;
  const FitModel& start;
  const ConstantsFitOptions& options;
  std::vector<StrikeFit> incumbent;  // strikes of the best constants so far
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<double> best_u;
  int evaluations = 0;
};

// One evaluation of the outer objective; a new best replaces the incumbent strikes.
double objective(OuterContext& c, const std::vector<double>& u) {
  ++c.evaluations;
  const auto model = model_of(c.start, u);
  if (!model) return std::numeric_limits<double>::infinity();
  std::vector<StrikeFit> refit(c.shots.size());
  for_each_shot(static_cast<int>(c.shots.size()), c.options.threads, [&](int i) {
    const auto k = static_cast<std::size_t>(i);
    refit[k] = refine_strike(c.shots[k], *model, c.incumbent[k], c.options.refine_iterations);
  });
  double cost = 0.0;
  for (const StrikeFit& f : refit) cost += f.cost;
  if (cost < c.best_cost) c.best_cost = cost, c.best_u = u, c.incumbent = std::move(refit);
  return cost;
}

// Nelder-Mead with the standard coefficients (reflection 1, expansion 2,
// contraction 1/2, shrink 1/2), the simplex built by steps `scale` from u0.
void nelder_mead(OuterContext& c, const std::vector<double>& u0, const std::vector<double>& scale) {
  const int n = kConstants;
  std::vector<std::vector<double>> x(n + 1, u0);
  std::vector<double> f(n + 1);
  for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i + 1)][static_cast<std::size_t>(i)] += scale[static_cast<std::size_t>(i)];
  for (int i = 0; i <= n && c.evaluations < c.options.max_evaluations; ++i) f[static_cast<std::size_t>(i)] = objective(c, x[static_cast<std::size_t>(i)]);
  const auto point = [&](const std::vector<double>& centre, const std::vector<double>& worst, double t) {
    std::vector<double> p(centre.size());
    for (std::size_t k = 0; k < p.size(); ++k) p[k] = centre[k] + t * (worst[k] - centre[k]);
    return p;
  };
  while (c.evaluations < c.options.max_evaluations) {
    std::vector<int> order(n + 1);
    for (int i = 0; i <= n; ++i) order[static_cast<std::size_t>(i)] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return f[static_cast<std::size_t>(a)] < f[static_cast<std::size_t>(b)]; });
    std::vector<std::vector<double>> xs;
    std::vector<double> fs;
    for (int i : order) xs.push_back(x[static_cast<std::size_t>(i)]), fs.push_back(f[static_cast<std::size_t>(i)]);
    x = xs, f = fs;
    if (std::isfinite(f[0]) && f[static_cast<std::size_t>(n)] - f[0] <= 1e-4 * f[0]) break;
    std::vector<double> centre(static_cast<std::size_t>(n), 0.0);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k) centre[static_cast<std::size_t>(k)] += x[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] / n;
    const std::vector<double>& worst = x[static_cast<std::size_t>(n)];
    const std::vector<double> xr = point(centre, worst, -1.0);
    const double fr = objective(c, xr);
    if (fr < f[0]) {
      const std::vector<double> xe = point(centre, worst, -2.0);
      const double fe = c.evaluations < c.options.max_evaluations ? objective(c, xe) : fr + 1;
      if (fe < fr) x[static_cast<std::size_t>(n)] = xe, f[static_cast<std::size_t>(n)] = fe;
      else x[static_cast<std::size_t>(n)] = xr, f[static_cast<std::size_t>(n)] = fr;
    } else if (fr < f[static_cast<std::size_t>(n - 1)]) {
      x[static_cast<std::size_t>(n)] = xr, f[static_cast<std::size_t>(n)] = fr;
    } else {
      const std::vector<double> xc = point(centre, worst, fr < f[static_cast<std::size_t>(n)] ? -0.5 : 0.5);
      const double fc = objective(c, xc);
      if (fc < std::min(fr, f[static_cast<std::size_t>(n)])) {
        x[static_cast<std::size_t>(n)] = xc, f[static_cast<std::size_t>(n)] = fc;
      } else {
        for (int i = 1; i <= n && c.evaluations < c.options.max_evaluations; ++i) {
          x[static_cast<std::size_t>(i)] = point(x[0], x[static_cast<std::size_t>(i)], 0.5);
          f[static_cast<std::size_t>(i)] = objective(c, x[static_cast<std::size_t>(i)]);
        }
      }
    }
  }
}

}  // namespace

void for_each_shot(int n, int threads, const std::function<void(int)>& job) {
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex lock;
  const auto work = [&] {
    for (int i = next++; i < n; i = next++) {
      try {
        job(i);
      } catch (...) {
        const std::lock_guard<std::mutex> guard(lock);
        if (!error) error = std::current_exception();
        next = n;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min(threads, n); ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

ConstantsFit fit_constants(const std::vector<PreparedShot>& shots, const FitModel& start,
                           const std::vector<StrikeFit>& strikes, const ConstantsFitOptions& options) {
  if (options.max_evaluations < 1 || options.max_evaluations > 10000)
    throw InvalidArgument("max_evaluations", options.max_evaluations, "[1, 10000]", "outer evaluations");
  if (options.refine_iterations < 1 || options.refine_iterations > 100)
    throw InvalidArgument("refine_iterations", options.refine_iterations, "[1, 100]", "strike refit iterations");
  if (options.threads < 1 || options.threads > 256) throw InvalidArgument("threads", options.threads, "[1, 256]", "threads");
  if (strikes.size() != shots.size())
    throw InvalidArgument("strikes", "strikes has " + std::to_string(strikes.size()) + " entries; allowed: one per shot (" +
                                         std::to_string(shots.size()) + ")");
  OuterContext c{shots, start, options, strikes, std::numeric_limits<double>::infinity(), to_vector(start), 0};
  const std::vector<double> u0 = to_vector(start);
  // Steps: cloth frictions by a factor of about 1.4, the cushion by 0.03.
  nelder_mead(c, u0, {0.35, 0.35, 0.35, -0.03, 0.03});
  ConstantsFit out;
  out.model = model_of(start, c.best_u).value_or(start);
  out.strikes = c.incumbent;
  out.cost = c.best_cost;
  out.evaluations = c.evaluations;
  return out;
}

}  // namespace cueball
