// Throughput of the quartic solver on ball-ball contact quartics, against two
// baselines run in the same process:
//  * naive Ferrari: the textbook closed form (depress, resolvent cubic by
//    Cardano / trigonometric formula, two quadratics by the schoolbook
//    formula), no polish: fast, but loses accuracy and roots;
//  * companion matrix: eigenvalues of the 4x4 companion matrix by Francis
//    double-shift QR (the numpy.roots approach used by several simulators),
//    real eigenvalues taken as the real roots.
// Each iteration solves one quartic of a fixed, pre-generated batch, so the
// reported time per iteration is ns per solve. Counters give, per method and
// over the whole batch: the worst residual |p(t)| / (eps sum |c_k| |t|^k) of
// a reported root (long double), and how many quartics got a different
// number of real roots than cueball's solver.
//
// Batches (fixed seed, 4096 quartics, R = 28.575 mm):
//  * table: ball pairs anywhere on a 9-ft table, each ball at rest, rolling
//    (deceleration ~0.1 m/s^2 along its velocity) or sliding (~2 m/s^2 in any
//    direction); most pairs never touch (no real roots), some are degenerate
//    (equal accelerations);
//  * contact: pairs less than 0.6 m apart aimed at each other, so most
//    quartics have real roots (contact and separation times).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "cueball/physics/polynomial_roots.hpp"
#include "cueball/core/vec.hpp"

namespace {

using cueball::QuarticCoefficients;
using cueball::Vec2;

constexpr double kR = 0.028575;
constexpr std::size_t kBatch = 4096;  // power of two: the index wraps with a mask

struct Roots4 {
  std::array<double, 4> t{};
  int count = 0;
};

void sort_roots(Roots4& r) {
  for (int i = 1; i < r.count; ++i)
    for (int j = i; j > 0 && r.t[static_cast<std::size_t>(j - 1)] > r.t[static_cast<std::size_t>(j)]; --j)
      std::swap(r.t[static_cast<std::size_t>(j - 1)], r.t[static_cast<std::size_t>(j)]);
}

// ---------------------------------------------------------- naive Ferrari

// Largest real root of x^3 + a x^2 + b x + c (Cardano / trigonometric).
double naive_cubic_root(double a, double b, double c) {
  const double q = (a * a - 3.0 * b) / 9.0;
  const double r = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0;
  if (r * r < q * q * q) {
    const double theta = std::acos(r / std::sqrt(q * q * q));
    return -2.0 * std::sqrt(q) * std::cos((theta - 2.0 * 3.14159265358979323846) / 3.0) - a / 3.0;
  }
  const double big = -std::copysign(std::cbrt(std::fabs(r) + std::sqrt(r * r - q * q * q)), r);
  return big + (big == 0.0 ? 0.0 : q / big) - a / 3.0;
}

Roots4 naive_ferrari(const QuarticCoefficients& c) {
  Roots4 out;
  const double a = c[3] / c[4];
  const double b = c[2] / c[4];
  const double cc = c[1] / c[4];
  const double d = c[0] / c[4];
  const double a2 = a * a;
  const double p = b - 3.0 * a2 / 8.0;
  const double q = cc - a * b / 2.0 + a2 * a / 8.0;
  const double r = d - a * cc / 4.0 + a2 * b / 16.0 - 3.0 * a2 * a2 / 256.0;
  auto quadratic = [&out, a](double bb, double cq) {  // y^2 + bb y + cq, then x = y - a/4
    const double disc = bb * bb - 4.0 * cq;
    if (disc < 0.0) return;
    const double s = std::sqrt(disc);
    out.t[static_cast<std::size_t>(out.count++)] = (-bb - s) / 2.0 - a / 4.0;
    out.t[static_cast<std::size_t>(out.count++)] = (-bb + s) / 2.0 - a / 4.0;
  };
  // Resolvent z^3 + 2p z^2 + (p^2 - 4r) z - q^2 = 0; y^4 + p y^2 + q y + r
  // = (y^2 + sqrt(z) y + (p + z)/2 - q/(2 sqrt z)) (y^2 - sqrt(z) y + ...).
  const double z = naive_cubic_root(2.0 * p, p * p - 4.0 * r, -q * q);
  if (z > 0.0) {
    const double sz = std::sqrt(z);
    quadratic(sz, 0.5 * (p + z) - q / (2.0 * sz));
    quadratic(-sz, 0.5 * (p + z) + q / (2.0 * sz));
  } else {  // biquadratic
    const double disc = p * p - 4.0 * r;
    if (disc >= 0.0) {
      for (double y2 : {(-p - std::sqrt(disc)) / 2.0, (-p + std::sqrt(disc)) / 2.0}) {
        if (y2 < 0.0) continue;
        out.t[static_cast<std::size_t>(out.count++)] = std::sqrt(y2) - a / 4.0;
        out.t[static_cast<std::size_t>(out.count++)] = -std::sqrt(y2) - a / 4.0;
      }
    }
  }
  sort_roots(out);
  return out;
}

// -------------------------------------------------------- companion matrix

// Real eigenvalues of the companion matrix of a quartic (leading coefficient
// nonzero), by the Francis double-shift QR iteration on the (already upper
// Hessenberg) companion matrix, working on the active unreduced block only
// (eigenvalues, no Schur vectors). Golub & Van Loan, Matrix Computations,
// Algorithm 7.5.1 / 7.5.2.
class Companion {
 public:
  explicit Companion(const QuarticCoefficients& c) {
    for (auto& row : h_) row.fill(0.0);
    for (std::size_t j = 0; j < 4; ++j) h_[0][j] = -c[3 - j] / c[4];
    for (std::size_t i = 1; i < 4; ++i) h_[i][i - 1] = 1.0;
  }

