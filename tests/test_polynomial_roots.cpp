// Tests for the real polynomial root solvers (src/physics/polynomial_roots.cpp).
//
// Every expected value is computed, never hard-coded: polynomials are built
// from known roots, compared with an independent long-double reference
// (bisection on sign changes between the critical points, found recursively
// from the derivatives), or checked through residuals and exact symmetries.
// Tolerances come from first-order perturbation theory (condition numbers),
// so a solver that loses accuracy beyond what the conditioning allows fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "cueball/physics/polynomial_roots.hpp"
#include "cueball/core/vec.hpp"
#include "test_scale.hpp"

namespace cueball {
namespace {

using LD = long double;
// long double is this test's reference precision: every double widened to
// it here is meant (clang's -Wdouble-promotion flags double -> long double
// too; GCC's only float -> double).
#if defined(__clang__)
#pragma clang diagnostic ignored "-Wdouble-promotion"
#endif
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kTol = kDefaultTangencyTolerance;
constexpr double kInf = std::numeric_limits<double>::infinity();

// ------------------------------------------------------------------ helpers

// Coefficients (ascending) of lead * prod (t - r_i), expanded in double.
template <std::size_t N>
std::array<double, N + 1> from_roots(const std::array<double, N>& r, double lead = 1.0) {
  std::array<double, N + 1> c{};
  c[0] = lead;
  for (std::size_t i = 0; i < N; ++i) {
    // multiply the degree-i polynomial c[0..i] by (t - r_i)
    c[i + 1] = c[i];
    for (std::size_t k = i; k > 0; --k) c[k] = c[k - 1] - r[i] * c[k];
    c[0] = -r[i] * c[0];
  }
  return c;
}

// p and sum |c_k| |t|^k in long double.
template <std::size_t M>
LD eval_ld(const std::array<double, M>& c, LD t) {
  LD p = 0;
  for (std::size_t k = M; k-- > 0;) p = p * t + static_cast<LD>(c[k]);
  return p;
}
template <std::size_t M>
LD bound_ld(const std::array<double, M>& c, LD t) {
  LD p = 0;
  const LD at = std::fabs(t);
  for (std::size_t k = M; k-- > 0;) p = p * at + std::fabs(static_cast<LD>(c[k]));
  return p;
}
template <std::size_t M>
LD deriv_ld(const std::array<double, M>& c, LD t) {
  LD d = 0;
  for (std::size_t k = M; k-- > 1;) d = d * t + static_cast<LD>(k) * static_cast<LD>(c[k]);
  return d;
}
template <std::size_t M>
LD half_second_deriv_ld(const std::array<double, M>& c, LD t) {
  LD d = 0;
  for (std::size_t k = M; k-- > 2;) d = d * t + static_cast<LD>(k * (k - 1) / 2) * static_cast<LD>(c[k]);
  return d;
}

// A simple root of the double-coefficient polynomial c itself, refined from
// a nearby estimate by Newton's method in long double.
template <std::size_t M>
double exact_root_near(const std::array<double, M>& c, double x0) {
  LD x = x0;
  for (int it = 0; it < 50; ++it) {
    const LD d = deriv_ld(c, x);
    if (d == 0) break;
    const LD next = x - eval_ld(c, x) / d;
    if (next == x) break;
    x = next;
  }
  return static_cast<double>(x);
}

// Simple root: first-order error bound C eps pbar(r) / |p'(r)|.
template <std::size_t M>
double simple_root_tol(const std::array<double, M>& c, double r, double C = 32) {
  return C * kEps * static_cast<double>(bound_ld(c, r) / std::fabs(deriv_ld(c, r)));
}
// Double root: the policy reports it within sqrt(tol pbar(r) / |p''(r)/2|);
// allow twice that.
template <std::size_t M>
double double_root_tol(const std::array<double, M>& c, double r) {
  return 2 * static_cast<double>(std::sqrt(static_cast<LD>(kTol) * bound_ld(c, r) / std::fabs(half_second_deriv_ld(c, r))));
}

// Relative first-order error bound for root i of prod (t - r_j) whose
// coefficients were rounded while being formed: the computed polynomial moves
// root i by about eps * prod_{j != i} (|r_i| + |r_j|) / |r_i - r_j| relative.
template <std::size_t N>
double product_condition(const std::array<double, N>& r, std::size_t i) {
  double cond = 1.0;
  for (std::size_t j = 0; j < N; ++j)
    if (j != i) cond *= (std::fabs(r[i]) + std::fabs(r[j])) / std::fabs(r[i] - r[j]);
  return cond;
}

// Does the tangency policy leave adjacent roots r[i], r[i+1] apart? It merges
// a pair when p is numerically zero at its midpoint (|p| <= tol * pbar); this
// asks for a clear margin (4x) so that round-off cannot tip the decision.
template <std::size_t N, std::size_t M>
bool policy_separates(const std::array<double, M>& c, const std::array<double, N>& r) {
  for (std::size_t i = 0; i + 1 < N; ++i) {
    const LD mid = (static_cast<LD>(r[i]) + static_cast<LD>(r[i + 1])) / 2;
    if (std::fabs(eval_ld(c, mid)) <= 4 * static_cast<LD>(kTol) * bound_ld(c, mid)) return false;
  }
  return true;
}

// Lower-degree coefficients in a wider array (leading zeros).
template <std::size_t N, std::size_t M>
std::array<double, N> pad(const std::array<double, M>& c) {
  static_assert(M <= N);
  std::array<double, N> out{};
  for (std::size_t k = 0; k < M; ++k) out[k] = c[k];
  return out;
}

// The distinct values of known roots, ascending.
template <std::size_t N>
std::vector<double> distinct_sorted(std::array<double, N> r) {
  std::sort(r.begin(), r.end());
  return std::vector<double>(r.begin(), std::unique(r.begin(), r.end()));
}

template <std::size_t N>
std::vector<double> roots_vector(const RealRoots<N>& r) {
  return std::vector<double>(r.begin(), r.end());
}

// Invariants of every result: ascending, distinct, finite, NaN past count.
template <std::size_t N>
void expect_well_formed(const RealRoots<N>& r) {
  ASSERT_GE(r.count, 0);
  ASSERT_LE(r.count, static_cast<int>(N));
  for (int i = 0; i < r.count; ++i) {
    EXPECT_TRUE(std::isfinite(r[static_cast<std::size_t>(i)]));
    if (i > 0) {
      EXPECT_LT(r[static_cast<std::size_t>(i - 1)], r[static_cast<std::size_t>(i)]);
    }
  }
  for (std::size_t i = static_cast<std::size_t>(r.count); i < N; ++i) EXPECT_TRUE(std::isnan(r[i]));
}

// ----------------------------------------------- independent slow reference
//
// Real roots of a polynomial (long double coefficients, ascending) at which
// it changes sign: the critical points (roots of p', found the same way,
// recursively) split the line into monotone pieces; a piece whose ends have
// opposite signs holds exactly one root, found by bisection to the last bit
// of long double. Even-multiplicity roots (no sign change) are not reported,
// which is fine for the random, generic polynomials this is used on. The
// critical points are returned too, for the ambiguity check.
struct Reference {
  std::vector<LD> roots;
  std::vector<LD> critical;
};

LD eval_poly(const std::vector<LD>& c, LD t) {
  LD p = 0;
  for (std::size_t k = c.size(); k-- > 0;) p = p * t + c[k];
  return p;
}

std::vector<LD> sign_change_roots(std::vector<LD> c, std::vector<LD>* critical_out = nullptr) {
  while (!c.empty() && c.back() == 0) c.pop_back();
  const std::size_t n = c.empty() ? 0 : c.size() - 1;
  if (n == 0) return {};
  if (n == 1) return {-c[0] / c[1]};
  if (c[0] == 0) {  // t = 0 exactly (bisection would stop at a tiny nonzero number)
    std::vector<LD> roots = sign_change_roots(std::vector<LD>(c.begin() + 1, c.end()));
    if (std::find(roots.begin(), roots.end(), LD{0}) == roots.end()) roots.push_back(0);
    std::sort(roots.begin(), roots.end());
    if (critical_out != nullptr) {  // critical points of p itself
      std::vector<LD> d(n);
      for (std::size_t k = 1; k <= n; ++k) d[k - 1] = static_cast<LD>(k) * c[k];
      *critical_out = sign_change_roots(d);
    }
    return roots;
  }
  std::vector<LD> d(n);
  for (std::size_t k = 1; k <= n; ++k) d[k - 1] = static_cast<LD>(k) * c[k];
  const std::vector<LD> crit = sign_change_roots(d);
  if (critical_out != nullptr) *critical_out = crit;
  LD bound = 0;
  for (std::size_t k = 0; k < n; ++k) bound = std::max(bound, std::fabs(c[k] / c[n]));
  bound = 2 * (1 + bound);
  std::vector<LD> pts;
  pts.push_back(-bound);
  for (LD x : crit)
    if (x > -bound && x < bound) pts.push_back(x);
  pts.push_back(bound);
  std::vector<LD> roots;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    LD lo = pts[i];
    LD hi = pts[i + 1];
    LD plo = eval_poly(c, lo);
    const LD phi = eval_poly(c, hi);
    if (plo == 0) {
      if (roots.empty() || roots.back() != lo) roots.push_back(lo);
      continue;
    }
    if (phi == 0 || (plo < 0) == (phi < 0)) continue;
    for (int it = 0; it < 400; ++it) {
      const LD mid = lo + (hi - lo) / 2;
      if (!(mid > lo && mid < hi)) break;
      const LD pm = eval_poly(c, mid);
      if (pm == 0) {
        lo = hi = mid;
        break;
      }
      if ((pm < 0) == (plo < 0)) {
        lo = mid;
        plo = pm;
      } else {
        hi = mid;
      }
    }
    roots.push_back(lo + (hi - lo) / 2);
  }
  if (eval_poly(c, pts.back()) == 0) roots.push_back(pts.back());
  return roots;
}

template <std::size_t M>
Reference reference_roots(const std::array<double, M>& c) {
  std::vector<LD> cl(M);
  for (std::size_t k = 0; k < M; ++k) cl[k] = static_cast<LD>(c[k]);
  Reference ref;
  ref.roots = sign_change_roots(cl, &ref.critical);
  return ref;
}

// Compares a solver result with the reference. Returns false (and records
// nothing) when the case is numerically ambiguous: a critical value within
// 100x the tangency resolution of zero, where the root count is not
// determined by the coefficients' precision.
template <std::size_t N>
bool compare_with_reference(const std::array<double, N + 1>& c, const RealRoots<N>& got, const char* what) {
  const Reference ref = reference_roots(c);
  for (LD x : ref.critical)
    if (std::fabs(eval_ld(c, x)) <= 100 * kTol * bound_ld(c, x)) return false;
  EXPECT_EQ(got.count, static_cast<int>(ref.roots.size())) << what;
  if (got.count != static_cast<int>(ref.roots.size())) return true;
  for (std::size_t i = 0; i < ref.roots.size(); ++i) {
    const LD r = ref.roots[i];
    // First-order error of a simple root: eps * pbar(r) / |p'(r)|.
    const double cond_abs = static_cast<double>(bound_ld(c, r) / std::fabs(deriv_ld(c, r)));
    EXPECT_NEAR(got[i], static_cast<double>(r), 16 * kEps * cond_abs) << what << " root " << i;
  }
  return true;
}

// Ball-ball contact quartic |dr + dv t + da t^2/2|^2 - (2R)^2, ascending.
QuarticCoefficients contact_quartic(Vec2 dr, Vec2 dv, Vec2 da, double R) {
  return {dot(dr, dr) - 4 * R * R, 2 * dot(dr, dv), dot(dv, dv) + dot(dr, da), dot(dv, da), 0.25 * dot(da, da)};
}
double separation(Vec2 dr, Vec2 dv, Vec2 da, double t) { return norm(dr + dv * t + da * (0.5 * t * t)); }

// ---------------------------------------------------------------- quadratic

TEST(SolveQuadratic, RandomRootsAcrossScales) {
  std::mt19937_64 rng(101);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int it = 0; it < 20000; ++it) {
    const double scale = std::pow(10.0, -6.0 + 9.0 * (0.5 + 0.5 * u(rng)));
    std::array<double, 2> r{scale * u(rng), scale * std::pow(10.0, 3.0 * u(rng)) * u(rng)};
    if (r[0] == r[1]) continue;
    std::sort(r.begin(), r.end());
    const double lead = std::pow(10.0, 4.0 * u(rng));
    const auto c = from_roots(r, lead);
    const QuadraticRoots got = solve_quadratic(c);
    expect_well_formed(got);
    EXPECT_EQ(got.degree, 2);
    const bool resolvable = 32 * kEps * product_condition(r, 0) < 0.25 * std::fabs(r[1] - r[0]) / std::fabs(r[0]);
    if (!resolvable || !policy_separates(c, r)) continue;
    ASSERT_EQ(got.count, 2) << r[0] << " " << r[1];
    for (std::size_t i = 0; i < 2; ++i)
      EXPECT_NEAR(got[i], r[i], 32 * kEps * product_condition(r, i) * std::fabs(r[i])) << r[0] << " " << r[1];
  }
}

