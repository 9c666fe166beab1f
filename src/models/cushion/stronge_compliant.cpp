// The `stronge_compliant` ball-cushion model: Stronge's compliant contact
// with tangential compliance at the cushion contact I of a free sphere.
//
// Sources: W. J. Stronge, "Impact Mechanics" (CUP, 1st ed. 2000, section 5.2;
// 2nd ed. 2018); pooltool's `stronge_compliant` model (see the header). The
// derivation below is ours; equation labels S1-S9 are the header's.
//
// S1. The contact point I of a sphere at r = R n moves with w = v + omega x r.
// An impulse J at I changes v by J / M and omega by r x J / I (I = 2/5 M R^2),
// so w by J / M + (R^2 / I) (J - n (n . J)) / M: 1/M along n and
// (1 + 5/2)/M = beta/M in the tangent plane, no cross terms. Normal and
// tangential problems separate, and a tangential impulse parallel to the
// initial slip keeps the slip on that line (Stronge's collinear case): one
// scalar v (tangential velocity of I along the initial slip direction t) and
// one spring deflection u along t.
//
// Units: velocities in V (the incoming normal speed of I, yG'(0) cos theta),
// time in 1/omega_n (omega_n^2 = k / M, the compression frequency), forces in
// M V omega_n, impulses in M V, deflections in V / omega_n.
//
// S2. Normal: M d(w_n)/dt = -k x during compression gives w_n = -cos t (taking
// w_n < 0 approaching, as Stronge does), the compression ends at t = pi/2
// with the spring's energy M V^2 / 2. Restitution unloads a spring k / e^2
// from the same force: frequency omega_n / e, so with phi = pi/2 +
// (t - pi/2)/e the force stays sin(phi) (continuous at pi/2), w_n =
// -e cos(phi), and separation is at phi = pi, t_f = (1 + e) pi/2, with
// w_n = e: the returned energy is e^2 times the stored one, Stronge's
// energetic coefficient (equal to the kinematic one here since friction
// does not act on the normal motion, S1). The normal impulse is
// p = integral of sin(phi) dt = 1 - cos t, then 1 - e cos(phi).
//
// S3-S6. The massless particle at I carries the tangential spring k_t. The
// spring force on the ball is k_t u (per M V omega_n: Omega^2 u / beta with
// Omega^2 = beta k_t / k), so dv/dt = Omega^2 u. Sticking, the particle is
// at rest on the cushion: du/dt = -v, hence u'' = -Omega^2 u (S6); Omega is
// the tangential natural frequency in units of omega_n (S3). Coulomb's law at
// the particle bounds the spring force by mu times the normal force:
// Omega^2 |u| / beta <= mu sin(phi), i.e. |u| <= L = mu eta^2 sin(phi) with
// eta^2 = beta / Omega^2 = k / k_t (S4). Slipping in direction sigma (the
// particle's velocity s = v + du/dt has the sign sigma), the spring force
// is at the limit against the slip, u = -sigma L, so dv/dt = -sigma mu beta
// sin(phi) and v(t) - v(t0) = -sigma mu beta (p(t) - p(t0)) (S5). With
// p = 1 - kappa cos(phi) and dphi/dt = 1/kappa (kappa = 1 in compression, e
// in restitution),
//   s = v(t0) - sigma mu beta kappa (cos phi0 - cos phi) - sigma mu eta^2 cos(phi) / kappa,
// affine in cos(phi): monotone in time within each normal phase, so its zero
// (slip -> stick, S7) has a closed form, and after a sign check there is at
// most one per phase. ds/dt = sigma mu sin(phi) (eta^2 / kappa^2 - beta):
// |s| can only fall while Omega > 1/kappa, which is also the condition for
// the stick to hold once s = 0 (the stick's |u|'' = -Omega^2 L must not
// exceed L'' = -L / kappa^2).
//
// S7. A stick holds while |u(t)| <= L(t) and breaks at the first t where
// |u| - L turns positive; slip then starts opposite the spring force,
// sigma = -sign(u), and friction stays continuous. |u(t)| is bounded by the
// amplitude a = sqrt(u_s^2 + (v_s / Omega)^2), so the break can only come
// where L < a: before phi = asin(a / (mu eta^2)) or after pi minus that. In
// those windows g = |u| - L is followed by steps that cannot pass its first
// zero: from a point with g < 0 each step is the largest h for which an
// upper bound of g on [t, t + h] is still negative (Stick::safe_step: a
// quadratic with |g''| <= Omega^2 a + mu eta^2 (dphi/dt)^2, which converges
// on a zero quadratically, like Newton's method from one side; lines from
// the concavity of |u| between its zeros and of L; and a quadratic with
// the exact slope and the curvature bounded over the step, for sticks that
// barely hold or barely break). A sampled scan would miss the short
// excursions of g above zero that stiff springs make (and the exit slip
// would jump). At t_f, L = 0, so a stick
// that lasts to the end leaves u = 0, as does a slip: the tangential spring
// returns all its energy and the ball's tangential energy beta^-1 v^2 / 2
// can only fall (friction at the particle does negative work), |v_f| <= v0.
//
// S8. At t = 0 the spring is unloaded and L = 0. A stick needs |du/dt| =
// |v0| within dL/dt = mu eta^2: v0 <= mu eta^2 starts sticking. Otherwise
// the slip runs on; s is monotone within each normal phase (S5), so the slip
// lasts to separation (gross slip) if s is still positive at the end of
// compression, s = v0 - mu beta, and at separation, s(t_f) = v0 - mu beta
// (1 + e) + mu eta^2 / e: v0 >= mu max(beta, (1 + e) beta - eta^2 / e); then
// v_f = v0 - mu beta (1 + e). pooltool's closed form has three cases (gross
// slip, stick-slip, slip-stick-slip) with at most one stick, the break in
// restitution and the final slip reversed, and tests gross slip with the
// second term only; that holds for e > 1/Omega and the usual constants (e =
// 0.85, Omega = 1.8), where it agrees with the phase loop here (the tests
// reproduce pooltool's reference values). The loop needs none of those
// assumptions.
//
// S9. Back to SI: the normal impulse (1 + e) M V along -n and the tangential
// (v_f - v0) M V / beta along t, applied to the free sphere; then the bed
// removes zG' (a vertical impulse at the bed contact C, through the centre:
// no torque, and it only removes kinetic energy).
#include "cueball/models/cushion/stronge_compliant.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = 0.5 * kPi;
constexpr double kBeta = 3.5;  // S1: 1 + M R^2 / I for a solid sphere
// A phase loop that has not reached separation after this many phases keeps
// the tangential velocity it has. Stiff springs make many short stick-slip
// cycles near separation, about 0.7 Omega phases (a few for Omega ~ 2, some
// 700 at the largest Omega validate() accepts, 1000).
constexpr int kMaxPhases = 4096;

