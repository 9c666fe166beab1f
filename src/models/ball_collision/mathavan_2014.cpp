// Ball-ball impact of Mathavan, Jackson & Parkin (2014), solved exactly
// (M1-M11 of include/cueball/models/ball_collision/mathavan_2014.hpp).
//
// Derivation. Per unit mass, the impulse P = p n + P_t t + P_z z on b at
// K = r_b - R n (-P on a at K = r_a + R n) and the cloth's F_X + N_X z on X
// at C_X = r_X - R z change (n x t = z, t x z = n, z x n = t)
//   v_X by the horizontal parts (the vertical ones cancel: the balls stay on
//       the cloth, M3),
//   w_b by (m/I) (-R n) x P + (m/I) (-R z) x F_b = 5/(2R) (P_z t - P_t z - z x F_b),
//   w_a by (m/I) (R n) x (-P) + (m/I) (-R z) x F_a = 5/(2R) (P_z t - P_t z - z x F_a)   (M4).
// The slips of M1 then change by (with (z x F) x n = -(F . n) z and
// (z x F) x z = F for horizontal F)
//   dc = -2 dp n - 7 dP_t t - 5 dP_z z + (dF_a - dF_b) + 5/2 ((dF_a + dF_b) . n) z
//   dsigma_X = dv_X - R dw_X x z = dv_X - 5/2 dP_z n + 5/2 dF_X                  (M5).
// The normal reaction of the cloth: the vertical friction at K is -dP_z on a
// and +dP_z on b; a ball pushed down is held by the cloth, gravity's impulse
// is O(g tau) with tau ~ 0.2 ms and is neglected, so dN_a = max(dP_z, 0) and
// dN_b = max(-dP_z, 0) (M3), and each pressed contact slips with Coulomb's
// dF_X = -mu_s sigma_X^ dN_X (M7).
//
// Coulomb at K (M6): (dP_t, dP_z) = mu_b s^ dp. If the slip stops, sticking
// needs ds = 0, i.e. dP_z = ((dF_a + dF_b) . n)/2, where |dF| <= mu_s |dP_z|:
// |dP_z| <= mu_s |dP_z| / 2 forces dP_z = 0, no cloth load, dF = 0, dP_t = 0.
// So a grip carries no friction and lasts to the end of the impact.
//
// M8: at s_z = 0 the friction has no vertical part, no cloth load and
// ds_z = 0: s_z keeps its sign, and the pressed ball is fixed by s_z(0).
//
// M7 (cloth slip at zero): its rate is h + 7/2 dF_X/dp, where h (M5 without
// the cloth) has the component along n of -(1 + 5/2 dP_z/dp) for a
// (pressed: dP_z > 0) and 1 - 5/2 dP_z/dp for b (pressed: dP_z < 0), so
// |h| >= 1, while |7/2 dF_X/dp| <= 7/2 mu_s mu_b <= 0.875 in the ranges of
// validate(): the contact cannot stick, and it starts to slip along h (the
// cloth contact is isotropic).
//
// Restitution (M9): W(p) = Int_0^p u_n dp; W_c = W(p_c) at u_n(p_c) = 0; the
// end p_f has W(p_f) = (1 - e^2) W_c (Stronge's energetic coefficient).
//
// Slip age (M10). Near a grip the slip s goes to zero after a finite normal
// impulse like a non-integer power (the anisotropy 7 vs 5 turns s^ towards
// z), where no polynomial integrator keeps its order. In the slip age L,
// mu_b dp = |s| dL, every rate is a smooth, bounded function times |s|:
//   dp/dL = |s|/mu_b,  dP_t/dL = s_t,  dP_z/dL = s_z,
//   dF_X/dL = -mu_s |s_z| sigma_X^ (pressed ball only),  dW/dL = u_n |s|/mu_b,
// with u_n, s, sigma linear in (p, P_t, P_z, F) (M5); the grip is L -> inf.
// Without cloth friction this is s_t0 e^{-7L}, s_z0 e^{-5L} of
// ball_collision.cpp (B7). But while |s| >> mu_b the impact is over in a
// tiny range of L in which p and W change fast; so the integration variable
// is tau with dL/dtau = mu_b / (|s| + mu_b) (in units of u_n(0)): the rates
// in tau are those in L times that factor, p ~ tau for a large slip and
// tau ~ L near a grip. The slip's relative rate of decay in tau is at most
// 7 mu_b / (|s| + mu_b) (bounded by 7), which also bounds the step for
// stability. The state is integrated by the Dormand-Prince 5(4) pair
// (Hairer, Norsett & Wanner, "Solving ODEs I", II.5; first stage of a step =
// last of the one before); the end of compression (u_n = 0) and the end of
// the impact (M9) are found on the step that crosses them: root of the cubic
// Hermite interpolant, then Newton's method on the step length.
//
// Everything is scaled: velocities (and R w) in units of u_n(0), impulses per
// unit mass in the same units. The solution scales exactly with u_n(0).
#include "cueball/models/ball_collision/mathavan_2014.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/dormand_prince.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

