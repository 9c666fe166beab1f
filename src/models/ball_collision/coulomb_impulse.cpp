// Ball-ball collision: Newton restitution along the line of centres, Coulomb
// friction integrated over the normal impulse across it (B1-B8 of
// include/cueball/models/ball_collision/coulomb_impulse.hpp).
//
// Derivation. Per unit mass, an impulse P = p_n n + p_t t + p_z z on b at
// K = r_b - R n (and -P on a at K = r_a + R n) changes
//   v_b by (p_n, p_t) in the bed's plane (p_z is cancelled by the bed, B3),
//   w_b by (m/I) (-R n) x P = 5/(2R) (p_z t - p_t z)           (n x t = z, n x z = -t)
//   w_a by (m/I) (+R n) x (-P) = the same                        (B4)
// so the relative contact velocity c = (v_a - v_b) + R (w_a + w_b) x n (B1)
// changes by
//   dc.n = -2 p_n,   dc.t = -2 p_t - 5 p_t = -7 p_t,   dc.z = -5 p_z   (B6):
// the normal and tangential parts are uncoupled (a sphere's contact normal
// passes through its centre), and the tangential compliance is anisotropic,
// 7 across the line of centres in the bed's plane (translation + rotation)
// and 5 vertically (rotation only: the bed holds the balls down).
//
// Normal impulse (B5): u_n' = -e u_n gives p_n = (1 + e) u_n / 2.
//
// Friction (B7). With mu dp the Coulomb friction impulse along the slip
// direction s^ = s / |s| (Stronge ch. 5; Mathavan et al. 2014), the slip
// obeys ds_t/dp = -7 mu s_t/|s|, ds_z/dp = -5 mu s_z/|s|. With the
// dimensionless "slip age" L defined by mu dp = |s| dL:
//   s_t(L) = s_t0 e^{-7L},   s_z(L) = s_z0 e^{-5L}
//   mu p(L) = |s0| * Int_0^L phi(l) dl,   phi(l) = sqrt(a e^{-14l} + b e^{-10l})
// with a = (s_t0/|s0|)^2, b = (s_z0/|s0|)^2, a + b = 1. The slip stops at
// L = infinity, after a finite normal impulse: Int_0^inf phi lies in
// [1/7, 1/5] (phi lies between e^{-7l} and e^{-5l}). So with
// tau = mu p_n / |s0|:
//   Int_0^inf phi <= tau:  the slip stops; it grips from then on:
//                          (p_t, p_z) = (s_t0/7, s_z0/5)
//   otherwise:             solve Int_0^L phi = tau for L; then
//                          p_t = s_t0 (1 - e^{-7L})/7,  p_z = s_z0 (1 - e^{-5L})/5.
// With one slip component only, phi is a single exponential and this is
// (p_t, p_z) = min(tau, 1/k) s0 (Alciatore, TP A.14).
//
// The integral has no elementary closed form (it is an incomplete elliptic
// integral): phi is analytic in the strip |Im l| < pi/4 (its branch points
// are where a e^{-4l} = -b), so composite 10-point Gauss-Legendre on panels of
// width 1/2 integrates it to round-off (checked against a 4000-panel
// long-double reference for b/a from 1e-12 to 1e4: relative error <= 5e-16).
// Panels cover l in [0, 8]; beyond, Int_8^inf phi <= e^{-40}/5.
//
// Energy: the normal part changes the kinetic energy by -(1 - e^2) m u_n^2/4,
// the tangential part by (m/2)(s_t'^2/7 + s_z'^2/5 - s_t0^2/7 - s_z0^2/5)
// <= 0, since each slip component keeps its sign and shrinks.
#include "cueball/models/ball_collision/coulomb_impulse.hpp"

#include <array>
#include <cmath>
#include <string>

#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

// Compliance of the slip to the friction impulse (B6).
constexpr double kHorizontalCompliance = 7.0;  // 2 x (1 + 5/2)
constexpr double kVerticalCompliance = 5.0;    // 2 x 5/2

// ------------------------------------------------------------ quadrature

