// Mathavan, Jackson & Parkin (2010), the ball-cushion impact of a rolling
// ball from a table: the `exact` solver's answer (mathavan_2010_exact.cpp)
// precomputed once per set of constants as piecewise Chebyshev interpolants
// in one variable, so that the commonest impact in a game costs a lookup.
//
// Why one variable. The friction rates depend only on the slip directions
// (mathavan_2010_equations.hpp), so the four slip velocities obey a closed,
// autonomous system, and the work W (16a) follows from them; the ends of
// compression (16c) and restitution (16b) are conditions on W and on the
// normal speed, itself a function of the slips (12b), (13b). The velocities
// are affine in the slips and the invariant J (the angular momentum about the
// line through C and I, mathavan_2010_exact.cpp), so the change of the
// velocity state over the impact depends on the initial slips alone. A
// rolling ball has no slip at C; in units of the incoming normal speed V its
// slip at I is (12a), (12b)
//   s_I = ((1 + s) xG' - c u_z, -(1 + s)),   s = sin(theta), c = cos(theta),
// (u = R w, rolling: u_x = -yG', u_y = xG'), so the whole impact is a function
// of xi = s_I,x / (1 + s) = xG' - c u_z / (1 + s), the incidence and the
// sidespin in one number, and scales with V (rate independence).
//
// The table. Over beta = atan(xi) in [0, atan(50)] the outputs (the change
// of xG', yG', u_x, u_y, u_z; P_I^c, P_I^f, W^c) are smooth except where the
// impact's sequence of slip and stick phases changes (a slip that reaches
// zero, a contact that sticks: kinks); negative xi is the mirror image
// X -> -X of positive xi (xG', u_y, u_z change sign), and xi = 0 exactly
// (head-on, no sidespin) is left to the exact solver. A scan of the exact
// solver's event signature locates those changes (bisected to 1e-12 rad);
// between them, Chebyshev interpolants of degree 15 are fitted on the exact
// solver at tolerance 1e-10 (within ~1e-8 of the solver at 1e-11 on the
// scans below, where the default 1e-7 is up to 7e-6 off) and each is
// checked against the solver between its nodes and at its ends, halving the
// piece until the check holds to 2e-8 x max(1, |xi|) (in units of V, i.e.
// relative to the largest incoming velocity) with the same signature
// everywhere. What cannot be fitted in pieces wider than 2e-4 rad (the
// neighbourhood of a kink; near xi = 0, where a slip closes in on zero and
// just misses it, the solver's answer is not smooth to 2e-8), and |xi| > 50
// (grazing, or sidespin beyond ~50 V/R), is left to the exact solver.
//
// Measured (a scratch scan, 20,000 random rolling balls per set of
// constants, alpha in [0.5, 90] deg, R w_z in [-3, 3] V, against the exact
// solver at tolerance 1e-11): worst error 5.3e-8 of the largest incoming
// velocity and 1.5e-6 deg of rebound angle over the carom and snooker
// cushions, the translator's fit, mu_w = 0.43, sin(theta) = 0.3 and 0.5, and
// e_e = 0.8 with mu_s = 0.5, mu_w = 0.3; left to the exact solver: at most
// 4e-3 rad of the 1.55 rad of beta. Where the two disagreed more (up to 7e-4
// with sin(theta) = 0.6, mu_s = 0.3, mu_w = 0.7, e_e = 0.9, grazing with
// large sidespin), the Richardson limit of the paper scheme sided with the
// table (1e-7): the exact solver's slip thresholds scale with the largest
// velocity, which is then large against the slips. The Runge-Kutta solve at
// tolerance 1e-7 (the default before 1e-8) is itself up to 7e-6 off the
// limit on rolling balls near xi = 0 with the snooker constants (tests/test_cushion_impact.cpp,
// CushionRollingTable.*, which check the table against both references).
//
// Cost: built on the first rolling ball (at the default tolerance, with
// rolling_table on) per set of constants (mu_w, mu_s, e_e, sin(theta)), not
// before: 550-1150 exact solves for the sets above (37,000-53,000 Runge-Kutta
// steps, 16-45 ms). The build stops at kMaxSolves solves or kMaxSteps steps,
// leaving the rest of beta to the exact solver: it did for mu_s = 1 with
// mu_w = tan(theta) and for sin(theta) = 0.6 with mu_w = 0.7 (which would
// take 2,200-5,900 solves and 0.2-0.9 s uncapped; 65-146 ms capped, on a
// loaded host, with 0.8-1.5 rad of the 1.55 rad of beta left to the solver).
// The build is deterministic (the same solves in the same order), and the
// kMaxTables most recently used tables are kept; an evicted one is rebuilt
// identically when needed, so an answer depends on the inputs and options
// alone, not on what the process did before. A lookup is an arctangent, a
// binary search and eight Chebyshev sums: ~730 instructions against ~19,800 for the Runge-Kutta solve
// (callgrind, the rolling grid of bench_cushion_impact); the simulator's
// (rebound(), the five velocities' sums alone) ~500.
//
// Sources: S. Mathavan, M. R. Jackson, R. M. Parkin, Proc. IMechE Part C 224
// (2010), equations (12), (13), (16) as numbered there. Chebyshev
// interpolation at the first-kind points and Clenshaw's recurrence: L. N.
// Trefethen, "Approximation Theory and Approximation Practice" (SIAM, 2013),
// chapters 3-4 and 8 (geometric convergence of analytic functions, the
// basis of the piecewise-smooth fit and of the check between the nodes).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include "mathavan_2010_equations.hpp"