// The scalar problem's constants.
struct Scalar {
  double mu;
  double e;
  double omega;   // Omega (S3)
  double eta2;    // eta^2 = beta / Omega^2
  double t_f;     // (1 + e) pi/2
  double limit;   // mu eta^2, the amplitude of L (S4)
};

// Normal phase angle phi(t) (S2).
inline double phase(const Scalar& k, double t) { return t <= kHalfPi ? t : kHalfPi + (t - kHalfPi) / k.e; }
// kappa of the normal phase: 1 in compression, e in restitution; dphi/dt = 1/kappa.
inline double kappa_at(const Scalar& k, double t) { return t < kHalfPi ? 1.0 : k.e; }

// The tangential state at a phase switch.
struct Tangential {
  double t;  // time
  double v;  // tangential velocity of I along t
  double u;  // spring deflection
};

// S5: slip in direction sigma from `x` to the first zero of s or the end of
// the normal phase. Returns true if the slip reached s = 0 (a stick starts).
bool slip(const Scalar& k, double sigma, Tangential& x) {
  const bool compressing = x.t < kHalfPi;
  const double kappa = compressing ? 1.0 : k.e;
  const double t_end = compressing ? kHalfPi : k.t_f;
  const double phi_end = compressing ? kHalfPi : kPi;
  const double cos0 = std::cos(phase(k, x.t));
  const double cos_end = std::cos(phi_end);
  const double drop = sigma * k.mu * kBeta * kappa;  // dv = -drop (cos phi0 - cos phi)
  const double a = x.v - drop * cos0;                // s = a + b cos(phi)
  const double b = sigma * k.mu * (kBeta * kappa - k.eta2 / kappa);
  const double s_end = a + b * cos_end;
  if (sigma * s_end > 0.0 || b == 0.0) {
    x.v -= drop * (cos0 - cos_end);
    x.t = t_end;
    x.u = -sigma * k.limit * std::sin(phi_end);
    return false;
  }
  // s changes sign in (phi0, phi_end]: cos(phi*) = -a / b, kept in the bracket.
  const double c = std::clamp(-a / b, cos_end, cos0);
  const double phi = std::acos(c);
  x.v -= drop * (cos0 - c);
  x.t = std::min(compressing ? phi : kHalfPi + (phi - kHalfPi) * k.e, t_end);
  x.u = -sigma * k.limit * std::sqrt(std::max(0.0, (1.0 - c) * (1.0 + c)));
  return true;
}