  Roots4 real_eigenvalues() {
    Roots4 out;
    int hi = 3;
    int its = 0;
    while (hi >= 0) {
      int l = hi;
      while (l > 0 && std::fabs(at(l, l - 1)) > kEps * (std::fabs(at(l - 1, l - 1)) + std::fabs(at(l, l)))) --l;
      if (l > 0) at(l, l - 1) = 0.0;
      if (l == hi) {  // 1x1 block
        out.t[static_cast<std::size_t>(out.count++)] = at(hi, hi);
        hi -= 1;
        its = 0;
      } else if (l == hi - 1) {  // 2x2 block
        const double a = at(hi - 1, hi - 1), b = at(hi - 1, hi), c = at(hi, hi - 1), d = at(hi, hi);
        const double p = 0.5 * (a - d);
        const double disc = p * p + b * c;
        if (disc >= 0.0) {
          const double z = p + std::copysign(std::sqrt(disc), p);
          out.t[static_cast<std::size_t>(out.count++)] = d + z;
          out.t[static_cast<std::size_t>(out.count++)] = z != 0.0 ? d - b * c / z : d;
        }
        hi -= 2;
        its = 0;
      } else {
        if (++its > 60) break;  // no convergence: give up on the rest
        francis_step(l, hi, its % 10 == 0);
      }
    }
    sort_roots(out);
    return out;
  }

 private:
  static constexpr double kEps = std::numeric_limits<double>::epsilon();
  double& at(int i, int j) { return h_[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]; }

  // Householder reflector I - beta v v^T taking (x0, x1[, x2]) to a multiple of e1.
  static double house(double* v, int n) {
    double norm2 = 0.0;
    for (int i = 0; i < n; ++i) norm2 += v[i] * v[i];
    if (norm2 == 0.0) return 0.0;
    v[0] += std::copysign(std::sqrt(norm2), v[0]);
    double vv = 0.0;
    for (int i = 0; i < n; ++i) vv += v[i] * v[i];
    return 2.0 / vv;
  }
  void reflect_rows(const double* v, double beta, int n, int r0, int c0, int c1) {
    for (int j = c0; j <= c1; ++j) {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += v[i] * at(r0 + i, j);
      for (int i = 0; i < n; ++i) at(r0 + i, j) -= beta * v[i] * s;
    }
  }
  void reflect_cols(const double* v, double beta, int n, int c0, int r0, int r1) {
    for (int i = r0; i <= r1; ++i) {
      double s = 0.0;
      for (int j = 0; j < n; ++j) s += at(i, c0 + j) * v[j];
      for (int j = 0; j < n; ++j) at(i, c0 + j) -= beta * s * v[j];
    }
  }

