// Ball-cushion impact (Mathavan, Jackson & Parkin 2010): the exact solver
// against the paper's Euler scheme (N = 5000) over the grid of the paper's
// Figs 8-10 widened: alpha = 1..90 deg, topspin K in {-1, -0.5, ..., 2},
// sidespin K in {-2, -1.5, ..., 2}, w = K V0 / R, V0 = 1 m/s, snooker ball,
// the paper's constants (e_e = 0.98, mu_w = 0.14).
//
// Counters:
//   BM_CushionExact / BM_CushionPaper5000   us_per_impact, steps (mean), events (mean),
//                           through cushion_impact() (validates the table's
//                           Parameters on every call)
//   BM_CushionExactModel    the simulator's path: the model validated once,
//                           solve_cushion_impact() per impact
//   BM_CushionExactUnchecked   solve_cushion_impact_unchecked() per impact
//   BM_CushionExactRolling  the model path on rolling balls only (topspin
//                           K = 1, sidespin -2..2, alpha 1..90 deg): the
//                           usual cushion hit in a game, looked up in the
//                           rolling-ball table (steps = 0 where it is)
//   BM_CushionExactRollingOde  the same balls by the Runge-Kutta solve
//                           (CushionImpactOptions::rolling_table = false)
//   BM_CushionSpeedup       exact and paper timed back to back in one process
//                           (CPU time): speedup = paper time / exact time over
//                           the same grid
//   BM_CushionAccuracy      exact against the N -> infinity limit of the paper
//                           scheme on a sample of the grid (alpha < 90 deg):
//                           the limit is the Richardson extrapolation 2 x(2N) - x(N)
//                           of the paper solver at N = 1e5 with its last step
//                           interpolated onto the end-of-restitution condition
//                           (which removes the O(dP) jitter of stopping "at the
//                           first step past", leaving a smooth O(1/N) error);
//                           max_dv_mps, max_dbeta_deg, max_R_dw_mps: the worst
//                           errors of exact (velocity, rebound angle, R x spin);
//                           limit_uncertainty_mps: how far the estimates from
//                           (N, 2N) and (2N, 4N) differ.
//   BM_CushionRandomAccuracy  the accuracy goal of the default on 200,000
//                           random sliding impacts over four cushions (see
//                           the function): worst errors, impacts beyond the
//                           goal (none), steps
//   BM_CushionTolerance     exact_tolerance 1e-8 (default) and 1e-7 (for
//                           planners) against 1e-11 on 20,000 random sliding
//                           impacts: time_ratio (1e-7 over 1e-8), steps and
//                           errors of each (see the function)
//   BM_CushionSlidingSmoothness  how smooth a sliding impact's outcome is in
//                           its three reduced inputs: Chebyshev interpolants
//                           along each, about the five-rail shot's sliding
//                           impact, and their worst error (what a table of
//                           sliding impacts would need; see the function)
//   BM_CushionSlidingTableCell  such a table built cell by cell: each of 100
//                           random sliding impacts' own tensor cell, whether
//                           it can be trusted, its error there, what a cell
//                           costs to build and to look up, and how many
//                           look-ups pay for it (see the function)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <string>
#include <vector>

#include "cueball/models/cushion/impact.hpp"
#include "cueball/core/parameters.hpp"
#include "cueball/io/scenario_json.hpp"
#include "cueball/simulation/scenario.hpp"