TEST(SolveQuadratic, NoCancellationForTheSmallRoot) {
  // t^2 + b t + 1 with huge b: roots ~ -b and ~ -1/b. The textbook formula
  // (-b + sqrt(b^2 - 4))/2 returns 0 or garbage for the small one.
  for (double b : {1e4, 1e8, 1e12, -1e15}) {
    const QuadraticRoots got = solve_quadratic({1.0, b, 1.0});
    ASSERT_EQ(got.count, 2);
    const double small = std::fabs(got[0]) < std::fabs(got[1]) ? got[0] : got[1];
    // Exact small root: -2 / (b + sign(b) sqrt(b^2 - 4)) = -1/b (1 + 1/b^2 + ...).
    const double expected = -1.0 / b * (1.0 + 1.0 / (b * b));
    EXPECT_NEAR(small, expected, 2 * kEps * std::fabs(expected)) << b;
  }
}

TEST(SolveQuadratic, DoubleRootIsReportedOnce) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> k(-4000, 4000);
  for (int it = 0; it < 2000; ++it) {
    // Dyadic r with a short mantissa: (t - r)^2 is exact in double.
    const double r = std::ldexp(static_cast<double>(k(rng)), -10 - (it % 20));
    const double lead = std::ldexp(1.0, (it % 7) - 3);
    const auto c = from_roots(std::array<double, 2>{r, r}, lead);
    const QuadraticRoots got = solve_quadratic(c);
    ASSERT_EQ(got.count, 1) << r;
    EXPECT_EQ(got[0], r);
  }
}

TEST(SolveQuadratic, RoundOffNegativeDiscriminantStillGrazes) {
  // (t - r)^2 + e: discriminant -4e. Within the tolerance band the double
  // root is reported (grazing contact); clearly outside it, nothing.
  for (double r : {1e-6, 0.37, 1.0, 250.0}) {
    const double band = kTol * 4.0 * r * r;  // |disc|/4 <= tol (3 b^2/4 + |ac|) = tol * 4 r^2 for a = 1
    for (double e : {0.25 * band, 0.9 * band}) {
      const QuadraticRoots got = solve_quadratic({r * r + e, -2.0 * r, 1.0});
      ASSERT_EQ(got.count, 1) << r << " " << e;
      EXPECT_NEAR(got[0], r, 4 * kEps * r);
    }
    EXPECT_EQ(solve_quadratic({r * r + 4.0 * band, -2.0 * r, 1.0}).count, 0) << r;
    EXPECT_EQ(solve_quadratic({r * r + 1e-6 * r * r, -2.0 * r, 1.0}).count, 0) << r;
    // Slightly positive discriminant beyond the band: two roots.
    const double d = 1e-3 * r;
    const QuadraticRoots two = solve_quadratic({r * r - d * d, -2.0 * r, 1.0});
    ASSERT_EQ(two.count, 2);
    EXPECT_NEAR(two[0], r - d, 1e-12 * r);
    EXPECT_NEAR(two[1], r + d, 1e-12 * r);
  }
}