// 10-point Gauss-Legendre rule on [-1, 1], nodes +-x_i, weights w_i
// (Abramowitz & Stegun, Table 25.4).
constexpr std::array<double, 5> kGaussNode{0.1488743389816312108848260, 0.4333953941292471907992659,
                                           0.6794095682990244062343274, 0.8650633666889845107320967,
                                           0.9739065285171717200779640};
constexpr std::array<double, 5> kGaussWeight{0.2955242247147528701738930, 0.2692667193099963550912269,
                                             0.2190863625159820439955349, 0.1494513491505805931457763,
                                             0.0666713443086881375935688};

constexpr double kPanelWidth = 0.5;
constexpr int kPanelCount = 16;  // l in [0, 8]
constexpr std::size_t kNodesPerPanel = 2 * kGaussNode.size();

// q = e^{-2l} at the panels' Gauss nodes and edges, computed once.
struct PanelTable {
  std::array<double, static_cast<std::size_t>(kPanelCount) * kNodesPerPanel> node_q{};
  std::array<double, kPanelCount + 1> edge_q{};
};

const PanelTable& panel_table() {
  static const PanelTable table = [] {
    PanelTable t;
    constexpr double half = 0.5 * kPanelWidth;
    for (int k = 0; k <= kPanelCount; ++k) {
      t.edge_q[static_cast<std::size_t>(k)] = std::exp(-2.0 * kPanelWidth * k);
    }
    for (int k = 0; k < kPanelCount; ++k) {
      const double centre = kPanelWidth * k + half;
      for (std::size_t i = 0; i < kGaussNode.size(); ++i) {
        const std::size_t j = static_cast<std::size_t>(k) * kNodesPerPanel + 2 * i;
        t.node_q[j] = std::exp(-2.0 * (centre - half * kGaussNode[i]));
        t.node_q[j + 1] = std::exp(-2.0 * (centre + half * kGaussNode[i]));
      }
    }
    return t;
  }();
  return table;
}

// The normalised slip speed |s(l)| / |s0| as a function of q = e^{-2l}:
// phi = sqrt(a q^7 + b q^5).
struct SlipDecay {
  double a;  // (s_t0 / |s0|)^2
  double b;  // (s_z0 / |s0|)^2

  double phi(double q) const {
    const double q2 = q * q;
    return std::sqrt(q2 * q2 * q * (a * q2 + b));
  }
  // -d ln(phi)/dl, between 5 and 7.
  double decay_rate(double q) const {
    const double q2 = q * q;
    return (7.0 * a * q2 + 5.0 * b) / (a * q2 + b);
  }
};

// Int_{l0}^{l0 + d} phi dl by one 10-point Gauss-Legendre panel (0 <= d <= kPanelWidth); q0 = e^{-2 l0}.
// The nodes l0 + d/2 (1 -+ x_i) pair up: their q's multiply to q0^2 e^{-2d}.
double integrate_partial_panel(const SlipDecay& s, double q0, double d) {
  const double half = 0.5 * d;
  const double q_end = q0 * std::exp(-2.0 * d);
  double sum = 0.0;
  for (std::size_t i = 0; i < kGaussNode.size(); ++i) {
    const double q_left = q0 * std::exp(-d * (1.0 - kGaussNode[i]));
    const double q_right = q0 * q_end / q_left;
    sum += kGaussWeight[i] * (s.phi(q_left) + s.phi(q_right));
  }
  return half * sum;
}

double integrate_panel(const SlipDecay& s, int k) {
  const PanelTable& t = panel_table();
  const double* q = t.node_q.data() + static_cast<std::size_t>(k) * kNodesPerPanel;
  double sum = 0.0;
  for (std::size_t i = 0; i < kGaussNode.size(); ++i) sum += kGaussWeight[i] * (s.phi(q[2 * i]) + s.phi(q[2 * i + 1]));
  return 0.5 * kPanelWidth * sum;
}

