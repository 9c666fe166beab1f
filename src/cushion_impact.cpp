// Ball-cushion impact of Mathavan, Jackson & Parkin (2010): the `paper`
// (explicit Euler, section 3.4) and `exact` (event-driven) solvers.
//
// Sources: S. Mathavan, M. R. Jackson, R. M. Parkin, Proc. IMechE Part C 224
// (2010), equations (1)-(17) as numbered there (Russian translation by
// S. Tikhonov, 2013, with the translator's afterword; digest in
// shared/spec/physics.md section 2). Slip, stick and slip reversal at a
// frictional contact, with the normal impulse as independent variable: W. J.
// Stronge, "Impact Mechanics" (CUP, 2000), chapters 4-5. Dormand-Prince 5(4)
// pair and its dense output: E. Hairer, S. P. Norsett, G. Wanner, "Solving
// Ordinary Differential Equations I" (2nd ed., Springer 1993), II.5 (DOPRI5).
//
// Everything inside is written in scaled units: velocities (and R times the
// angular velocities, u = R w) in units of the incoming normal speed
// V = yG'(0), impulses in units of M V, work in units of M V^2. The equations
// then lose M and R (with I = 2/5 M R^2 the factor 5/(2MR) of (14d-f) becomes
// 5/2), and the solution scales exactly with V (rate independence).
//
// With f = (a, b) the friction impulse rate at I along (X, Y') and
// g = (g_x, g_y) the one at C along (X, Y), all per unit P_I, eqs (3), (4)
// and (3d) give (14) in the form used here:
//   d xG'/dP = a + g_x                       (3a)
//   d yG'/dP = -cos(theta) - b sin(theta) + g_y   (3b)
//   d u_x /dP = 5/2 (b + g_y)                (4a)
//   d u_y /dP = 5/2 (a sin(theta) - g_x)     (4b)
//   d u_z /dP = -5/2 a cos(theta)            (4c)
//   n_C = dP_C/dP = sin(theta) - b cos(theta) (3d)
// and, while a contact slips, Coulomb's law (7a, 7b), (10a, 10b):
//   (a, b) = -mu_w (cos Phi, sin Phi),  g = -mu_s n_C (cos Phi', sin Phi').
// Slip velocities (12), (13) (zG' = 0 by (14c)):
//   s_I = (xG' + u_y sin(theta) - u_z cos(theta), -yG' sin(theta) + u_x)
//   s_C = (xG' - u_y, yG' + u_x)
// so that their rates are linear in the friction rates:
//   d s_I/dP = (0, sc) + diag(7/2, s^2 + 5/2) f + diag(1 - 5s/2, 5/2 - s) g
//   d s_C/dP = (0, -c) + diag(1 - 5s/2, 5/2 - s) f + diag(7/2, 7/2) g
// (s = sin(theta), c = cos(theta)). The friction rates depend only on the
// slip directions (and on which contacts stick), never on slip magnitudes.
#include "cueball/cushion_impact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "cueball/errors.hpp"