  void francis_step(int l, int hi, bool exceptional) {
    double s = at(hi - 1, hi - 1) + at(hi, hi);
    double t = at(hi - 1, hi - 1) * at(hi, hi) - at(hi - 1, hi) * at(hi, hi - 1);
    if (exceptional) {  // break a cycle with an ad hoc shift
      const double w = std::fabs(at(hi, hi - 1)) + std::fabs(at(hi - 1, hi - 2));
      s = 1.5 * w;
      t = w * w;
    }
    double v[3] = {at(l, l) * at(l, l) + at(l, l + 1) * at(l + 1, l) - s * at(l, l) + t,
                   at(l + 1, l) * (at(l, l) + at(l + 1, l + 1) - s), at(l + 1, l) * at(l + 2, l + 1)};
    for (int k = l; k <= hi - 2; ++k) {
      const double beta = house(v, 3);
      if (beta != 0.0) {
        reflect_rows(v, beta, 3, k, std::max(l, k - 1), hi);
        reflect_cols(v, beta, 3, k, l, std::min(k + 3, hi));
      }
      v[0] = at(k + 1, k);
      v[1] = at(k + 2, k);
      v[2] = k < hi - 2 ? at(k + 3, k) : 0.0;
    }
    const double beta = house(v, 2);
    if (beta != 0.0) {
      reflect_rows(v, beta, 2, hi - 1, hi - 2, hi);
      reflect_cols(v, beta, 2, hi - 1, l, hi);
    }
  }