// S6, S7: the stick from `x` to its break (returns true, `x` at the break)
// or to separation (returns false, `x` at t_f).
class Stick {
 public:
  Stick(const Scalar& k, const Tangential& x)
      : k_(k),
        t_s_(x.t),
        u_s_(x.u),
        v_s_(x.v),
        amp_(std::sqrt(x.u * x.u + (x.v / k.omega) * (x.v / k.omega))),
        rate_(std::max(1.0, 1.0 / k.e)),
        curvature_(k.omega * k.omega * amp_ + k.limit * rate_ * rate_),
        tolerance_(1e-14 * (amp_ + k.limit)) {}

  bool run(Tangential& x) const {
    double t_break = k_.t_f;
    bool broke = false;
    if (amp_ >= k_.limit) {
      broke = search(t_s_, k_.t_f, t_break);
    } else {
      // L < amp only for phi < alpha or phi > pi - alpha.
      const double alpha = std::asin(amp_ / k_.limit);
      const double t_a = alpha;
      const double t_b = kHalfPi + k_.e * (kHalfPi - alpha);
      if (t_s_ < t_a) broke = search(t_s_, t_a, t_break);
      if (!broke) broke = search(std::max(t_s_, t_b), k_.t_f, t_break);
    }
    const Value end = at(broke ? t_break : k_.t_f);
    x.t = broke ? t_break : k_.t_f;
    x.u = end.u;
    x.v = end.v;
    return broke && t_break < k_.t_f;
  }

 private:
  struct Value {
    double g;      // |u| - L
    double slope;  // |du/dt| - dL/dt >= dg/dt
    double u;
    double v;
    double dl;     // dL/dt
  };

  Value at(double t) const {
    const double w = k_.omega * (t - t_s_);
    const double sw = std::sin(w);
    const double cw = std::cos(w);
    const double u = u_s_ * cw - v_s_ / k_.omega * sw;
    const double v = k_.omega * u_s_ * sw + v_s_ * cw;  // v = -du/dt
    const double phi = phase(k_, t);
    const double l = k_.limit * std::sin(phi);
    const double dl = k_.limit * std::cos(phi) / kappa_at(k_, t);
    return {std::abs(u) - l, std::abs(v) - dl, u, v, dl};
  }