// Solves Int_{l0}^{l0 + d} phi = target for d in [0, kPanelWidth], given that
// the root lies there. The integral F(d) is increasing and concave, with
// F' = phi and F'' = -k phi (k = decay_rate), so Halley's iteration (cubic)
// is cheap; it is safeguarded by bisection on the bracket, and started from
// the exponential model phi ~ phi0 e^{-k0 (l - l0)}.
double solve_in_panel(const SlipDecay& s, double q0, double target) {
  const double phi0 = s.phi(q0);
  const double k0 = s.decay_rate(q0);
  const double x = k0 * target / phi0;
  double lo = 0.0;
  double hi = kPanelWidth;
  double d = x < 1.0 ? -std::log1p(-x) / k0 : hi;
  if (!(d > lo && d < hi)) d = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double f = integrate_partial_panel(s, q0, d) - target;
    if (f == 0.0) return d;
    if (f > 0.0) {
      hi = d;
    } else {
      lo = d;
    }
    const double q = q0 * std::exp(-2.0 * d);
    const double newton = f / s.phi(q);
    double next = d - newton / (1.0 + 0.5 * s.decay_rate(q) * newton);
    const bool halley = next > lo && next < hi;
    if (!halley) next = 0.5 * (lo + hi);
    const double step = next - d;
    d = next;
    // The error after a Halley step of size h is O(h^3) (the derivatives of
    // ln phi are bounded by 7): once a step is this small, what is left is
    // below round-off.
    if ((halley && std::abs(step) <= 1e-6 * d) || hi - lo <= 4e-16 * hi) break;
  }
  return d;
}

struct FrictionImpulse {
  double along_t;     // p_t
  double vertical;    // p_z
  bool gripped;
};

// B7: the friction impulse per unit mass for incoming slip (s_t, s_z) with
// |s0| = slip_speed > 0 and tau = mu p_n / |s0| > 0.
FrictionImpulse friction_impulse(double s_t, double s_z, double slip_speed, double tau) {
  constexpr double kt = kHorizontalCompliance;
  constexpr double kz = kVerticalCompliance;
  const FrictionImpulse grip{s_t / kt, s_z / kz, true};
  // One component only: friction keeps its direction; the slip stops after
  // mu p = |s0| / k.
  if (s_z == 0.0) return tau * kt >= 1.0 ? grip : FrictionImpulse{tau * s_t, 0.0, false};
  if (s_t == 0.0) return tau * kz >= 1.0 ? grip : FrictionImpulse{0.0, tau * s_z, false};

  const double ut = s_t / slip_speed;
  const double uz = s_z / slip_speed;
  const SlipDecay decay{ut * ut, uz * uz};
  const PanelTable& table = panel_table();
  double done = 0.0;  // Int_0^{l_k} phi
  for (int k = 0; k < kPanelCount; ++k) {
    const double q0 = table.edge_q[static_cast<std::size_t>(k)];
    const double phi0 = decay.phi(q0);
    const double remaining = tau - done;
    // What is left of the integral, Int_{l_k}^inf phi, is at most phi0/5:
    // friction outlasts the slip.
    if (remaining * kz >= phi0) return grip;
    // The panel's integral is at least phi0 (1 - e^{-7h})/7 (phi decays no
    // faster than e^{-7l}); only compute it when that does not settle it.
    const double panel_lower_bound = phi0 * -std::expm1(-kt * kPanelWidth) / kt;
    if (remaining > panel_lower_bound) {
      const double panel = integrate_panel(decay, k);
      if (remaining > panel) {
        done += panel;
        continue;
      }
    }
    const double slip_age = kPanelWidth * k + solve_in_panel(decay, q0, remaining);
    // p_t = s_t0 (1 - e^{-7L})/7, p_z = s_z0 (1 - e^{-5L})/5.
    return {-s_t * std::expm1(-kt * slip_age) / kt, -s_z * std::expm1(-kz * slip_age) / kz, false};
  }
  return grip;  // Int_8^inf phi <= e^{-40}/5: the slip has stopped
}

}  // namespace