TEST(SolveQuadratic, DegenerateDegrees) {
  const QuadraticCoefficients linear{3.0, -2.0, 0.0};
  const QuadraticRoots lin = solve_quadratic(linear);
  EXPECT_EQ(lin.degree, 1);
  ASSERT_EQ(lin.count, 1);
  EXPECT_EQ(lin[0], -linear[0] / linear[1]);
  const QuadraticRoots cst = solve_quadratic({3.0, 0.0, 0.0});
  EXPECT_EQ(cst.degree, 0);
  EXPECT_EQ(cst.count, 0);
  EXPECT_FALSE(cst.identically_zero());
  const QuadraticRoots zero = solve_quadratic({0.0, 0.0, 0.0});
  EXPECT_TRUE(zero.identically_zero());
  EXPECT_EQ(zero.degree, -1);
  EXPECT_EQ(zero.count, 0);
  const QuadraticRoots complex_pair = solve_quadratic({1.0, 0.0, 1.0});
  EXPECT_EQ(complex_pair.count, 0);
  const std::array<double, 2> r0{0.0, 2.0};  // exact zero root
  EXPECT_EQ(roots_vector(solve_quadratic(from_roots(r0, 2.0))), distinct_sorted(r0));
  expect_well_formed(lin);
  expect_well_formed(zero);
}

TEST(SolveQuadratic, ExtremeScalesAreRescaledNotOverflowed) {
  // b^2 overflows and a c underflows in the naive discriminant.
  for (double s : {1e-200, 1e-160, 1e160, 1e200}) {
    const std::array<double, 2> r{-3.0 * s, 0.5 * s};
    const QuadraticRoots got = solve_quadratic(from_roots(r, 1.0 / s));
    ASSERT_EQ(got.count, 2) << s;
    EXPECT_NEAR(got[0], r[0], 8 * kEps * std::fabs(r[0]));
    EXPECT_NEAR(got[1], r[1], 8 * kEps * std::fabs(r[1]));
  }
  const QuadraticRoots wide = solve_quadratic({1e-300, 1e300, 1.0});  // roots ~ -1e300, -1e-600 (underflows)
  ASSERT_GE(wide.count, 1);
  EXPECT_NEAR(wide[0], -1e300, 1e285);
}

// -------------------------------------------------------------------- cubic

TEST(SolveCubic, RandomRootsAcrossScalesAndClusters) {
  std::mt19937_64 rng(202);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int it = 0; it < 50000; ++it) {
    const double scale = std::pow(10.0, -6.0 + 9.0 * (0.5 + 0.5 * u(rng)));
    std::array<double, 3> r{};
    if (it % 3 == 0) {  // a cluster of two around a random centre
      const double centre = scale * u(rng);
      const double gap = std::pow(10.0, -7.0 + 5.0 * (0.5 + 0.5 * u(rng)));
      r = {centre, centre * (1.0 + gap), scale * std::pow(10.0, 3.0 * u(rng)) * u(rng)};
    } else {
      for (double& x : r) x = scale * std::pow(10.0, 3.0 * u(rng)) * u(rng);
    }
    std::sort(r.begin(), r.end());
    if (r[0] == r[1] || r[1] == r[2]) continue;
    const auto c = from_roots(r, std::pow(10.0, 3.0 * u(rng)));
    const CubicRoots got = solve_cubic(c);
    expect_well_formed(got);
    bool resolvable = true;
    for (std::size_t i = 0; i < 3; ++i) {
      const double gap = std::min(i > 0 ? r[i] - r[i - 1] : kInf, i < 2 ? r[i + 1] - r[i] : kInf);
      resolvable = resolvable && 32 * kEps * product_condition(r, i) * std::fabs(r[i]) < 0.25 * gap;
    }
    if (!resolvable || !policy_separates(c, r)) continue;
    ++checked;
    ASSERT_EQ(got.count, 3) << r[0] << " " << r[1] << " " << r[2];
    for (std::size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(got[i], r[i], 32 * kEps * product_condition(r, i) * std::fabs(r[i]))
          << r[0] << " " << r[1] << " " << r[2];
  }
  EXPECT_GT(checked, 40000);
}

TEST(SolveCubic, OneRealRootAndAComplexPair) {
  std::mt19937_64 rng(203);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int it = 0; it < 20000; ++it) {
    const double s = std::pow(10.0, 4.0 * u(rng));
    const double r = s * u(rng);
    const double re = s * u(rng);
    const double im = s * (0.01 + std::fabs(u(rng)));
    // (t - r)(t^2 - 2 re t + re^2 + im^2)
    const std::array<double, 3> q{re * re + im * im, -2.0 * re, 1.0};
    const CubicCoefficients c{-r * q[0], q[0] - r * q[1], q[1] - r, 1.0};
    const CubicRoots got = solve_cubic(c);
    ASSERT_EQ(got.count, 1) << r << " " << re << " " << im;
    const double cond = static_cast<double>(bound_ld(c, r) / std::fabs(deriv_ld(c, r)));
    EXPECT_NEAR(got[0], r, 32 * kEps * cond);
  }
}

TEST(SolveCubic, DoubleAndTripleRoots) {
  std::mt19937_64 rng(204);
  std::uniform_int_distribution<int> k(-2000, 2000);
  std::uniform_int_distribution<int> apart(16, 2000);
  for (int it = 0; it < 3000; ++it) {
    // Short dyadic mantissas: the expanded coefficients are exact.
    const int e = -8 - (it % 16);
    const double r = std::ldexp(static_cast<double>(k(rng)), e);
    const double s = r + std::ldexp(static_cast<double>((it % 2 ? 1 : -1) * apart(rng)), e);
    const auto c = from_roots(std::array<double, 3>{r, r, s});
    const CubicRoots dbl = solve_cubic(c);
    ASSERT_EQ(dbl.count, 2) << r << " " << s;
    // The simple root to full accuracy; the double root to ~sqrt(tol).
    const std::size_t is = s < r ? 0 : 1;
    EXPECT_NEAR(dbl[is], s, simple_root_tol(c, s)) << r << " " << s;
    EXPECT_NEAR(dbl[1 - is], r, double_root_tol(c, r)) << r << " " << s;
    // A triple root: (tol pbar)^(1/3) resolution; at least one root, all near.
    const auto c3 = from_roots(std::array<double, 3>{r, r, r});
    const CubicRoots triple = solve_cubic(c3);
    ASSERT_GE(triple.count, 1) << r;
    const double tol3 = 2 * std::cbrt(kTol * static_cast<double>(bound_ld(c3, r)));
    for (double x : triple) EXPECT_NEAR(x, r, tol3) << r;
  }
}

TEST(SolveCubic, DegenerateDegreesAndZeroRoot) {
  // Leading zero: the quadratic (t - 1)(t - 2), whose roots are exact.
  const std::array<double, 2> r2{1.0, 2.0};
  const CubicRoots q = solve_cubic(pad<4>(from_roots(r2)));
  EXPECT_EQ(q.degree, 2);
  EXPECT_EQ(roots_vector(q), distinct_sorted(r2));
  EXPECT_EQ(solve_cubic({5.0, 0.0, 0.0, 0.0}).degree, 0);
  EXPECT_TRUE(solve_cubic({0.0, 0.0, 0.0, 0.0}).identically_zero());
  // t (t - 1)(t + 2): exact zero root, deflated; the rest exact too.
  const std::array<double, 3> rz{0.0, 1.0, -2.0};
  EXPECT_EQ(roots_vector(solve_cubic(from_roots(rz))), distinct_sorted(rz));
  // t^2 (t - 3): zero is a double root, reported once.
  const std::array<double, 3> rz2{0.0, 0.0, 3.0};
  EXPECT_EQ(roots_vector(solve_cubic(from_roots(rz2))), distinct_sorted(rz2));
  // 2 t^3: one root.
  const std::array<double, 3> rz3{0.0, 0.0, 0.0};
  EXPECT_EQ(roots_vector(solve_cubic(from_roots(rz3, 2.0))), distinct_sorted(rz3));
}