  // The first step from the start of the stick, where g = 0. After a slip
  // (|u| = L, dg/dt = 0), g'' = (dphi/dt^2 - Omega^2) L < 0 and the bound
  // Omega^3 amp + mu eta^2 (dphi/dt)^3 on the third derivative keep g below
  // zero up to -3 g'' / that bound (half of it is taken; u keeps its sign
  // there, and the step stays in the normal phase, where L is smooth). At
  // t = 0 (u = L = 0) the general step applies, with a probe for the
  // borderline v0 = mu eta^2.
  double first_step(const Value& start) const {
    const double probe = kPi / 16.0 / std::max(k_.omega, rate_);
    if (start.u == 0.0) return start.slope < 0.0 ? -2.0 * start.slope / curvature_ : probe;
    const bool compressing = t_s_ < kHalfPi;
    const double rate = compressing ? 1.0 : 1.0 / k_.e;
    const double g2 = (rate * rate - k_.omega * k_.omega) * std::abs(start.u);
    if (!(g2 < 0.0)) return 0.0;
    const double g3 = k_.omega * k_.omega * k_.omega * amp_ + k_.limit * rate * rate * rate;
    const double h = 0.5 * std::min(-3.0 * g2 / g3, std::abs(start.u) / (k_.omega * amp_));
    return compressing ? std::min(h, kHalfPi - t_s_) : h;
  }

  // How far g surely stays negative from a point where g < 0, within the
  // current normal phase (dphi/dt = rate, 1 or 1/e): the larger of two
  // bounds, then grown by a third. (1) g(t + h) <= g + slope h +
  // C h^2 / 2 with C = Omega^2 amp + mu eta^2 rate^2 >= |g''|: converges on a
  // break quadratically. (2) |u| is concave between its zeros and |du/dt| <=
  // Omega amp, so |u(t + h)| <= max(|u| + h d|u|/dt, Omega amp h - |u|);
  // L is concave on [0, t_f] with L(t_f) = 0, so L(t + h) >= L (1 - h /
  // (t_f - t)): lines, which take long steps where (1) is slow (u and L both
  // small, |u| falling).
  double safe_step(double t, const Value& v) const {
    const bool compressing = t < kHalfPi;
    const double rate = compressing ? 1.0 : 1.0 / k_.e;
    const double curvature = k_.omega * k_.omega * amp_ + k_.limit * rate * rate;
    const double quadratic = (-v.slope + std::sqrt(v.slope * v.slope - 2.0 * curvature * v.g)) / curvature;
    const double au = std::abs(v.u);
    const double l = au - v.g;
    const double chord = l / (k_.t_f - t);                     // -(chord slope of L to t_f)
    const double rise = u_rate(v);                               // d|u|/dt
    const double first = rise + chord > 0.0 ? -v.g / (rise + chord) : kPi;  // |u| + h d|u|/dt reaches L
    const double second = (au + l) / (k_.omega * amp_ + chord);  // Omega amp h - |u| reaches L
    double h = std::max(quadratic, std::min(first, second));
    // (3) While u keeps its sign, g'' = -Omega^2 |u| + dphi/dt^2 L exactly,
    // and over [t, t + h] it is at most C(h) = -Omega^2 max(0, |u| - Omega amp h)
    // + rate^2 min(mu eta^2, L + max(0, dL/dt) h); with the true slope g' that
    // certifies g + g' s + C(h) s^2 / 2 < 0 on [0, h]. Where the curvature
    // bound of (1) is far above the real g'' (a stick that barely holds or
    // barely breaks) this takes steps many times longer: h is doubled while
    // that holds.
    const double g1 = rise - v.dl;
    const double no_zero = au / (k_.omega * amp_);  // u keeps its sign this long
    for (int i = 0; i < 40; ++i) {
      const double next = 2.0 * h;
      if (!(next <= no_zero) || !below_zero(v.g, g1, local_curvature(au, l, v.dl, rate, next), next)) break;
      h = next;
    }
    return compressing ? std::min(h, kHalfPi - t) : h;
  }

