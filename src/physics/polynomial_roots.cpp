// Real polynomial roots: see include/cueball/physics/polynomial_roots.hpp for the API,
// the tolerance policy and the references.
//
// Layout of this file:
//  1. small helpers: monic evaluation, guarded Newton polish, the candidate
//     buffer with its sort-and-merge step, exact power-of-two equilibration;
//  2. the quadratic-factor step shared by the cubic and the quartic (stable
//     formula + the double-root policy);
//  3. the fallback: root isolation between critical points + bisection;
//  4. the cubic kernel (dominant root of the depressed cubic, polish,
//     Kahan-style deflation);
//  5. the quartic kernel (Orellana & De Michele 2020, Algorithm 1010, with a
//     backward-error certificate);
//  6. the public entry points: degree dispatch, zero-root deflation, range
//     check and rescaling; smallest_root_in with its Bernstein exclusion.
//
// Internally the cubic and quartic kernels work on the monic polynomial
// x^n + m[n-1] x^(n-1) + ... + m[0] (m[k] = c[k]/c[n], one rounding each);
// the policy tests and the Newton polish evaluate that monic polynomial.
#include "cueball/physics/polynomial_roots.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cstdint>
#include <cmath>
#include <complex>

namespace cueball {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kThird = 1.0 / 3.0;
constexpr double kInf = std::numeric_limits<double>::infinity();

// A quadratic factor whose discriminant is within this fraction of
// h^2 + |beta| (roots within ~2^-14 relative of each other) is tested as a
// candidate double root; the decision itself is the |p(m)| <= tol * pbar(m)
// test. Adjacent roots closer than kMergeGap (relative) are merge candidates.
constexpr double kClosePair = 0x1p-28;
constexpr double kMergeGap = 0x1p-14;
// A real quadratic factor of the quartic whose discriminant is below
// -kSurelyComplex * (h^2 + |beta|) has a complex pair that no refinement can
// make real; refining a factorization with two such factors is skipped.
constexpr double kSurelyComplex = 0x1p-20;
constexpr double kTrustedFactorization = 0x1p-30;
// A quartic factorization whose backward error (see factorization_within)
// exceeds this after refinement is not trusted: the robust fallback solves.
// Unrefined factorizations with both factors surely complex must meet the
// tighter kTrustedFactorization to skip refinement.
constexpr double kCertify = 0x1p-24;
// Relative size below which the quartic's LDL^T pivot d2 is round-off.
constexpr double kD2Noise = 64.0 * std::numeric_limits<double>::epsilon();

// Maximum guarded Newton steps when polishing a root on the full polynomial.
constexpr int kPolishSteps = 3;
constexpr double kPolishConverged = 0x1p-26;
// ... and for the cubic's first root, which may start far off (see there);
// after polishing it must be a root to within this (relative to pbar), or
// the fallback solves the cubic.
constexpr int kRootPolishSteps = 8;
constexpr double kCubicRootCheck = 0x1p-40;

// Fast path: root scale within 2^-80..2^80, so that the quartic's weight-12
// intermediates (squares of the resolvent's weight-6 coefficient) stay normal.
constexpr double kScaleHi = 0x1p80;
constexpr double kScaleLo = 0x1p-80;

// ------------------------------------------------------------------ helpers

// Value of the monic polynomial x^N + m[N-1] x^(N-1) + ... + m[0].
template <int N>
inline double eval_monic(const double* m, double x) noexcept {
  double p = 1.0;
  for (int k = N - 1; k >= 0; --k) p = p * x + m[k];
  return p;
}

// Value and derivative of the monic polynomial.
template <int N>
inline void eval_monic_d(const double* m, double x, double& p, double& dp) noexcept {
  p = 1.0;
  dp = 0.0;
  for (int k = N - 1; k >= 0; --k) {
    dp = dp * x + p;
    p = p * x + m[k];
  }
}

// The policy test: does p vanish at x to within tol * sum |m_k| |x|^k?
template <int N>
inline bool numerically_zero(const double* m, double x, double tol) noexcept {
  const double ax = std::fabs(x);
  double p = 1.0;
  double bound = 1.0;
  for (int k = N - 1; k >= 0; --k) {
    p = p * x + m[k];
    bound = bound * ax + std::fabs(m[k]);
  }
  return std::fabs(p) <= tol * bound;
}

// Guarded Newton on the full monic polynomial: a step is kept only if it
// strictly reduces |p|, so a polish can never walk away from a root. Stops
// early once a step is below sqrt(eps) relative: Newton converges
// quadratically, so the next one would only move round-off.
template <int N, int Steps = kPolishSteps>
inline double polish(const double* m, double x) noexcept {
  double p = 0.0;
  double dp = 0.0;
  eval_monic_d<N>(m, x, p, dp);
  for (int it = 0; it < Steps; ++it) {
    if (p == 0.0 || dp == 0.0) break;
    const double dx = p / dp;
    const double xn = x - dx;
    double pn = 0.0;
    double dpn = 0.0;
    eval_monic_d<N>(m, xn, pn, dpn);
    if (!(std::fabs(pn) < std::fabs(p))) break;
    x = xn;
    p = pn;
    dp = dpn;
    if (std::fabs(dx) <= kPolishConverged * std::fabs(x)) break;
  }
  return x;
}

// Candidate roots before sorting and merging. A quartic has at most four,
// but the fallback can propose a tangency point next to the two sign changes
// around it; room for eight, and never written past the end.
struct Candidates {
  static constexpr int kCapacity = 8;
  double v[kCapacity] = {};
  int n = 0;
  void push(double x) noexcept {
    if (n < kCapacity) v[n++] = x;
  }
};

// Drops non-finite candidates and sorts the rest ascending.
inline void sort_candidates(Candidates& r) noexcept {
  int k = 0;
  for (int i = 0; i < r.n; ++i)
    if (std::isfinite(r.v[i])) r.v[k++] = r.v[i];
  r.n = k;
  for (int i = 1; i < r.n; ++i) {
    const double x = r.v[i];
    int j = i - 1;
    while (j >= 0 && r.v[j] > x) {
      r.v[j + 1] = r.v[j];
      --j;
    }
    r.v[j + 1] = x;
  }
}

// Sorts the candidates and merges adjacent ones that are equal, or that are
// numerically one double root of the monic polynomial m (see the policy in
// the header): closer than kMergeGap relative, with p numerically zero at the
// midpoint. With m == nullptr only exact duplicates merge.
template <int N>
inline void sort_and_merge(const double* m, double tol, Candidates& r) noexcept {
  sort_candidates(r);
  int k = 0;
  for (int i = 0; i < r.n; ++i) {
    if (k > 0) {
      const double a = r.v[k - 1];
      const double b = r.v[i];
      if (a == b) continue;
      if (m != nullptr && b - a <= kMergeGap * std::max(std::fabs(a), std::fabs(b))) {
        const double mid = 0.5 * (a + b);
        if (numerically_zero<N>(m, mid, tol)) {
          r.v[k - 1] = mid;
          continue;
        }
      }
    }
    r.v[k++] = r.v[i];
  }
  r.n = k;
}

// Writes the candidates, scaled back by `scale` (a power of two), to `out`;
// roots that overflow on scaling back are dropped, and never more than N.
template <std::size_t N>
inline void copy_out(const Candidates& r, RealRoots<N>& out, double scale) noexcept {
  std::size_t k = 0;
  for (int i = 0; i < r.n && k < N; ++i) {
    const double x = r.v[i] * scale;
    if (std::isfinite(x)) out.t[k++] = x;
  }
  out.count = static_cast<int>(k);
}

// Exact power-of-two equilibration of c[0] + ... + c[N] t^N (c[N] != 0):
// writes the monic coefficients m of the polynomial in x = t / 2^e, with e
// chosen so that every |m[k]| <= 1 and the root scale is O(1). Slow path only.
template <int N>
inline int equilibrate(const double* c, double* m) noexcept {
  const int en = std::ilogb(c[N]);
  int e = INT_MIN;
  for (int k = 0; k < N; ++k) {
    if (c[k] == 0.0) continue;
    const int num = std::ilogb(c[k]) - en + 1;
    const int den = N - k;
    const int ek = num >= 0 ? (num + den - 1) / den : -((-num) / den);  // ceil(num/den)
    if (ek > e) e = ek;
  }
  if (e == INT_MIN) e = 0;
  const double lead = std::scalbn(c[N], -en);
  for (int k = 0; k < N; ++k) m[k] = std::scalbn(c[k], (k - N) * e - en) / lead;
  return e;
}

// Is the monic polynomial's root scale max_k |m[k]|^(1/(N-k)) within the fast
// path's range 2^-80 .. 2^80? Written so that NaN or infinity fail.
template <int N>
inline bool in_fast_range(const double* m) noexcept {
  bool big_ok = true;
  bool some_large = false;
  double hi = kScaleHi;
  double lo = kScaleLo;
  for (int k = N - 1; k >= 0; --k) {
    const double a = std::fabs(m[k]);
    big_ok = big_ok && (a <= hi);
    some_large = some_large || (a >= lo);
    hi *= kScaleHi;
    lo *= kScaleLo;
  }
  return big_ok && some_large;
}

// ------------------------------------------------- quadratic factor (shared)

// Roots of the monic factor x^2 + alpha x + beta of the monic degree-N
// polynomial m, with the double-root policy applied against m. Real roots
// are computed without cancellation (q and beta/q) and then Newton-polished
// on m itself, which makes them accurate to their condition number even when
// the factor's coefficients carry a little error.
template <int N>
inline void factor_roots(double alpha, double beta, const double* m, double tol, Candidates& out) noexcept {
  const double h = -0.5 * alpha;
  const double disc = h * h - beta;
  if (std::fabs(disc) <= kClosePair * (h * h + std::fabs(beta)) && numerically_zero<N>(m, h, tol)) {
    out.push(h);  // one (double) root at the pair's mean
    return;
  }
  if (disc < 0.0) return;
  const double q = h + std::copysign(std::sqrt(disc), h);
  out.push(polish<N>(m, q));
  out.push(polish<N>(m, q != 0.0 ? beta / q : 0.0));
}

// ------------------------------------------- fallback: isolation + bisection
//
// A slow (~1-2 us) but robust solver, used only when the fast quartic path
// cannot certify its factorization (backward error above kCertify). That
// happens when the roots spread over ~30 orders of magnitude or more: never
// on the benchmark's table batches, about once per million for random
// coefficients spread over 1e-3..1e3. The real
// critical points (roots of p', found the same way, recursively) split the
// line into monotone pieces; a piece whose ends have strictly opposite signs
// holds one root, found by bisection on the binary representation (at most
// ~64 halvings of the representable numbers in between, so tiny and huge
// roots keep full relative accuracy). A critical point where p is
// numerically zero is a double root (the tangency policy).

inline std::int64_t ordered_bits(double x) noexcept {
  const auto i = std::bit_cast<std::int64_t>(x);
  return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;  // monotone in x, -0 == +0
}
inline double from_ordered_bits(std::int64_t i) noexcept {
  return std::bit_cast<double>(i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i);
}

// Root of the monic polynomial in [lo, hi], where it has strictly opposite
// signs at the two ends (p_lo is the value at lo).
template <int N>
inline double bisect(const double* m, double lo, double hi, double p_lo) noexcept {
  std::int64_t a = ordered_bits(lo);
  std::int64_t b = ordered_bits(hi);
  while (b - a > 1) {
    const std::int64_t mid_bits = a + (b - a) / 2;
    const double mid = from_ordered_bits(mid_bits);
    const double pm = eval_monic<N>(m, mid);
    if (pm == 0.0) return mid;
    if ((pm < 0.0) == (p_lo < 0.0)) {
      a = mid_bits;
    } else {
      b = mid_bits;
    }
  }
  const double x = from_ordered_bits(a);
  const double y = from_ordered_bits(b);
  return std::fabs(eval_monic<N>(m, x)) <= std::fabs(eval_monic<N>(m, y)) ? x : y;
}

// Real roots of the monic degree-N polynomial m: sign changes, plus critical
// points where p touches zero by the tangency policy; ascending, merged by
// the policy. Degrees 1 and 2 are solved directly.
template <int N>
inline void isolate_roots(const double* m, double tol, Candidates& out) noexcept {
  if constexpr (N == 1) {
    out.push(-m[0]);
  } else if constexpr (N == 2) {
    const double h = -0.5 * m[1];
    const double disc = h * h - m[0];
    if (std::fabs(disc) <= tol * (3.0 * h * h + std::fabs(m[0]))) {
      out.push(h);
    } else if (disc > 0.0) {
      const double q = h + std::copysign(std::sqrt(disc), h);
      out.push(q);
      out.push(m[0] / q);
    }
    sort_candidates(out);
  } else {
    // Monic derivative p'(x)/N and its real roots.
    double dm[static_cast<std::size_t>(N - 1)];
    for (int k = 0; k < N - 1; ++k) dm[k] = static_cast<double>(k + 1) * m[k + 1] / static_cast<double>(N);
    Candidates crit;
    isolate_roots<N - 1>(dm, 0.0, crit);
    // Fujiwara's bound: every root has |x| <= 2 max_k |m_k|^(1/(N-k)).
    double bound = 0.0;
    for (int k = 0; k < N; ++k) bound = std::max(bound, std::pow(std::fabs(m[k]), 1.0 / static_cast<double>(N - k)));
    if (bound == 0.0) {  // x^N
      out.push(0.0);
      return;
    }
    bound = std::min(2.0000001 * bound, std::numeric_limits<double>::max());
    double pts[static_cast<std::size_t>(N + 2)];
    int np = 0;
    pts[np++] = -bound;
    for (int i = 0; i < crit.n; ++i)
      if (crit.v[i] > -bound && crit.v[i] < bound) pts[np++] = crit.v[i];
    pts[np++] = bound;
    // Values at the points. A critical point where p is numerically zero and
    // |p| is no larger than at its neighbours (p touches zero there, rather
    // than peaking between two zeros) is a (double) root, and counts as an
    // exact zero for its two pieces.
    double val[static_cast<std::size_t>(N + 2)];
    for (int i = 0; i < np; ++i) val[i] = eval_monic<N>(m, pts[i]);
    bool touches[static_cast<std::size_t>(N + 2)] = {};
    for (int i = 1; i + 1 < np; ++i)
      touches[i] = std::fabs(val[i]) <= std::fabs(val[i - 1]) && std::fabs(val[i]) <= std::fabs(val[i + 1]) &&
                   numerically_zero<N>(m, pts[i], tol);
    for (int i = 1; i + 1 < np; ++i) {
      if (!touches[i]) continue;
      out.push(pts[i]);
      val[i] = 0.0;
    }
    for (int i = 0; i + 1 < np; ++i) {
      double lo = pts[i];
      const double hi = pts[i + 1];
      double p_lo = val[i];
      const double p_hi = val[i + 1];
      if (p_lo == 0.0 || p_hi == 0.0 || (p_lo < 0.0) == (p_hi < 0.0)) continue;
      if (lo < 0.0 && hi > 0.0) {  // bisect on one side of zero: the bit trick needs one sign
        const double p0 = eval_monic<N>(m, 0.0);
        if (p0 == 0.0) {
          out.push(0.0);
          continue;
        }
        if ((p0 < 0.0) == (p_lo < 0.0)) {
          lo = 0.0;
          p_lo = p0;
        } else {
          out.push(bisect<N>(m, lo, 0.0, p_lo));
          continue;
        }
      }
      out.push(bisect<N>(m, lo, hi, p_lo));
    }
    sort_and_merge<N>(m, tol, out);
  }
}

// ------------------------------------------------------------------- cubic

// Dominant (largest-magnitude) real root of the depressed cubic y^3 + p y + q.
// With Q = -p/3, R = -q/2 the cubic is y^3 - 3Q y - 2R. Three real roots
// (R^2 < Q^3): y = 2 sqrt(Q) cos((theta + 2 pi k)/3), cos(theta) = R/Q^(3/2);
// the dominant one is sign(R) 2 sqrt(Q) cos(theta'/3), theta' = acos(|R|/Q^1.5).
// Otherwise Cardano with the cancellation-free choice u^3 = R + sign(R)
// sqrt(R^2 - Q^3), y = u + Q/u. Both branches meet continuously at R^2 = Q^3,
// where the dominant root is the simple one (the other root is double).
inline double dominant_depressed_root(double p, double q) noexcept {
  const double Q = -p * kThird;
  const double R = -0.5 * q;
  const double Q3 = Q * Q * Q;
  const double R2 = R * R;
  if (R2 < Q3) {
    const double sq = std::sqrt(Q);
    const double ratio = std::min(std::fabs(R) / (Q * sq), 1.0);
    const double theta = std::acos(ratio);
    return std::copysign(2.0 * sq * std::cos(theta * kThird), R);
  }
  const double u = std::cbrt(R + std::copysign(std::sqrt(R2 - Q3), R));
  return u == 0.0 ? 0.0 : u + Q / u;
}

// Real roots of the monic cubic x^3 + m[2] x^2 + m[1] x + m[0], m[0] != 0.
inline void cubic_monic(const double* m, double tol, Candidates& out) noexcept {
  const double a = m[2];
  const double b = m[1];
  const double c = m[0];
  const double third = a * kThird;
  const double p = b - a * third;
  const double q = c + third * (2.0 * third * third - b);
  // x1 can carry a large relative error when the root is small compared with
  // a/3 (cancellation in y - a/3): Newton then needs a few more steps.
  double x1 = dominant_depressed_root(p, q) - third;
  x1 = polish<3, kRootPolishSteps>(m, x1);
  if (!numerically_zero<3>(m, x1, kCubicRootCheck)) {  // not a root after all: let the fallback solve
    isolate_roots<3>(m, tol, out);
    return;
  }
  // Deflation x^3 + a x^2 + b x + c = (x - x1)(x^2 + e x + f). Kahan's
  // choice: from the top (e = a + x1) when x1 is small, from the constant term
  // (f = -c/x1) when x1 is large compared with the product of the others.
  double e = 0.0;
  double f = 0.0;
  if (std::fabs(x1 * x1 * x1) > std::fabs(c)) {
    f = -c / x1;
    e = (f - b) / x1;
  } else {
    e = a + x1;
    f = b + x1 * e;
  }
  out.push(x1);
  factor_roots<3>(e, f, m, tol, out);
}

// ------------------------------------------------------------------ quartic
//
// Orellana & De Michele (2020). The monic quartic x^4 + a x^3 + b x^2 + c x + d
// is written as
//     (x^2 + l1 x + l3)^2 + d2 (x + l2)^2,   l1 = a/2,  l3 = b/6 + phi/2,
//     d2 = 2b/3 - phi - l1^2,
// which holds when phi is a root of the depressed resolvent cubic
// phi^3 + g phi + h (g, h below; they are invariant under a shift of x, and
// are computed after shifting x to an inflection point of the quartic to
// reduce cancellation). With the dominant root phi0, d2 <= 0 gives two real
// quadratic factors (x^2 + l1 x + l3)^2 - (gamma (x + l2))^2, gamma = sqrt(-d2);
// d2 > 0 means a conjugate pair of complex factors, which happens only when
// all four roots are complex and well away from the real axis: a (near-)real
// double root makes the two resolvent roots of the other pairings (nearly)
// equal, so the dominant one is always the real factorization's.

// Dominant root of the depressed resolvent, Newton-polished.
inline double resolvent_phi0(double a, double b, double c, double d) noexcept {
  double s = -0.25 * a;  // shift: an inflection point when one exists, eq. (87)
  const double disc = 9.0 * a * a - 24.0 * b;
  if (disc > 0.0) s = -2.0 * b / (3.0 * a + std::copysign(std::sqrt(disc), a));
  const double aq = a + 4.0 * s;
  const double bq = b + 3.0 * s * (a + 2.0 * s);
  const double cq = c + s * (2.0 * b + s * (3.0 * a + 4.0 * s));
  const double dq = d + s * (c + s * (b + s * (a + s)));
  const double gg = bq * bq * (1.0 / 9.0);
  const double hh = aq * cq;
  const double g = hh - 4.0 * dq - 3.0 * gg;
  const double h = (8.0 * dq + hh - 2.0 * gg) * bq * kThird - cq * cq - dq * aq * aq;
  double x = dominant_depressed_root(g, h);
  double f = x * (x * x + g) + h;
  const double scale = std::max({std::fabs(x * x * x), std::fabs(g * x), std::fabs(h)});
  if (std::fabs(f) > kEps * scale) {
    for (int it = 0; it < 8; ++it) {
      const double df = 3.0 * x * x + g;
      if (df == 0.0) break;
      const double xn = x - f / df;
      const double fn = xn * (xn * xn + g) + h;
      if (!(std::fabs(fn) < std::fabs(f))) break;
      x = xn;
      f = fn;
      if (f == 0.0) break;
    }
  }
  return x;
}

// Weights turning residuals in a, b, c, d into relative errors (absolute for
// a zero coefficient), as in eqs. (29)-(30), (48)-(51), (68)-(69).
struct Weights {
  double a, b, c, d;
};
inline double weight(double x) noexcept { return x == 0.0 ? 1.0 : 1.0 / std::fabs(x); }

// Error of reproducing b, c, d from an LDL^T candidate, eqs. (29)-(30).
inline double ldlt_error(const double* m, const Weights& w, double d2, double l1, double l2, double l3) noexcept {
  const double eb = d2 + l1 * l1 + 2.0 * l3;
  const double ec = 2.0 * d2 * l2 + 2.0 * l1 * l3;
  const double ed = d2 * l2 * l2 + l3 * l3;
  return std::fabs(eb - m[2]) * w.b + std::fabs(ec - m[1]) * w.c + std::fabs(ed - m[0]) * w.d;
}

// Error of the factor coefficients (alpha1, beta1, alpha2, beta2) in
// reproducing a, b, c (and d when `with_d`).
template <typename T>
inline double factor_error(const double* m, const Weights& w, T a1, T b1, T a2, T b2, bool with_d) noexcept {
  using std::abs;
  double err = abs(a1 + a2 - m[3]) * w.a + abs(b1 + a1 * a2 + b2 - m[2]) * w.b + abs(b1 * a2 + a1 * b2 - m[1]) * w.c;
  if (with_d) err += abs(b1 * b2 - m[0]) * w.d;
  return err;
}

// Is (x^2 + a1 x + b1)(x^2 + a2 x + b2) a factorization of the monic quartic
// m with backward error at most `bound`, each coefficient's residual measured
// against the size of the terms that form it: |residual_k| <= bound *
// (sum |terms_k| + |m_k|)? Unlike the paper's per-coefficient relative error
// this does not blow up for a coefficient that is zero or cancels. Used to
// certify a factorization before trusting it.
template <typename T>
inline bool factorization_within(const double* m, T a1, T b1, T a2, T b2, double bound) noexcept {
  using std::abs;
  const T p0 = b1 * b2;
  const T p1 = b1 * a2;
  const T p2 = a1 * b2;
  const T p3 = a1 * a2;
  return abs(p0 - m[0]) <= bound * (abs(p0) + std::fabs(m[0])) &&
         abs(p1 + p2 - m[1]) <= bound * (abs(p1) + abs(p2) + std::fabs(m[1])) &&
         abs(b1 + p3 + b2 - m[2]) <= bound * (abs(b1) + abs(p3) + abs(b2) + std::fabs(m[2])) &&
         abs(a1 + a2 - m[3]) <= bound * (abs(a1) + abs(a2) + std::fabs(m[3]));
}

// Newton-Raphson on (alpha1, beta1, alpha2, beta2) for the system
// alpha1 + alpha2 = a, beta1 + alpha1 alpha2 + beta2 = b,
// beta1 alpha2 + alpha1 beta2 = c, beta1 beta2 = d (sec. 2.3). The Jacobian's
// determinant is the resultant of the two factors; its adjugate is written out.
// Returns the final backward error (relative, per coefficient).
inline double refine_factors(const double* m, const Weights& wt, double& a1, double& b1, double& a2,
                             double& b2) noexcept {
  auto residual = [m](double x0, double x1, double x2, double x3, double* f) {
    f[0] = x1 * x3 - m[0];
    f[1] = x1 * x2 + x0 * x3 - m[1];
    f[2] = x1 + x0 * x2 + x3 - m[2];
    f[3] = x0 + x2 - m[3];
  };
  auto size = [&wt](const double* f) {
    return std::fabs(f[0]) * wt.d + std::fabs(f[1]) * wt.c + std::fabs(f[2]) * wt.b + std::fabs(f[3]) * wt.a;
  };
  double f[4];
  residual(a1, b1, a2, b2, f);
  double err = size(f);
  for (int it = 0; it < 8 && err != 0.0; ++it) {
    const double u = a1 - a2;
    const double v = b2 - b1;
    const double w = a2 * b1 - a1 * b2;
    const double det = v * v - u * w;
    if (det == 0.0) break;
    // Rows of adj(J) for the unknowns (alpha1, beta1, alpha2, beta2).
    const double da1 = u * f[0] + v * f[1] + w * f[2] - (a1 * w + b1 * v) * f[3];
    const double db1 = (a1 * u + v) * f[0] - b1 * (u * f[1] + v * f[2] + w * f[3]);
    const double db2 = -(a2 * u + v) * f[0] + b2 * (u * f[1] + v * f[2] + w * f[3]);
    const double da2 = -u * f[0] - v * f[1] - w * f[2] + (a2 * w + b2 * v) * f[3];
    const double inv_det = 1.0 / det;
    const double n0 = a1 - da1 * inv_det;
    const double n1 = b1 - db1 * inv_det;
    const double n2 = a2 - da2 * inv_det;
    const double n3 = b2 - db2 * inv_det;
    double fn[4];
    residual(n0, n1, n2, n3, fn);
    const double errn = size(fn);
    if (!(errn < err)) break;
    a1 = n0;
    b1 = n1;
    a2 = n2;
    b2 = n3;
    err = errn;
    for (int k = 0; k < 4; ++k) f[k] = fn[k];
  }
  return err;
}

// The smaller-magnitude beta of a pair from d / (the larger): their product
// is d exactly and the small one keeps full relative accuracy.
inline void balance_betas(double d, double& b1, double& b2) noexcept {
  if (std::fabs(b2) < std::fabs(b1)) {
    b2 = d / b1;
  } else if (std::fabs(b2) > std::fabs(b1)) {
    b1 = d / b2;
  }
}

// Recomputes the smaller-magnitude alpha of a real factorization from
// whichever of the equivalent formulas (47)/(53) reproduces a, b, c best.
inline void refine_alpha(const double* m, const Weights& w, double& a1, double b1, double& a2, double b2) noexcept {
  const bool first_small = std::fabs(a1) < std::fabs(a2);
  const double big = first_small ? a2 : a1;
  const double b_small = first_small ? b1 : b2;  // beta paired with the small alpha
  const double b_big = first_small ? b2 : b1;
  double cand[3];
  int nc = 0;
  if (b_big != 0.0) cand[nc++] = (m[1] - b_small * big) / b_big;
  if (big != 0.0) cand[nc++] = (m[2] - b_small - b_big) / big;
  cand[nc++] = m[3] - big;
  double best_err = kInf;
  double best_alpha = first_small ? a1 : a2;
  for (int k = 0; k < nc; ++k) {
    const double e = first_small ? factor_error(m, w, cand[k], b1, a2, b2, false)
                                 : factor_error(m, w, a1, b1, cand[k], b2, false);
    if (e < best_err) {
      best_err = e;
      best_alpha = cand[k];
    }
  }
  (first_small ? a1 : a2) = best_alpha;
}

// Real roots of the monic quartic x^4 + m[3] x^3 + m[2] x^2 + m[1] x + m[0],
// m[0] != 0.
inline void quartic_monic(const double* m, double tol, Candidates& out) noexcept {
  const double a = m[3];
  const double b = m[2];
  const double c = m[1];
  const double d = m[0];
  const double phi0 = resolvent_phi0(a, b, c, d);
  const double l1 = 0.5 * a;
  const double l3 = b * (1.0 / 6.0) + 0.5 * phi0;
  const double del2 = c - a * l3;
  const double d2_from_b = 2.0 * b * kThird - phi0 - l1 * l1;
  const Weights w{weight(a), weight(b), weight(c), weight(d)};
  const double d3 = d - l3 * l3;  // d - l3^2, the last pivot when d2 = 0

  // Up to three algebraically equivalent (d2, l2) pairs, eq. (28) and after;
  // keep the one that best reproduces b, c, d.
  double d2 = 0.0;
  double l2 = 0.0;
  double best = kInf;
  auto consider = [&](double d2c, double l2c) {
    const double e = ldlt_error(m, w, d2c, l1, l2c, l3);
    if (e < best) {
      best = e;
      d2 = d2c;
      l2 = l2c;
    }
  };
  if (d2_from_b != 0.0) consider(d2_from_b, del2 / (2.0 * d2_from_b));
  if (del2 != 0.0) {
    const double l2_from_d = 2.0 * d3 / del2;
    if (l2_from_d != 0.0) consider(del2 / (2.0 * l2_from_d), l2_from_d);
    consider(d2_from_b, l2_from_d);
  }

  // Case I: real factors (d2 < 0); case II: complex conjugate factors.
  bool real_factors = false;
  double a1 = 0.0, b1 = 0.0, a2 = 0.0, b2 = 0.0;
  std::complex<double> ca1, cb1;  // case II: alpha1, beta1 (alpha2, beta2 conjugate)
  if (d2 < 0.0) {
    real_factors = true;
    const double gamma = std::sqrt(-d2);
    a1 = l1 + gamma;
    b1 = l3 + gamma * l2;
    a2 = l1 - gamma;
    b2 = l3 - gamma * l2;
    balance_betas(d, b1, b2);
  } else if (d2 > 0.0) {
    const double gamma = std::sqrt(d2);
    ca1 = {l1, gamma};
    cb1 = {l3, gamma * l2};
  }

  // Case III: d2 is zero or at round-off level, where its computed sign
  // cannot be trusted: the d2 = 0 factorization (x^2 + l1 x + l3)^2 + d3
  // competes, judged by backward error. Unlike the paper (|d2| <= eps * scale)
  // this is also done for any d2 > 0 and for |d2| up to 64 eps * scale: d2 is
  // a difference of O(scale) terms carrying a few ulps of error each, and a
  // symmetric quartic (roots symmetric about a point, exact d2 = 0) can come
  // out with d2 slightly above the paper's threshold, wrongly "complex".
  bool flat_complex = false;  // chosen: (x^2 + l1 x + l3)^2 + d3 with d3 > 0
  const double d2_scale = std::max({std::fabs(2.0 * b * kThird), std::fabs(phi0), l1 * l1});
  if (!(d2 < -kD2Noise * d2_scale)) {
    double err0 = kInf;
    if (d2 < 0.0) {
      err0 = factor_error(m, w, a1, b1, a2, b2, true);
    } else if (d2 > 0.0) {
      err0 = factor_error(m, w, ca1, cb1, std::conj(ca1), std::conj(cb1), true);
    }
    if (d3 <= 0.0) {
      const double r = std::sqrt(-d3);
      double e1 = l3 + r;
      double e2 = l3 - r;
      balance_betas(d, e1, e2);
      const double err1 = factor_error(m, w, l1, e1, l1, e2, true);
      if (d2 == 0.0 || err1 < err0) {
        real_factors = true;
        a1 = l1;
        b1 = e1;
        a2 = l1;
        b2 = e2;
      }
    } else {
      const std::complex<double> cb{l3, std::sqrt(d3)};
      const double err1 =
          factor_error(m, w, std::complex<double>(l1), cb, std::complex<double>(l1), std::conj(cb), true);
      if (d2 == 0.0 || err1 < err0) {
        real_factors = false;
        flat_complex = true;
      }
    }
  }

  if (real_factors) {
    // Refining the factors only matters if one of them may have real roots:
    // skip it when both discriminants are clearly negative and the
    // factorization is trustworthy (small backward error).
    const double h1 = 0.5 * a1;
    const double h2 = 0.5 * a2;
    if (h1 * h1 - b1 > -kSurelyComplex * (h1 * h1 + std::fabs(b1)) ||
        h2 * h2 - b2 > -kSurelyComplex * (h2 * h2 + std::fabs(b2)) ||
        !factorization_within(m, a1, b1, a2, b2, kTrustedFactorization)) {
      refine_alpha(m, w, a1, b1, a2, b2);
      refine_factors(m, w, a1, b1, a2, b2);
      if (!factorization_within(m, a1, b1, a2, b2, kCertify)) {
        isolate_roots<4>(m, tol, out);
        return;
      }
      factor_roots<4>(a1, b1, m, tol, out);
      factor_roots<4>(a2, b2, m, tol, out);
    }
    return;
  }
  // An uncertified complex factorization: let the fallback decide.
  const bool certified =
      flat_complex ? factorization_within(m, std::complex<double>(l1), std::complex<double>(l3, std::sqrt(d3)),
                                          std::complex<double>(l1), std::complex<double>(l3, -std::sqrt(d3)), kCertify)
                   : factorization_within(m, ca1, cb1, std::conj(ca1), std::conj(cb1), kCertify);
  if (!certified) {
    isolate_roots<4>(m, tol, out);
    return;
  }
  if (flat_complex) {
    // p = (x^2 + l1 x + l3)^2 + d3 with small d3 > 0: the only candidates for
    // a grazing double root are the real roots of x^2 + l1 x + l3.
    const double h = -0.5 * l1;
    const double disc = h * h - l3;
    if (disc >= 0.0) {
      const double q = h + std::copysign(std::sqrt(disc), h);
      const double r1 = q;
      const double r2 = q != 0.0 ? l3 / q : 0.0;
      if (numerically_zero<4>(m, r1, tol)) out.push(r1);
      if (numerically_zero<4>(m, r2, tol)) out.push(r2);
    } else if (numerically_zero<4>(m, h, tol)) {
      out.push(h);
    }
  }
  // Case II proper (d2 clearly > 0): all roots complex and far from the axis.
}

// ------------------------------------------------------------ entry points

template <std::size_t M>
inline bool all_finite(const std::array<double, M>& c) noexcept {
  bool ok = true;
  for (double x : c) ok = ok && std::isfinite(x);
  return ok;
}

// The quadratic kernel on a t^2 + b t + c, a != 0, all products in range.
inline void quadratic_kernel(double a, double b, double c, double tol, Candidates& out) noexcept {
  const double h = -0.5 * b;
  const double hh = h * h;
  const double ac = a * c;
  const double disc = hh - ac;
  // |p(m)| <= tol * pbar(m) at m = h/a, in closed form.
  if (std::fabs(disc) <= tol * (3.0 * hh + std::fabs(ac))) {
    out.push(h / a);
    return;
  }
  if (disc < 0.0) return;
  const double q = h + std::copysign(std::sqrt(disc), h);
  const double x1 = q / a;
  const double x2 = c / q;  // q != 0 here: q == 0 would need h == 0 and disc == 0
  if (x1 < x2) {
    out.push(x1);
    out.push(x2);
  } else {
    out.push(x2);
    out.push(x1);
  }
}

inline bool quadratic_in_range(double a, double b, double c) noexcept {
  constexpr double hi = 0x1p500;
  constexpr double lo = 0x1p-500;
  auto ok = [](double x) {
    const double ax = std::fabs(x);
    return ax == 0.0 || (ax >= lo && ax <= hi);
  };
  return ok(a) && ok(b) && ok(c);
}

}  // namespace

