// Real roots of quadratic, cubic and quartic polynomials, for event prediction.
//
// The table simulator predicts collision times from closed-form trajectories
// that are piecewise quadratic in time: ball-cushion contact is a quadratic,
// ball-ball, jaw and pocket contact are quartics. These kernels find all real
// roots (or the earliest one in a time window) with no allocation and few
// branches; they are meant for millions of calls per second.
//
// Coefficient order: ascending powers throughout,
//     p(t) = c[0] + c[1] t + c[2] t^2 + ... + c[n] t^n.
//
// Results: the distinct real roots, ascending, in a fixed-size array; unused
// slots hold NaN. `degree` is the true degree that was solved.
//
// Degree dispatch. A leading coefficient is dropped only when it is exactly
// zero (e.g. two balls with bit-identical accelerations). A tiny but nonzero
// leading coefficient is kept on purpose: any "negligible relative to the
// others" threshold is scale dependent (for roots near 1e3 s the quartic's
// leading coefficient is 1e-12 of its constant term) and would silently move
// or drop roots. A tiny leading coefficient instead produces genuinely large
// roots (~ c[n-1]/c[n]), which are reported when finite, while the small
// roots keep full relative accuracy. A zero constant term is deflated
// exactly (root t = 0). All coefficients zero: `degree == -1`,
// `identically_zero()`, no roots listed. Non-finite coefficients: no roots.
//
// Method (details and equation numbers in src/physics/polynomial_roots.cpp):
//  * quadratic: the cancellation-free q = -(b + sign(b) sqrt(b^2 - 4ac))/2,
//    roots q/a and c/q (Press et al., Numerical Recipes, 3rd ed., sec. 5.6).
//  * cubic: the dominant (largest-magnitude) root of the depressed cubic in
//    closed form (trigonometric or Cardano branch, whichever has no
//    cancellation), Newton-polished on the original cubic, then deflation in
//    the stable direction as in Kahan, "To solve a real cubic equation"
//    (1986), leaving a quadratic. The dominant root of a depressed cubic is a
//    simple root whenever the cubic has a double root, so a grazing double
//    root always lands in the quadratic factor.
//  * quartic: Orellana & De Michele, "Algorithm 1010: Boosting efficiency in
//    solving quartic equations with no compromise in accuracy", ACM TOMS
//    46(2), 2020: an LDL^T factorization driven by the dominant root of the
//    depressed resolvent cubic, the best of several equivalent formulas chosen
//    by backward error, Newton-Raphson refinement of the two real quadratic
//    factors, the stable quadratic on each; a factorization with two surely
//    complex factors is not refined (no real roots; the common case for ball
//    pairs that never touch). Departures from the paper: the "d2 ~ 0" case is
//    entered for any d2 > 0 and up to 64 eps (the paper's eps lets symmetric
//    quartics come out with no roots), and every factorization is certified
//    by its backward error before its roots are trusted.
//  * every real root from a quadratic factor is Newton-polished on the
//    original polynomial (guarded: a step is kept only if |p| decreases).
//  * fallback: when a factorization cannot be certified (roots spread over
//    ~30 orders of magnitude or more), the real critical points (recursively,
//    from the derivatives) split the line into monotone pieces and each sign
//    change is bisected on the binary representation; slow (~1-2 us) but
//    robust, and never triggered by ordinary table physics.
//  * range: inputs whose root scale lies within 2^-80..2^80 are solved
//    directly; others are first rescaled by an exact power of two (t = 2^e x),
//    so no intermediate overflows or underflows.
//
// Accuracy. Simple roots are accurate to their condition number,
// |error| <~ eps * sum_k |c_k| |t|^k / |p'(t)| (the level at which the sign
// of p is lost in double arithmetic; tested at <= 16x that bound against a
// long-double reference, typically within 2x).
//
// Tolerance policy for double roots (grazing contact). Round-off cannot decide
// whether a nearly tangent polynomial has two close roots, one double root or
// a close complex pair. The solvers report roots at a resolution `tol`
// (default kDefaultTangencyTolerance = 64 eps ~ 1.4e-14):
//  * a pair of roots (real or complex, from one quadratic factor) lying within
//    ~2^-14 relative of each other is reported as ONE root at their mean m
//    when p vanishes there to within round-off,
//        |p(m)| <= tol * sum_k |c_k| |m|^k,
//    otherwise as the two real roots, or none, that the discriminant says. In
//    particular a discriminant that is slightly negative by round-off at a
//    double root still yields the root, and a genuinely missing contact
//    (|p(m)| above that level) does not. For the standalone quadratic this is
//    exactly |b^2/4 - a c| <= tol * (3 b^2/4 + |a c|) -> root -b/(2a);
//  * two adjacent real roots closer than 2^-14 relative with p numerically
//    zero (as above) at their midpoint are merged into the midpoint.
// Consequences: a double root is located to about sqrt(tol) relative (the
// best any method can do: its position is that sensitive to the
// coefficients); roots inside a cluster where p is numerically zero may be
// reported as fewer roots, never as none. Larger `tol` (e.g. 1e-10) makes
// grazing detection more generous; keep it below ~1e-8.
//
// Known limits: a near-quadruple root (p flat to fourth order, e.g. a ball
// circling another at exactly contact distance) whose complex pairs are more
// than 2^-14 apart is not reported even if p only misses zero by round-off;
// roots smaller than ~1e-200 times the largest root lose relative accuracy or
// underflow to 0 (subnormal range).
//
// References: W. H. Press et al., Numerical Recipes (3rd ed., 2007), 5.6;
// W. Kahan, "To solve a real cubic equation", UC Berkeley tech. note (1986);
// A. G. Orellana, C. De Michele, ACM TOMS 46(2), Art. 20 (2020),
// doi:10.1145/3386241; G. H. Golub, C. F. Van Loan, Matrix Computations
// (companion-matrix baseline in bench/bench_polynomial_roots.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <optional>