  double local_curvature(double au, double l, double dl, double rate, double h) const {
    const double u_low = std::max(0.0, au - k_.omega * amp_ * h);
    const double l_high = std::min(k_.limit, l + std::max(0.0, dl) * h);
    return -k_.omega * k_.omega * u_low + rate * rate * l_high;
  }

  // g + g1 s + c s^2 / 2 < 0 for all s in [0, h], given g < 0.
  static bool below_zero(double g, double g1, double c, double h) {
    auto q = [&](double s) { return g + g1 * s + 0.5 * c * s * s; };
    if (q(h) >= 0.0) return false;
    if (c < 0.0) {
      const double top = -g1 / c;  // the maximum of a concave q
      if (top > 0.0 && top < h && q(top) >= 0.0) return false;
    }
    return true;
  }

  // d|u|/dt = -sign(u) v (|u| grows at |v| from u = 0).
  static double u_rate(const Value& v) { return v.u > 0.0 ? -v.v : v.u < 0.0 ? v.v : std::abs(v.v); }

  // The first break in [lo, hi]: stepping by safe_step() never passes one (a
  // sampled scan would miss the short excursions of g above zero that stiff
  // springs make). A break is declared where g >= -tolerance.
  bool search(double lo, double hi, double& t_break) const {
    if (!(hi > lo)) return false;
    double t = lo;
    Value v = at(t);
    for (int i = 0; i < kMaxSteps; ++i) {
      double h = 0.0;
      if (v.g < -tolerance_) {
        h = safe_step(t, v);
      } else if (i == 0 && lo == t_s_) {
        h = first_step(v);
      }
      // g has reached zero (or the step is below the resolution of t): the stick breaks at t
      if (!(h > 0.0) || !(t + h > t)) break;
      if (t + h >= hi) return false;
      t += h;
      v = at(t);
    }
    t_break = t;
    return true;
  }

  static constexpr int kMaxSteps = 10000;

  const Scalar& k_;
  double t_s_;
  double u_s_;
  double v_s_;
  double amp_;        // amplitude of u
  double rate_;       // the fastest dphi/dt, max(1, 1/e)
  double curvature_;  // bound on |g''|
  double tolerance_;  // g >= -tolerance is a break
};

// The tangential velocity of I at separation, v_f, from v0 >= 0 (S8).
double tangential_exit(const Scalar& k, double v0) {
  Tangential x{0.0, v0, 0.0};
  bool sticking = v0 <= k.limit;
  double sigma = 1.0;
  for (int i = 0; i < kMaxPhases && x.t < k.t_f; ++i) {
    if (sticking) {
      if (!Stick(k, x).run(x)) break;
      sigma = x.u > 0.0 ? -1.0 : 1.0;  // slip against the spring force: friction stays continuous
      sticking = false;
    } else {
      sticking = slip(k, sigma, x);
    }
  }
  return x.v;
}

Scalar scalar(const StrongeCompliantCushion& c) {
  const double omega = c.frequency_ratio;
  const double eta2 = kBeta / (omega * omega);
  return {c.friction, c.restitution, omega, eta2, (1.0 + c.restitution) * kHalfPi, c.friction * eta2};
}

[[noreturn]] void reject(const char* field, double value, const std::string& allowed, const char* meaning) {
  throw InvalidArgument(field, value, allowed, meaning);
}

}  // namespace

// ------------------------------------------------------------------ public