namespace cueball {

namespace {

constexpr double kPi = 3.14159265358979323846;

// ------------------------------------------------------------------ constants

// The model's constants in the scaled equations.
struct Coefficients {
  double mu_w;  // cushion friction at I
  double mu_s;  // cloth friction at C
  double e;     // restitution e_e
  double s;     // sin(theta)
  double c;     // cos(theta)
  double k1;    // 1 - 5s/2: x-coupling between the contacts
  double k2;    // 5/2 - s:  y-coupling between the contacts
  double kyy;   // s^2 + 5/2: effective inverse mass of I along Y'
};

Coefficients coefficients(const CushionImpactModel& m) {
  const double s = m.sin_theta;
  const double c = std::sqrt((1.0 - s) * (1.0 + s));
  return {m.cushion_friction, m.cloth_friction, m.restitution, s, c, 1.0 - 2.5 * s, 2.5 - s, s * s + 2.5};
}

// |v| (std::hypot is slow, and these speeds are far from overflow).
inline double length(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }

// Scaled state: xG', yG', u_x, u_y, u_z (u = R w) and the work W (16a).
using State = std::array<double, 6>;
enum : std::size_t { kVx = 0, kVy = 1, kUx = 2, kUy = 3, kUz = 4, kWork = 5 };

// Slip velocity at I in the X-Y' plane, (12a), (12b) with zG' = 0.
constexpr Vec2 cushion_slip(const Coefficients& k, const State& y) {
  return {y[kVx] + y[kUy] * k.s - y[kUz] * k.c, -y[kVy] * k.s + y[kUx]};
}
// Slip velocity at C in the X-Y plane, (13a), (13b).
constexpr Vec2 bed_slip(const State& y) { return {y[kVx] - y[kUy], y[kVy] + y[kUx]}; }

// Friction impulse rates per unit P_I: at I along (X, Y'), at C along (X, Y).
struct Friction {
  Vec2 cushion;
  Vec2 bed;
};

// Normal impulse rate at C, dP_C/dP_I = sin(theta) - (dP^I_y'/dP_I) cos(theta) (3d), (8).
constexpr double bed_normal_rate(const Coefficients& k, const Friction& f) { return k.s - f.cushion.y * k.c; }

// d State / dP for given friction rates: (14a)-(14f) through (3a), (3b), (4a)-(4c);
// dW/dP = z_I' = -yG' cos(theta) (16a, 16c).
inline State rates(const Coefficients& k, const State& y, const Friction& f) {
  const double a = f.cushion.x;
  const double b = f.cushion.y;
  return {a + f.bed.x,                           // (14a)
          -k.c - b * k.s + f.bed.y,              // (14b)
          2.5 * (b + f.bed.y),                   // (14d)
          2.5 * (a * k.s - f.bed.x),             // (14e)
          -2.5 * a * k.c,                        // (14f) (printed as a second "14e")
          -y[kVy] * k.c};                        // (16a)
}

// Rates of the slip velocities, linear in the friction rates (see the header comment).
constexpr Vec2 cushion_slip_rate(const Coefficients& k, const Friction& f) {
  return {3.5 * f.cushion.x + k.k1 * f.bed.x, k.s * k.c + k.kyy * f.cushion.y + k.k2 * f.bed.y};
}
constexpr Vec2 bed_slip_rate(const Coefficients& k, const Friction& f) {
  return {k.k1 * f.cushion.x + 3.5 * f.bed.x, -k.c + k.k2 * f.cushion.y + 3.5 * f.bed.y};
}

// ------------------------------------------------------------------ validation

[[noreturn]] void reject(const char* field, double value, const std::string& allowed, const char* meaning) {
  throw InvalidArgument(field, value, allowed, meaning);
}

std::string number(double v) {
  std::string text = std::to_string(v);
  while (text.size() > 1 && text.back() == '0') text.pop_back();
  if (!text.empty() && text.back() == '.') text.pop_back();
  return text;
}

void validate_ball(const IncomingBall& ball) {
  require_finite("velocity.x", ball.velocity.x);
  require_finite("velocity.y", ball.velocity.y);
  require_finite("velocity.z", ball.velocity.z);
  require_finite("angular_velocity.x", ball.angular_velocity.x);
  require_finite("angular_velocity.y", ball.angular_velocity.y);
  require_finite("angular_velocity.z", ball.angular_velocity.z);
  if (!(ball.velocity.y > 0.0)) {
    reject("velocity.y", ball.velocity.y, "(0, inf)", "normal speed yG' into the cushion, m/s");
  }
  if (ball.velocity.z != 0.0) {
    reject("velocity.z", ball.velocity.z, "0", "vertical speed zG' of a ball on the bed (14c), m/s");
  }
}

void validate_options(const CushionImpactOptions& options) {
  if (options.solver != CushionSolver::exact && options.solver != CushionSolver::paper) {
    throw InvalidArgument("solver", "solver is not a CushionSolver value");
  }
  if (options.paper_steps < 1 || options.paper_steps > 1'000'000'000) {
    reject("paper_steps", options.paper_steps, "[1, 1e9]", "N, Euler steps per (1 + e_e) M yG'(0) (section 3.4)");
  }
}

// ------------------------------------------------------------------ common

// Scaled initial state.
State scaled_state(const IncomingBall& ball, double radius, double speed_unit) {
  return {ball.velocity.x / speed_unit,
          ball.velocity.y / speed_unit,
          radius * ball.angular_velocity.x / speed_unit,
          radius * ball.angular_velocity.y / speed_unit,
          radius * ball.angular_velocity.z / speed_unit,
          0.0};
}

// Converts scaled quantities back to SI.
struct Units {
  double speed;    // V, m/s
  double radius;   // R, m
  double impulse;  // M V, N s
  double work;     // M V^2, J
};

CushionImpactSample sample(const Coefficients& k, const Units& units, double p, const State& y) {
  const Vec2 si = cushion_slip(k, y);
  const Vec2 sc = bed_slip(y);
  CushionImpactSample out;
  out.normal_impulse = p * units.impulse;
  out.cushion_slip_speed = length(si) * units.speed;
  out.cushion_slip_angle = std::atan2(si.y, si.x);  // Phi (5a, 5b)
  out.bed_slip_speed = length(sc) * units.speed;
  out.bed_slip_angle = std::atan2(sc.y, sc.x);      // Phi' (9a, 9b)
  out.velocity = {y[kVx] * units.speed, y[kVy] * units.speed, 0.0};
  const double spin = units.speed / units.radius;
  out.angular_velocity = {y[kUx] * spin, y[kUy] * spin, y[kUz] * spin};
  out.work = y[kWork] * units.work;
  return out;
}

// Largest |component| of the velocities in the state: the scale for "zero".
double velocity_scale(const State& y) {
  double m = 0.0;
  for (std::size_t i = kVx; i <= kUz; ++i) m = std::max(m, std::abs(y[i]));
  return m;
}

[[noreturn]] void wedged() {
  throw InfeasibleShot("P_I^f < infinity",
                       "the normal velocity at the cushion never reverses (the ball wedges between cushion and "
                       "bed); the rigid-body model has no rebound for these constants");
}

// Bound on the normal impulse, in units of M yG'(0): a frictionless rebound
// needs 1 + e_e <= 2; the model's friction changes that by a modest factor.
constexpr double kMaxScaledImpulse = 200.0;

// ------------------------------------------------------------------ paper

// Friction of the paper's scheme: Coulomb at each slipping contact (7), (10);
// zero where a slip speed is zero (15a), (15b).
Friction paper_friction(const Coefficients& k, const State& y, double zero_slip) {
  Friction f{};
  const Vec2 si = cushion_slip(k, y);
  const double s = length(si);
  if (s > zero_slip) f.cushion = -k.mu_w / s * si;  // (7a), (7b): cos Phi = s_x/s, sin Phi = s_y'/s
  const Vec2 sc = bed_slip(y);
  const double sp = length(sc);
  if (sp > zero_slip) f.bed = -k.mu_s * bed_normal_rate(k, f) / sp * sc;  // (10a), (10b) with (8)
  return f;
}

struct Outcome {
  State final_state{};
  double compression_impulse = 0.0;
  double total_impulse = 0.0;
  double compression_work = 0.0;
  int steps = 0;
  int events = 0;
};

Outcome solve_paper(const Coefficients& k, State y, int n_steps, const Units& units,
                    std::vector<CushionImpactSample>* history) {
  const double dp = (1.0 + k.e) / n_steps;  // dP_I = (1 + e_e) M V0 sin(alpha) / N (section 3.4)
  const double zero_slip = 1e-14 * velocity_scale(y);
  const long long max_steps = static_cast<long long>(kMaxScaledImpulse / dp) + 1;
  if (history) {
    history->reserve(static_cast<std::size_t>(1.15 * n_steps) + 2);
    history->push_back(sample(k, units, 0.0, y));
  }
  Outcome out;
  bool compressing = true;
  double work_target = 0.0;
  for (long long n = 1;; ++n) {
    if (n > max_steps) wedged();
    const Friction f = paper_friction(k, y, zero_slip);
    const State d = rates(k, y, f);
    const double z_before = -y[kVy] * k.c;  // z_I' = -yG' cos(theta) (16c note)
    for (std::size_t i = kVx; i <= kUz; ++i) y[i] += d[i] * dp;  // (17a) and the five like it
    const double z_after = -y[kVy] * k.c;
    y[kWork] += dp * 0.5 * (z_before + z_after);  // trapezoid rule (16a)
    const double p = static_cast<double>(n) * dp;
    if (history) history->push_back(sample(k, units, p, y));
    if (compressing) {
      if (y[kVy] <= 0.0) {  // z_I' = 0 reached: end of compression (16c)
        compressing = false;
        out.compression_impulse = p;
        out.compression_work = y[kWork];
        work_target = (1.0 - k.e * k.e) * y[kWork];  // W(P_I^f) = (1 - e_e^2) W(P_I^c) (16b)
      }
    } else if (y[kWork] >= work_target) {  // first step past (16b)
      out.total_impulse = p;
      out.steps = static_cast<int>(std::min<long long>(n, std::numeric_limits<int>::max()));
      out.events = 2;
      out.final_state = y;
      return out;
    }
  }
}

// ------------------------------------------------------------------ exact: contact modes

enum class ContactMode : unsigned char { slipping, sticking };
constexpr ContactMode kSlip = ContactMode::slipping;
constexpr ContactMode kStick = ContactMode::sticking;

// The contact modes of a smooth segment. A slipping contact's friction
// opposes its slip; `*_direction` is the slip direction to use while the slip
// is still zero (at the onset of slip, before it has a direction of its own).
struct Modes {
  ContactMode cushion = kSlip;
  ContactMode bed = kSlip;
  Vec2 cushion_direction{1.0, 0.0};
  Vec2 bed_direction{1.0, 0.0};
};

// Friction rates for given modes and unit slip directions (a sticking
// contact's direction is ignored). A sticking contact carries the friction
// that keeps its slip rate zero (Stronge ch. 5), from the linear slip-rate
// equations in the header comment.
Friction friction_for(const Coefficients& k, ContactMode cushion, Vec2 cushion_dir, ContactMode bed, Vec2 bed_dir) {
  Friction f{};
  if (cushion == kSlip) {
    f.cushion = -k.mu_w * cushion_dir;  // (7a), (7b)
    if (bed == kSlip) {
      f.bed = -k.mu_s * bed_normal_rate(k, f) * bed_dir;  // (10a), (10b) with (8)
    } else {
      // d s_C/dP = 0: g = -((0, -c) + diag(k1, k2) f) / (7/2).
      f.bed = {-k.k1 * f.cushion.x / 3.5, (k.c - k.k2 * f.cushion.y) / 3.5};
    }
  } else if (bed == kSlip) {
    // d s_I/dP = 0 with g = -mu_s (s - c b) bed_dir, (3d) and (10): linear in (a, b).
    const double b = (k.k2 * k.mu_s * k.s * bed_dir.y - k.s * k.c) / (k.kyy + k.k2 * k.mu_s * k.c * bed_dir.y);
    const double load = k.s - k.c * b;  // n_C (3d)
    f.cushion = {k.k1 * k.mu_s * load * bed_dir.x / 3.5, b};
    f.bed = -k.mu_s * load * bed_dir;
  } else {
    // Both stick: no x rates; the y block [kyy k2; k2 7/2] (b, g_y) = (-sc, c).
    const double det = 3.5 * k.kyy - k.k2 * k.k2;
    f.cushion = {0.0, (-3.5 * k.s * k.c - k.k2 * k.c) / det};
    f.bed = {0.0, (k.kyy * k.c + k.k2 * k.s * k.c) / det};
  }
  return f;
}

// How far a sticking contact's friction lies outside its cone (> 0: outside):
// |friction rate| - mu x (normal impulse rate at that contact: 1 at I, n_C at C).
double cushion_cone_excess(const Coefficients& k, const Friction& f) { return length(f.cushion) - k.mu_w; }
double bed_cone_excess(const Coefficients& k, const Friction& f) {
  return length(f.bed) - k.mu_s * bed_normal_rate(k, f);
}

constexpr double kConeTolerance = 1e-12;  // friction rates are O(1)

Vec2 unit(Vec2 v) { return v / length(v); }

// The direction in which a contact at zero slip starts to slip when it cannot
// stick: a unit u whose slip rate r(u) = lambda u with lambda > 0 (the slip
// grows along a ray; for an isotropic contact, along the part of the rate
// that sticking cannot cancel). Found by scanning the angle for sign changes
// of cross(u, r(u)) and bisecting; of the rays, an attracting one (a slip
// direction near it turns towards it, as the Euler scheme's does) with the
// fastest growth is taken. `rate_for(u)` is the contact's slip rate.
template <class RateFor>
bool slip_onset_direction(RateFor rate_for, Vec2& direction) {
  constexpr int kSamples = 96;
  auto g = [&](double phi) {
    const Vec2 u{std::cos(phi), std::sin(phi)};
    return cross(u, rate_for(u));
  };
  bool found = false;
  bool found_attracting = false;
  double best_growth = 0.0;
  auto consider = [&](Vec2 u, bool attracting) {
    const double growth = dot(u, rate_for(u));
    if (!(growth > 0.0)) return;
    if (found && found_attracting && !attracting) return;
    if (found && found_attracting == attracting && growth <= best_growth) return;
    found = true;
    found_attracting = attracting;
    best_growth = growth;
    direction = u;
  };
  // Exact axis directions first: symmetric (head-on) impacts slip exactly along them.
  for (const Vec2 u : {Vec2{0.0, 1.0}, Vec2{0.0, -1.0}, Vec2{1.0, 0.0}, Vec2{-1.0, 0.0}}) {
    if (cross(u, rate_for(u)) == 0.0) {
      const double phi = std::atan2(u.y, u.x);
      consider(u, g(phi - 1e-7) >= 0.0 && g(phi + 1e-7) <= 0.0);
    }
  }
  double phi0 = -kPi;
  double g0 = g(phi0);
  for (int i = 1; i <= kSamples; ++i) {
    const double phi1 = -kPi + 2.0 * kPi * i / kSamples;
    const double g1 = g(phi1);
    if ((g0 > 0.0 && g1 < 0.0) || (g0 < 0.0 && g1 > 0.0)) {
      double lo = phi0;
      double hi = phi1;
      for (int it = 0; it < 60 && hi - lo > 1e-15; ++it) {
        const double mid = 0.5 * (lo + hi);
        if ((g(mid) > 0.0) == (g0 > 0.0)) {
          lo = mid;
        } else {
          hi = mid;
        }
      }
      const double phi = 0.5 * (lo + hi);
      Vec2 u{std::cos(phi), std::sin(phi)};
      if (std::abs(u.x) < 1e-14) u = {0.0, u.y > 0.0 ? 1.0 : -1.0};
      if (std::abs(u.y) < 1e-14) u = {u.x > 0.0 ? 1.0 : -1.0, 0.0};
      consider(u, g0 > 0.0);  // + to -: the angle flows towards the root
    }
    phi0 = phi1;
    g0 = g1;
  }
  return found;
}

// Chooses the modes at a state where the contacts flagged `*_at_zero` have
// zero slip (the others slip along their slip velocity). Tried in order:
// both stick, the cushion sticks, the bed sticks, both slip; the first whose
// sticking frictions lie in their cones (and whose new slips can grow) is
// taken: a contact at zero slip sticks when it can (Stronge ch. 5).
Modes select_modes(const Coefficients& k, Vec2 cushion_slip_now, Vec2 bed_slip_now, bool cushion_at_zero,
                   bool bed_at_zero) {
  Modes m;
  if (!cushion_at_zero) m.cushion_direction = unit(cushion_slip_now);
  if (!bed_at_zero) m.bed_direction = unit(bed_slip_now);

  if (cushion_at_zero && bed_at_zero) {
    const Friction both = friction_for(k, kStick, {}, kStick, {});
    if (cushion_cone_excess(k, both) <= kConeTolerance && bed_cone_excess(k, both) <= kConeTolerance) {
      m.cushion = kStick;  // wedged: excluded by validate(CushionImpactModel); kept for completeness
      m.bed = kStick;
      return m;
    }
  }
  if (cushion_at_zero) {
    Vec2 bed_dir = m.bed_direction;
    const bool ok =
        !bed_at_zero ||
        slip_onset_direction([&](Vec2 u) { return bed_slip_rate(k, friction_for(k, kStick, {}, kSlip, u)); }, bed_dir);
    if (ok && cushion_cone_excess(k, friction_for(k, kStick, {}, kSlip, bed_dir)) <= kConeTolerance) {
      m.cushion = kStick;
      m.bed = kSlip;
      m.bed_direction = bed_dir;
      return m;
    }
  }
  if (bed_at_zero) {
    Vec2 cushion_dir = m.cushion_direction;
    const bool ok = !cushion_at_zero ||
                    slip_onset_direction(
                        [&](Vec2 u) { return cushion_slip_rate(k, friction_for(k, kSlip, u, kStick, {})); }, cushion_dir);
    if (ok && bed_cone_excess(k, friction_for(k, kSlip, cushion_dir, kStick, {})) <= kConeTolerance) {
      m.cushion = kSlip;
      m.bed = kStick;
      m.cushion_direction = cushion_dir;
      return m;
    }
  }
  m.cushion = kSlip;
  m.bed = kSlip;
  if (cushion_at_zero && bed_at_zero) {
    // Onset at both contacts at once: alternate the two one-contact problems.
    Vec2 cd = unit(cushion_slip_rate(k, friction_for(k, kStick, {}, kStick, {})) + Vec2{1e-9, 0.0});
    Vec2 bd = unit(bed_slip_rate(k, friction_for(k, kStick, {}, kStick, {})) + Vec2{1e-9, 0.0});
    for (int it = 0; it < 16; ++it) {
      slip_onset_direction([&](Vec2 u) { return cushion_slip_rate(k, friction_for(k, kSlip, u, kSlip, bd)); }, cd);
      slip_onset_direction([&](Vec2 u) { return bed_slip_rate(k, friction_for(k, kSlip, cd, kSlip, u)); }, bd);
    }
    m.cushion_direction = cd;
    m.bed_direction = bd;
  } else if (cushion_at_zero) {
    // Fallback if no ray grows: opposite the friction that sticking would need.
    m.cushion_direction = -1.0 * unit(friction_for(k, kStick, {}, kSlip, m.bed_direction).cushion);
    slip_onset_direction(
        [&](Vec2 u) { return cushion_slip_rate(k, friction_for(k, kSlip, u, kSlip, m.bed_direction)); },
        m.cushion_direction);
  } else if (bed_at_zero) {
    // Isotropic at C: the ray is the direction of the slip rate's u-independent part.
    const Friction f = friction_for(k, kSlip, m.cushion_direction, kSlip, m.cushion_direction);
    const Vec2 g0{k.k1 * f.cushion.x, -k.c + k.k2 * f.cushion.y};
    if (length(g0) > 0.0) m.bed_direction = unit(g0);
  }
  return m;
}

// Sets a contact's slip exactly to zero by adjusting the spins (by the
// residual that event location leaves, of the order of the tolerances).
void snap_cushion_slip(const Coefficients& k, State& y) {
  const Vec2 si = cushion_slip(k, y);
  y[kUx] -= si.y;        // (12b)
  y[kUz] += si.x / k.c;  // (12a)
}
void snap_bed_slip(State& y) {
  const Vec2 sc = bed_slip(y);
  y[kUy] += sc.x;  // (13a)
  y[kUx] -= sc.y;  // (13b)
}

// ------------------------------------------------------------------ exact: slip near zero

// Near zero slip the direction of a slipping contact is fast: in polar form
// the slip s = r (cos phi, sin phi) obeys dr/dP = D(phi) = dot(u, ds/dP) and
// dphi/dP = F(phi) / r with F(phi) = cross(u, ds/dP), u = (cos phi, sin phi),
// and ds/dP depends on phi only (and on the other contact). As r -> 0 the
// direction turns ever faster (the equations become stiff: this is where
// RKF45 fails in the translator's afterword), and a slip reaching zero does so
// like |P* - P|^(1 + gamma) with a non-integer gamma, where no polynomial
// integrator keeps its order. Two treatments:
//  - a slip starting from zero (a rolling ball's s', a slip reversal, a stick
//    that breaks), or a small slip whose direction has settled onto a root of
//    F, is "slaved": its direction is the slow manifold of that singularly
//    perturbed equation, the root phi0 of F (Newton from the step start) plus
//    the first-order lag r phi0'/F_phi, an O(r^2) approximation;
//  - a free slip closing in on zero is finished, once below `small_slip`, by
//    integrating the polar equations with ln(r0/r) as the independent
//    variable (smooth, not stiff), with the other contact's slip direction
//    frozen: an error of order (P* - P)^2.

// Regime of a slipping contact.
//
// Directions are handled as unit vectors and turned by small rotations, never
// through angles and trigonometry: a head-on impact then stays exactly in its
// plane (cos(pi/2) is not 0 in floating point, and the model amplifies such
// seeds near zero slip).
struct SlipRegime {
  bool slaved = false;          // direction from the slow manifold, not from the slip velocity
  Vec2 direction{1.0, 0.0};     // slaved: the direction at the step start (Newton's start)
  bool approach_armed = true;   // free: the small-slip event finishes an approach to zero
};

struct SlavedDirection {
  Vec2 u;
  double f_phi;  // dF/dphi at the root: < 0 where it attracts
};

// u turned by the angle a (to first order, then normalised; exact for a = 0).
Vec2 turn(Vec2 u, double a) { return unit(u + a * perp(u)); }

// Slip rate of one contact slipping in direction u while the other contact is
// in mode `other` (slipping in direction w, or sticking).
Vec2 slip_rate_when_slipping(const Coefficients& k, bool at_cushion, Vec2 u, ContactMode other, Vec2 w) {
  return at_cushion ? cushion_slip_rate(k, friction_for(k, kSlip, u, other, w))
                    : bed_slip_rate(k, friction_for(k, other, w, kSlip, u));
}

Friction friction_when_slipping(const Coefficients& k, bool at_cushion, Vec2 u, ContactMode other, Vec2 w) {
  return at_cushion ? friction_for(k, kSlip, u, other, w) : friction_for(k, other, w, kSlip, u);
}

// The bed slipping while the cushion slips along w: its friction is
// isotropic, d s_C/dP = g0 - (7/2) mu_s n_C u with g0 = (0, -c) + diag(k1, k2) f
// independent of u, so the root of F is the direction of g0, F_phi = -|g0|,
// and its motion follows from that of w (closed form of the general case below).
SlavedDirection slaved_bed_direction(const Coefficients& k, double r, Vec2 w, Vec2 cushion_slip_now) {
  const Friction f = friction_for(k, kSlip, w, kSlip, w);  // f.cushion = -mu_w w
  const Vec2 g0{k.k1 * f.cushion.x, -k.c + k.k2 * f.cushion.y};
  const double g = length(g0);
  const Vec2 u0 = g0 / g;
  double lag = 0.0;
  const double r_cushion = length(cushion_slip_now);
  if (r > 0.0 && r_cushion > 0.0) {
    // dw/dP from the cushion's slip rate; dg0/dP = diag(k1, k2) (-mu_w dw/dP); phi0' = cross(u0, dg0/dP) / |g0|.
    const Vec2 u_bed = u0;
    const Vec2 rate = cushion_slip_rate(k, friction_for(k, kSlip, w, kSlip, u_bed));
    const Vec2 dw = (rate - dot(w, rate) * w) / r_cushion;
    const Vec2 dg0{-k.mu_w * k.k1 * dw.x, -k.mu_w * k.k2 * dw.y};
    const double dphi0 = cross(u0, dg0) / g;
    lag = std::clamp(r * dphi0 / -g, -0.25, 0.25);  // r phi0' / F_phi
  }
  return {turn(u0, lag), -g};
}

// The slow-manifold direction near `start` (see above), for a slip of size r.
SlavedDirection slaved_direction(const Coefficients& k, bool at_cushion, Vec2 start, double r, ContactMode other,
                                 Vec2 w, Vec2 other_slip) {
  if (!at_cushion && other == kSlip) return slaved_bed_direction(k, r, w, other_slip);
  auto F = [&](Vec2 u, Vec2 ww) { return cross(u, slip_rate_when_slipping(k, at_cushion, u, other, ww)); };
  constexpr double eps = 1e-6;
  Vec2 u = start;
  double f_phi = 0.0;
  for (int it = 0; it < 3; ++it) {
    f_phi = (F(turn(u, eps), w) - F(turn(u, -eps), w)) / (2.0 * eps);
    if (!(std::abs(f_phi) > 1e-14)) break;
    u = turn(u, -std::clamp(F(u, w) / f_phi, -0.25, 0.25));  // Newton
  }
  const double r_other = length(other_slip);
  if (other == kSlip && f_phi < 0.0 && r > 0.0 && r_other > 0.0) {
    // The lag behind the moving root; phi0 moves only through the other
    // contact's slip direction w(P).
    const Vec2 other_rate = at_cushion ? bed_slip_rate(k, friction_for(k, kSlip, u, kSlip, w))
                                       : cushion_slip_rate(k, friction_for(k, kSlip, w, kSlip, u));
    const Vec2 dw = (other_rate - dot(w, other_rate) * w) / r_other;
    const double f_p = (F(u, unit(w + eps * dw)) - F(u, unit(w - eps * dw))) / (2.0 * eps);
    u = turn(u, std::clamp(r * (-f_p / f_phi) / f_phi, -0.25, 0.25));
  }
  return {u, f_phi};
}

// The rest of a free slip's approach to zero (see above), from slip s0 with
// the other contact in mode `other` along w. On success returns the impulse
// dP it takes and the friction impulses J = integral of the friction rates
// over it; false if the slip stops closing in (a near miss).
bool finish_approach(const Coefficients& k, bool at_cushion, Vec2 s0, ContactMode other, Vec2 w, double& dp,
                     Friction& impulse) {
  const double r0 = length(s0);
  auto rate_at = [&](Vec2 u) { return slip_rate_when_slipping(k, at_cushion, u, other, w); };
  // With sigma = ln(r0 / r): dphi/dsigma = -F/D, dP/dsigma = -r/D, dJ/dsigma = f dP/dsigma.
  // Where the direction relaxes fast in sigma too (|F_phi / D| >= 2) it is
  // already on its root, and the slip runs straight in.
  const Vec2 u0 = unit(s0);
  {
    constexpr double eps = 1e-6;
    const double d0 = dot(u0, rate_at(u0));
    if (!(d0 < -1e-9)) return false;
    const double f_phi = (cross(turn(u0, eps), rate_at(turn(u0, eps))) -
                          cross(turn(u0, -eps), rate_at(turn(u0, -eps)))) / (2.0 * eps);
    if (std::abs(f_phi / d0) >= 2.0) {
      Vec2 u = u0;
      for (int it = 0; it < 3 && std::abs(f_phi) > 1e-14; ++it) {
        u = turn(u, -std::clamp(cross(u, rate_at(u)) / f_phi, -0.25, 0.25));  // Newton on F
      }
      const double d = dot(u, rate_at(u));
      if (!(d < -1e-9)) return false;
      dp = r0 / -d;
      const Friction f = friction_when_slipping(k, at_cushion, u, other, w);
      impulse = {dp * f.cushion, dp * f.bed};
      return true;
    }
  }
  struct Point {
    double ux, uy, p, ax, ay, bx, by;  // direction, P, J
  };
  bool closing = true;
  auto deriv = [&](double sigma, const Point& z) {
    const Vec2 u = unit({z.ux, z.uy});
    const Vec2 rate = rate_at(u);
    const double d = dot(u, rate);  // dr/dP
    if (!(d < -1e-9)) {
      closing = false;
      return Point{0, 0, 0, 0, 0, 0, 0};
    }
    const double dp_dsigma = -r0 * std::exp(-sigma) / d;
    const Vec2 du = (-cross(u, rate) / d) * perp(u);
    const Friction f = friction_when_slipping(k, at_cushion, u, other, w);
    return Point{du.x, du.y, dp_dsigma, f.cushion.x * dp_dsigma, f.cushion.y * dp_dsigma,
                 f.bed.x * dp_dsigma, f.bed.y * dp_dsigma};
  };
  auto axpy = [](const Point& z, double h, const Point& d) {
    return Point{z.ux + h * d.ux, z.uy + h * d.uy, z.p + h * d.p, z.ax + h * d.ax,
                 z.ay + h * d.ay, z.bx + h * d.bx, z.by + h * d.by};
  };
  Point z{u0.x, u0.y, 0, 0, 0, 0, 0};
  constexpr double h = 0.5;   // |h F_phi / D| < 1: stable and accurate
  constexpr int kSteps = 28;  // to r = r0 e^-14
  for (int i = 0; i < kSteps && closing; ++i) {
    const double sigma = i * h;
    const Point d1 = deriv(sigma, z);
    const Point d2 = deriv(sigma + 0.5 * h, axpy(z, 0.5 * h, d1));
    const Point d3 = deriv(sigma + 0.5 * h, axpy(z, 0.5 * h, d2));
    const Point d4 = deriv(sigma + h, axpy(z, h, d3));
    auto avg = [&](double Point::*m) { return h / 6 * (d1.*m + 2 * d2.*m + 2 * d3.*m + d4.*m); };  // classical RK4
    const Vec2 u = unit({z.ux + avg(&Point::ux), z.uy + avg(&Point::uy)});
    z = Point{u.x,
              u.y,
              z.p + avg(&Point::p),
              z.ax + avg(&Point::ax),
              z.ay + avg(&Point::ay),
              z.bx + avg(&Point::bx),
              z.by + avg(&Point::by)};
  }
  if (!closing) return false;
  // The last e^-14 of the slip runs straight in: dP = r / |D| = dP/dsigma there.
  const Point tail = deriv(kSteps * h, z);
  if (!closing) return false;
  const Friction f_end = friction_when_slipping(k, at_cushion, {z.ux, z.uy}, other, w);
  dp = z.p + tail.p;
  impulse.cushion = Vec2{z.ax, z.ay} + tail.p * f_end.cushion;
  impulse.bed = Vec2{z.bx, z.by} + tail.p * f_end.bed;
  return true;
}

// ------------------------------------------------------------------ exact: integration

// How close (rad) a small slip's direction must be to its slow manifold to be slaved to it.
constexpr double kManifoldAngle = 1e-4;

// The smooth system of one segment. Within a step, a free slipping contact's
// friction direction is its slip direction continued through zero (the sign
// chosen to agree with the direction at the step start, `*_ref`): the
// right-hand side stays smooth across a zero of the slip, so the step is
// accepted and the zero is located as an event on the dense output rather
// than stepped into.
struct Exact {
  Coefficients k;
  Modes modes;
  double zero_slip;    // slip speeds below this have no direction (scaled units)
  double slaved_slip;  // below this a slip's direction may be slaved (see above)
  double small_slip;   // a free slip closing in on zero is finished below this
  Vec2 cushion_ref{1.0, 0.0};
  Vec2 bed_ref{1.0, 0.0};
  SlipRegime cushion_regime;
  SlipRegime bed_regime;