namespace cueball {

/// Default resolution of the double-root (tangency) policy, relative to
/// sum_k |c_k| |t|^k. See the file comment.
inline constexpr double kDefaultTangencyTolerance = 64.0 * std::numeric_limits<double>::epsilon();

/// Coefficients in ascending powers: c[k] multiplies t^k.
using QuadraticCoefficients = std::array<double, 3>;
using CubicCoefficients = std::array<double, 4>;
using QuarticCoefficients = std::array<double, 5>;

/// The distinct real roots of a polynomial of degree at most N.
template <std::size_t N>
struct RealRoots {
  /// Ascending; entries [count, N) are NaN.
  std::array<double, N> t = filled_with_nan();
  /// Number of distinct real roots listed in `t`.
  int count = 0;
  /// True degree solved: index of the highest nonzero coefficient, or -1 when
  /// every coefficient is zero.
  int degree = -1;

  /// Every t is a root (all coefficients zero); `count` is 0.
  constexpr bool identically_zero() const noexcept { return degree < 0; }
  constexpr const double* begin() const noexcept { return t.data(); }
  constexpr const double* end() const noexcept { return t.data() + count; }
  constexpr double operator[](std::size_t i) const noexcept { return t[i]; }

 private:
  static constexpr std::array<double, N> filled_with_nan() noexcept {
    std::array<double, N> a{};
    for (auto& x : a) x = std::numeric_limits<double>::quiet_NaN();
    return a;
  }
};

using QuadraticRoots = RealRoots<2>;
using CubicRoots = RealRoots<3>;
using QuarticRoots = RealRoots<4>;

/// Real roots of c[0] + c[1] t + c[2] t^2.
QuadraticRoots solve_quadratic(const QuadraticCoefficients& c,
                               double tol = kDefaultTangencyTolerance) noexcept;

/// Real roots of c[0] + c[1] t + c[2] t^2 + c[3] t^3.
CubicRoots solve_cubic(const CubicCoefficients& c, double tol = kDefaultTangencyTolerance) noexcept;

/// Real roots of c[0] + c[1] t + c[2] t^2 + c[3] t^3 + c[4] t^4.
QuarticRoots solve_quartic(const QuarticCoefficients& c, double tol = kDefaultTangencyTolerance) noexcept;

/// The earliest real root in [t_min, t_max] (closed), or none; exactly the
/// first root the full solver reports inside the window (same tolerance
/// policy, no slack added at the ends). For an identically zero polynomial
/// every t is a root and t_min is returned. Empty or NaN window: none.
///
/// Fast path: p is first rewritten in the Bernstein basis on the window (a
/// Taylor shift and a fixed weighting, ~30 flops, no division); when all
/// Bernstein coefficients share a sign by a margin no reported root can cross
/// (4 tol + 64 eps times sum |c_k| (|t_min| + width)^k), p provably has no
/// root in the window and the solve is skipped. Most ball pairs are far apart
/// over a prediction window, so this is the common case.
std::optional<double> smallest_root_in(const QuadraticCoefficients& c, double t_min, double t_max,
                                       double tol = kDefaultTangencyTolerance) noexcept;
std::optional<double> smallest_root_in(const CubicCoefficients& c, double t_min, double t_max,
                                       double tol = kDefaultTangencyTolerance) noexcept;
std::optional<double> smallest_root_in(const QuarticCoefficients& c, double t_min, double t_max,
                                       double tol = kDefaultTangencyTolerance) noexcept;

/// p(t) by Horner's rule, ascending coefficients.
template <std::size_t M>
constexpr double evaluate(const std::array<double, M>& c, double t) noexcept {
  static_assert(M >= 1);
  double p = c[M - 1];
  for (std::size_t k = M - 1; k-- > 0;) p = p * t + c[k];
  return p;
}

}  // namespace cueball