TEST(SolveCubic, AgreesWithSlowReference) {
  std::mt19937_64 rng(205);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int compared = 0;
  const int cases = test::scaled(20000, 2000);
  for (int it = 0; it < cases; ++it) {
    const double s = std::pow(10.0, 4.5 * u(rng) - 1.5);  // root scale 1e-6 .. 1e3
    const double lead = std::pow(10.0, 3.0 * u(rng));
    CubicCoefficients c{};
    for (std::size_t k = 0; k < 4; ++k) c[k] = lead * n(rng) * std::pow(s, 3.0 - static_cast<double>(k));
    const CubicRoots got = solve_cubic(c);
    expect_well_formed(got);
    if (compare_with_reference<3>(c, got, "cubic")) ++compared;
  }
  EXPECT_GT(compared, cases * 99 / 100);
}

// ------------------------------------------------------------------ quartic

TEST(SolveQuartic, RandomRootsAcrossScalesAndClusters) {
  std::mt19937_64 rng(301);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  const int cases = 100000;
  for (int it = 0; it < cases; ++it) {
    const double scale = std::pow(10.0, -6.0 + 9.0 * (0.5 + 0.5 * u(rng)));  // 1e-6 .. 1e3
    std::array<double, 4> r{};
    for (double& x : r) x = scale * std::pow(10.0, 3.0 * u(rng)) * u(rng);
    if (it % 4 == 1) {  // a close pair
      r[1] = r[0] * (1.0 + std::pow(10.0, -7.0 + 6.0 * (0.5 + 0.5 * u(rng))));
    } else if (it % 4 == 2) {  // two close pairs
      r[1] = r[0] * (1.0 + std::pow(10.0, -6.0 + 5.0 * (0.5 + 0.5 * u(rng))));
      r[3] = r[2] * (1.0 - std::pow(10.0, -6.0 + 5.0 * (0.5 + 0.5 * u(rng))));
    } else if (it % 4 == 3) {  // a cluster of three
      const double g = std::pow(10.0, -4.0 + 3.0 * (0.5 + 0.5 * u(rng)));
      r[1] = r[0] * (1.0 + g);
      r[2] = r[0] * (1.0 + 2.5 * g);
    }
    std::sort(r.begin(), r.end());
    if (r[0] == r[1] || r[1] == r[2] || r[2] == r[3]) continue;
    const auto c = from_roots(r, std::pow(10.0, 3.0 * u(rng)));
    const QuarticRoots got = solve_quartic(c);
    expect_well_formed(got);
    EXPECT_EQ(got.degree, 4);
    bool resolvable = true;
    for (std::size_t i = 0; i < 4; ++i) {
      const double gap = std::min(i > 0 ? r[i] - r[i - 1] : kInf, i < 3 ? r[i + 1] - r[i] : kInf);
      resolvable = resolvable && 32 * kEps * product_condition(r, i) * std::fabs(r[i]) < 0.25 * gap;
    }
    if (!resolvable || !policy_separates(c, r)) continue;
    ++checked;
    ASSERT_EQ(got.count, 4) << r[0] << " " << r[1] << " " << r[2] << " " << r[3];
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_NEAR(got[i], r[i], 32 * kEps * product_condition(r, i) * std::fabs(r[i]))
          << r[0] << " " << r[1] << " " << r[2] << " " << r[3];
    }
  }
  EXPECT_GT(checked, cases * 9 / 10);
}

TEST(SolveQuartic, RealPairTimesComplexPair) {
  std::mt19937_64 rng(302);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int it = 0; it < 50000; ++it) {
    const double s = std::pow(10.0, -6.0 + 9.0 * (0.5 + 0.5 * u(rng)));
    std::array<double, 2> r{s * u(rng), s * std::pow(10.0, 2.0 * u(rng)) * u(rng)};
    std::sort(r.begin(), r.end());
    const double re = s * std::pow(10.0, 2.0 * u(rng)) * u(rng);
    const double im = std::fabs(re) * std::pow(10.0, -3.0 * (0.5 + 0.5 * u(rng))) + s * 1e-3;
    const auto pr = from_roots(r);
    const std::array<double, 3> pc{re * re + im * im, -2.0 * re, 1.0};
    QuarticCoefficients c{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) c[i + j] += pr[i] * pc[j];
    const QuarticRoots got = solve_quartic(c);
    expect_well_formed(got);
    // The complex pair is well off the axis (im >= 1e-3 |re|): no tangency.
    const bool resolvable = r[1] - r[0] > 1e-6 * std::max(std::fabs(r[0]), std::fabs(r[1]));
    if (!resolvable) continue;
    ASSERT_EQ(got.count, 2) << r[0] << " " << r[1] << " " << re << " " << im;
    for (std::size_t i = 0; i < 2; ++i) {
      const double cond = static_cast<double>(bound_ld(c, r[i]) / std::fabs(deriv_ld(c, r[i])));
      EXPECT_NEAR(got[i], r[i], 64 * kEps * cond) << r[0] << " " << r[1] << " " << re << " " << im;
    }
  }
}

TEST(SolveQuartic, ComplexOnlyQuarticsReportNone) {
  std::mt19937_64 rng(303);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int it = 0; it < 50000; ++it) {
    const double s = std::pow(10.0, -6.0 + 9.0 * (0.5 + 0.5 * u(rng)));
    QuarticCoefficients c{0, 0, 0, 0, 0};
    std::array<double, 3> f1{}, f2{};
    for (auto* f : {&f1, &f2}) {
      const double re = s * std::pow(10.0, 2.0 * u(rng)) * u(rng);
      const double im = std::fabs(re) * std::pow(10.0, -3.0 * (0.5 + 0.5 * u(rng))) + s * 1e-3;
      *f = {re * re + im * im, -2.0 * re, 1.0};
    }
    const double lead = std::pow(10.0, 3.0 * u(rng));
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) c[i + j] += lead * f1[i] * f2[j];
    const QuarticRoots got = solve_quartic(c);
    EXPECT_EQ(got.count, 0) << c[0] << " " << c[1] << " " << c[2] << " " << c[3] << " " << c[4];
    expect_well_formed(got);
  }
}