namespace {

// A lower-degree result in a wider array.
template <std::size_t N, std::size_t M>
RealRoots<N> widen(const RealRoots<M>& q) noexcept {
  static_assert(M <= N);
  RealRoots<N> r;
  r.degree = q.degree;
  r.count = q.count;
  for (std::size_t i = 0; i < M; ++i) r.t[i] = q.t[i];
  return r;
}

// Roots of t * (c[1] + c[2] t + ...): t = 0 exactly, merged with the roots of
// the deflated polynomial (which may contain 0 again).
template <std::size_t N, std::size_t M>
RealRoots<N> with_zero_root(const RealRoots<M>& q) noexcept {
  Candidates cand;
  cand.push(0.0);
  for (double x : q) cand.push(x);
  sort_and_merge<1>(nullptr, 0.0, cand);
  RealRoots<N> r;
  r.degree = static_cast<int>(N);
  copy_out(cand, r, 1.0);
  return r;
}

}  // namespace

QuadraticRoots solve_quadratic(const QuadraticCoefficients& c, double tol) noexcept {
  QuadraticRoots r;
  if (c[2] == 0.0) {
    if (c[1] == 0.0) {
      r.degree = c[0] == 0.0 ? -1 : 0;
      return r;
    }
    r.degree = 1;
    const double x = -c[0] / c[1];
    if (std::isfinite(x)) {
      r.t[0] = x;
      r.count = 1;
    }
    return r;
  }
  r.degree = 2;
  if (!all_finite(c)) return r;
  Candidates cand;
  double scale = 1.0;
  if (quadratic_in_range(c[2], c[1], c[0])) {
    quadratic_kernel(c[2], c[1], c[0], tol, cand);
  } else {
    double m[2];
    scale = std::ldexp(1.0, equilibrate<2>(c.data(), m));
    quadratic_kernel(1.0, m[1], m[0], tol, cand);
  }
  copy_out(cand, r, scale);
  return r;
}