  Vec2 free_direction(Vec2 slip, Vec2 ref) const {
    const double r = length(slip);
    if (!(r > zero_slip)) return ref;
    const Vec2 d = slip / r;
    return dot(d, ref) < 0.0 ? -d : d;
  }

  // Friction directions at state y (a sticking contact's is unused).
  void directions(const State& y, Vec2& cushion_dir, Vec2& bed_dir) const {
    const Vec2 si = cushion_slip(k, y);
    const Vec2 sc = bed_slip(y);
    const bool cushion_slaved = modes.cushion == kSlip && cushion_regime.slaved;
    const bool bed_slaved = modes.bed == kSlip && bed_regime.slaved;
    cushion_dir = cushion_slaved ? cushion_ref : free_direction(si, cushion_ref);
    bed_dir = bed_slaved ? bed_ref : free_direction(sc, bed_ref);
    if (cushion_slaved) {
      cushion_dir = slaved_direction(k, true, cushion_regime.direction, length(si), modes.bed, bed_dir, sc).u;
    }
    if (bed_slaved) {
      bed_dir = slaved_direction(k, false, bed_regime.direction, length(sc), modes.cushion, cushion_dir, si).u;
    }
  }
  Friction friction(const State& y) const {
    Vec2 cd;
    Vec2 bd;
    directions(y, cd, bd);
    return friction_for(k, modes.cushion, cd, modes.bed, bd);
  }
  State rhs(const State& y) const {
    if (modes.cushion == kSlip && modes.bed == kSlip && !cushion_regime.slaved && !bed_regime.slaved) {
      // The common case, both contacts slipping freely: (7), (8), (10) inline.
      const Vec2 si = cushion_slip(k, y);
      const Vec2 sc = bed_slip(y);
      const double ri2 = dot(si, si);
      const double rc2 = dot(sc, sc);
      const double zero2 = zero_slip * zero_slip;
      if (ri2 > zero2 && rc2 > zero2) {
        const double wi = (dot(si, cushion_ref) < 0.0 ? k.mu_w : -k.mu_w) / std::sqrt(ri2);
        const double wc = (dot(sc, bed_ref) < 0.0 ? k.mu_s : -k.mu_s) / std::sqrt(rc2);
        Friction f;
        f.cushion = wi * si;
        f.bed = (wc * bed_normal_rate(k, f)) * sc;
        return rates(k, y, f);
      }
    }
    return rates(k, y, friction(y));
  }