TEST(SolveQuartic, ExactDoubleRootsAreFoundOnce) {
  // Short dyadic roots make the expanded coefficients exact, so these really
  // are double roots; round-off inside the solver must not lose them.
  std::mt19937_64 rng(304);
  std::uniform_int_distribution<int> k(-1500, 1500);
  auto dy = [&](int e) { return std::ldexp(static_cast<double>(k(rng)), e); };
  for (int it = 0; it < 20000; ++it) {
    const int e = -8 - (it % 24);  // roots ~ 1e-8 .. 1
    const double r = dy(e);
    double s = dy(e);
    double v = dy(e);
    if (s == r) s += std::ldexp(3.0, e);
    if (v == r || v == s) v = r + s + std::ldexp(5.0, e);
    // (t - r)^2 (t - s)(t - v): three distinct roots, the first double.
    const auto c3 = from_roots(std::array<double, 4>{r, r, s, v});
    const QuarticRoots g3 = solve_quartic(c3);
    expect_well_formed(g3);
    std::array<double, 3> want{r, s, v};
    std::sort(want.begin(), want.end());
    ASSERT_EQ(g3.count, 3) << r << " " << s << " " << v;
    for (std::size_t i = 0; i < 3; ++i) {
      const double scale = std::max({std::fabs(r), std::fabs(s), std::fabs(v)});
      EXPECT_NEAR(g3[i], want[i], 1e-6 * scale) << r << " " << s << " " << v;
    }
    // (t - r)^2 (t - s)^2: two double roots.
    const QuarticRoots g22 = solve_quartic(from_roots(std::array<double, 4>{r, r, s, s}));
    ASSERT_EQ(g22.count, 2) << r << " " << s;
    EXPECT_NEAR(g22[0], std::min(r, s), 1e-6 * std::max(std::fabs(r), std::fabs(s)));
    EXPECT_NEAR(g22[1], std::max(r, s), 1e-6 * std::max(std::fabs(r), std::fabs(s)));
    // (t - r)^2 ((t - s)^2 + w^2): a grazing double root and a complex pair.
    const double w = std::fabs(dy(e)) + std::ldexp(1.0, e + 4);
    const auto pr = from_roots(std::array<double, 2>{r, r});
    const std::array<double, 3> pc{s * s + w * w, -2.0 * s, 1.0};
    QuarticCoefficients c{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) c[i + j] += pr[i] * pc[j];
    const QuarticRoots g = solve_quartic(c);
    ASSERT_EQ(g.count, 1) << r << " " << s << " " << w;
    EXPECT_NEAR(g[0], r, 1e-6 * std::max({std::fabs(r), std::fabs(s), w}));
  }
}

TEST(SolveQuartic, NearDoubleRootsResolvedOrMergedByThePolicy) {
  // (t - r)^2 - e times a well-separated quadratic: for e > 0 two roots
  // r +- sqrt(e), for e < 0 none, and within the tangency band one root.
  std::mt19937_64 rng(305);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int merged = 0, two = 0, none = 0;
  for (int it = 0; it < 20000; ++it) {
    const double s = std::pow(10.0, -3.0 + 5.0 * (0.5 + 0.5 * u(rng)));
    const double r = s * (0.5 + 0.5 * std::fabs(u(rng)));
    const double e = r * r * std::pow(10.0, -17.0 + 12.0 * (0.5 + 0.5 * u(rng))) * (u(rng) < 0 ? -1.0 : 1.0);
    const std::array<double, 3> f{r * r - e, -2.0 * r, 1.0};
    const std::array<double, 3> g{2.0 * s * s, 2.0 * s, 1.0};  // roots -s +- i s, far away
    QuarticCoefficients c{};
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) c[i + j] += f[i] * g[j];
    const QuarticRoots got = solve_quartic(c);
    expect_well_formed(got);
    // The policy's quantity at the pair's centre, in long double.
    const LD level = std::fabs(eval_ld(c, r)) / bound_ld(c, r);
    if (level < 0.5L * static_cast<LD>(kTol)) {
      // Inside the band: one (double) root near r, whatever the sign of e.
      ASSERT_EQ(got.count, 1) << r << " " << e;
      EXPECT_NEAR(got[0], r, 4 * std::sqrt(std::fabs(e)) + 1e-6 * r);
      ++merged;
    } else if (level > 2.0L * static_cast<LD>(kTol) && std::fabs(e) > 1e-12 * r * r) {
      if (e > 0) {
        ASSERT_EQ(got.count, 2) << r << " " << e;
        const double d = std::sqrt(e);
        const double tol = 64 * kEps * r * r / d;
        EXPECT_NEAR(got[0], r - d, tol) << r << " " << e;
        EXPECT_NEAR(got[1], r + d, tol) << r << " " << e;
        ++two;
      } else {
        EXPECT_EQ(got.count, 0) << r << " " << e;
        ++none;
      }
    }
  }
  EXPECT_GT(merged, 1000);
  EXPECT_GT(two, 1000);
  EXPECT_GT(none, 1000);
}

TEST(SolveQuartic, SymmetricAndBiquadraticQuartics) {
  // p(t) = q((t - c)^2) with q(y) = (y - A)(y - B): roots c +- sqrt(A),
  // c +- sqrt(B) (complex for a negative A or B). The two quadratic factors
  // share their linear coefficient, so the LDL^T pivot d2 is exactly zero
  // and comes out as round-off of either sign: the "case III" branch. With
  // c = 0 these are biquadratics, which ball-ball quartics become when
  // dr.dv = 0 and dv.da = 0.
  std::mt19937_64 rng(310);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int it = 0; it < 40000; ++it) {
    const double s = std::pow(10.0, -4.0 + 6.0 * (0.5 + 0.5 * u(rng)));
    const double c = it % 3 == 0 ? 0.0 : s * 10.0 * u(rng) * std::pow(10.0, -2.0 * (0.5 + 0.5 * u(rng)));
    const double A = s * s * (0.01 + 0.99 * std::fabs(u(rng))) * (u(rng) < 0.0 ? -1.0 : 1.0);
    const double B = s * s * (0.01 + 0.99 * std::fabs(u(rng))) * (u(rng) < 0.0 ? -1.0 : 1.0);
    if (std::fabs(A - B) < 0.05 * s * s) continue;
    // (t^2 - 2ct + c^2)^2 - (A + B)(t^2 - 2ct + c^2) + AB
    const double y0 = c * c;
    const double y1 = -2.0 * c;
    const QuarticCoefficients p{y0 * y0 - (A + B) * y0 + A * B, 2.0 * y0 * y1 - (A + B) * y1,
                                y1 * y1 + 2.0 * y0 - (A + B), 2.0 * y1, 1.0};
    std::vector<double> want;
    for (double v : {A, B})
      if (v > 0.0) {
        want.push_back(c - std::sqrt(v));
        want.push_back(c + std::sqrt(v));
      }
    std::sort(want.begin(), want.end());
    const QuarticRoots got = solve_quartic(p);
    expect_well_formed(got);
    ASSERT_EQ(got.count, static_cast<int>(want.size())) << "c=" << c << " A=" << A << " B=" << B;
    // want[] are the roots for exact c, A, B; compare with the roots of the
    // rounded coefficients actually passed.
    for (std::size_t i = 0; i < want.size(); ++i) {
      const double exact = exact_root_near(p, want[i]);
      EXPECT_NEAR(got[i], exact, simple_root_tol(p, exact)) << "c=" << c << " A=" << A << " B=" << B;
    }
    ++checked;
  }
  EXPECT_GT(checked, 30000);
}

TEST(SolveQuartic, AgreesWithSlowReference) {
  std::mt19937_64 rng(306);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int compared = 0;
  const int cases = test::scaled(40000, 4000);
  for (int it = 0; it < cases; ++it) {
    const double s = std::pow(10.0, 4.5 * u(rng) - 1.5);  // root scale 1e-6 .. 1e3
    const double lead = std::pow(10.0, 3.0 * u(rng));
    QuarticCoefficients c{};
    for (std::size_t k = 0; k < 5; ++k) c[k] = lead * n(rng) * std::pow(s, 4.0 - static_cast<double>(k));
    const QuarticRoots got = solve_quartic(c);
    expect_well_formed(got);
    if (compare_with_reference<4>(c, got, "quartic")) ++compared;
  }
  EXPECT_GT(compared, cases * 99 / 100);
}

TEST(SolveQuartic, WideDynamicRangeAgreesWithSlowReference) {
  // Coefficients whose magnitudes vary independently over 1e-10 .. 1e10:
  // roots spread over dozens of orders of magnitude. The fast factorization
  // cannot always be certified here, and the isolation fallback takes over.
  std::mt19937_64 rng(311);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int compared = 0;
  const int cases = test::scaled(20000, 2000);
  for (int it = 0; it < cases; ++it) {
    QuarticCoefficients c{};
    for (double& x : c) x = n(rng) * std::pow(10.0, 10.0 * u(rng));
    const QuarticRoots got = solve_quartic(c);
    expect_well_formed(got);
    if (compare_with_reference<4>(c, got, "wide")) ++compared;
  }
  EXPECT_GT(compared, cases * 99 / 100);
}

