// Tests of the cushion fit (src/models/cushion/fit.cpp, paper section 3.5): it
// recovers known constants from synthetic rebounds with noise (fixed seed),
// reports how well they are determined, and flags that head-on rolling data
// alone fix only one combination of e_e and mu_w.
#include "cueball/models/cushion/fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>

#include "cueball/core/errors.hpp"

namespace cueball {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;

// Standard normal deviates from mt19937_64 by Box-Muller (the same on every
// standard library, unlike std::normal_distribution).
class Noise {
 public:
  explicit Noise(std::uint64_t seed) : engine_(seed) {}
  double normal() {
    const double u1 = uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
  }

 private:
  double uniform() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }
  std::mt19937_64 engine_;
};

const double kTrueRestitution = 0.95;
const double kTrueFriction = 0.18;

CushionParameters truth(const Parameters& p) { return {kTrueRestitution, kTrueFriction, default_cushion_height(p.ball)}; }

CushionFitData synthetic(bool with_oblique, double sigma_speed, double sigma_angle, CushionSolver solver, int n) {
  const Parameters p = snooker_parameters();
  CushionImpactOptions o;
  o.solver = solver;
  o.paper_steps = n;
  Noise noise(20100901);
  CushionFitData data;
  for (const double v0 : {0.4, 0.6, 0.8, 1.0, 1.2, 1.4}) {
    const PaperIncidence in{v0, 90 * kDeg, v0 / p.ball.radius, 0.0};
    const double v = cushion_impact(incoming_ball(in), p, truth(p), o).rebound_speed;
    data.head_on.push_back({v0, v + sigma_speed * noise.normal()});
  }
  if (with_oblique) {
    for (const double a : {20.0, 35.0, 50.0, 65.0}) {
      for (const auto& [kt, ks] : {std::pair{1.0, 0.0}, std::pair{1.0, 1.0}, std::pair{0.0, -1.0}}) {
        const double v0 = 0.9;
        const PaperIncidence in{v0, a * kDeg, kt * v0 / p.ball.radius, ks * v0 / p.ball.radius};
        const CushionImpactResult r = cushion_impact(incoming_ball(in), p, truth(p), o);
        data.oblique.push_back(
            {in, r.rebound_speed + sigma_speed * noise.normal(), r.rebound_angle + sigma_angle * noise.normal()});
      }
    }
  }
  return data;
}

TEST(CushionFit, RecoversKnownConstantsFromNoisyObliqueAndHeadOnData) {
  const CushionFitData data = synthetic(true, 0.003, 0.2 * kDeg, CushionSolver::exact, 5000);
  const CushionFit fit = fit_cushion(data, snooker_parameters());
  EXPECT_FALSE(fit.poorly_separated);
  EXPECT_LT(fit.restitution_sigma, 0.02);
  EXPECT_LT(fit.friction_sigma, 0.02);
  EXPECT_GT(fit.restitution_sigma, 0.0);
  EXPECT_NEAR(fit.restitution, kTrueRestitution, std::max(4.0 * fit.restitution_sigma, 0.002));
  EXPECT_NEAR(fit.friction, kTrueFriction, std::max(4.0 * fit.friction_sigma, 0.002));
  // The refinement improves on the 0.01 grid, which brackets the answer.
  EXPECT_LE(fit.residual, fit.grid_residual);
  EXPECT_NEAR(fit.grid_restitution, fit.restitution, 0.011);
  EXPECT_NEAR(fit.grid_friction, fit.friction, 0.011);
  EXPECT_EQ(fit.residuals, data.head_on.size() + 2 * data.oblique.size());
  EXPECT_EQ(fit.beyond_rigid_cushion_limit, 0u);
}

TEST(CushionFit, NoiseFreeDataGiveTheConstantsToHighAccuracy) {
  const CushionFitData data = synthetic(true, 0.0, 0.0, CushionSolver::exact, 5000);
  const CushionFit fit = fit_cushion(data, snooker_parameters());
  EXPECT_NEAR(fit.restitution, kTrueRestitution, 1e-5);
  EXPECT_NEAR(fit.friction, kTrueFriction, 1e-5);
  EXPECT_LT(fit.residual, 1e-14);
}

TEST(CushionFit, HeadOnRollingDataAloneDoNotSeparateTheConstants) {
  // The model has no speed scale: all head-on rolling points predict the same
  // V_out / V0, so only that one combination of (e_e, mu_w) is determined.
  const Parameters p = snooker_parameters();
  const CushionFitData data = synthetic(false, 0.003, 0.0, CushionSolver::exact, 5000);
  const CushionFit fit = fit_cushion(data, p);
  EXPECT_TRUE(fit.poorly_separated);
  EXPECT_GT(std::abs(fit.correlation), 0.98);
  // The fitted pair lies on the curve of the true ratio, wherever along it.
  const PaperIncidence unit{1.0, 90 * kDeg, 1.0 / p.ball.radius, 0.0};
  const double true_ratio = cushion_impact(incoming_ball(unit), p, truth(p)).rebound_speed;
  CushionParameters fitted = truth(p);
  fitted.restitution = fit.restitution;
  fitted.friction = fit.friction;
  EXPECT_NEAR(cushion_impact(incoming_ball(unit), p, fitted).rebound_speed, true_ratio, 0.004);
  // ... and so does another pair of the same grid: the paper's minimum is not unique.
  EXPECT_LT(fit.grid_residual, 6 * 0.003 * 0.003 * 3);
}

TEST(CushionFit, FitsWithThePaperSolverToo) {
  // Constants belong to the solver they were fitted with: data made by the
  // paper scheme (N = 400) are fitted by it on a coarse grid.
  const CushionFitData data = synthetic(true, 0.0, 0.0, CushionSolver::paper, 400);
  CushionFitOptions o;
  o.solver = CushionSolver::paper;
  o.paper_steps = 400;
  o.grid_step = 0.05;
  const CushionFit fit = fit_cushion(data, snooker_parameters(), o);
  EXPECT_NEAR(fit.restitution, kTrueRestitution, 0.01);
  EXPECT_NEAR(fit.friction, kTrueFriction, 0.01);
}

TEST(CushionFit, RejectsBadDataNamingTheField) {
  const Parameters p = snooker_parameters();
  auto expect_field = [&](const std::string& field, const CushionFitData& data, const CushionFitOptions& o) {
    try {
      fit_cushion(data, p, o);
      ADD_FAILURE() << "no InvalidArgument for " << field;
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  expect_field("data", {}, {});
  CushionFitData d;
  d.head_on = {{1.0, 0.9}, {0.0, 0.5}};
  expect_field("head_on[1].incoming_speed", d, {});
  d.head_on = {{1.0, -0.9}};
  expect_field("head_on[0].rebound_speed", d, {});
  d.head_on = {{1.0, 0.9}};
  d.oblique = {{{1.0, 100 * kDeg, 0.0, 0.0}, 0.8, 0.5}};
  expect_field("oblique[0].incidence.alpha", d, {});
  d.oblique = {{{1.0, 40 * kDeg, 0.0, 0.0}, 0.8, std::nan("")}};
  expect_field("oblique[0].rebound_angle", d, {});
  d.oblique.clear();
  CushionFitOptions o;
  o.grid_step = 0.0;
  expect_field("grid_step", d, o);
  o = {};
  o.contact_height = 3.0 * p.ball.radius;
  expect_field("h", d, o);
  o = {};
  o.paper_steps = 0;
  o.solver = CushionSolver::paper;
  expect_field("paper_steps", d, o);
}

}  // namespace
}  // namespace cueball