void validate(const BallCollisionParameters& p) {
  check_range(kBallRestitutionRange, p.restitution);
  check_range(kBallFrictionRange, p.friction);
  check_range(kBallFrictionExcessRange, p.friction_excess);
  check_range(kBallFrictionDecayRange, p.friction_decay);
  if (!(p.friction + p.friction_excess <= 1.0)) {
    throw InvalidArgument("friction_excess",
                          "friction_excess = " + std::to_string(p.friction_excess) + " with friction = " +
                              std::to_string(p.friction) +
                              " gives a ball-ball friction above 1 at zero slip speed "
                              "(friction + friction_excess must be at most 1)");
  }
}

BallCollisionParameters ball_collision_alciatore() {
  BallCollisionParameters p;
  p.restitution = 0.95;       // Alciatore: ball-ball restitution 0.92-0.98
  p.friction = 9.951e-3;      // TP A.14: mu(v) = a + b exp(-c v), a
  p.friction_excess = 0.108;  //   b
  p.friction_decay = 1.088;   //   c, s/m
  return p;
}

BallCollisionParameters ball_collision_frictionless(double restitution) {
  BallCollisionParameters p;
  p.restitution = restitution;
  return p;
}

double ball_friction(const BallCollisionParameters& p, double slip_speed) {
  return p.friction_excess == 0.0 ? p.friction
                                  : p.friction + p.friction_excess * std::exp(-p.friction_decay * slip_speed);
}

BallCollisionResult resolve_ball_collision(const BallState& a, const BallState& b, const BallParameters& ball,
                                           const BallCollisionParameters& contact) noexcept {
  BallCollisionResult out;
  out.a = a;
  out.b = b;
  if (!balls_approaching(a, b)) return out;

  const double radius = ball.radius;
  const Vec2 n = (b.position - a.position) / norm(b.position - a.position);
  const Vec2 t = perp(n);  // z^ x n

  // B1: relative contact velocity c = (v_a - v_b) + R (w_a + w_b) x n.
  const Vec2 dv = a.velocity - b.velocity;
  const Vec3 w = a.angular_velocity + b.angular_velocity;
  const double approach_speed = dot(dv, n);                  // c . n
  const double slip_t = dot(dv, t) + radius * w.z;           // c . t
  const double slip_z = radius * cross(horizontal(w), n);    // c . z
  const double slip_speed = std::sqrt(slip_t * slip_t + slip_z * slip_z);

  // B5.
  const double p_n = 0.5 * (1.0 + contact.restitution) * approach_speed;

  // B7, B8.
  double p_t = 0.0;
  double p_z = 0.0;
  const double mu = ball_friction(contact, slip_speed);
  if (slip_speed > 0.0 && mu > 0.0) {
    const FrictionImpulse f = friction_impulse(slip_t, slip_z, slip_speed, mu * p_n / slip_speed);
    p_t = f.along_t;
    p_z = f.vertical;
    out.gripped = f.gripped;
  }

  // B3: velocities in the bed's plane.
  const Vec2 dv_b = p_n * n + p_t * t;
  out.a.velocity = a.velocity - dv_b;
  out.b.velocity = b.velocity + dv_b;
  // B4: the same angular impulse on both balls, 5/(2R) (p_z t - p_t z).
  const double k = 2.5 / radius;
  const Vec3 dw{k * p_z * t.x, k * p_z * t.y, -k * p_t};
  out.a.angular_velocity = a.angular_velocity + dw;
  out.b.angular_velocity = b.angular_velocity + dw;

  out.normal_impulse = ball.mass * p_n;
  out.tangential_impulse = ball.mass * p_t;
  out.vertical_impulse = ball.mass * p_z;
  out.friction = mu;
  out.slip_speed = slip_speed;
  return out;
}

std::pair<BallState, BallState> collide_balls(const BallState& a, const BallState& b, const BallParameters& ball,
                                              const BallCollisionParameters& contact) noexcept {
  const BallCollisionResult r = resolve_ball_collision(a, b, ball, contact);
  return {r.a, r.b};
}

}  // namespace cueball