namespace cueball::mathavan_2010 {

namespace {

constexpr std::size_t kNodes = 16;            // Chebyshev points per piece (degree 15)
constexpr std::size_t kOutputs = 8;           // d xG', d yG', d u_x, d u_y, d u_z, P_I^c, P_I^f, W^c
constexpr double kBuildTolerance = 1e-10;  // the exact solver's local tolerance for the table
constexpr double kFitError = 2e-8;     // per output, x max(1, |xi|), in units of V
constexpr double kXiMax = 50.0;        // |xi| beyond this: the exact solver
constexpr int kScan = 512;             // signature scan of [0, beta_max]
constexpr double kBoundaryWidth = 1e-12;  // a change of signature is located to this (rad)
constexpr double kMinPiece = 2e-4;     // narrower pieces are left to the exact solver (rad)
// Tables kept (least recently used evicted; rebuilt, identically, when needed
// again). A table is ~0.2 MB (its coefficients stored twice, by output and by degree).
constexpr std::size_t kMaxTables = 16;
// Exact solves a table may cost (~5-50 us each), and their Runge-Kutta
// steps (~1 us each); past either, what is left is left to the exact solver
// (see the measurements above).
constexpr int kMaxSolves = 6000;
constexpr long kMaxSteps = 120'000;  // and their Runge-Kutta steps (the build's time)

// A rolling ball's slip at C below this (x the velocity scale) is zero: the
// simulator's rolling balls have none to rounding.
constexpr double kRollingSlip = 1e-12;

struct Piece {
  double lo = 0.0;  // beta
  double hi = 0.0;
  bool fitted = false;  // false: the exact solver
  int events = 0;
  std::array<std::array<double, kNodes>, kOutputs> c{};  // Chebyshev coefficients
  std::array<std::array<double, kOutputs>, kNodes> by_degree{};  // the same, c[o][m] at [m][o]
};

struct RollingTable {
  double mu_w, mu_s, e, s;
  double beta_max = 0.0;
  int solves = 0;  // exact solves it took to build
  long steps = 0;  // and their Runge-Kutta steps
  std::vector<double> starts;  // pieces[i].lo, for the search
  std::vector<Piece> pieces;
};

bool same_constants(const RollingTable& t, const Coefficients& k) {
  return t.mu_w == k.mu_w && t.mu_s == k.mu_s && t.e == k.e && t.s == k.s;
}

// ------------------------------------------------------------------ building

struct Sample {
  bool ok = false;
  std::uint64_t signature = 0;
  int events = 0;
  int steps = 0;
  std::array<double, kOutputs> v{};
};

// The rolling ball with the given beta = atan(xi): yG' = 1, xG' = u_y = xi, u_x = -1, u_z = 0.
Sample solve_at(const Coefficients& k, double beta) {
  const double xi = std::tan(beta);
  const State y0{xi, 1.0, -1.0, xi, 0.0, 0.0};
  Sample out;
  try {
    const Outcome o = solve_exact(k, y0, {1.0, 1.0, 1.0, 1.0}, nullptr, kBuildTolerance);
    for (std::size_t i = kVx; i <= kUz; ++i) out.v[i] = o.final_state[i] - y0[i];
    out.v[5] = o.compression_impulse;
    out.v[6] = o.total_impulse;
    out.v[7] = o.compression_work;
    out.signature = o.signature;
    out.events = o.events;
    out.steps = o.steps;
    out.ok = std::all_of(out.v.begin(), out.v.end(), [](double x) { return std::isfinite(x); });
  } catch (...) {
    out.ok = false;  // wedged or out of steps: left to the exact solver
    out.steps = 20000;  // counted as the solver's most (its max_attempts)
  }
  return out;
}

// Chebyshev points of the first kind on [-1, 1].
double node(std::size_t j) { return std::cos(kPi * (static_cast<double>(j) + 0.5) / kNodes); }

// Sum of c_m T_m(x), Clenshaw's recurrence.
double clenshaw(const std::array<double, kNodes>& c, double x) {
  double b1 = 0.0;
  double b2 = 0.0;
  const double x2 = 2.0 * x;
  for (std::size_t m = kNodes - 1; m >= 1; --m) {
    const double b0 = c[m] + x2 * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + x * b1 - b2;
}

// clenshaw() of the first N outputs at once, from Piece::by_degree: the
// recurrences side by side (each a chain of dependent operations; together
// they fill the SIMD lanes and overlap), the same operations per output in
// the same order as clenshaw(), so the same values. N = 5 is the outgoing
// velocities alone (the simulator's rebound()), N = kOutputs everything.
template <std::size_t N>
std::array<double, N> clenshaw_all(const std::array<std::array<double, kOutputs>, kNodes>& c, double x) {
  static_assert(N <= kOutputs);
  std::array<double, N> b1{};
  std::array<double, N> b2{};
  const double x2 = 2.0 * x;
#pragma GCC unroll 16
  for (std::size_t m = kNodes - 1; m >= 1; --m) {
    for (std::size_t o = 0; o < N; ++o) {
      const double b0 = c[m][o] + x2 * b1[o] - b2[o];
      b2[o] = b1[o];
      b1[o] = b0;
    }
  }
  std::array<double, N> out;
  for (std::size_t o = 0; o < N; ++o) out[o] = c[0][o] + x * b1[o] - b2[o];
  return out;
}

struct Builder {
  Coefficients k;
  std::vector<Piece> pieces;
  int solves = 0;
  long steps = 0;

  bool spent() const { return solves >= kMaxSolves || steps >= kMaxSteps; }
  Sample solve(double beta) {
    ++solves;
    const Sample s = solve_at(k, beta);
    steps += s.steps;
    return s;
  }

  void fallback(double lo, double hi) {
    if (!(hi > lo)) return;
    if (!pieces.empty() && !pieces.back().fitted) {
      pieces.back().hi = hi;
      return;
    }
    Piece p;
    p.lo = lo;
    p.hi = hi;
    pieces.push_back(p);
  }

  // Fits [lo, hi], where the signature should be `signature` throughout,
  // halving until the check holds; appends the pieces in order.
  void fit(double lo, double hi, std::uint64_t signature) {
    if (!(hi - lo >= kMinPiece) || spent()) {
      fallback(lo, hi);
      return;
    }
    const double mid = 0.5 * (lo + hi);
    const double half = 0.5 * (hi - lo);
    Piece p;
    p.lo = lo;
    p.hi = hi;
    bool ok = true;
    std::array<std::array<double, kNodes>, kOutputs> f{};
    for (std::size_t j = 0; j < kNodes && ok; ++j) {
      const Sample s = solve(mid + half * node(j));
      ok = s.ok && s.signature == signature;
      p.events = s.events;
      for (std::size_t o = 0; o < kOutputs; ++o) f[o][j] = s.v[o];
    }
    if (ok) {
      for (std::size_t o = 0; o < kOutputs; ++o) {
        for (std::size_t m = 0; m < kNodes; ++m) {
          double sum = 0.0;
          for (std::size_t j = 0; j < kNodes; ++j) {
            sum += f[o][j] * std::cos(kPi * static_cast<double>(m) * (static_cast<double>(j) + 0.5) / kNodes);
          }
          p.c[o][m] = (m == 0 ? 1.0 : 2.0) * sum / kNodes;
        }
      }
      // The check: between the nodes (x = cos(pi j / n)) and at both ends.
      for (std::size_t j = 0; j <= kNodes && ok; ++j) {
        const double x = std::cos(kPi * static_cast<double>(j) / kNodes);
        const double beta = mid + half * x;
        const Sample s = solve(beta);
        ok = s.ok && s.signature == signature;
        const double allowed = kFitError * std::max(1.0, std::abs(std::tan(beta)));
        for (std::size_t o = 0; o < kOutputs && ok; ++o) ok = std::abs(clenshaw(p.c[o], x) - s.v[o]) <= allowed;
      }
    }
    if (ok) {
      p.fitted = true;
      pieces.push_back(p);
      return;
    }
    fit(lo, mid, signature);
    fit(mid, hi, signature);
  }
};

RollingTable build_table(const Coefficients& k) {
  RollingTable t{k.mu_w, k.mu_s, k.e, k.s, std::atan(kXiMax), 0, 0, {}, {}};
  Builder b{k, {}};
  const double beta_max = t.beta_max;
  auto signature_at = [&](double beta) {
    const Sample s = b.solve(beta);
    return s.ok ? s.signature : ~std::uint64_t{0};
  };
  auto beta_at = [&](int i) { return beta_max * i / kScan; };
  // Runs of one signature on the scan, their ends bisected.
  std::vector<std::uint64_t> scan(kScan + 1);
  for (int i = 0; i <= kScan; ++i) scan[static_cast<std::size_t>(i)] = signature_at(beta_at(i));
  auto fit_run = [&](double lo, double hi, std::uint64_t sig) {
    if (sig != ~std::uint64_t{0}) {
      b.fit(lo, hi, sig);
    } else {
      b.fallback(lo, hi);
    }
  };
  double run_lo = 0.0;
  std::uint64_t run_signature = scan[0];
  int i = 1;
  for (;;) {
    while (i <= kScan && scan[static_cast<std::size_t>(i)] == run_signature) ++i;
    if (i > kScan) {
      fit_run(run_lo, beta_max, run_signature);
      break;
    }
    // The signature changes in (lo, hi]: bisected.
    double lo = std::max(beta_at(i - 1), run_lo);
    double hi = beta_at(i);
    while (hi - lo > kBoundaryWidth && !b.spent()) {
      const double mid = 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) break;
      if (signature_at(mid) == run_signature) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    fit_run(run_lo, lo, run_signature);
    b.fallback(lo, hi);
    run_lo = hi;
    run_signature = signature_at(hi);  // scan point i is compared with the new run next
  }
  t.pieces = std::move(b.pieces);
  for (Piece& p : t.pieces) {
    for (std::size_t o = 0; o < kOutputs; ++o) {
      for (std::size_t m = 0; m < kNodes; ++m) p.by_degree[m][o] = p.c[o][m];
    }
  }
  t.solves = b.solves;
  t.steps = b.steps;
  t.starts.reserve(t.pieces.size());
  for (const Piece& p : t.pieces) t.starts.push_back(p.lo);
  return t;
}

// ------------------------------------------------------------------ the cache

// Tables are immutable once built. The cache holds the kMaxTables most
// recently used, most recent last; each thread also holds the last table it
// used, so that a table evicted meanwhile stays alive while that thread
// looks answers up in it, and so that the usual lookup (the same constants
// as the last impact on this thread) takes no lock. Building happens under
// the cache's lock: a thread that needs a table another is building waits
// for it rather than building it twice.
using TablePtr = std::shared_ptr<const RollingTable>;

struct Cache {
  std::mutex mutex;
  std::vector<TablePtr> tables;  // least recently used first
  std::size_t builds = 0;
};

Cache& cache() {
  static Cache* const c = new Cache;  // never destroyed: threads may outlive static destruction
  return *c;
}

thread_local TablePtr t_last;

// The table for k, built on first use. The pointer stays valid until this
// thread's next call.
const RollingTable& table_for(const Coefficients& k) {
  if (t_last != nullptr && same_constants(*t_last, k)) return *t_last;
  Cache& c = cache();
  const std::lock_guard<std::mutex> lock(c.mutex);
  const auto it = std::find_if(c.tables.begin(), c.tables.end(), [&](const TablePtr& t) { return same_constants(*t, k); });
  if (it != c.tables.end()) {
    std::rotate(it, it + 1, c.tables.end());  // now the most recently used
  } else {
    c.tables.push_back(std::make_shared<const RollingTable>(build_table(k)));
    ++c.builds;
    if (c.tables.size() > kMaxTables) c.tables.erase(c.tables.begin());
  }
  t_last = c.tables.back();
  return *t_last;
}

}  // namespace

RollingTableStats rolling_table_stats(const Coefficients& k) {
  RollingTableStats st;
  const RollingTable* t = &table_for(k);
  st.built = true;
  st.beta_max = t->beta_max;
  st.solves = t->solves;
  st.steps = t->steps;
  for (const Piece& p : t->pieces) {
    if (p.fitted) {
      ++st.fitted_pieces;
    } else {
      ++st.fallback_pieces;
      st.fallback_width += p.hi - p.lo;
    }
  }
  return st;
}

bool solve_rolling(const Coefficients& k, const State& y0, Outcome& out, RollingOutputs outputs) {
  const double scale = std::max(velocity_scale(y0), 1.0);
  const Vec2 sc = bed_slip(y0);
  const double limit = kRollingSlip * scale;
  if (!(sc.x * sc.x + sc.y * sc.y <= limit * limit)) return false;
  const double xi = cushion_slip(k, y0).x * k.inv_1ps;
  // Exactly head-on without sidespin: the Runge-Kutta solve, which keeps the
  // impact in its plane exactly (and is piecewise linear there, in few steps).
  if (!(std::abs(xi) <= kXiMax) || xi == 0.0) return false;
  const RollingTable* t = &table_for(k);  // built here, on the first rolling impact with these constants
  const double beta = std::atan(std::abs(xi));
  const auto it = std::upper_bound(t->starts.begin(), t->starts.end(), beta);
  if (it == t->starts.begin()) return false;
  const Piece& p = t->pieces[static_cast<std::size_t>(it - t->starts.begin()) - 1];
  if (!p.fitted || !(beta <= p.hi)) return false;
  const double x = std::clamp((2.0 * beta - p.lo - p.hi) / (p.hi - p.lo), -1.0, 1.0);
  // The mirror image X -> -X of an impact (xi -> -xi) turns xG', u_y, u_z
  // and keeps yG', u_x, the impulses and the work.
  const double mirror = xi < 0.0 ? -1.0 : 1.0;
  auto set_velocities = [&](const auto& v) {
    out.final_state[kVx] = y0[kVx] + mirror * v[kVx];
    out.final_state[kVy] = y0[kVy] + v[kVy];
    out.final_state[kUx] = y0[kUx] + v[kUx];
    out.final_state[kUy] = y0[kUy] + mirror * v[kUy];
    out.final_state[kUz] = y0[kUz] + mirror * v[kUz];
  };
  out.steps = 0;
  out.events = p.events;
  if (outputs == RollingOutputs::velocities) {
    set_velocities(clenshaw_all<kUz + 2>(p.by_degree, x));
    return true;
  }
  const std::array<double, kOutputs> v = clenshaw_all<kOutputs>(p.by_degree, x);
  set_velocities(v);
  out.compression_impulse = v[5];
  out.total_impulse = v[6];
  out.compression_work = v[7];
  out.final_state[kWork] = (1.0 - k.e * k.e) * out.compression_work;  // (16b)
  return true;
}

}  // namespace cueball::mathavan_2010