TEST(SolveQuartic, RootsOnThreeScalesTouchingNowAndFarFuture) {
  // A tiny root (~1e-16..1e-20, e.g. a pair touching now), two ordinary ones
  // and a huge one (~1e16..1e20, nearly equal accelerations): the roots span
  // 32-40 orders of magnitude. The factorization alone gets a few percent of
  // these wrong; its backward-error certificate must catch every one and hand
  // it to the isolation fallback.
  std::mt19937_64 rng(312);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int it = 0; it < 20000; ++it) {
    const double sign_tiny = u(rng) < 0.0 ? -1.0 : 1.0;
    const double sign_huge = u(rng) < 0.0 ? -1.0 : 1.0;
    std::array<double, 4> r{sign_tiny * std::pow(10.0, -18.0 + 2.0 * u(rng)), u(rng), u(rng),
                            sign_huge * std::pow(10.0, 18.0 + 2.0 * u(rng))};
    std::sort(r.begin(), r.end());
    if (std::fabs(r[1] - r[2]) < 1e-3 || r[0] == r[1] || r[2] == r[3]) continue;
    const auto c = from_roots(r);
    const QuarticRoots got = solve_quartic(c);
    expect_well_formed(got);
    ASSERT_EQ(got.count, 4) << r[0] << " " << r[1] << " " << r[2] << " " << r[3];
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_NEAR(got[i], r[i], 32 * kEps * product_condition(r, i) * std::fabs(r[i]))
          << r[0] << " " << r[1] << " " << r[2] << " " << r[3];
  }
}

TEST(SolveQuartic, ResidualsAreAtRoundOffLevel) {
  // Every reported root satisfies |p(x)| <= C eps sum |c_k| |x|^k: Newton-
  // polished simple roots at a few ulps, policy roots within the tolerance.
  std::mt19937_64 rng(307);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int it = 0; it < 40000; ++it) {
    const double s = std::pow(10.0, 4.5 * u(rng) - 1.5);
    QuarticCoefficients c{};
    for (std::size_t k = 0; k < 5; ++k) c[k] = n(rng) * std::pow(s, 4.0 - static_cast<double>(k));
    for (double x : solve_quartic(c))
      EXPECT_LE(std::fabs(eval_ld(c, x)), (kTol + 8 * kEps) * bound_ld(c, x)) << x;
  }
}