CubicRoots solve_cubic(const CubicCoefficients& c, double tol) noexcept {
  if (c[3] == 0.0) return widen<3>(solve_quadratic({c[0], c[1], c[2]}, tol));
  CubicRoots r;
  r.degree = 3;
  if (!all_finite(c)) return r;
  if (c[0] == 0.0) return with_zero_root<3>(solve_quadratic({c[1], c[2], c[3]}, tol));
  double m[3] = {c[0] / c[3], c[1] / c[3], c[2] / c[3]};
  double scale = 1.0;
  if (!in_fast_range<3>(m)) scale = std::ldexp(1.0, equilibrate<3>(c.data(), m));
  Candidates cand;
  cubic_monic(m, tol, cand);
  sort_and_merge<3>(m, tol, cand);
  copy_out(cand, r, scale);
  return r;
}

QuarticRoots solve_quartic(const QuarticCoefficients& c, double tol) noexcept {
  if (c[4] == 0.0) return widen<4>(solve_cubic({c[0], c[1], c[2], c[3]}, tol));
  QuarticRoots r;
  r.degree = 4;
  if (!all_finite(c)) return r;
  if (c[0] == 0.0) return with_zero_root<4>(solve_cubic({c[1], c[2], c[3], c[4]}, tol));
  double m[4] = {c[0] / c[4], c[1] / c[4], c[2] / c[4], c[3] / c[4]};
  double scale = 1.0;
  if (!in_fast_range<4>(m)) scale = std::ldexp(1.0, equilibrate<4>(c.data(), m));
  Candidates cand;
  quartic_monic(m, tol, cand);
  sort_and_merge<4>(m, tol, cand);
  copy_out(cand, r, scale);
  return r;
}