void validate(const StrongeCompliantCushion& c) {
  if (!(std::isfinite(c.radius) && c.radius > 0.0)) reject("radius", c.radius, "(0, inf)", "ball radius R, m");
  if (!(std::isfinite(c.restitution) && c.restitution > 0.0 && c.restitution <= 1.0)) {
    reject("e", c.restitution, "(0, 1]", "ball-cushion energetic coefficient of restitution (S2)");
  }
  require_in_range("mu", c.friction, 0.0, 1.0, "ball-cushion Coulomb friction at I (S4)");
  if (!(std::isfinite(c.sin_theta) && c.sin_theta >= 0.0 && c.sin_theta < 1.0)) {
    reject("sin_theta", c.sin_theta, "[0, 1)", "sin(theta) = (h - R)/R of the contact normal at I");
  }
  if (!(std::isfinite(c.frequency_ratio) && c.frequency_ratio > 1.0 && c.frequency_ratio <= 1000.0)) {
    reject("Omega", c.frequency_ratio, "(1, 1000]",
           "ratio omega_t/omega_n of the tangential to the normal natural frequency (S3)");
  }
  // S9: yG' after = yG' (1 - (1 + e) cos^2) - (friction impulse along Y') sin, and
  // that impulse is at most mu (1 + e) V: the ball leaves the cushion for sure if
  // (1 + e) cos (cos - mu sin) > 1.
  const double s = c.sin_theta;
  const double co = std::sqrt((1.0 - s) * (1.0 + s));
  if (!((1.0 + c.restitution) * co * (co - c.friction * s) > 1.0)) {
    reject("sin_theta", s,
           "(1 + e) cos(theta) (cos(theta) - mu sin(theta)) > 1 (here " +
               format_number((1.0 + c.restitution) * co * (co - c.friction * s)) + ")",
           "sin(theta) of the contact normal at I: the bed absorbs the vertical part of the rebound (S9), "
           "and with this much of it the ball may not leave the cushion");
  }
}

StrongeCompliantCushion stronge_compliant_cushion(const BallParameters& ball, const StrongeCompliantConstants& k) {
  const StrongeCompliantCushion c{ball.radius, k.restitution, k.friction, k.sin_theta, k.frequency_ratio};
  validate(c);
  return c;
}

double stronge_frequency_ratio(double nu) {
  if (!(std::isfinite(nu) && nu >= 0.0 && nu < 0.5)) {
    reject("nu", nu, "[0, 0.5)", "Poisson's ratio of the cushion contact");
  }
  const double eta2 = (2.0 - nu) / (2.0 * (1.0 - nu));
  return std::sqrt(kBeta / eta2);
}

CushionRebound stronge_compliant_rebound(const IncomingBall& ball, const StrongeCompliantCushion& c) noexcept {
  const double s = c.sin_theta;
  const double co = std::sqrt((1.0 - s) * (1.0 + s));
  const double r = c.radius;
  const Vec3 v = ball.velocity;
  const Vec3 w = ball.angular_velocity;
  // S1: velocity of I, normal (into the cushion) and in the tangent plane along
  // X and Y' = (0, -sin theta, cos theta) (Mathavan's (12a), (12b) with zG' = 0).
  const double vn = v.y * co;
  const double sx = v.x + r * (w.y * s - w.z * co);
  const double sy = -v.y * s + r * w.x;
  const double slip = std::sqrt(sx * sx + sy * sy);
  double jt = 0.0;  // tangential impulse / M along the slip, m/s
  double tx = 0.0;
  double ty = 0.0;
  if (slip > 0.0 && c.friction > 0.0) {
    const double vf = tangential_exit(scalar(c), slip / vn);
    jt = (vf * vn - slip) / kBeta;
    tx = sx / slip;
    ty = sy / slip;
  }
  const double jn = (1.0 + c.restitution) * vn;  // S2: normal impulse / M along -n
  // S9: J/M = -jn n + jt (tx X + ty Y'); the spin changes by 5/(2R) n x J/M,
  // with n x X = (0, sin, -cos) and n x Y' = (1, 0, 0); then zG' = 0.
  const double spin = 2.5 * jt / r;
  CushionRebound out;
  out.velocity = {v.x + jt * tx, v.y - jn * co - jt * ty * s, 0.0};
  out.angular_velocity = {w.x + spin * ty, w.y + spin * tx * s, w.z - spin * tx * co};
  return out;
}

}  // namespace cueball