TEST(SolveQuartic, DegenerateDegreesDispatchOnTheTrueDegree) {
  // Leading zeros: solve_quartic must agree with the lower-degree solver.
  const std::array<double, 3> roots3{1.0, 2.0, 3.0};
  const auto c3 = from_roots(roots3);
  const QuarticRoots r3 = solve_quartic(pad<5>(c3));
  EXPECT_EQ(r3.degree, 3);
  EXPECT_EQ(roots_vector(r3), roots_vector(solve_cubic(c3)));
  ASSERT_EQ(r3.count, 3);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(r3[i], roots3[i], simple_root_tol(c3, roots3[i]));
  const auto c2 = from_roots(std::array<double, 2>{1.0, 2.0});
  const QuarticRoots r2 = solve_quartic(pad<5>(c2));
  EXPECT_EQ(r2.degree, 2);
  EXPECT_EQ(roots_vector(r2), roots_vector(solve_quadratic(c2)));
  const QuarticCoefficients c1{2.0, -4.0, 0.0, 0.0, 0.0};
  const QuarticRoots r1 = solve_quartic(c1);
  EXPECT_EQ(r1.degree, 1);
  ASSERT_EQ(r1.count, 1);
  EXPECT_EQ(r1[0], -c1[0] / c1[1]);
  const QuarticRoots r0 = solve_quartic({2.0, 0.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(r0.degree, 0);
  EXPECT_EQ(r0.count, 0);
  EXPECT_FALSE(r0.identically_zero());
  const QuarticRoots rz = solve_quartic({0.0, 0.0, 0.0, 0.0, 0.0});
  EXPECT_TRUE(rz.identically_zero());
  EXPECT_EQ(rz.count, 0);
  expect_well_formed(rz);
  // Exact zero roots are deflated: t^2 (t - 1)(t + 1) and 3 t^4.
  const std::array<double, 4> zeros2{0.0, 0.0, 1.0, -1.0};
  EXPECT_EQ(roots_vector(solve_quartic(from_roots(zeros2))), distinct_sorted(zeros2));
  const std::array<double, 4> rz4{0.0, 0.0, 0.0, 0.0};
  EXPECT_EQ(roots_vector(solve_quartic(from_roots(rz4, 3.0))), distinct_sorted(rz4));
  // Non-finite input: no roots.
  EXPECT_EQ(solve_quartic({1.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 1.0}).count, 0);
  EXPECT_EQ(solve_quartic({-1.0, 0.0, 0.0, 0.0, kInf}).count, 0);
  EXPECT_EQ(solve_cubic({-1.0, 0.0, std::numeric_limits<double>::quiet_NaN(), 1.0}).count, 0);
  EXPECT_EQ(solve_quadratic({-1.0, kInf, 1.0}).count, 0);
}

TEST(SolveQuartic, TinyLeadingCoefficientKeepsTheSmallRoots) {
  // prod (t - r_i) with two moderate roots and two huge ones: the leading
  // coefficient is tiny relative to the others, and must not be dropped.
  for (double big : {1e6, 1e9, 1e12, 1e15}) {
    const std::array<double, 4> r{-2.5 * big, 0.125, 0.75, big};
    const QuarticRoots got = solve_quartic(from_roots(r, 1.0 / (big * big)));
    ASSERT_EQ(got.count, 4) << big;
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_NEAR(got[i], r[i], 32 * kEps * product_condition(r, i) * std::fabs(r[i])) << big;
  }
}

TEST(SolveQuartic, PowerOfTwoScalingCommutesIncludingTheRescaledPath) {
  // t -> 2^e t scales the roots exactly: c_k -> c_k 2^((2-k) e) (the factor
  // 2^(2e) on the whole polynomial keeps every coefficient finite for |e| up
  // to 500, where the monic coefficients c_k/c_4 overflow). |e| > 80
  // exercises the exact power-of-two rescaling used outside 2^-80..2^80. The
  // solvers' arithmetic is homogeneous, so results agree to the last bits
  // (not bitwise: libm's cbrt is not exactly scale-equivariant).
  std::mt19937_64 rng(308);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int it = 0; it < 2000; ++it) {
    QuarticCoefficients c{};
    for (double& x : c) x = n(rng);
    const CubicCoefficients c3{c[0], c[1], c[2], c[3]};
    const QuarticRoots base = solve_quartic(c);
    const CubicRoots base3 = solve_cubic(c3);
    for (int e : {-500, -230, -150, -81, -9, 7, 64, 100, 200, 500}) {
      QuarticCoefficients cs{};
      CubicCoefficients cs3{};
      for (std::size_t k = 0; k < 5; ++k) cs[k] = std::ldexp(c[k], (2 - static_cast<int>(k)) * e);
      for (std::size_t k = 0; k < 4; ++k) cs3[k] = std::ldexp(c3[k], (2 - static_cast<int>(k)) * e);
      const QuarticRoots scaled = solve_quartic(cs);
      const CubicRoots scaled3 = solve_cubic(cs3);
      ASSERT_EQ(scaled.count, base.count) << e;
      ASSERT_EQ(scaled3.count, base3.count) << e;
      for (std::size_t i = 0; i < static_cast<std::size_t>(base.count); ++i)
        EXPECT_NEAR(std::ldexp(scaled[i], -e), base[i], simple_root_tol(c, base[i], 4)) << e;
      for (std::size_t i = 0; i < static_cast<std::size_t>(base3.count); ++i)
        EXPECT_NEAR(std::ldexp(scaled3[i], -e), base3[i], simple_root_tol(c3, base3[i], 4)) << e;
    }
  }
}

// ------------------------------------------------------ ball-ball contact

TEST(BallBallQuartic, EqualAccelerationsDegenerateToTheQuadratic) {
  std::mt19937_64 rng(401);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 0.028575;
  int hits = 0;
  for (int it = 0; it < 20000; ++it) {
    const Vec2 dr{1.2 * u(rng), 0.6 * u(rng)};
    if (norm(dr) <= 2 * R) continue;
    const Vec2 dv{3.0 * u(rng), 3.0 * u(rng)};
    const QuarticCoefficients c = contact_quartic(dr, dv, {0.0, 0.0}, R);
    ASSERT_EQ(c[4], 0.0);
    ASSERT_EQ(c[3], 0.0);
    const QuarticRoots got = solve_quartic(c);
    EXPECT_EQ(got.degree, 2);
    EXPECT_EQ(roots_vector(got), roots_vector(solve_quadratic({c[0], c[1], c[2]})));
    // Straight-line contact times from geometry: |dr + dv t| = 2R.
    const double a = dot(dv, dv);
    const double b = dot(dr, dv);
    const double disc = b * b - a * (dot(dr, dr) - 4 * R * R);
    if (disc > 1e-9 * b * b) {
      ASSERT_EQ(got.count, 2);
      ++hits;
      for (double t : got) EXPECT_NEAR(separation(dr, dv, {0, 0}, t), 2 * R, 1e-12);
    } else if (disc < -1e-9 * b * b) {
      EXPECT_EQ(got.count, 0);
    }
  }
  EXPECT_GT(hits, 1000);
}

TEST(BallBallQuartic, ContactTimesHaveTheRightSeparation) {
  std::mt19937_64 rng(402);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 0.028575;
  int hits = 0;
  const int cases = test::scaled(50000, 5000);
  for (int it = 0; it < cases; ++it) {
    const Vec2 dr{1.2 * u(rng), 0.6 * u(rng)};
    if (norm(dr) <= 2 * R) continue;
    const Vec2 dv{4.0 * u(rng), 4.0 * u(rng)};
    const Vec2 da{2.5 * u(rng), 2.5 * u(rng)};
    const QuarticCoefficients c = contact_quartic(dr, dv, da, R);
    const QuarticRoots got = solve_quartic(c);
    expect_well_formed(got);
    if (compare_with_reference<4>(c, got, "contact")) {
      for (double t : got) {
        // d|d|/dt = d.d'/|d|: the separation error is the time error times
        // the normal speed, which is what the accuracy bound allows.
        const Vec2 d = dr + dv * t + da * (0.5 * t * t);
        const Vec2 dd = dv + da * t;
        const double normal_speed = std::fabs(dot(d, dd)) / norm(d);
        const double cond_abs = static_cast<double>(bound_ld(c, t) / std::fabs(deriv_ld(c, t)));
        EXPECT_NEAR(separation(dr, dv, da, t), 2 * R, 16 * kEps * cond_abs * normal_speed + 1e-15);
        ++hits;
      }
    }
  }
  EXPECT_GT(hits, cases / 50);
}

TEST(BallBallQuartic, GrazingContactIsReportedAndANearMissIsNot) {
  // Tangency by construction: at t* the relative position is 2R n and the
  // relative velocity u is perpendicular to n, with |d|^2 at a minimum.
  std::mt19937_64 rng(403);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 0.028575;
  int grazes = 0;
  for (int it = 0; it < 20000; ++it) {
    const double ts = 0.05 + 2.0 * (0.5 + 0.5 * u(rng));
    const double ang = 3.14159 * u(rng);
    const Vec2 n{std::cos(ang), std::sin(ang)};
    const Vec2 tangential = perp(n) * (0.05 + 2.0 * u(rng));
    Vec2 da{1.5 * u(rng), 1.5 * u(rng)};
    if (it % 5 == 0) da = {0.0, 0.0};  // straight lines: degenerates to a quadratic
    if (dot(tangential, tangential) + 2 * R * dot(n, da) <= 0.05) continue;  // need a strict minimum
    const Vec2 dv = tangential - da * ts;
    const Vec2 contact = n * (2 * R);
    for (double gap : {0.0, 1e-7, -1e-7}) {
      const Vec2 at = contact + n * gap;
      const Vec2 dr = at - dv * ts - da * (0.5 * ts * ts);
      const QuarticCoefficients c = contact_quartic(dr, dv, da, R);
      const QuarticRoots got = solve_quartic(c);
      expect_well_formed(got);
      EXPECT_EQ(got.degree, it % 5 == 0 ? 2 : 4);
      // Roots near t*: within the policy's double-root resolution of t*.
      const double curvature = 0.5 * static_cast<double>(std::fabs(2 * dot(tangential, tangential) + 4 * R * dot(n, da)));
      const double window = std::sqrt(4 * kTol * static_cast<double>(bound_ld(c, ts)) / curvature);
      // Roots belonging to this contact: within the overlap case's spread.
      const double spread = 2 * std::sqrt(4 * R * 1e-7 / curvature) + 1e-6;
      std::vector<double> near;
      for (double t : got)
        if (std::fabs(t - ts) < spread) near.push_back(t);
      if (gap == 0.0) {
        ASSERT_EQ(near.size(), 1u) << "graze at " << ts << " missed";
        EXPECT_NEAR(near[0], ts, window);
        ++grazes;
        // The smallest-root helper finds it too.
        const auto first = smallest_root_in(c, 0.0, ts + 1.0);
        ASSERT_TRUE(first.has_value());
        EXPECT_LE(*first, near[0]);
      } else if (gap > 0.0) {
        EXPECT_TRUE(near.empty()) << "near miss by " << gap << " reported as contact";
      } else {
        ASSERT_EQ(near.size(), 2u) << "shallow overlap by " << -gap << " lost";
        EXPECT_NEAR(separation(dr, dv, da, near[0]), 2 * R, 1e-12);
        EXPECT_NEAR(separation(dr, dv, da, near[1]), 2 * R, 1e-12);
      }
    }
  }
  EXPECT_GT(grazes, 10000);
}

TEST(BallBallQuartic, NearlyEqualAccelerationsMatchTheStraightLineTimes) {
  // da tiny but nonzero: the quartic's leading coefficient is ~1e-20 of the
  // others. The physical contact times must equal the da = 0 ones to first
  // order, not be lost to a degree-drop threshold.
  std::mt19937_64 rng(404);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 0.028575;
  int hits = 0;
  for (int it = 0; it < 5000; ++it) {
    const Vec2 dr{1.2 * u(rng), 0.6 * u(rng)};
    if (norm(dr) <= 2 * R) continue;
    const Vec2 dv{3.0 * u(rng), 3.0 * u(rng)};
    const Vec2 da{1e-10 * u(rng), 1e-10 * u(rng)};
    const QuarticRoots straight = solve_quartic(contact_quartic(dr, dv, {0.0, 0.0}, R));
    const QuarticRoots got = solve_quartic(contact_quartic(dr, dv, da, R));
    EXPECT_EQ(got.degree, 4);
    // The straight-line roots reappear, moved by first-order perturbation
    // theory: dt = -dp(t)/p'(t) with dp = dr.da t^2 + dv.da t^3 + |da|^2/4 t^4
    // (the other two roots are ~1e10 s away).
    for (double t : straight) {
      if (std::fabs(t) > 10.0) continue;
      const double slope = 2 * dot(dr + dv * t, dv);  // p'(t) of the straight-line quadratic
      if (std::fabs(slope) < 1e-3 * dot(dv, dv)) continue;  // near-grazing: first order does not apply
      const double dp = t * t * (dot(dr, da) + t * (dot(dv, da) + 0.25 * t * dot(da, da)));
      const double expected = t - dp / slope;
      double best = kInf;
      for (double x : got) best = std::min(best, std::fabs(x - expected));
      EXPECT_LT(best, 1e-12 * (1.0 + std::fabs(t)) + 32 * kEps * static_cast<double>(bound_ld(contact_quartic(dr, dv, da, R), t)) / std::fabs(slope)) << t;
      ++hits;
    }
  }
  EXPECT_GT(hits, 500);
}

TEST(BallBallQuartic, JustAfterContactWithNearlyEqualAccelerations) {
  // The hard case right after a collision: the pair touches (|dr| = 2R, so
  // the constant term is round-off, ~1e-18) while the accelerations differ
  // by round-off (~1e-15 m/s^2, so the leading coefficient is ~1e-31). The
  // roots then spread from ~1e-18 s to ~1e15 s.
  std::mt19937_64 rng(405);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 0.028575;
  int compared = 0;
  const int cases = test::scaled(20000, 2000);
  for (int it = 0; it < cases; ++it) {
    const double ang = 3.14159 * u(rng);
    const Vec2 dr = Vec2{std::cos(ang), std::sin(ang)} * (2 * R);
    const Vec2 dv{2.0 * u(rng), 2.0 * u(rng)};
    const Vec2 da = Vec2{u(rng), u(rng)} * std::pow(10.0, -15.0 + 3.0 * u(rng));
    const QuarticCoefficients c = contact_quartic(dr, dv, da, R);  // c[0] is often exactly 0: deflated
    const QuarticRoots got = solve_quartic(c);
    expect_well_formed(got);
    if (compare_with_reference<4>(c, got, "after contact")) ++compared;
  }
  EXPECT_GT(compared, cases * 95 / 100);
}

// --------------------------------------------------- smallest root in [a, b]

TEST(SmallestRootIn, PicksTheEarliestRootInsideTheWindow) {
  const std::array<double, 4> r{-1.0, 0.5, 2.0, 3.0};
  const QuarticCoefficients c = from_roots(r);
  const QuarticRoots all = solve_quartic(c);
  ASSERT_EQ(all.count, 4);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(all[i], r[i], 8 * kEps);
  EXPECT_EQ(smallest_root_in(c, 0.0, 10.0), std::optional<double>(all[1]));
  EXPECT_EQ(smallest_root_in(c, 0.6, 10.0), std::optional<double>(all[2]));
  EXPECT_EQ(smallest_root_in(c, -5.0, 10.0), std::optional<double>(all[0]));
  EXPECT_EQ(smallest_root_in(c, 0.6, 1.9), std::nullopt);
  EXPECT_EQ(smallest_root_in(c, 3.5, 10.0), std::nullopt);
  // Closed window: end points count.
  EXPECT_EQ(smallest_root_in(c, all[2], all[2]), std::optional<double>(all[2]));
  EXPECT_EQ(smallest_root_in(c, 0.0, all[1]), std::optional<double>(all[1]));
  EXPECT_EQ(smallest_root_in(c, all[3], 10.0), std::optional<double>(all[3]));
  EXPECT_EQ(smallest_root_in(c, std::nextafter(all[3], 10.0), 10.0), std::nullopt);
  // Empty or NaN window.
  EXPECT_EQ(smallest_root_in(c, 1.0, 0.0), std::nullopt);
  EXPECT_EQ(smallest_root_in(c, std::numeric_limits<double>::quiet_NaN(), 10.0), std::nullopt);
  // Identically zero: every t is a root, the earliest is t_min.
  EXPECT_EQ(smallest_root_in(QuarticCoefficients{0, 0, 0, 0, 0}, 0.25, 1.0), std::optional<double>(0.25));
  // Lower degrees go through the same dispatch.
  const QuadraticCoefficients q{2.0, -3.0, 1.0};  // roots 1, 2
  EXPECT_EQ(smallest_root_in(q, 1.5, 9.0), std::optional<double>(solve_quadratic(q)[1]));
  const CubicCoefficients cu{-6.0, 11.0, -6.0, 1.0};  // roots 1, 2, 3
  EXPECT_EQ(smallest_root_in(cu, 1.5, 2.5), std::optional<double>(solve_cubic(cu)[1]));
  EXPECT_EQ(smallest_root_in(QuarticCoefficients{2.0, -3.0, 1.0, 0.0, 0.0}, 1.5, 9.0),
            smallest_root_in(q, 1.5, 9.0));
  EXPECT_EQ(smallest_root_in(QuadraticCoefficients{1.0, 0.0, 1.0}, -9.0, 9.0), std::nullopt);
}

// What smallest_root_in must return: the first root of the full solve that
// lies in the closed window.
std::optional<double> first_root_in(const QuarticRoots& all, double lo, double hi) {
  if (!(lo <= hi)) return std::nullopt;
  if (all.identically_zero()) return lo;
  for (double x : all)
    if (x >= lo && x <= hi) return x;
  return std::nullopt;
}

TEST(SmallestRootIn, AgreesWithTheFullSolveOnRandomWindows) {
  std::mt19937_64 rng(501);
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int found = 0;
  for (int it = 0; it < 20000; ++it) {
    QuarticCoefficients c{};
    for (double& x : c) x = n(rng);
    double lo = u(rng);
    double hi = u(rng);
    if (lo > hi) std::swap(lo, hi);
    const auto got = smallest_root_in(c, lo, hi);
    EXPECT_EQ(got, first_root_in(solve_quartic(c), lo, hi));
    found += got.has_value();
  }
  EXPECT_GT(found, 2000);
}

TEST(SmallestRootIn, WindowsEndingAtRootsAndGrazesAgreeWithTheFullSolve) {
  // smallest_root_in first tries to prove that p keeps one sign on the window
  // (Bernstein bounds) and skips the solve when it can; that shortcut must
  // never hide a root the solver reports, however close the root is to the
  // window's ends, and however flat p is there (grazing).
  std::mt19937_64 rng(502);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double R = 0.028575;
  int checked = 0;
  for (int it = 0; it < 20000; ++it) {
    QuarticCoefficients c{};
    if (it % 2 == 0) {  // ball-ball contact, sometimes grazing
      const double ts = 0.05 + 1.5 * (0.5 + 0.5 * u(rng));
      const double ang = 3.14159 * u(rng);
      const Vec2 nrm{std::cos(ang), std::sin(ang)};
      const Vec2 tangential = perp(nrm) * (0.3 + 2.0 * std::fabs(u(rng)));
      const Vec2 da{0.5 * u(rng), 0.5 * u(rng)};
      const Vec2 dv = tangential - da * ts;
      const double gap = (it % 4 == 0) ? 0.0 : 1e-4 * u(rng);
      const Vec2 dr = nrm * (2 * R + gap) - dv * ts - da * (0.5 * ts * ts);
      c = contact_quartic(dr, dv, da, R);
    } else {
      const std::array<double, 4> r{u(rng), u(rng), u(rng), u(rng)};
      c = from_roots(r, std::pow(10.0, 3.0 * u(rng)));
    }
    const QuarticRoots all = solve_quartic(c);
    for (double x : all) {
      const double w = std::pow(10.0, -12.0 + 11.0 * (0.5 + 0.5 * u(rng)));
      const double below = std::nextafter(x, -kInf);
      const double above = std::nextafter(x, kInf);
      const std::array<std::array<double, 2>, 7> windows{{{x, x},
                                                          {x - w, x},
                                                          {x, x + w},
                                                          {x - w, below},
                                                          {above, x + w},
                                                          {x - w, x + w},
                                                          {0.0, x}}};
      for (const auto& win : windows) {
        EXPECT_EQ(smallest_root_in(c, win[0], win[1]), first_root_in(all, win[0], win[1]))
            << "window [" << win[0] << ", " << win[1] << "] root " << x;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 50000);
}

}  // namespace
}  // namespace cueball