// State, a function of tau (M10): p, P_t, P_z, the pressed ball's cloth
// friction impulse F in (n, t) components, and the normal work W.
constexpr std::size_t kStateSize = 6;
using State = std::array<double, kStateSize>;
enum : std::size_t { kP = 0, kPt = 1, kPz = 2, kFn = 3, kFt = 4, kWork = 5 };

struct Model {
  double inv_mu;     // 1 / mu_b
  double mu_s;       // cloth friction
  double st0, sz0;   // incoming ball-ball slip (M1)
  double pressed;    // +1: a pressed into the cloth, -1: b, 0: neither (M8)
  double sn0, stt0;  // the pressed ball's incoming cloth slip along n, t

  double slip_t(const State& y) const { return st0 - 7.0 * y[kPt] + pressed * y[kFt]; }
  double slip_z(const State& y) const { return sz0 - 5.0 * y[kPz] + 2.5 * y[kFn]; }
  double approach(const State& y) const { return 1.0 - 2.0 * y[kP] + pressed * y[kFn]; }

  // dy/dtau (M10): the rates in L times dL/dtau = mu_b / (|s| + mu_b).
  State rates(const State& y) const {
    const double st = slip_t(y);
    const double sz = slip_z(y);
    const double slip = std::sqrt(st * st + sz * sz);
    const double to_tau = 1.0 / (slip * inv_mu + 1.0);
    const double dp = slip * inv_mu;
    State d{dp * to_tau, st * to_tau, sz * to_tau, 0.0, 0.0, approach(y) * dp * to_tau};
    if (pressed != 0.0) {
      double sn = sn0 - pressed * y[kP] - 2.5 * y[kPz] + 3.5 * y[kFn];
      double stt = stt0 - pressed * y[kPt] + 3.5 * y[kFt];
      double m = std::sqrt(sn * sn + stt * stt);
      if (!(m > 1e-300)) {
        // At zero slip: along the rate that friction cannot cancel (M7).
        sn = -pressed * dp - 2.5 * sz;
        stt = -pressed * st;
        m = std::sqrt(sn * sn + stt * stt);
      }
      const double k = m > 0.0 ? -mu_s * std::abs(sz) * to_tau / m : 0.0;
      d[kFn] = k * sn;
      d[kFt] = k * stt;
    }
    return d;
  }
  // The largest step in tau that DOPRI5 keeps stable at this state: the slip
  // decays at most like e^{-7 mu_b tau / (|s| + mu_b)}, and |s| may halve
  // within the step; 7 x 0.4 = 2.8 < 3.3, the stability limit on the real axis.
  double max_step(const State& y) const {
    const double st = slip_t(y);
    const double sz = slip_z(y);
    return 0.4 * (0.5 * std::sqrt(st * st + sz * sz) * inv_mu + 1.0);
  }
};

// ------------------------------------------------------------ Dormand-Prince 5(4)

using namespace dormand_prince;
constexpr double b1 = a71, b3 = a73, b4 = a74, b5 = a75, b6 = a76;