  // At a step start: enter the slaved regime when a small slip has settled
  // onto its slow manifold (its direction within kManifoldAngle of it), leave
  // it once the slip has grown, re-arm the approach finishing, and set the
  // reference directions.
  void set_references(const State& y) {
    const Vec2 si = cushion_slip(k, y);
    const Vec2 sc = bed_slip(y);
    const double ri = length(si);
    const double rc = length(sc);
    update_regime(cushion_regime, ri);
    update_regime(bed_regime, rc);
    cushion_ref = ri > zero_slip ? si / ri : modes.cushion_direction;
    bed_ref = rc > zero_slip ? sc / rc : modes.bed_direction;
    if (cushion_regime.slaved) cushion_ref = cushion_regime.direction;
    if (bed_regime.slaved) bed_ref = bed_regime.direction;
    try_enslave(true, si, ri, sc);
    try_enslave(false, sc, rc, si);
    if (!cushion_regime.slaved && !bed_regime.slaved) return;
    Vec2 cd;
    Vec2 bd;
    directions(y, cd, bd);
    if (cushion_regime.slaved) {
      cushion_ref = cd;
      cushion_regime.direction = cd;
    }
    if (bed_regime.slaved) {
      bed_ref = bd;
      bed_regime.direction = bd;
    }
  }
  void update_regime(SlipRegime& g, double r) const {
    if (g.slaved && r >= 2.0 * slaved_slip) g.slaved = false;
    if (!g.approach_armed && r > 2.0 * small_slip) g.approach_armed = true;
  }
  void try_enslave(bool at_cushion, Vec2 slip, double r, Vec2 other_slip) {
    SlipRegime& g = at_cushion ? cushion_regime : bed_regime;
    const ContactMode mode = at_cushion ? modes.cushion : modes.bed;
    if (mode != kSlip || g.slaved || !(r < slaved_slip) || !(r > zero_slip)) return;
    const ContactMode other = at_cushion ? modes.bed : modes.cushion;
    const Vec2 w = at_cushion ? bed_ref : cushion_ref;
    const SlavedDirection sd = slaved_direction(k, at_cushion, slip / r, r, other, w, other_slip);
    if (sd.f_phi < 0.0 && std::abs(cross(sd.u, slip / r)) < kManifoldAngle && dot(sd.u, slip) > 0.0) {
      g.slaved = true;
      g.direction = sd.u;
    }
  }
  // Starts the slaved regime of a contact slipping from zero along u.
  void enslave(bool at_cushion, Vec2 u) {
    SlipRegime& g = at_cushion ? cushion_regime : bed_regime;
    g = {};
    g.slaved = true;
    g.direction = u;
  }
};

// Dormand-Prince 5(4) (DOPRI5) coefficients (Hairer, Norsett & Wanner II.5).
namespace dp {
constexpr double a21 = 1.0 / 5.0;
constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0, a54 = -212.0 / 729.0;
constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                 a65 = -5103.0 / 18656.0;
constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0, a75 = -2187.0 / 6784.0,
                 a76 = 11.0 / 84.0;
constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                 e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                 d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                 d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
}  // namespace dp

// One DOPRI5 step of size h from y0 with k1 = f(y0): the 5th-order solution,
// f at it (first same as last), the error estimate, and the stages for the
// dense output (Hairer's CONTD5, 4th order), computed on demand.
struct Step {
  State y1{};
  State k7{};
  State err{};
  std::array<State, 5> stages{};  // k1, k3, k4, k5, k6
  std::array<State, 4> dense{};   // filled by make_dense()
};

Step dopri5_step(const Exact& sys, const State& y0, const State& k1, double h) {
  using namespace dp;
  constexpr std::size_t n = std::tuple_size_v<State>;
  State t;
  for (std::size_t i = 0; i < n; ++i) t[i] = y0[i] + h * a21 * k1[i];
  const State k2 = sys.rhs(t);
  for (std::size_t i = 0; i < n; ++i) t[i] = y0[i] + h * (a31 * k1[i] + a32 * k2[i]);
  const State k3 = sys.rhs(t);
  for (std::size_t i = 0; i < n; ++i) t[i] = y0[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
  const State k4 = sys.rhs(t);
  for (std::size_t i = 0; i < n; ++i) t[i] = y0[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
  const State k5 = sys.rhs(t);
  for (std::size_t i = 0; i < n; ++i) {
    t[i] = y0[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
  }
  const State k6 = sys.rhs(t);
  Step st;
  for (std::size_t i = 0; i < n; ++i) {
    st.y1[i] = y0[i] + h * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
  }
  st.k7 = sys.rhs(st.y1);
  for (std::size_t i = 0; i < n; ++i) {
    st.err[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * st.k7[i]);
  }
  st.stages = {k1, k3, k4, k5, k6};
  return st;
}

void make_dense(const State& y0, double h, Step& st) {
  using namespace dp;
  const auto& [k1, k3, k4, k5, k6] = st.stages;
  for (std::size_t i = 0; i < y0.size(); ++i) {
    const double r2 = st.y1[i] - y0[i];
    const double r3 = h * k1[i] - r2;
    st.dense[0][i] = r2;
    st.dense[1][i] = r3;
    st.dense[2][i] = r2 - h * st.k7[i] - r3;
    st.dense[3][i] = h * (d1 * k1[i] + d3 * k3[i] + d4 * k4[i] + d5 * k5[i] + d6 * k6[i] + d7 * st.k7[i]);
  }
}

// Dense output at the fraction t of the step.
State interpolate(const State& y0, const Step& st, double t) {
  State out;
  const double u = 1.0 - t;
  for (std::size_t i = 0; i < y0.size(); ++i) {
    out[i] = y0[i] + t * (st.dense[0][i] + u * (st.dense[1][i] + t * (st.dense[2][i] + u * st.dense[3][i])));
  }
  return out;
}

enum class Event : unsigned char {
  none,
  compression_ends,      // z_I' = -yG' cos(theta) reaches 0 (16c)
  restitution_ends,      // W = (1 - e_e^2) W_c (16b)
  cushion_slip_zero,     // the slip at I runs through zero
  bed_slip_zero,         // the slip at C runs through zero
  cushion_slip_small,    // a free s falls to small_slip (finish its approach to zero)
  bed_slip_small,        // s' likewise
  cushion_stick_breaks,  // the friction needed to stick at I reaches mu_w
  bed_stick_breaks,      // the friction needed to stick at C reaches mu_s n_C
};

constexpr std::array<Event, 8> kEvents{Event::compression_ends,     Event::restitution_ends,
                                       Event::cushion_slip_zero,    Event::bed_slip_zero,
                                       Event::cushion_slip_small,   Event::bed_slip_small,
                                       Event::cushion_stick_breaks, Event::bed_stick_breaks};

// Event functions of one step, each crossing from <= 0 to > 0 at its event.
//
// A slip speed s = |slip| is a norm: it touches zero linearly and never
// changes sign, so it is never root-found as if it did. A slip reaching zero
// is located where its component along its direction at the step start
// changes sign (exact for a slip running straight through zero, as head-on,
// and for one arriving along its slaved direction); one closing in on zero
// while it turns is handed to finish_approach() at `small_slip`.
struct EventFunctions {
  const Exact* sys;
  bool compressing;
  double work_target;
  double tiny_slip;   // the small-slip threshold once an approach could not be finished
  double cushion_r0;  // slip speeds at the step start
  double bed_r0;

  double small_threshold(const SlipRegime& g) const { return g.approach_armed ? sys->small_slip : tiny_slip; }

  bool active(Event e) const {
    const Modes& m = sys->modes;
    const SlipRegime& gi = sys->cushion_regime;
    const SlipRegime& gc = sys->bed_regime;
    switch (e) {
      case Event::compression_ends: return compressing;
      case Event::restitution_ends: return !compressing;
      case Event::cushion_slip_zero: return m.cushion == kSlip;
      case Event::bed_slip_zero: return m.bed == kSlip;
      case Event::cushion_slip_small: return m.cushion == kSlip && !gi.slaved && cushion_r0 > small_threshold(gi);
      case Event::bed_slip_small: return m.bed == kSlip && !gc.slaved && bed_r0 > small_threshold(gc);
      case Event::cushion_stick_breaks: return m.cushion == kStick;
      case Event::bed_stick_breaks: return m.bed == kStick;
      case Event::none: break;
    }
    return false;
  }

  double value(Event e, const State& y) const {
    const Coefficients& k = sys->k;
    switch (e) {
      case Event::compression_ends: return -y[kVy];                 // (16c)
      case Event::restitution_ends: return y[kWork] - work_target;  // (16b)
      case Event::cushion_slip_zero: return -dot(cushion_slip(k, y), sys->cushion_ref);
      case Event::bed_slip_zero: return -dot(bed_slip(y), sys->bed_ref);
      case Event::cushion_slip_small: return small_threshold(sys->cushion_regime) - length(cushion_slip(k, y));
      case Event::bed_slip_small: return small_threshold(sys->bed_regime) - length(bed_slip(y));
      case Event::cushion_stick_breaks: return cushion_cone_excess(k, sys->friction(y));
      case Event::bed_stick_breaks: return bed_cone_excess(k, sys->friction(y));
      case Event::none: break;
    }
    return -1.0;
  }

  // Whether a slip's component along its reference direction could dip to
  // zero inside a step although it is positive at both ends: only if it is
  // within one step's worth of change of zero at either end.
  bool may_dip(Event e, const State& y0, const State& d0, const State& y1, const State& d1, double h) const {
    const Coefficients& k = sys->k;
    const bool at_cushion = e == Event::cushion_slip_zero;
    const Vec2 ref = at_cushion ? sys->cushion_ref : sys->bed_ref;
    auto slip = [&](const State& s) { return at_cushion ? cushion_slip(k, s) : bed_slip(s); };
    const double s0 = dot(slip(y0), ref);
    const double s1 = dot(slip(y1), ref);
    const double r0 = std::abs(dot(slip(d0), ref)) + std::abs(cross(slip(d0), ref));
    const double r1 = std::abs(dot(slip(d1), ref)) + std::abs(cross(slip(d1), ref));
    return s0 <= h * (r0 + r1) || s1 <= h * (r0 + r1);
  }
};

// Root in (0, 1] of an event function g(t) on a step's dense output, given
// g(0) <= 0 < g(1): the Illinois variant of regula falsi (superlinear, and
// the bracket closes from both sides), to 1e-13 of the step. Returns the end
// of the bracket where g > 0, so that the event is not missed by rounding.
template <class G>
double locate(G g, double g_lo, double g_hi) {
  double lo = 0.0;
  double hi = 1.0;
  int side = 0;
  for (int it = 0; it < 50 && hi - lo > 1e-13; ++it) {
    double t = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    const double gt = g(t);
    if (gt > 0.0) {
      hi = t;
      g_hi = gt;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    } else {
      lo = t;
      g_lo = gt;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    }
  }
  return hi;
}

// Accuracy and effort of the exact solver, relative to the velocity scale
// (the largest initial velocity component, in units of the normal speed).
struct ExactLimits {
  static constexpr double tolerance = 2e-9;     // local error per Runge-Kutta step
  static constexpr double slaved_slip = 1e-3;   // a small slip may be slaved below this
  static constexpr double small_slip = 1e-6;    // a free slip closing in on zero is finished below this
  static constexpr double tiny_slip = 1e-10;    // a slip this small is zero
  static constexpr int max_attempts = 20000;    // Runge-Kutta steps, accepted or not
  static constexpr int max_events = 64;
};

Outcome solve_exact(const Coefficients& k, State y, const Units& units, std::vector<CushionImpactSample>* history) {
  const double scale = std::max(velocity_scale(y), 1.0);
  const double tiny_slip = ExactLimits::tiny_slip * scale;
  const double atol = ExactLimits::tolerance * scale;
  Exact sys{};
  sys.k = k;
  sys.zero_slip = 1e-13 * scale;
  sys.slaved_slip = ExactLimits::slaved_slip * scale;
  sys.small_slip = ExactLimits::small_slip * scale;

  // Modes at a state where the flagged contacts have zero slip; a contact
  // that starts to slip from zero does so along its slaved direction.
  auto choose_modes = [&](bool cushion_zero, bool bed_zero) {
    if (cushion_zero) snap_cushion_slip(k, y);
    if (bed_zero) snap_bed_slip(y);
    sys.modes = select_modes(k, cushion_slip(k, y), bed_slip(y), cushion_zero, bed_zero);
    if (cushion_zero) sys.cushion_regime = {};
    if (bed_zero) sys.bed_regime = {};
    if (cushion_zero && sys.modes.cushion == kSlip) sys.enslave(true, sys.modes.cushion_direction);
    if (bed_zero && sys.modes.bed == kSlip) sys.enslave(false, sys.modes.bed_direction);
  };
  choose_modes(length(cushion_slip(k, y)) <= tiny_slip, length(bed_slip(y)) <= tiny_slip);
  if (history) history->push_back(sample(k, units, 0.0, y));

  Outcome out;
  bool compressing = true;
  double work_target = 0.0;
  double p = 0.0;
  double h = 0.05 * (1.0 + k.e);
  // Step-size control: a PI controller (Gustafsson; Hairer's DOPRI5 uses
  // err^-(0.2 - 0.75 beta) err_old^beta with beta = 0.04); here err^-3/16
  // err_old^1/16, whose powers are square roots.
  double err_previous_root = 0.5;  // err_old^(1/16): err_old = 1.5e-5 before the first step
  bool rejected = false;
  sys.set_references(y);
  State k1 = sys.rhs(y);
  for (int attempts = 1;; ++attempts) {
    if (attempts > ExactLimits::max_attempts || p > kMaxScaledImpulse) wedged();
    Step st = dopri5_step(sys, y, k1, h);
    // max_i |err_i| / (atol + rtol |y_i|), with one division.
    double err_num = 0.0;
    double err_den = 1.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      const double sc = atol + ExactLimits::tolerance * std::max(std::abs(y[i]), std::abs(st.y1[i]));
      const double e = std::abs(st.err[i]);
      if (e * err_den > err_num * sc) {
        err_num = e;
        err_den = sc;
      }
    }
    const double err = err_num / err_den;
    const double root8 = std::sqrt(std::sqrt(std::sqrt(std::max(err, 1e-5))));
    const double root16 = std::sqrt(root8);
    if (!(err <= 1.0)) {
      h /= std::min(10.0, root8 * root16 / 0.9);  // err^(3/16)
      rejected = true;
      continue;
    }
    ++out.steps;
    double h_next = h / std::clamp(root8 * root16 / err_previous_root / 0.9, 0.2, 10.0);
    if (rejected) h_next = std::min(h_next, h);
    err_previous_root = root16;
    rejected = false;

    // The earliest event inside the step, located on the dense output.
    const EventFunctions ev{&sys, compressing, work_target, tiny_slip, length(cushion_slip(k, y)),
                            length(bed_slip(y))};
    Event first = Event::none;
    double t_first = 2.0;
    bool dense_ready = false;
    for (const Event e : kEvents) {
      if (!ev.active(e)) continue;
      double t_hi = 1.0;
      double g_hi = ev.value(e, st.y1);
      if (!(g_hi > 0.0) && (e == Event::cushion_slip_zero || e == Event::bed_slip_zero) &&
          ev.may_dip(e, y, k1, st.y1, st.k7, h)) {
        // A slip may run through zero and back within one step: look inside.
        if (!dense_ready) make_dense(y, h, st);
        dense_ready = true;
        for (const double tt : {0.25, 0.5, 0.75}) {
          const double g = ev.value(e, interpolate(y, st, tt));
          if (g > 0.0) {
            t_hi = tt;
            g_hi = g;
            break;
          }
        }
      }
      if (!(g_hi > 0.0)) continue;
      const double g_start = ev.value(e, y);
      double t = 0.0;
      if (g_start <= 0.0) {
        if (!dense_ready) make_dense(y, h, st);
        dense_ready = true;
        t = t_hi * locate([&](double tt) { return ev.value(e, interpolate(y, st, t_hi * tt)); }, g_start, g_hi);
      }
      if (t < t_first) {
        t_first = t;
        first = e;
      }
    }

    if (first == Event::none) {
      y = st.y1;
      p += h;
      sys.set_references(y);
      k1 = st.k7;
      if (history) history->push_back(sample(k, units, p, y));
      h = h_next;
      continue;
    }

    // The state at the event: the dense output (4th order, within the step's
    // error tolerance; exact for the piecewise-linear head-on impact).
    const double he = h * t_first;
    const State ye = t_first > 0.0 ? interpolate(y, st, t_first) : y;
    y = ye;
    p += he;
    if (++out.events > ExactLimits::max_events) wedged();

    bool cushion_zero = false;
    bool bed_zero = false;
    switch (first) {
      case Event::compression_ends:
        compressing = false;
        out.compression_impulse = p;
        out.compression_work = y[kWork];
        work_target = (1.0 - k.e * k.e) * y[kWork];  // (16b)
        break;
      case Event::restitution_ends:
        out.total_impulse = p;
        out.final_state = y;
        if (history) history->push_back(sample(k, units, p, y));
        return out;
      case Event::cushion_slip_small:
      case Event::bed_slip_small: {
        const bool at_cushion = first == Event::cushion_slip_small;
        SlipRegime& g = at_cushion ? sys.cushion_regime : sys.bed_regime;
        if (g.approach_armed) {
          const Vec2 slip = at_cushion ? cushion_slip(k, y) : bed_slip(y);
          const Vec2 other_slip = at_cushion ? bed_slip(y) : cushion_slip(k, y);
          const ContactMode other = at_cushion ? sys.modes.bed : sys.modes.cushion;
          const Vec2 w = sys.free_direction(other_slip, at_cushion ? sys.bed_ref : sys.cushion_ref);
          double dp_rest = 0.0;
          Friction impulse{};
          if (!finish_approach(k, at_cushion, slip, other, w, dp_rest, impulse)) {
            g.approach_armed = false;  // a near miss: integrate on
            break;
          }
          // Velocities are affine in the friction impulses (14); W by the trapezoid rule (16a).
          const double vy_before = y[kVy];
          const State d = rates(k, y, {impulse.cushion / dp_rest, impulse.bed / dp_rest});
          for (std::size_t i = kVx; i <= kUz; ++i) y[i] += d[i] * dp_rest;
          y[kWork] += -0.5 * (vy_before + y[kVy]) * k.c * dp_rest;
          p += dp_rest;
        }
        cushion_zero = at_cushion;
        bed_zero = !at_cushion;
        break;
      }
      case Event::cushion_slip_zero: cushion_zero = true; break;
      case Event::bed_slip_zero: bed_zero = true; break;
      case Event::cushion_stick_breaks: {
        // Slip starts opposite the friction on the cone, so friction stays continuous.
        const Vec2 u0 = -1.0 * unit(sys.friction(y).cushion);
        snap_cushion_slip(k, y);
        sys.modes.cushion = kSlip;
        sys.modes.cushion_direction = u0;
        sys.enslave(true, u0);
        break;
      }
      case Event::bed_stick_breaks: {
        const Vec2 u0 = -1.0 * unit(sys.friction(y).bed);
        snap_bed_slip(y);
        sys.modes.bed = kSlip;
        sys.modes.bed_direction = u0;
        sys.enslave(false, u0);
        break;
      }
      case Event::none: break;
    }
    if (cushion_zero || bed_zero) {
      // A slip reached zero: the other contact is at zero too if it sticks or its slip is tiny.
      cushion_zero = cushion_zero || sys.modes.cushion == kStick || length(cushion_slip(k, y)) <= tiny_slip;
      bed_zero = bed_zero || sys.modes.bed == kStick || length(bed_slip(y)) <= tiny_slip;
      choose_modes(cushion_zero, bed_zero);
    }
    if (history) history->push_back(sample(k, units, p, y));
    sys.set_references(y);
    k1 = sys.rhs(y);
  }
}

}  // namespace

// ------------------------------------------------------------------ public

CushionParameters cushion_mathavan2010_paper_fit(const BallParameters& ball) {
  return {0.98, 0.14, default_cushion_height(ball)};  // section 3.5
}

CushionParameters cushion_translator_exact_fit(const BallParameters& ball) {
  return {0.986, 0.2093, default_cushion_height(ball)};  // translator's afterword
}

void validate(const CushionImpactModel& m) {
  if (!(std::isfinite(m.mass) && m.mass > 0.0)) reject("mass", m.mass, "(0, inf)", "ball mass M, kg");
  if (!(std::isfinite(m.radius) && m.radius > 0.0)) reject("radius", m.radius, "(0, inf)", "ball radius R, m");
  require_in_range("mu_s", m.cloth_friction, 0.0, 1.0, "ball-bed friction at C");
  if (!(std::isfinite(m.restitution) && m.restitution > 0.0 && m.restitution <= 1.0)) {
    reject("e_e", m.restitution, "(0, 1]", "ball-cushion coefficient of restitution (16b)");
  }
  if (!(std::isfinite(m.sin_theta) && m.sin_theta > 0.0 && m.sin_theta < 1.0)) {
    reject("sin_theta", m.sin_theta, "(0, 1)", "sin(theta) = (h - R)/R of the contact normal at I");
  }
  const double s = m.sin_theta;
  const double c = std::sqrt((1.0 - s) * (1.0 + s));
  const double tan_theta = s / c;
  if (!(std::isfinite(m.cushion_friction) && m.cushion_friction >= 0.0 && m.cushion_friction <= tan_theta)) {
    reject("mu_w", m.cushion_friction, "[0, tan(theta)] = [0, " + number(tan_theta) + "]",
           "ball-cushion friction; above tan(theta) it could lift the ball off the bed, against (3d)");
  }
  const double wedge = c / (1.0 + s);
  if (m.cushion_friction >= wedge && m.cloth_friction >= wedge) {
    reject("mu_w", m.cushion_friction, "< cos(theta)/(1 + sin(theta)) = " + number(wedge) + " when mu_s is as large",
           "both contacts could stick and wedge the ball");
  }
}

CushionImpactModel cushion_impact_model(const Parameters& table, const CushionParameters& cushion) {
  validate(table);
  const double r = table.ball.radius;
  if (!(std::isfinite(cushion.restitution) && cushion.restitution > 0.0 && cushion.restitution <= 1.0)) {
    reject("e_e", cushion.restitution, "(0, 1]", "ball-cushion coefficient of restitution (16b)");
  }
  if (!(std::isfinite(cushion.friction) && cushion.friction >= 0.0)) {
    reject("mu_w", cushion.friction, "[0, inf)", "ball-cushion sliding friction (7a, 7b)");
  }
  if (!(std::isfinite(cushion.contact_height) && cushion.contact_height > r && cushion.contact_height < 2.0 * r)) {
    reject("h", cushion.contact_height, "(R, 2R) = (" + number(r) + ", " + number(2.0 * r) + ")",
           "height of the cushion contact I above the bed, m");
  }
  CushionImpactModel m;
  m.mass = table.ball.mass;
  m.radius = r;
  m.cloth_friction = table.cloth.sliding_friction;
  m.cushion_friction = cushion.friction;
  m.restitution = cushion.restitution;
  m.sin_theta = cushion_sin_theta(cushion, table.ball);
  validate(m);
  return m;
}

IncomingBall incoming_ball(const PaperIncidence& in) {
  if (!(std::isfinite(in.speed) && in.speed > 0.0)) reject("V0", in.speed, "(0, inf)", "incoming speed, m/s");
  if (!(std::isfinite(in.angle) && in.angle > 0.0 && in.angle <= 0.5 * kPi)) {
    reject("alpha", in.angle, "(0, pi/2] rad", "angle between the velocity and the cushion; pi/2 is head-on");
  }
  require_finite("w_T", in.topspin);
  require_finite("w_S", in.sidespin);
  const double ca = std::cos(in.angle);
  const double sa = std::sin(in.angle);
  IncomingBall b;
  b.velocity = {in.speed * ca, in.speed * sa, 0.0};                         // section 3.1
  b.angular_velocity = {-in.topspin * sa, in.topspin * ca, in.sidespin};  // section 3.1
  return b;
}

CushionImpactResult solve_cushion_impact(const IncomingBall& ball, const CushionImpactModel& model,
                                         const CushionImpactOptions& options) {
  validate(model);
  validate_ball(ball);
  validate_options(options);

  const Coefficients k = coefficients(model);
  const double v_normal = ball.velocity.y;
  const Units units{v_normal, model.radius, model.mass * v_normal, model.mass * v_normal * v_normal};
  const State y0 = scaled_state(ball, model.radius, v_normal);

  CushionImpactResult r;
  std::vector<CushionImpactSample>* history = options.record_history ? &r.history : nullptr;
  const Outcome o = options.solver == CushionSolver::paper ? solve_paper(k, y0, options.paper_steps, units, history)
                                                           : solve_exact(k, y0, units, history);
  const State& y = o.final_state;
  const double spin = units.speed / units.radius;
  r.velocity = {y[kVx] * units.speed, y[kVy] * units.speed, 0.0};
  r.angular_velocity = {y[kUx] * spin, y[kUy] * spin, y[kUz] * spin};
  r.rebound_speed = norm(r.velocity);
  r.rebound_angle = std::atan2(-r.velocity.y, r.velocity.x);
  r.compression_impulse = o.compression_impulse * units.impulse;
  r.total_impulse = o.total_impulse * units.impulse;
  r.compression_work = o.compression_work * units.work;
  r.beyond_rigid_cushion_limit = v_normal > kRigidCushionSpeedLimit;
  r.solver_steps = o.steps;
  r.solver_events = o.events;
  return r;
}

CushionImpactResult cushion_impact(const IncomingBall& ball, const Parameters& table, const CushionParameters& cushion,
                                   const CushionImpactOptions& options) {
  return solve_cushion_impact(ball, cushion_impact_model(table, cushion), options);
}

}  // namespace cueball