namespace {

template <std::size_t N>
std::optional<double> first_in(const RealRoots<N>& r, double t_min, double t_max) noexcept {
  if (r.identically_zero()) return t_min;
  for (double x : r)
    if (x >= t_min) return x <= t_max ? std::optional<double>(x) : std::nullopt;
  return std::nullopt;
}

// Weights C(i,k)/C(n,k) taking power-basis coefficients on [0, 1] to
// Bernstein coefficients: b_i = sum_{k<=i} w[i][k] q_k.
template <std::size_t M>
constexpr std::array<std::array<double, M>, M> bernstein_weights() {
  std::array<std::array<double, M>, M> w{};
  auto binom = [](std::size_t a, std::size_t b) {
    double r = 1.0;
    for (std::size_t j = 1; j <= b; ++j) r = r * static_cast<double>(a - b + j) / static_cast<double>(j);
    return r;
  };
  for (std::size_t i = 0; i < M; ++i)
    for (std::size_t k = 0; k <= i; ++k) w[i][k] = binom(i, k) / binom(M - 1, k);
  return w;
}

// Cheap exclusion for smallest_root_in: true when p provably keeps one strict
// sign on [t0, t1] by a margin no reported root can cross. p(t0 + h u) is
// rewritten in the Bernstein basis on u in [0, 1] (a Taylor shift, then a
// fixed weighting); p lies between the smallest and largest Bernstein
// coefficient. The margin covers the rounding of this conversion (at most
// ~7 eps * pbar(|t0| + h), bounded by 32 eps here) plus the residual any
// reported root can have (tol * pbar for a policy root, a few eps for a
// polished one), with a factor 4 to spare. No divisions; ~30 flops.
template <std::size_t M>
bool surely_rootless(const std::array<double, M>& c, double t0, double t1, double tol) noexcept {
  constexpr int n = static_cast<int>(M) - 1;
  static constexpr auto w = bernstein_weights<M>();
  double q[M];
  for (std::size_t k = 0; k < M; ++k) q[k] = c[k];
  for (int i = 0; i < n; ++i)  // Taylor shift: q_k = p^(k)(t0) / k!
    for (int k = n - 1; k >= i; --k) q[k] += t0 * q[k + 1];
  const double h = t1 - t0;
  double hk = h;
  for (std::size_t k = 1; k < M; ++k) {
    q[k] *= hk;
    hk *= h;
  }
  double lo = q[0];
  double hi = q[0];
  for (std::size_t i = 1; i < M; ++i) {
    double b = 0.0;
    for (std::size_t k = 0; k <= i; ++k) b += w[i][k] * q[k];
    lo = std::min(lo, b);
    hi = std::max(hi, b);
  }
  const double x = std::fabs(t0) + h;
  double bound = 0.0;
  for (std::size_t k = M; k-- > 0;) bound = bound * x + std::fabs(c[k]);
  const double margin = (4.0 * tol + 64.0 * kEps) * bound;
  return lo > margin || hi < -margin;
}

template <std::size_t M, typename Solve>
std::optional<double> smallest_root(const std::array<double, M>& c, double t_min, double t_max, double tol,
                                    Solve solve) noexcept {
  if (!(t_min <= t_max)) return std::nullopt;
  if (surely_rootless(c, t_min, t_max, tol)) return std::nullopt;
  return first_in(solve(c, tol), t_min, t_max);
}

}  // namespace

std::optional<double> smallest_root_in(const QuadraticCoefficients& c, double t_min, double t_max,
                                       double tol) noexcept {
  return smallest_root(c, t_min, t_max, tol, solve_quadratic);
}
std::optional<double> smallest_root_in(const CubicCoefficients& c, double t_min, double t_max,
                                       double tol) noexcept {
  return smallest_root(c, t_min, t_max, tol, solve_cubic);
}
std::optional<double> smallest_root_in(const QuarticCoefficients& c, double t_min, double t_max,
                                       double tol) noexcept {
  return smallest_root(c, t_min, t_max, tol, solve_quartic);
}

}  // namespace cueball