  std::array<std::array<double, 4>, 4> h_{};
};

Roots4 companion_roots(const QuarticCoefficients& c) { return Companion(c).real_eigenvalues(); }

Roots4 cueball_roots(const QuarticCoefficients& c) {
  const cueball::QuarticRoots r = cueball::solve_quartic(c);
  Roots4 out;
  out.count = r.count;
  for (std::size_t i = 0; i < 4; ++i) out.t[i] = r.t[i];
  return out;
}

// ------------------------------------------------------------------ batches

QuarticCoefficients contact_quartic(Vec2 dr, Vec2 dv, Vec2 da) {
  return {dot(dr, dr) - 4 * kR * kR, 2 * dot(dr, dv), dot(dv, dv) + dot(dr, da), dot(dv, da), 0.25 * dot(da, da)};
}

struct Ball {
  Vec2 r, v, a;
};

Ball random_ball(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double pi = 3.14159265358979323846;
  Ball b{{2.54 * u(rng), 1.27 * u(rng)}, {0, 0}, {0, 0}};
  const double kind = u(rng);
  if (kind < 0.25) return b;  // at rest
  const double speed = 4.0 * u(rng);
  const double heading = 2 * pi * u(rng);
  b.v = Vec2{std::cos(heading), std::sin(heading)} * speed;
  if (kind < 0.5) {  // rolling: decelerates along its velocity
    b.a = b.v * (-0.1 / std::max(speed, 1e-12));
  } else {  // sliding: friction opposes the (random) contact-point slip
    const double slip = 2 * pi * u(rng);
    b.a = Vec2{std::cos(slip), std::sin(slip)} * 2.0;
  }
  return b;
}

const std::vector<QuarticCoefficients>& table_batch() {
  static const std::vector<QuarticCoefficients> batch = [] {
    std::mt19937_64 rng(2024);
    std::vector<QuarticCoefficients> out;
    while (out.size() < kBatch) {
      const Ball b1 = random_ball(rng);
      const Ball b2 = random_ball(rng);
      const Vec2 dr = b2.r - b1.r;
      if (norm(dr) <= 2 * kR) continue;
      QuarticCoefficients c = contact_quartic(dr, b2.v - b1.v, b2.a - b1.a);
      if (c[4] == 0.0) continue;  // keep true quartics in this batch
      out.push_back(c);
    }
    return out;
  }();
  return batch;
}

const std::vector<QuarticCoefficients>& contact_batch() {
  static const std::vector<QuarticCoefficients> batch = [] {
    std::mt19937_64 rng(2025);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<QuarticCoefficients> out;
    while (out.size() < kBatch) {
      const Ball b1 = random_ball(rng);
      Ball b2 = random_ball(rng);
      // b2 within 0.6 m of b1, aimed at it with an impact parameter below 2R,
      // at 0.5 .. 4 m/s relative speed.
      const double pi = 3.14159265358979323846;
      const double dist = 2 * kR + 0.001 + 0.6 * u(rng);
      const double bearing = 2 * pi * u(rng);
      b2.r = b1.r + Vec2{std::cos(bearing), std::sin(bearing)} * dist;
      const Vec2 dr = b2.r - b1.r;
      const Vec2 toward = dr * (-1.0 / norm(dr));
      const double offset = 2 * kR * (2 * u(rng) - 1) * 0.95;
      const Vec2 dir = toward * std::sqrt(dist * dist - offset * offset) / dist + perp(toward) * (offset / dist);
      b2.v = b1.v + dir * (0.5 + 3.5 * u(rng));
      QuarticCoefficients c = contact_quartic(dr, b2.v - b1.v, b2.a - b1.a);
      if (c[4] == 0.0) continue;
      out.push_back(c);
    }
    return out;
  }();
  return batch;
}

// ------------------------------------------------------- accuracy counters

using Solver = Roots4 (*)(const QuarticCoefficients&);

void add_accuracy_counters(benchmark::State& state, const std::vector<QuarticCoefficients>& batch, Solver solve) {
  using LD = long double;
  double worst = 0.0;
  double count_diff = 0.0;
  double roots = 0.0;
  for (const auto& c : batch) {
    const Roots4 r = solve(c);
    roots += r.count;
    if (r.count != cueball::solve_quartic(c).count) count_diff += 1.0;
    for (int i = 0; i < r.count; ++i) {
      const LD t = r.t[static_cast<std::size_t>(i)];
      LD p = 0, bound = 0;
      for (std::size_t k = 5; k-- > 0;) {
        p = p * t + static_cast<LD>(c[k]);
        bound = bound * std::fabs(t) + std::fabs(static_cast<LD>(c[k]));
      }
      worst = std::max(worst, static_cast<double>(std::fabs(p) / bound) / std::numeric_limits<double>::epsilon());
    }
  }
  state.counters["max_residual_eps"] = worst;
  state.counters["root_count_differs"] = count_diff;
  state.counters["real_roots_per_quartic"] = roots / static_cast<double>(batch.size());
}

template <Solver solve>
void run(benchmark::State& state, const std::vector<QuarticCoefficients>& batch) {
  std::size_t i = 0;
  for (auto _ : state) {
    Roots4 r = solve(batch[i++ & (kBatch - 1)]);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations());
  add_accuracy_counters(state, batch, solve);
}

void BM_Quartic_Table_Cueball(benchmark::State& s) { run<cueball_roots>(s, table_batch()); }
void BM_Quartic_Table_NaiveFerrari(benchmark::State& s) { run<naive_ferrari>(s, table_batch()); }
void BM_Quartic_Table_CompanionQR(benchmark::State& s) { run<companion_roots>(s, table_batch()); }
void BM_Quartic_Contact_Cueball(benchmark::State& s) { run<cueball_roots>(s, contact_batch()); }
void BM_Quartic_Contact_NaiveFerrari(benchmark::State& s) { run<naive_ferrari>(s, contact_batch()); }
void BM_Quartic_Contact_CompanionQR(benchmark::State& s) { run<companion_roots>(s, contact_batch()); }

// The event predictor's call: the earliest contact in the next 0.5 s. The
// helper first tries to prove the window root-free (no division, ~30 flops)
// and only then solves; compare with a full solve followed by a scan.
void BM_EarliestContact_Table_SmallestRootIn(benchmark::State& state) {
  const auto& batch = table_batch();
  std::size_t i = 0;
  for (auto _ : state) {
    auto t = cueball::smallest_root_in(batch[i++ & (kBatch - 1)], 0.0, 0.5);
    benchmark::DoNotOptimize(t);
  }
  state.SetItemsProcessed(state.iterations());
}
void BM_EarliestContact_Table_SolveThenScan(benchmark::State& state) {
  const auto& batch = table_batch();
  std::size_t i = 0;
  for (auto _ : state) {
    const cueball::QuarticRoots r = cueball::solve_quartic(batch[i++ & (kBatch - 1)]);
    double first = -1.0;
    for (double x : r)
      if (x >= 0.0) {
        if (x <= 0.5) first = x;
        break;
      }
    benchmark::DoNotOptimize(first);
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK(BM_Quartic_Table_Cueball);
BENCHMARK(BM_Quartic_Table_NaiveFerrari);
BENCHMARK(BM_Quartic_Table_CompanionQR);
BENCHMARK(BM_Quartic_Contact_Cueball);
BENCHMARK(BM_Quartic_Contact_NaiveFerrari);
BENCHMARK(BM_Quartic_Contact_CompanionQR);
BENCHMARK(BM_EarliestContact_Table_SmallestRootIn);
BENCHMARK(BM_EarliestContact_Table_SolveThenScan);