struct Step {
  State y;
  State error;
  State rate;  // dy/dtau at y (first stage of the next step)
};

// One step of length h from y, whose rate is k1.
Step dopri_step(const Model& m, const State& y, const State& k1, double h) {
  constexpr std::size_t n = kStateSize;
  State z;
  for (std::size_t i = 0; i < n; ++i) z[i] = y[i] + h * a21 * k1[i];
  const State k2 = m.rates(z);
  for (std::size_t i = 0; i < n; ++i) z[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
  const State k3 = m.rates(z);
  for (std::size_t i = 0; i < n; ++i) z[i] = y[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
  const State k4 = m.rates(z);
  for (std::size_t i = 0; i < n; ++i) z[i] = y[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
  const State k5 = m.rates(z);
  for (std::size_t i = 0; i < n; ++i) {
    z[i] = y[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
  }
  const State k6 = m.rates(z);
  Step out;
  for (std::size_t i = 0; i < n; ++i) {
    out.y[i] = y[i] + h * (b1 * k1[i] + b3 * k3[i] + b4 * k4[i] + b5 * k5[i] + b6 * k6[i]);
  }
  out.rate = m.rates(out.y);
  const State& k7 = out.rate;
  for (std::size_t i = 0; i < n; ++i) {
    out.error[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
  }
  return out;
}

constexpr double kTolerance = 1e-10;  // per step, relative to the velocity scale (global errors come out ~1e-12)
constexpr int kMaxSteps = 4000;       // never reached in practice; the closed form finishes

// Finds h* in (0, h] where g(step(y, h*)) = 0, given g(y) > 0 >= g(step(y, h)).
// The start is the root of the cubic Hermite interpolant of g over the step
// (from g and its slopes at both ends); then Newton's method on the step
// length with real steps, dg/dh = grad g . dy/dtau at the step's end,
// safeguarded by the bracket. Returns the step to there.
template <class Event, class Slope>
Step locate(const Model& m, const State& y, const State& k1, double h, const Step& end, Event g, Slope slope) {
  const double g0 = g(y);
  const double g1 = g(end.y);
  const double d0 = h * slope(k1);
  const double d1 = h * slope(end.rate);
  // Hermite cubic on theta in [0, 1]; Newton from the secant root, kept in the bracket.
  auto cubic = [&](double u) {
    const double v = 1.0 - u;
    return g0 * v * v * (1.0 + 2.0 * u) + g1 * u * u * (3.0 - 2.0 * u) + d0 * u * v * v - d1 * u * u * v;
  };
  auto cubic_slope = [&](double u) {
    return 6.0 * u * (1.0 - u) * (g1 - g0) + d0 * (1.0 - u) * (1.0 - 3.0 * u) + d1 * u * (3.0 * u - 2.0);
  };
  double u = g0 / (g0 - g1);
  for (int it = 0; it < 8; ++it) {
    const double c = cubic_slope(u);
    if (c == 0.0) break;
    const double next = u - cubic(u) / c;
    if (!(next > 0.0 && next <= 1.0)) break;
    const bool done = std::abs(next - u) <= 1e-15;
    u = next;
    if (done) break;
  }
  double lo = 0.0;
  double hi = h;
  Step best = end;
  double best_g = std::abs(g1);
  double x = u * h;
  for (int it = 0; it < 30; ++it) {
    if (!(x > lo && x <= hi)) x = 0.5 * (lo + hi);
    const Step at = dopri_step(m, y, k1, x);
    const double gx = g(at.y);
    if (std::abs(gx) < best_g) {
      best = at;
      best_g = std::abs(gx);
    }
    if (best_g <= 1e-14) break;
    if (gx > 0.0) {
      lo = x;
    } else {
      hi = x;
    }
    const double d = slope(at.rate);
    const double next = d != 0.0 ? x - gx / d : 0.5 * (lo + hi);
    if (std::abs(next - x) <= 1e-15 * h || hi - lo <= 1e-15 * h) break;
    x = next;
  }
  return best;
}

struct Outcome {
  State y{};
  bool gripped = false;
};

// The rest of the impact with no friction (M6 after a grip, or no slip or
// friction at all): du_n/dp = -2. `compressing` with u_n >= 0, else the end's
// work `work_target` is known.
void finish_frictionless(double restitution, const Model& m, bool compressing, double work_target, State& y) {
  const double u = m.approach(y);
  if (compressing) {
    const double u_pos = std::max(u, 0.0);
    const double work_c = y[kWork] + 0.25 * u_pos * u_pos;
    y[kP] += 0.5 * u_pos + restitution * std::sqrt(work_c);
    return;
  }
  // W + u d - d^2 = work_target, d >= 0 (u <= 0).
  const double excess = std::max(y[kWork] - work_target, 0.0);
  const double root = std::sqrt(u * u + 4.0 * excess);
  y[kP] += u >= 0.0 ? 0.5 * (u + root) : 2.0 * excess / (root - u);
}

Outcome solve(const Model& m, double restitution, double slip_speed, double velocity_scale) {
  Outcome out;
  State y{};
  bool compressing = true;
  double work_target = 0.0;
  const double grip_slip = 1e-9 * slip_speed;
  State k1 = m.rates(y);
  double h = std::min(m.max_step(y), 0.2);
  const auto approach = [&](const State& z) { return m.approach(z); };
  const auto approach_slope = [&](const State& d) { return -2.0 * d[kP] + m.pressed * d[kFn]; };
  const auto work_left = [&](const State& z) { return z[kWork] - work_target; };
  const auto work_slope = [](const State& d) { return d[kWork]; };
  for (int step = 0; step < kMaxSteps; ++step) {
    const Step s = dopri_step(m, y, k1, h);
    double err = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double scale = std::max({velocity_scale, std::abs(y[i]), std::abs(s.y[i])});
      err = std::max(err, std::abs(s.error[i]) / (kTolerance * scale));
    }
    if (!(err <= 1.0)) {
      h *= std::clamp(0.9 * std::pow(err, -0.2), 0.2, 0.9);
      continue;
    }
    if (compressing && m.approach(s.y) <= 0.0) {
      const Step at = locate(m, y, k1, h, s, approach, approach_slope);
      y = at.y;
      k1 = at.rate;
      compressing = false;
      work_target = (1.0 - restitution * restitution) * y[kWork];
      if (restitution == 0.0) {
        out.y = y;
        return out;
      }
      h = std::min(h, m.max_step(y));
      continue;
    }
    if (!compressing && s.y[kWork] <= work_target) {
      out.y = locate(m, y, k1, h, s, work_left, work_slope).y;
      return out;
    }
    y = s.y;
    k1 = s.rate;
    const double st = m.slip_t(y);
    const double sz = m.slip_z(y);
    const double slip2 = st * st + sz * sz;
    if (slip2 <= grip_slip * grip_slip) {
      // The grip (tau -> inf). The last sliver of slip decays at the rate
      // k = -d ln|s| / dtau and takes the normal impulse (dp/dtau) / k; its
      // cloth friction, O(mu_s |s|), is dropped.
      const double decay = -(st * k1[kPt] + sz * k1[kPz]) / slip2;
      const double rest = k1[kP] / decay;
      y[kWork] += m.approach(y) * rest;
      y[kP] += rest;
      y[kPt] += st / 7.0;
      y[kPz] += sz / 5.0;
      out.gripped = true;
      break;
    }
    // The growth is capped so that a vanishing slip is never integrated with
    // steps that amplify it (max_step).
    const double grow = err > 0.0 ? 0.9 * std::pow(err, -0.2) : 5.0;
    h = std::min(h * std::clamp(grow, 0.2, 5.0), m.max_step(y));
  }
  finish_frictionless(restitution, m, compressing, work_target, y);
  out.y = y;
  return out;
}

}  // namespace

Mathavan2014Contact mathavan_2014_contact() { return {0.89, 0.05, 0.21}; }

void validate(const Mathavan2014Contact& c) {
  check_range(kMathavan2014RestitutionRange, c.restitution);
  check_range(kMathavan2014BallFrictionRange, c.ball_friction);
  check_range(kMathavan2014ClothFrictionRange, c.cloth_friction);
}

BallCollisionResult mathavan_2014_collision(const BallState& a, const BallState& b, const BallParameters& ball,
                                            const Mathavan2014Contact& c) noexcept {
  BallCollisionResult out;
  out.a = a;
  out.b = b;
  out.friction = c.ball_friction;
  if (!balls_approaching(a, b)) return out;

  const double radius = ball.radius;
  const Vec2 n = (b.position - a.position) / norm(b.position - a.position);
  const Vec2 t = perp(n);

  // M1, scaled by the approach speed u0.
  const Vec2 dv = a.velocity - b.velocity;
  const Vec3 w = a.angular_velocity + b.angular_velocity;
  const double u0 = dot(dv, n);
  const double inv_u0 = 1.0 / u0;
  Model m{};
  m.st0 = (dot(dv, t) + radius * w.z) * inv_u0;
  m.sz0 = radius * cross(horizontal(w), n) * inv_u0;
  m.mu_s = c.cloth_friction;
  const double slip_speed = std::sqrt(m.st0 * m.st0 + m.sz0 * m.sz0);
  out.slip_speed = slip_speed * u0;

  // M8: the ball that the vertical friction presses into the cloth.
  const BallState* pressed = nullptr;
  if (c.cloth_friction > 0.0 && m.sz0 != 0.0) {
    m.pressed = m.sz0 > 0.0 ? 1.0 : -1.0;
    pressed = m.sz0 > 0.0 ? &a : &b;
    const Vec3 pw = pressed->angular_velocity;
    const Vec2 sigma = (pressed->velocity + radius * Vec2{-pw.y, pw.x}) * inv_u0;  // v - R w x z
    m.sn0 = dot(sigma, n);
    m.stt0 = dot(sigma, t);
  }
  double velocity_scale = std::max(1.0, slip_speed);
  velocity_scale = std::max(velocity_scale, std::sqrt(m.sn0 * m.sn0 + m.stt0 * m.stt0));
  // A cloth slip at round-off level is a rolling (or resting) ball: zero.
  if (std::abs(m.sn0) + std::abs(m.stt0) <= 1e-13 * velocity_scale) m.sn0 = m.stt0 = 0.0;

  Outcome r;
  if (c.ball_friction > 0.0 && slip_speed > 0.0) {
    m.inv_mu = 1.0 / c.ball_friction;
    r = solve(m, c.restitution, slip_speed, velocity_scale);
  } else {
    finish_frictionless(c.restitution, m, true, 0.0, r.y);
  }
  const State& y = r.y;

  // M4 with the scaled impulses.
  const Vec2 dv_b = u0 * (y[kP] * n + y[kPt] * t);
  const Vec2 cloth = u0 * (y[kFn] * n + y[kFt] * t);
  const double k = 2.5 / radius;
  const Vec3 dw{k * u0 * y[kPz] * t.x, k * u0 * y[kPz] * t.y, -k * u0 * y[kPt]};
  out.a.velocity = a.velocity - dv_b;
  out.b.velocity = b.velocity + dv_b;
  out.a.angular_velocity = a.angular_velocity + dw;
  out.b.angular_velocity = b.angular_velocity + dw;
  if (pressed != nullptr) {
    BallState& p = pressed == &a ? out.a : out.b;
    p.velocity = p.velocity + cloth;
    const Vec2 spin = -k * perp(cloth);  // -5/(2R) z x F
    p.angular_velocity = p.angular_velocity + Vec3{spin.x, spin.y, 0.0};
  }
  out.normal_impulse = ball.mass * u0 * y[kP];
  out.tangential_impulse = ball.mass * u0 * y[kPt];
  out.vertical_impulse = ball.mass * u0 * y[kPz];
  out.gripped = r.gripped;
  return out;
}

}  // namespace cueball