namespace {

using namespace cueball;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

const std::vector<IncomingBall>& grid() {
  static const std::vector<IncomingBall> balls = [] {
    const double radius = snooker_parameters().ball.radius;
    const double v0 = 1.0;
    std::vector<IncomingBall> out;
    for (int alpha = 1; alpha <= 90; ++alpha) {
      for (int t = -2; t <= 4; ++t) {      // topspin K = t / 2
        for (int s = -4; s <= 4; ++s) {    // sidespin K = s / 2
          out.push_back(incoming_ball({v0, alpha * kDegree, 0.5 * t * v0 / radius, 0.5 * s * v0 / radius}));
        }
      }
    }
    return out;
  }();
  return balls;
}

struct GridRun {
  double seconds = 0.0;
  double steps = 0.0;
  double events = 0.0;
  double checksum = 0.0;
};

const std::vector<IncomingBall>& rolling_grid() {
  static const std::vector<IncomingBall> balls = [] {
    const double radius = snooker_parameters().ball.radius;
    const double v0 = 1.0;
    std::vector<IncomingBall> out;
    for (int alpha = 1; alpha <= 90; ++alpha) {
      for (int s = -4; s <= 4; ++s) {  // sidespin K = s / 2
        out.push_back(incoming_ball({v0, alpha * kDegree, v0 / radius, 0.5 * s * v0 / radius}));
      }
    }
    return out;
  }();
  return balls;
}

// How an impact is solved: through cushion_impact() with the table's
// Parameters, or with a validated model, checked or not.
enum class Entry { table, model, unchecked };

GridRun run_grid(const CushionImpactOptions& options, Entry entry = Entry::table,
                 const std::vector<IncomingBall>& balls = grid()) {
  static const Parameters table = snooker_parameters();
  static const CushionParameters cushion = cushion_mathavan2010_paper_fit(table.ball);
  static const CushionImpactModel model = cushion_impact_model(table, cushion);
  GridRun run;
  const std::clock_t start = std::clock();  // CPU time: robust to a busy machine
  for (const IncomingBall& ball : balls) {
    const CushionImpactResult r = entry == Entry::table ? cushion_impact(ball, table, cushion, options)
                                  : entry == Entry::model ? solve_cushion_impact(ball, model, options)
                                                          : solve_cushion_impact_unchecked(ball, model, options);
    run.steps += r.solver_steps;
    run.events += r.solver_events;
    run.checksum += r.velocity.x + r.velocity.y;
  }
  run.seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  return run;
}

CushionImpactOptions paper_options(int n) {
  CushionImpactOptions o;
  o.solver = CushionSolver::paper;
  o.paper_steps = n;
  return o;
}

void report(benchmark::State& state, const GridRun& total, int runs, std::size_t grid_size) {
  const double impacts = static_cast<double>(grid_size) * runs;
  state.counters["us_per_impact"] = 1e6 * total.seconds / impacts;
  state.counters["steps"] = total.steps / impacts;
  state.counters["events"] = total.events / impacts;
  state.counters["impacts"] = benchmark::Counter(impacts, benchmark::Counter::kIsRate);
}

void run_solver(benchmark::State& state, const CushionImpactOptions& options, Entry entry = Entry::table,
                const std::vector<IncomingBall>& balls = grid()) {
  GridRun total;
  int runs = 0;
  for (auto _ : state) {
    const GridRun r = run_grid(options, entry, balls);
    benchmark::DoNotOptimize(r.checksum);
    total.seconds += r.seconds;
    total.steps += r.steps;
    total.events += r.events;
    ++runs;
  }
  report(state, total, runs, balls.size());
}

void BM_CushionExact(benchmark::State& state) { run_solver(state, {}); }
BENCHMARK(BM_CushionExact)->Unit(benchmark::kMillisecond);

void BM_CushionExactModel(benchmark::State& state) { run_solver(state, {}, Entry::model); }
BENCHMARK(BM_CushionExactModel)->Unit(benchmark::kMillisecond);

void BM_CushionExactUnchecked(benchmark::State& state) { run_solver(state, {}, Entry::unchecked); }
BENCHMARK(BM_CushionExactUnchecked)->Unit(benchmark::kMillisecond);

void BM_CushionExactRolling(benchmark::State& state) { run_solver(state, {}, Entry::model, rolling_grid()); }
BENCHMARK(BM_CushionExactRolling)->Unit(benchmark::kMillisecond);

CushionImpactOptions without_rolling_table() {
  CushionImpactOptions o;
  o.rolling_table = false;
  return o;
}
void BM_CushionExactRollingOde(benchmark::State& state) {
  run_solver(state, without_rolling_table(), Entry::model, rolling_grid());
}
BENCHMARK(BM_CushionExactRollingOde)->Unit(benchmark::kMillisecond);

void BM_CushionPaper5000(benchmark::State& state) { run_solver(state, paper_options(5000)); }
BENCHMARK(BM_CushionPaper5000)->Unit(benchmark::kMillisecond);

// Both solvers back to back, so that they see the same machine.
void BM_CushionSpeedup(benchmark::State& state) {
  double exact = 0.0;
  double paper = 0.0;
  for (auto _ : state) {
    exact += run_grid({}).seconds;
    paper += run_grid(paper_options(5000)).seconds;
  }
  state.counters["speedup"] = paper / exact;
  const double impacts = static_cast<double>(grid().size()) * static_cast<double>(state.iterations());
  state.counters["us_exact"] = 1e6 * exact / impacts;
  state.counters["us_paper"] = 1e6 * paper / impacts;
}
BENCHMARK(BM_CushionSpeedup)->Unit(benchmark::kSecond)->Iterations(3);

// ------------------------------------------------------------------ accuracy

struct Outgoing {
  Vec3 velocity;
  Vec3 angular_velocity;
};

// The paper solver with its last step interpolated onto W = (1 - e_e^2) W_c (16b).
Outgoing paper_interpolated(const IncomingBall& ball, const Parameters& table, const CushionParameters& cushion,
                            int n) {
  CushionImpactOptions o = paper_options(n);
  o.record_history = true;
  const CushionImpactResult r = cushion_impact(ball, table, cushion, o);
  const double target = (1.0 - cushion.restitution * cushion.restitution) * r.compression_work;
  const CushionImpactSample& a = r.history[r.history.size() - 2];
  const CushionImpactSample& b = r.history.back();
  const double f = (target - a.work) / (b.work - a.work);
  return {a.velocity + f * (b.velocity - a.velocity), a.angular_velocity + f * (b.angular_velocity - a.angular_velocity)};
}

Outgoing richardson(const Outgoing& coarse, const Outgoing& fine) {
  return {2.0 * fine.velocity - coarse.velocity, 2.0 * fine.angular_velocity - coarse.angular_velocity};
}

double beta_of(Vec3 v) { return std::atan2(-v.y, v.x); }

void BM_CushionAccuracy(benchmark::State& state) {
  const Parameters table = snooker_parameters();
  const CushionParameters cushion = cushion_mathavan2010_paper_fit(table.ball);
  const double radius = table.ball.radius;
  double max_dv = 0.0;
  double max_dbeta = 0.0;
  double max_dspin = 0.0;
  double max_uncertainty = 0.0;
  int samples = 0;
  for (auto _ : state) {
    for (const int alpha : {1, 7, 15, 25, 35, 45, 55, 65, 75, 85, 89}) {
      for (int t = -2; t <= 4; t += 2) {
        for (int s = -4; s <= 4; s += 2) {
          const IncomingBall ball =
              incoming_ball({1.0, alpha * kDegree, 0.5 * t / radius, 0.5 * s / radius});
          const CushionImpactResult exact = cushion_impact(ball, table, cushion);
          const Outgoing p1 = paper_interpolated(ball, table, cushion, 100000);
          const Outgoing p2 = paper_interpolated(ball, table, cushion, 200000);
          const Outgoing p4 = paper_interpolated(ball, table, cushion, 400000);
          const Outgoing limit = richardson(p1, p2);
          const Outgoing limit_fine = richardson(p2, p4);
          max_dv = std::max(max_dv, norm(exact.velocity - limit_fine.velocity));
          max_dspin = std::max(max_dspin, radius * norm(exact.angular_velocity - limit_fine.angular_velocity));
          max_dbeta = std::max(max_dbeta, std::abs(exact.rebound_angle - beta_of(limit_fine.velocity)) / kDegree);
          max_uncertainty = std::max(max_uncertainty, norm(limit.velocity - limit_fine.velocity));
          ++samples;
        }
      }
    }
  }
  state.counters["samples"] = samples;
  state.counters["max_dv_mps"] = max_dv;
  state.counters["max_dbeta_deg"] = max_dbeta;
  state.counters["max_R_dw_mps"] = max_dspin;
  state.counters["limit_uncertainty_mps"] = max_uncertainty;
}
BENCHMARK(BM_CushionAccuracy)->Unit(benchmark::kSecond)->Iterations(1);

// The exact solver's tolerance (CushionImpactOptions::exact_tolerance): the
// default 1e-8 and the planners' 1e-7 against the solve at 1e-11 on 20,000
// random sliding impacts (snooker ball and constants, V0 0.2-3 m/s, alpha
// 1-90 deg, topspin -1..2 and sidespin -2..2 V0/R; seed 1), each solved
// without the rolling-ball table. time_ratio is the 1e-7 solves' CPU time
// over the 1e-8 solves', timed alternately in one process; steps_* the mean
// Runge-Kutta steps; the errors are of the outgoing velocity and R x spin, in
// units of the largest incoming velocity (median, 99.9th percentile, worst;
// beyond_1e-6 counts the impacts beyond the accuracy goal), and of the
// rebound angle, degrees.
void BM_CushionTolerance(benchmark::State& state) {
  const Parameters table = snooker_parameters();
  const CushionImpactModel model = cushion_impact_model(table, cushion_mathavan2010_paper_fit(table.ball));
  const double radius = table.ball.radius;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<IncomingBall> balls;
  for (int i = 0; i < 20000; ++i) {
    const double v0 = 0.2 + 2.8 * u(rng);
    const double alpha = (1.0 + 89.0 * u(rng)) * kDegree;
    const double top = -1.0 + 3.0 * u(rng);
    const double side = -2.0 + 4.0 * u(rng);
    balls.push_back(incoming_ball({v0, alpha, top * v0 / radius, side * v0 / radius}));
  }
  CushionImpactOptions reference;
  reference.rolling_table = false;
  reference.exact_tolerance = 1e-11;
  auto largest = [&](const IncomingBall& b) {
    return std::max({std::abs(b.velocity.x), std::abs(b.velocity.y), radius * norm(b.angular_velocity)});
  };
  auto gap = [&](const CushionImpactResult& a, const CushionImpactResult& b) {
    return std::max(norm(a.velocity - b.velocity), radius * norm(a.angular_velocity - b.angular_velocity));
  };
  std::vector<CushionImpactResult> ref;
  for (const IncomingBall& b : balls) ref.push_back(solve_cushion_impact(b, model, reference));
  // One record per tolerance; the two are solved alternately in each iteration.
  struct Run {
    const char* name;
    double tolerance;
    double seconds = 0.0;
    double steps = 0.0;  // of the last iteration
    double worst_angle_deg = 0.0;
    std::vector<double> errors;  // of the last iteration
  };
  std::array<Run, 2> runs{Run{"tol_1e-8", 1e-8, 0.0, 0.0, 0.0, {}}, Run{"tol_1e-7", 1e-7, 0.0, 0.0, 0.0, {}}};
  for (auto _ : state) {
    for (Run& run : runs) {
      CushionImpactOptions o = reference;
      o.exact_tolerance = run.tolerance;
      run.errors.clear();
      run.steps = 0.0;
      const std::clock_t start = std::clock();
      for (std::size_t i = 0; i < balls.size(); ++i) {
        const CushionImpactResult r = solve_cushion_impact(balls[i], model, o);
        run.steps += r.solver_steps;
        run.errors.push_back(gap(r, ref[i]) / largest(balls[i]));
        run.worst_angle_deg = std::max(run.worst_angle_deg, std::abs(r.rebound_angle - ref[i].rebound_angle) / kDegree);
      }
      run.seconds += static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    }
  }
  for (Run& run : runs) {
    std::vector<double>& e = run.errors;
    std::sort(e.begin(), e.end());
    const std::string prefix = run.name;
    state.counters[prefix + "_steps"] = run.steps / static_cast<double>(balls.size());
    state.counters[prefix + "_median"] = e[e.size() / 2];
    state.counters[prefix + "_p999"] = e[e.size() * 999 / 1000];
    state.counters[prefix + "_worst"] = e.back();
    state.counters[prefix + "_beyond_1e-6"] =
        static_cast<double>(std::count_if(e.begin(), e.end(), [](double x) { return x > 1e-6; }));
    state.counters[prefix + "_worst_angle_deg"] = run.worst_angle_deg;
  }
  state.counters["time_ratio"] = runs[1].seconds / runs[0].seconds;
}
BENCHMARK(BM_CushionTolerance)->Unit(benchmark::kSecond)->Iterations(3);

// BM_CushionRandomAccuracy's draw of sliding impacts (seed 29): V0 0.2-3
// m/s, alpha 1-90 deg, sidespin -2..2 V0/R, topspin -1..2 V0/R, or within 2 %
// of natural roll for every third impact.
struct RandomSlidingImpacts {
  std::mt19937_64 rng{29};
  std::uniform_real_distribution<double> speed{0.2, 3.0}, angle{1.0, 90.0}, top{-1.0, 2.0}, side{-2.0, 2.0},
      near_roll{-0.02, 0.02};
  IncomingBall next(int i, double radius) {
    const double v0 = speed(rng);
    const double alpha = angle(rng) * kDegree;
    const double topspin = i % 3 == 0 ? 1.0 + near_roll(rng) : top(rng);
    return incoming_ball({v0, alpha, topspin * v0 / radius, side(rng) * v0 / radius});
  }
};

// The accuracy goal of the default (within 1e-6 of the largest incoming
// velocity, R x spin included, and 1e-4 deg of rebound angle from the
// N -> infinity limit; here the solve at tolerance 1e-11, which is ~1e-9 of
// it where the impact is smooth) on 200,000 random sliding impacts: 50,000
// on each of four cushions (the snooker paper fit, the translator's fit, the
// pool and carom cushion heights with the paper's constants), V0 0.2-3 m/s,
// alpha 1-90 deg, sidespin -2..2 V0/R, topspin -1..2 V0/R for two thirds and
// within 2 % of natural roll for the rest (the bed's slip starts near zero,
// as for the simulator's usual sliding ball); seed 29. Counters: the worst
// error in units of the largest incoming velocity and the worst rebound
// angle error (deg), the impacts beyond 1e-6 and beyond 1e-4 deg (the goal:
// none), the mean steps of the default and the reference.
void BM_CushionRandomAccuracy(benchmark::State& state) {
  const Parameters table = snooker_parameters();
  const double radius = table.ball.radius;
  CushionParameters carom = cushion_mathavan2010_paper_fit(table.ball);
  carom.contact_height = 1.2 * radius;
  CushionParameters pool = cushion_mathavan2010_paper_fit(table.ball);
  pool.contact_height = (1.0 + 0.3125 / 1.125) * radius;
  const CushionParameters cushions[] = {cushion_mathavan2010_paper_fit(table.ball),
                                        cushion_translator_exact_fit(table.ball), pool, carom};
  CushionImpactOptions reference;
  reference.rolling_table = false;
  reference.exact_tolerance = 1e-11;
  double worst = 0.0;
  double worst_angle = 0.0;
  int beyond = 0;
  int beyond_angle = 0;
  double steps = 0.0;
  double reference_steps = 0.0;
  int impacts = 0;
  for (auto _ : state) {
    RandomSlidingImpacts draw;
    for (const CushionParameters& cushion : cushions) {
      const CushionImpactModel model = cushion_impact_model(table, cushion);
      for (int i = 0; i < 50000; ++i) {
        const IncomingBall b = draw.next(i, radius);
        const CushionImpactResult r = solve_cushion_impact(b, model);
        const CushionImpactResult ref = solve_cushion_impact(b, model, reference);
        const double largest =
            std::max({std::abs(b.velocity.x), std::abs(b.velocity.y), radius * norm(b.angular_velocity)});
        const double e =
            std::max(norm(r.velocity - ref.velocity), radius * norm(r.angular_velocity - ref.angular_velocity)) /
            largest;
        const double a = std::abs(r.rebound_angle - ref.rebound_angle) / kDegree;
        worst = std::max(worst, e);
        worst_angle = std::max(worst_angle, a);
        beyond += e > 1e-6 ? 1 : 0;
        beyond_angle += a > 1e-4 ? 1 : 0;
        steps += r.solver_steps;
        reference_steps += ref.solver_steps;
        ++impacts;
      }
    }
  }
  state.counters["impacts"] = impacts;
  state.counters["worst"] = worst;
  state.counters["worst_angle_deg"] = worst_angle;
  state.counters["beyond_1e-6"] = beyond;
  state.counters["beyond_1e-4_deg"] = beyond_angle;
  state.counters["steps"] = steps / impacts;
  state.counters["reference_steps"] = reference_steps / impacts;
}
BENCHMARK(BM_CushionRandomAccuracy)->Unit(benchmark::kSecond)->Iterations(1);

// Issue 29: could a table over a sliding ball's impact replace its
// Runge-Kutta solve, as the rolling-ball table does for rolling ones? The
// outcome (the change of the velocities) depends on the three reduced inputs
// s_C,x, s_C,y and s_I,x over the normal speed (the fourth slip component is
// s_C,y - 1 - sin(theta); the conserved angular momentum J drops out of the
// change). About the sliding impact of BM_OneBallCushions (bench_simulator,
// its second rail: the ball as the simulator passes it, carom cushion and
// cloth), each input is moved alone (xG' moves s_C,x and s_I,x, R w_x moves
// s_C,y, R w_z moves s_I,x) over a width w (in units of the normal speed),
// the solver's answers at 1e-10 are interpolated at n + 1 Chebyshev points,
// and the interpolant is checked at 61 points: counter err_<input>_w<w>_n<n>
// is its worst error over the five outgoing velocities (units of the normal
// speed). A tensor-product table cell of width w and degree n in all three
// inputs costs (n + 1)^3 solves to build and (n + 1)^3 x 8 multiply-adds to
// evaluate. Measured: width 0.25 and degree 6 holds 1e-8 to 3e-7 (degree 10:
// 5e-10); width 1 fails even at degree 15 along s_C (6e-4, 2.5e-3), where the
// interval passes the rolling line s_C = 0: a bed slip starting from nearly
// zero turns onto its slow manifold, and the outcome is not smooth there
// (docs/cushion-speed.md).
void BM_CushionSlidingSmoothness(benchmark::State& state) {
  const Scenario carom = scenario_from_json(R"({"table": "carom_10ft", "balls": [{"id": 0, "position": [0.7, 0.4]}]})");
  const CushionImpactModel model =
      cushion_impact_model(carom.settings.parameters, {0.98, 0.14, carom.table.cushions[0].contact_height});
  const double radius = model.radius;
  const double vy = 2.0831885121411111;
  // xG', R w_x, R w_y, R w_z over yG'
  const std::array<double, 4> base{0.93366427908441474 / vy, -2.1213718209671208 / vy, 0.24316628797279705 / vy,
                                   2.3482759763839991 / vy};
  CushionImpactOptions options;
  options.rolling_table = false;
  options.exact_tolerance = 1e-10;
  auto solve = [&](const std::array<double, 4>& x) {
    IncomingBall b;
    b.velocity = {x[0], 1.0, 0.0};
    b.angular_velocity = {x[1] / radius, x[2] / radius, x[3] / radius};
    const CushionImpactResult r = solve_cushion_impact(b, model, options);
    return std::array<double, 5>{r.velocity.x, r.velocity.y, radius * r.angular_velocity.x,
                                 radius * r.angular_velocity.y, radius * r.angular_velocity.z};
  };
  const struct {
    const char* name;
    std::size_t component;
  } inputs[] = {{"bed_x", 0}, {"bed_y", 1}, {"cushion_x", 3}};
  const struct {
    double width;
    int degree;
  } fits[] = {{1.0, 15}, {0.25, 6}, {0.25, 10}};
  for (auto _ : state) {
    for (const auto& in : inputs) {
      for (const auto& fit : fits) {
        const int n = fit.degree;
        auto at = [&](double t) {
          std::array<double, 4> x = base;
          x[in.component] += 0.5 * fit.width * t;
          return solve(x);
        };
        std::vector<std::array<double, 5>> coefficients(static_cast<std::size_t>(n + 1));
        for (int j = 0; j <= n; ++j) {
          const double theta = kPi * (j + 0.5) / (n + 1);
          const std::array<double, 5> f = at(std::cos(theta));
          for (int m = 0; m <= n; ++m) {
            for (std::size_t o = 0; o < 5; ++o) {
              coefficients[static_cast<std::size_t>(m)][o] += f[o] * std::cos(m * theta) * (m == 0 ? 1.0 : 2.0) / (n + 1);
            }
          }
        }
        double worst = 0.0;
        for (int i = 0; i <= 60; ++i) {
          const double t = -1.0 + 2.0 * i / 60.0;
          const std::array<double, 5> exact = at(t);
          for (std::size_t o = 0; o < 5; ++o) {
            double v = 0.0;
            for (int m = 0; m <= n; ++m) v += coefficients[static_cast<std::size_t>(m)][o] * std::cos(m * std::acos(t));
            worst = std::max(worst, std::abs(v - exact[o]));
          }
        }
        char name[64];
        std::snprintf(name, sizeof name, "err_%s_w%g_n%d", in.name, fit.width, n);
        state.counters[name] = worst;
      }
    }
  }
}
BENCHMARK(BM_CushionSlidingSmoothness)->Unit(benchmark::kSecond)->Iterations(1);

// Issue 29's eighth round: route (a) as a table would be built, cell by cell
// on first use. A cell is a cube of width 0.25 in the three reduced inputs
// (s_I,x, s_C,x, s_C,y over the normal speed, the other inputs set so that
// R w_z = 0), with the solver's answers at 1e-10 at n Chebyshev points
// (second kind) per axis, n = state.range(0), and the five outgoing
// velocities (R x spin included) as a tensor Chebyshev series. A cell is
// trusted where every node's solve has the same number of events and the
// series' last two coefficients along any axis stay below 1e-8 of the
// velocity scale (the same events alone is not enough: a cell at (0.25,
// 0.25, 1.5) on the carom cushion passed it and was 1.8e-6 off). Over 100
// random sliding impacts (BM_CushionRandomAccuracy's draw on the paper's
// cushion), each impact's own cell: valid_share, the worst error at the
// impacts in the trusted cells against the solve at 1e-11 (units of the
// velocity scale), the mean time to build a cell (build_ms), a look-up
// (plain loops; lookup_us) against the default solve of the same impact
// (solve_us), and how many look-ups a cell must serve to pay for its
// build (hits_to_pay).
void BM_CushionSlidingTableCell(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const auto un = static_cast<std::size_t>(n);
  const Parameters table = snooker_parameters();
  const CushionImpactModel model = cushion_impact_model(table, cushion_mathavan2010_paper_fit(table.ball));
  const double radius = model.radius;
  const double s = model.sin_theta;
  const double c = std::sqrt(1.0 - s * s);
  constexpr double kWidth = 0.25;
  CushionImpactOptions build_options;
  build_options.rolling_table = false;
  build_options.exact_tolerance = 1e-10;
  CushionImpactOptions reference = build_options;
  reference.exact_tolerance = 1e-11;
  CushionImpactOptions plain;
  plain.rolling_table = false;
  using Out = std::array<double, 5>;
  // The ball with reduced inputs x (R w_z = 0) and its outgoing velocities, in units of the normal speed.
  auto ball_at = [&](const std::array<double, 3>& x) {
    const double uy = (x[0] - x[1]) / (1.0 + s);
    IncomingBall b;
    b.velocity = {x[1] + uy, 1.0, 0.0};
    b.angular_velocity = {(x[2] - 1.0) / radius, uy / radius, 0.0};
    return b;
  };
  auto outputs = [&](const CushionImpactResult& r) {
    return Out{r.velocity.x, r.velocity.y, radius * r.angular_velocity.x, radius * r.angular_velocity.y,
               radius * r.angular_velocity.z};
  };
  int valid = 0;
  int impacts = 0;
  double worst = 0.0;
  double build_s = 0.0;
  double lookup_s = 0.0;
  double solve_s = 0.0;
  for (auto _ : state) {
    RandomSlidingImpacts draw;
    for (int impact = 0; impact < 100; ++impact) {
      const IncomingBall b = draw.next(impact, radius);
      const double vn = b.velocity.y;
      const Vec3 u = (radius / vn) * b.angular_velocity;
      const std::array<double, 3> x{b.velocity.x / vn + u.y * s - u.z * c, b.velocity.x / vn - u.y, 1.0 + u.x};
      std::array<double, 3> lo{};
      for (std::size_t a = 0; a < 3; ++a) lo[a] = std::floor(x[a] / kWidth) * kWidth;
      // The cell: values at the nodes, then a DCT-I along each axis.
      const auto t0 = std::chrono::steady_clock::now();
      std::vector<Out> f(un * un * un);
      auto at = [&](std::size_t i, std::size_t j, std::size_t l) -> Out& { return f[(i * un + j) * un + l]; };
      std::vector<double> node(un);
      for (std::size_t k = 0; k < un; ++k) node[k] = std::cos(kPi * static_cast<double>(k) / (n - 1));
      int events = -1;
      bool same_events = true;
      for (std::size_t i = 0; i < un; ++i) {
        for (std::size_t j = 0; j < un; ++j) {
          for (std::size_t l = 0; l < un; ++l) {
            const std::array<double, 3> xn{lo[0] + kWidth * 0.5 * (1.0 + node[i]), lo[1] + kWidth * 0.5 * (1.0 + node[j]),
                                           lo[2] + kWidth * 0.5 * (1.0 + node[l])};
            const CushionImpactResult r = solve_cushion_impact(ball_at(xn), model, build_options);
            at(i, j, l) = outputs(r);
            if (events < 0) events = r.solver_events;
            same_events = same_events && r.solver_events == events;
          }
        }
      }
      auto dct = [&](auto&& element) {  // along one axis: element(k) is the k-th value of a line
        std::vector<Out> line(un);
        for (std::size_t m = 0; m < un; ++m) {
          Out sum{};
          for (std::size_t k = 0; k < un; ++k) {
            const double weight = (k == 0 || k == un - 1 ? 0.5 : 1.0) * std::cos(kPi * static_cast<double>(m * k) / (n - 1));
            for (std::size_t o = 0; o < 5; ++o) sum[o] += weight * element(k)[o];
          }
          const double scale = 2.0 / (n - 1) * (m == 0 || m == un - 1 ? 0.5 : 1.0);
          for (std::size_t o = 0; o < 5; ++o) line[m][o] = scale * sum[o];
        }
        for (std::size_t m = 0; m < un; ++m) element(m) = line[m];
      };
      for (int axis = 0; axis < 3; ++axis) {
        for (std::size_t p = 0; p < un; ++p) {
          for (std::size_t q = 0; q < un; ++q) {
            dct([&](std::size_t k) -> Out& { return axis == 0 ? at(k, p, q) : axis == 1 ? at(p, k, q) : at(p, q, k); });
          }
        }
      }
      const auto t1 = std::chrono::steady_clock::now();
      build_s += std::chrono::duration<double>(t1 - t0).count();
      double tail = 0.0;
      for (std::size_t i = 0; i < un; ++i) {
        for (std::size_t j = 0; j < un; ++j) {
          for (std::size_t l = 0; l < un; ++l) {
            if (i + 2 < un && j + 2 < un && l + 2 < un) continue;
            for (const double v : at(i, j, l)) tail = std::max(tail, std::abs(v));
          }
        }
      }
      auto lookup = [&](const std::array<double, 3>& xs) {
        std::array<std::vector<double>, 3> t;
        for (std::size_t a = 0; a < 3; ++a) {
          const double v = 2.0 * (xs[a] - lo[a]) / kWidth - 1.0;
          t[a].assign(un, 1.0);
          t[a][1] = v;
          for (std::size_t k = 2; k < un; ++k) t[a][k] = 2.0 * v * t[a][k - 1] - t[a][k - 2];
        }
        Out sum{};
        for (std::size_t i = 0; i < un; ++i) {
          for (std::size_t j = 0; j < un; ++j) {
            for (std::size_t l = 0; l < un; ++l) {
              const double w = t[0][i] * t[1][j] * t[2][l];
              for (std::size_t o = 0; o < 5; ++o) sum[o] += w * at(i, j, l)[o];
            }
          }
        }
        return sum;
      };
      const IncomingBall canonical = ball_at(x);
      const double largest = std::max({std::abs(canonical.velocity.x), 1.0, radius * norm(canonical.angular_velocity)});
      const auto t2 = std::chrono::steady_clock::now();
      double sink = 0.0;
      for (int r = 0; r < 100; ++r) sink += lookup(x)[0];
      const auto t3 = std::chrono::steady_clock::now();
      for (int r = 0; r < 100; ++r) sink += solve_cushion_impact(b, model, plain).velocity.x;
      const auto t4 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(sink);
      lookup_s += std::chrono::duration<double>(t3 - t2).count() / 100;
      solve_s += std::chrono::duration<double>(t4 - t3).count() / 100;
      ++impacts;
      if (!same_events || tail > 1e-8 * largest) continue;
      ++valid;
      const Out exact = outputs(solve_cushion_impact(canonical, model, reference));
      const Out table_value = lookup(x);
      for (std::size_t o = 0; o < 5; ++o) worst = std::max(worst, std::abs(table_value[o] - exact[o]) / largest);
    }
  }
  state.counters["valid_share"] = static_cast<double>(valid) / impacts;
  state.counters["worst_valid_error"] = worst;
  state.counters["build_ms"] = 1e3 * build_s / impacts;
  state.counters["lookup_us"] = 1e6 * lookup_s / impacts;
  state.counters["solve_us"] = 1e6 * solve_s / impacts;
  state.counters["hits_to_pay"] = build_s / (solve_s - lookup_s);
}
BENCHMARK(BM_CushionSlidingTableCell)->Arg(7)->Arg(9)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
