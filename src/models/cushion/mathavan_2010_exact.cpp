// Mathavan, Jackson & Parkin (2010), the ball-cushion impact: the `exact`
// solver, the same model as the paper's Euler scheme without its
// discretisation error (the N -> infinity limit of `paper`). Event-driven: a
// slip reaching zero and a stick breaking end a smooth segment, the ends of
// compression (16c) and restitution (16b) are located on the way. Each
// contact slips or sticks (Stronge ch. 5; select_modes), the state is
// integrated in slip form (four slip velocities and the work W), near zero
// slip a slip's direction follows its slow manifold or an approach to zero
// is finished in logarithmic slip time, and smooth segments are integrated
// by the Dormand-Prince 5(4) pair with dense output (dopri5_step, and
// FreeSlipStep, the same step written for SIMD while both contacts slip);
// where both slips are clear of zero, without the event machinery
// (SmoothMiddle, the smooth middle of a sliding impact).
// Everything a Runge-Kutta step calls is in this file, so that it inlines.
// The equations, the scaled units and the state are in
// mathavan_2010_equations.hpp.
//
// Sources: S. Mathavan, M. R. Jackson, R. M. Parkin, Proc. IMechE Part C 224
// (2010), equations (1)-(17) as numbered there (the translator's afterword
// on RKF45 near zero slip). Slip, stick and slip reversal at a frictional
// contact, with the normal impulse as independent variable: W. J. Stronge,
// "Impact Mechanics" (CUP, 2000), chapters 4-5. Dormand-Prince 5(4) pair and
// its dense output: E. Hairer, S. P. Norsett, G. Wanner, "Solving Ordinary
// Differential Equations I" (2nd ed., Springer 1993), II.5 (DOPRI5).
// Predictive step-size control: K. Gustafsson, ACM TOMS 20 (1994) 496-517.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

#include "core/dormand_prince.hpp"
#include "mathavan_2010_equations.hpp"

namespace cueball::mathavan_2010 {

namespace {

// ------------------------------------------------------------------ contact modes

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
// equations in mathavan_2010_equations.hpp.
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
// of cross(u, r(u)) and refining each by regula falsi; of the rays, an
// attracting one (a slip direction near it turns towards it, as the Euler
// scheme's does) with the fastest growth is taken. `rate_for(u)` is the
// contact's slip rate.
constexpr int kOnsetSamples = 96;

// The angles of the scan below and their unit vectors (cosines and sines
// apart, so that the scan's samples are worked out two at a time), computed
// once (the same values as evaluating cos and sin at each angle in every scan).
struct OnsetSamples {
  std::array<double, kOnsetSamples + 1> phi;
  std::array<double, kOnsetSamples + 1> cos_phi;
  std::array<double, kOnsetSamples + 1> sin_phi;
  OnsetSamples() {
    for (std::size_t i = 0; i <= kOnsetSamples; ++i) {
      phi[i] = -kPi + 2.0 * kPi * static_cast<int>(i) / kOnsetSamples;
      cos_phi[i] = std::cos(phi[i]);
      sin_phi[i] = std::sin(phi[i]);
    }
  }
};
const OnsetSamples& onset_samples() {
  static const OnsetSamples samples;
  return samples;
}

// A sign change of g(phi) = cross(u, r(u)) between two neighbouring angles
// of the scan: a ray lies between them (no initialisers: the scan's array
// of them is filled only as far as it finds any).
struct OnsetBracket {
  double lo;
  double hi;
  double g_lo;
  double g_hi;
};

// The ray in a bracket, to 1e-15 rad: the Illinois variant of regula falsi
// (superlinear, and both ends of the bracket close), 6-10 evaluations of g
// where bisection took 46. Directions within 1e-14 of an axis are put on it.
template <class G>
Vec2 onset_ray(G g, OnsetBracket b) {
  double lo = b.lo;
  double hi = b.hi;
  double g_lo = b.g_lo;
  double g_hi = b.g_hi;
  int side = 0;
  for (int it = 0; it < 60 && hi - lo > 1e-15; ++it) {
    double mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
    const double g_mid = g(mid);
    if (g_mid == 0.0) {
      lo = mid;
      hi = mid;
    } else if ((g_mid > 0.0) == (g_lo > 0.0)) {
      lo = mid;
      g_lo = g_mid;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    } else {
      hi = mid;
      g_hi = g_mid;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    }
  }
  const double phi = 0.5 * (lo + hi);
  Vec2 u{std::cos(phi), std::sin(phi)};
  if (std::abs(u.x) < 1e-14) u = {0.0, u.y > 0.0 ? 1.0 : -1.0};
  if (std::abs(u.y) < 1e-14) u = {u.x > 0.0 ? 1.0 : -1.0, 0.0};
  return u;
}

// The choice among the rays: an attracting one (a slip direction near it
// turns towards it) over any repelling one, then the fastest growth (the
// first of equals, in the order offered); only a growing ray counts.
struct OnsetChoice {
  bool found = false;
  bool attracting = false;
  double growth = 0.0;
  Vec2 direction;

  void consider(Vec2 u, bool ray_attracts, double ray_growth) {
    if (!(ray_growth > 0.0)) return;
    if (found && attracting && !ray_attracts) return;
    if (found && attracting == ray_attracts && ray_growth <= growth) return;
    found = true;
    attracting = ray_attracts;
    growth = ray_growth;
    direction = u;
  }
};

// The scan offers the exact axis directions first, then the rays in the
// order of their angles; the brackets of attracting rays are refined first,
// and those of repelling rays only when no attracting ray grows: a repelling
// ray cannot be chosen over a growing attracting one, so the choice is the
// one the rays in scan order would give (half the refinements of a typical
// onset, one ray of each kind).
template <class RateFor>
bool slip_onset_direction(RateFor rate_for, Vec2& direction) {
  constexpr int kSamples = kOnsetSamples;
  const OnsetSamples& samples = onset_samples();
  auto g = [&](double phi) {
    const Vec2 u{std::cos(phi), std::sin(phi)};
    return cross(u, rate_for(u));
  };

  OnsetChoice choice;
  choice.direction = direction;
  // Exact axis directions first: symmetric (head-on) impacts slip exactly along them.
  for (const Vec2 u : {Vec2{0.0, 1.0}, Vec2{0.0, -1.0}, Vec2{1.0, 0.0}, Vec2{-1.0, 0.0}}) {
    if (cross(u, rate_for(u)) == 0.0) {
      const double phi = std::atan2(u.y, u.x);
      choice.consider(u, g(phi - 1e-7) >= 0.0 && g(phi + 1e-7) <= 0.0, dot(u, rate_for(u)));
    }
  }
  std::array<double, kSamples + 1> g_at;  // g at each sample
  for (std::size_t i = 0; i <= kSamples; ++i) {
    const Vec2 u{samples.cos_phi[i], samples.sin_phi[i]};
    g_at[i] = cross(u, rate_for(u));
  }
  std::array<OnsetBracket, kSamples> brackets;
  std::size_t count = 0;
  for (std::size_t i = 1; i <= kSamples; ++i) {
    const double g0 = g_at[i - 1];
    const double g1 = g_at[i];
    if ((g0 > 0.0 && g1 < 0.0) || (g0 < 0.0 && g1 > 0.0)) brackets[count++] = {samples.phi[i - 1], samples.phi[i], g0, g1};
  }
  // + to -: the angle flows towards the root (attracting).
  for (bool attracting : {true, false}) {
    if (!attracting && choice.found && choice.attracting) break;
    for (std::size_t b = 0; b < count; ++b) {
      if ((brackets[b].g_lo > 0.0) != attracting) continue;
      const Vec2 u = onset_ray(g, brackets[b]);
      choice.consider(u, attracting, dot(u, rate_for(u)));
    }
  }
  if (choice.found) direction = choice.direction;
  return choice.found;
}

// The bed slipping while the cushion slips along w: the bed's friction is
// isotropic, d s_C/dP = g0 - (7/2) mu_s n_C u with the drive
// g0 = (0, -c) + diag(k1, k2) f independent of u (f = -mu_w w, (7a), (7b)).
struct BedDrive {
  Vec2 f;   // the cushion's friction rate
  Vec2 g0;
};
BedDrive bed_drive(const Coefficients& k, Vec2 w) {
  const Vec2 f = -k.mu_w * w;
  return {f, {k.k1 * f.x, -k.c + k.k2 * f.y}};
}

// So the bed's only ray is the direction of g0 (attracting, F_phi = -|g0|),
// growing at |g0| - (7/2) mu_s n_C: slip_onset_direction() of the bed in
// closed form. Sets `direction` and returns true if that slip grows.
bool bed_onset_direction(const Coefficients& k, Vec2 w, Vec2& direction) {
  const BedDrive d = bed_drive(k, w);
  const double g = length(d.g0);
  if (!(g - 3.5 * k.mu_s * bed_normal_rate(k, {d.f, {}}) > 0.0)) return false;
  direction = d.g0 / g;
  return true;
}

// A slip rate affine in the slip direction u, r(u) = p + u_x r_x + u_y r_y:
// the cushion's while the bed slips along a given direction or sticks
// ((7a), (7b), (10a), (10b) and (3d) are linear in u). Made from three
// evaluations of the rate, it costs slip_onset_direction()'s scan a few
// multiply-adds a sample.
struct AffineRate {
  Vec2 p;
  Vec2 r_x;
  Vec2 r_y;
  Vec2 operator()(Vec2 u) const { return p + u.x * r_x + u.y * r_y; }
};
template <class RateFor>
AffineRate affine_rate(RateFor rate_for) {
  const Vec2 p = rate_for(Vec2{0.0, 0.0});
  return {p, rate_for(Vec2{1.0, 0.0}) - p, rate_for(Vec2{0.0, 1.0}) - p};
}

// Whether two vectors are equal to the bit (signed zeros told apart).
bool same_bits(Vec2 a, Vec2 b) {
  return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
         std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y);
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
                    slip_onset_direction(affine_rate([&](Vec2 u) {
                                           return cushion_slip_rate(k, friction_for(k, kSlip, u, kStick, {}));
                                         }),
                                         cushion_dir);
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
    // Each round is a function of (cd, bd) alone, so once a round leaves both
    // unchanged to the bit the remaining rounds would too: stop there.
    for (int it = 0; it < 16; ++it) {
      const Vec2 cd_before = cd;
      const Vec2 bd_before = bd;
      slip_onset_direction(
          affine_rate([&](Vec2 u) { return cushion_slip_rate(k, friction_for(k, kSlip, u, kSlip, bd)); }), cd);
      bed_onset_direction(k, cd, bd);
      if (same_bits(cd, cd_before) && same_bits(bd, bd_before)) break;
    }
    m.cushion_direction = cd;
    m.bed_direction = bd;
  } else if (cushion_at_zero) {
    // Fallback if no ray grows: opposite the friction that sticking would need.
    m.cushion_direction = -1.0 * unit(friction_for(k, kStick, {}, kSlip, m.bed_direction).cushion);
    slip_onset_direction(
        affine_rate([&](Vec2 u) { return cushion_slip_rate(k, friction_for(k, kSlip, u, kSlip, m.bed_direction)); }),
        m.cushion_direction);
  } else if (bed_at_zero) {
    // Isotropic at C: the ray is the direction of the slip rate's u-independent part.
    const Vec2 g0 = bed_drive(k, m.cushion_direction).g0;
    if (length(g0) > 0.0) m.bed_direction = unit(g0);
  }
  return m;
}

// ------------------------------------------------------------------ the state in slip form

// The exact solver integrates the slip velocities themselves: the friction
// rates depend on the slip directions only, so (s_I, s_C) obey a closed
// system of four equations (mathavan_2010_equations.hpp). The
// velocities follow from the slips and one invariant: both contact forces
// act on the line through C and I, so the angular momentum about that line is
// conserved, J = cos(theta) xG' + 2/5 (cos(theta) u_y + (1 + sin(theta)) u_z)
// (by (14a), (14e), (14f): dJ/dP = 0 whatever the friction). Then
//   yG' = (s_C,y - s_I,y') / (1 + s),   u_x = s_C,y - yG'        (12b), (13b)
//   u_y = (c J - c^2 s_C,x - 2/5 (1 + s)(s_C,x - s_I,x)) / ((1 + s)(9/5 - s))
//   xG' = s_C,x + u_y,   u_z = (s_C,x - s_I,x + (1 + s) u_y) / c    (12a), (13a)
// (s = sin(theta), c = cos(theta)). The work W (16a) is integrated
// alongside. Slip events are then conditions on components of the state, and
// a stage of the Runge-Kutta method needs only the four slips. They are
// stored x components first, (s_I,x, s_C,x, s_I,y', s_C,y), so that the two
// x components and the two y components each fill one SIMD register
// (FreeSlipStep).
using SlipState = std::array<double, 5>;
enum : std::size_t { kSix = 0, kScx = 1, kSiy = 2, kScy = 3, kW = 4 };
constexpr std::size_t kSlips = 4;

constexpr Vec2 slip_i(const SlipState& z) { return {z[kSix], z[kSiy]}; }
constexpr Vec2 slip_c(const SlipState& z) { return {z[kScx], z[kScy]}; }
// (1 + sin theta) yG': the normal speed, up to a positive factor.
constexpr double scaled_normal_speed(const SlipState& z) { return z[kScy] - z[kSiy]; }

// The invariant J of a velocity state (scaled units, u = R w).
double line_momentum(const Coefficients& k, const State& y) {
  return k.c * y[kVx] + 0.4 * (k.c * y[kUy] + (1.0 + k.s) * y[kUz]);
}
SlipState slip_state(const Coefficients& k, const State& y) {
  const Vec2 si = cushion_slip(k, y);
  const Vec2 sc = bed_slip(y);
  SlipState z;
  z[kSix] = si.x;
  z[kSiy] = si.y;
  z[kScx] = sc.x;
  z[kScy] = sc.y;
  z[kW] = y[kWork];
  return z;
}
State velocity_state(const Coefficients& k, const SlipState& z, double j) {
  const double vy = scaled_normal_speed(z) * k.inv_1ps;
  const double dx = z[kScx] - z[kSix];
  const double uy = (k.c * j - k.c * k.c * z[kScx] - 0.4 * (1.0 + k.s) * dx) * k.inv_1ps / (1.8 - k.s);
  const double uz = (dx + (1.0 + k.s) * uy) / k.c;
  return {z[kScx] + uy, vy, z[kScy] - vy, uy, uz, z[kW]};
}

// d SlipState / dP for given friction rates: the slip rates
// (mathavan_2010_equations.hpp) and (16a).
inline SlipState slip_rates(const Coefficients& k, const SlipState& z, const Friction& f) {
  const Vec2 a = f.cushion;
  const Vec2 g = f.bed;
  SlipState d;
  d[kSix] = 3.5 * a.x + k.k1 * g.x;
  d[kSiy] = k.s * k.c + k.kyy * a.y + k.k2 * g.y;
  d[kScx] = k.k1 * a.x + 3.5 * g.x;
  d[kScy] = -k.c + k.k2 * a.y + 3.5 * g.y;
  d[kW] = -k.c * (scaled_normal_speed(z) * k.inv_1ps);
  return d;
}

// Sets a contact's slip exactly to zero by adjusting the spins (by the
// residual that event location leaves, of the order of the tolerances).
void snap_cushion_slip(SlipState& z) {
  z[kScy] -= z[kSiy];  // (12b): R w_x by -s_y', which moves s'_y by as much (13b)
  z[kSix] = 0.0;       // (12a): by R w_y, R w_z and xG' at constant J
  z[kSiy] = 0.0;
}
void snap_bed_slip(const Coefficients& k, SlipState& z) {
  z[kSix] += k.s * z[kScx];  // (13a): R w_y by s'_x, which moves s_x by sin(theta) s'_x (12a)
  z[kSiy] -= z[kScy];        // (13b): R w_x by -s'_y, which moves s_y' by as much (12b)
  z[kScx] = 0.0;
  z[kScy] = 0.0;
}

// ------------------------------------------------------------------ slip near zero

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
//    the lag behind it as phi0 moves, r phi0' / (F_phi - D), an O(r^2)
//    approximation (with psi = phi - phi0 and r changing at the rate D,
//    dpsi/dP = F_phi psi / r - phi0' has the solution psi = r phi0' /
//    (F_phi - D) for steady rates; the quasi-steady r phi0'/F_phi is its
//    limit |D| << |F_phi|, and a slip growing from zero has D ~ |F_phi|);
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

// turn(u, +-1e-6), the small angle of the finite differences below, as a
// rotation (a unit vector stays one: no normalisation).
inline Vec2 turn_eps(Vec2 u, double sign) {
  constexpr double c = 0.9999999999995;  // 1 / sqrt(1 + eps^2) to double precision
  constexpr double s = 9.999999999995e-7;  // eps / sqrt(1 + eps^2)
  return {c * u.x - sign * s * u.y, sign * s * u.x + c * u.y};
}

// turn(u, a) for a unit u: 1/sqrt(1 + a^2) = 1 - a^2/2 + 3a^4/8 - ... is
// 1 - a^2/2 to double precision for |a| < 1e-4 (the usual lag of a slaved slip).
inline Vec2 turn_small(Vec2 u, double a) {
  if (!(std::abs(a) < 1e-4)) return turn(u, a);
  return (1.0 - 0.5 * a * a) * (u + a * perp(u));
}

// Slip rate of one contact slipping in direction u while the other contact is
// in mode `other` (slipping in direction w, or sticking).
// Inlined where it is called (a slaved direction's Newton iterations call it
// some eight times with the same contact and mode, which the branches below
// then fold away).
[[gnu::always_inline]] inline Vec2 slip_rate_when_slipping(const Coefficients& k, bool at_cushion, Vec2 u,
                                                          ContactMode other, Vec2 w) {
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
SlavedDirection slaved_bed_direction(const Coefficients& k, double r, Vec2 w, double r_cushion) {
  const auto [f, g0] = bed_drive(k, w);
  const double g = length(g0);
  const double inv_g = 1.0 / g;
  const Vec2 u0 = inv_g * g0;
  double lag = 0.0;
  if (r > 0.0 && r_cushion > 0.0) {
    // dw/dP from the cushion's slip rate (with the bed's friction along u0,
    // (3d), (10)); dg0/dP = diag(k1, k2) (-mu_w dw/dP); phi0' = cross(u0, dg0/dP) / |g0|.
    const double load = bed_normal_rate(k, {f, {}});  // n_C (3d)
    const Vec2 fb = (-k.mu_s * load) * u0;
    const Vec2 rate = cushion_slip_rate(k, {f, fb});
    const Vec2 dw = (rate - dot(w, rate) * w) / r_cushion;
    const Vec2 dg0{-k.mu_w * k.k1 * dw.x, -k.mu_w * k.k2 * dw.y};
    const double dphi0 = cross(u0, dg0) * inv_g;
    const double d = g - 3.5 * k.mu_s * load;  // dr/dP = dot(u0, g0 - 7/2 mu_s n_C u0)
    lag = std::clamp(-r * dphi0 / (g + d), -0.25, 0.25);  // r phi0' / (F_phi - D)
  }
  return {turn_small(u0, lag), -g};
}

// The slow-manifold direction near `start` (see above), for a slip of size r.
SlavedDirection slaved_direction(const Coefficients& k, bool at_cushion, Vec2 start, double r, ContactMode other,
                                 Vec2 w, Vec2 other_slip) {
  if (!at_cushion && other == kSlip) return slaved_bed_direction(k, r, w, length(other_slip));
  auto F = [&](Vec2 u, Vec2 ww) { return cross(u, slip_rate_when_slipping(k, at_cushion, u, other, ww)); };
  constexpr double eps = 1e-6;
  // Newton from the start (the previous slaved direction, usually within
  // 1e-6 rad of the root), with the derivative of the first iterate.
  Vec2 u = start;
  const double f_phi = (F(turn_eps(u, 1.0), w) - F(turn_eps(u, -1.0), w)) / (2.0 * eps);
  if (std::abs(f_phi) > 1e-14) {
    for (int it = 0; it < 4; ++it) {
      const double step = std::clamp(F(u, w) / f_phi, -0.25, 0.25);
      u = turn(u, -step);
      if (std::abs(step) < 1e-10) break;
    }
  }
  const double r_other = length(other_slip);
  if (other == kSlip && f_phi < 0.0 && r > 0.0 && r_other > 0.0) {
    // The lag behind the moving root; phi0 moves only through the other
    // contact's slip direction w(P).
    const Vec2 other_rate = at_cushion ? bed_slip_rate(k, friction_for(k, kSlip, u, kSlip, w))
                                       : cushion_slip_rate(k, friction_for(k, kSlip, w, kSlip, u));
    const Vec2 dw = (other_rate - dot(w, other_rate) * w) / r_other;
    const double f_p = (F(u, unit(w + eps * dw)) - F(u, unit(w - eps * dw))) / (2.0 * eps);
    const double d = dot(u, slip_rate_when_slipping(k, at_cushion, u, other, w));  // dr/dP
    const double relax = f_phi - d < 0.0 ? f_phi - d : f_phi;
    u = turn(u, std::clamp(r * (-f_p / f_phi) / relax, -0.25, 0.25));
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
    const Vec2 up = turn_eps(u0, 1.0);
    const Vec2 um = turn_eps(u0, -1.0);
    const double f_phi = (cross(up, rate_at(up)) - cross(um, rate_at(um))) / (2.0 * eps);
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

// ------------------------------------------------------------------ integration

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
  double zero_slip2;   // zero_slip^2
  bool free_slip = false;  // both contacts slip, neither slaved: rhs() inline (and FreeSlipStep)
  bool slaved_bed = false;  // both slip, the bed's slip slaved: rhs() inline
  double cushion_r = 0.0;  // slip speeds at the step start (set_references)
  double bed_r = 0.0;
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
  void directions(const SlipState& y, Vec2& cushion_dir, Vec2& bed_dir) const {
    const Vec2 si = slip_i(y);
    const Vec2 sc = slip_c(y);
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
  Friction friction(const SlipState& y) const {
    Vec2 cd;
    Vec2 bd;
    directions(y, cd, bd);
    return friction_for(k, modes.cushion, cd, modes.bed, bd);
  }
  // d SlipState / dP. The common case, both contacts slipping freely, is inline:
  // (7), (8), (10) with the slip directions from the slip velocities.
  SlipState rhs(const SlipState& y) const {
    if (free_slip) {
      const Vec2 si = slip_i(y);
      const Vec2 sc = slip_c(y);
      const double ri2 = dot(si, si);
      const double rc2 = dot(sc, sc);
      if (ri2 > zero_slip2 && rc2 > zero_slip2) {
        const double wi = (dot(si, cushion_ref) < 0.0 ? k.mu_w : -k.mu_w) / std::sqrt(ri2);
        const double wc = (dot(sc, bed_ref) < 0.0 ? k.mu_s : -k.mu_s) / std::sqrt(rc2);
        Friction f;
        f.cushion = wi * si;
        f.bed = (wc * bed_normal_rate(k, f)) * sc;
        return slip_rates(k, y, f);
      }
    }
    if (slaved_bed) {
      // A rolling ball's start: the cushion slips freely and the bed's slip
      // grows from zero along its slow manifold (directions(), inline).
      const Vec2 si = slip_i(y);
      const double ri2 = dot(si, si);
      if (ri2 > zero_slip2) {
        const double ri = std::sqrt(ri2);
        Vec2 w = si / ri;
        if (dot(w, cushion_ref) < 0.0) w = -w;
        Friction f;
        f.cushion = -k.mu_w * w;
        f.bed = (-k.mu_s * bed_normal_rate(k, f)) * slaved_bed_direction(k, length(slip_c(y)), w, ri).u;
        return slip_rates(k, y, f);
      }
    }
    return rhs_general(y);
  }
  [[gnu::noinline]] SlipState rhs_general(const SlipState& y) const { return slip_rates(k, y, friction(y)); }

  // At a step start: enter the slaved regime when a small slip has settled
  // onto its slow manifold (its direction within kManifoldAngle of it), leave
  // it once the slip has grown, re-arm the approach finishing, and set the
  // reference directions.
  void set_references(const SlipState& y) {
    const Vec2 si = slip_i(y);
    const Vec2 sc = slip_c(y);
    const double ri = length(si);
    const double rc = length(sc);
    cushion_r = ri;
    bed_r = rc;
    update_regime(cushion_regime, ri);
    update_regime(bed_regime, rc);
    cushion_ref = ri > zero_slip ? si / ri : modes.cushion_direction;
    bed_ref = rc > zero_slip ? sc / rc : modes.bed_direction;
    if (cushion_regime.slaved) cushion_ref = cushion_regime.direction;
    if (bed_regime.slaved) bed_ref = bed_regime.direction;
    if (ri < slaved_slip) try_enslave(true, si, ri, sc);
    if (rc < slaved_slip) try_enslave(false, sc, rc, si);
    free_slip = modes.cushion == kSlip && modes.bed == kSlip && !cushion_regime.slaved && !bed_regime.slaved;
    slaved_bed = modes.cushion == kSlip && modes.bed == kSlip && !cushion_regime.slaved && bed_regime.slaved;
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
    // Within kManifoldAngle of the manifold; a slip of a few small_slip also
    // where it is off by no more than 0.05 small_slip (its direction then
    // chatters about the manifold in steps of ~r / |F_phi|, too short to
    // settle it: a slip closing in on zero that slowly used to hover there
    // until it was set to zero).
    const double angle = std::max(kManifoldAngle, 0.05 * small_slip / r);
    if (sd.f_phi < 0.0 && std::abs(cross(sd.u, slip / r)) < angle && dot(sd.u, slip) > 0.0) {
      g.slaved = true;
      g.direction = sd.u;
    }
  }
  // The longest step whose error estimate can be trusted while a free slip
  // grows from near zero: its direction s/|s| is analytic in P only up to
  // the nearest complex zero of |s|^2, at the distance |s|/|ds/dP| to first
  // order (the roots of |s0 + v P|^2 lie at |P| = |s0|/|v|), the radius of
  // convergence of the solution's Taylor series. A Runge-Kutta step longer
  // than that is no longer in the asymptotic regime of its order, and its
  // embedded error estimate says nothing: on a nearly rolling ball (the bed's
  // slip at 0.4 % of the normal speed, growing) a step 2.7 times that
  // distance was accepted with an estimate of 0.86 times the tolerance and a
  // true local error of 1,700 times it, 2.8e-6 of the largest incoming
  // velocity in the outcome. A slip moving towards zero is not bounded: the
  // zero ahead is an event, the friction direction is continued through it
  // within a step (free_direction()), and a close pass is retried shorter.
  // Slaved slips follow their slow manifold, which is smooth; a sticking
  // contact has no direction, nor has a slip below zero_slip (its direction
  // is the reference's). Infinity where nothing bounds the step.
  double step_bound(const SlipState& y, const SlipState& dy) const {
    double bound = std::numeric_limits<double>::infinity();
    auto limit = [&](bool slipping, const SlipRegime& g, Vec2 slip, Vec2 rate) {
      const double r2 = dot(slip, slip);
      if (!slipping || g.slaved || !(r2 > zero_slip2) || dot(slip, rate) < 0.0) return;
      const double v2 = dot(rate, rate);
      if (v2 * bound * bound > r2) bound = std::sqrt(r2 / v2);
    };
    limit(modes.cushion == kSlip, cushion_regime, slip_i(y), slip_i(dy));
    limit(modes.bed == kSlip, bed_regime, slip_c(y), slip_c(dy));
    return bound;
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
namespace dp = dormand_prince;

struct Step {
  SlipState y1;
  SlipState k3, k4, k5, k6, k7;  // the stages the dense output needs (and k1)
  std::array<SlipState, 4> dense;  // filled by make_dense()
};

// One DOPRI5 step of size h from y0 with k1 = f(y0): the 5th-order solution
// y1, f at it (k7, first same as last), and the stages for the dense output
// (Hairer's CONTD5, 4th order), which is computed on demand. Returns the
// error estimate max_i |err_i| / atol (the state is in units of the normal
// speed; atol is relative to the largest initial velocity).
template <class Rhs>
double dopri5_step(const Rhs& sys, const SlipState& y0, const SlipState& k1, double h, double atol, Step& st) {
  using namespace dp;
  constexpr std::size_t n = std::tuple_size_v<SlipState>;
  // The right-hand side reads the slips only: the stages need no W.
  SlipState t{};
  for (std::size_t i = 0; i < kSlips; ++i) t[i] = y0[i] + (h * a21) * k1[i];
  const SlipState k2 = sys.rhs(t);
  for (std::size_t i = 0; i < kSlips; ++i) t[i] = (y0[i] + h * (a31 * k1[i])) + (h * a32) * k2[i];
  st.k3 = sys.rhs(t);
  const SlipState& k3 = st.k3;
  for (std::size_t i = 0; i < kSlips; ++i) t[i] = (y0[i] + h * (a41 * k1[i] + a42 * k2[i])) + (h * a43) * k3[i];
  st.k4 = sys.rhs(t);
  const SlipState& k4 = st.k4;
  for (std::size_t i = 0; i < kSlips; ++i) {
    t[i] = (y0[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i])) + (h * a54) * k4[i];
  }
  st.k5 = sys.rhs(t);
  const SlipState& k5 = st.k5;
  for (std::size_t i = 0; i < kSlips; ++i) {
    t[i] = (y0[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i])) + (h * a65) * k5[i];
  }
  st.k6 = sys.rhs(t);
  const SlipState& k6 = st.k6;
  for (std::size_t i = 0; i < n; ++i) {
    st.y1[i] = (y0[i] + h * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i])) + (h * a76) * k6[i];
  }
  st.k7 = sys.rhs(st.y1);
  const SlipState& k7 = st.k7;
  double err = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    err = std::max(err, std::abs(e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]));
  }
  return h * err / atol;
}

// The same step while both contacts slip freely (Exact::rhs's common case),
// written for its dependency chain: the stages are one long chain of
// dependent operations (the slip directions need a square root and a
// division), so each stage's state is formed from the previous stage's
// friction as soon as that is known: every other term is summed in advance
// (each rate as it becomes available is added to the sums of all later
// stages), and the new state waits for few operations:
//  - mu/|s| is formed as (mu/|s|^2) |s|, so that the square root and the
//    division run side by side instead of one after the other;
//  - the bed's friction q s_C (q = wc (sin(theta) - wi cos(theta) s_I,y'),
//    (8), (10)) enters expanded, wc sin(theta) s_C - wi wc cos(theta) s_I,y' s_C,
//    so the new slips wait on wi, wc and wi wc, not on q.
// The results agree with dopri5_step (the scalar formulae of Exact::rhs) to
// rounding, not bit for bit.
//
// The two contacts are computed side by side, as Pairs: the x components
// (s_I,x, s_C,x) in one and the y components (s_I,y', s_C,y) in the other,
// so that both slip speeds take one square root and one division, and each
// sum one operation for two components.
class FreeSlipStep {
 public:
  // Made once per solve: the constants of `e` (its coefficients and zero
  // slip); each step reads the reference directions that e has at the time.
  explicit FreeSlipStep(const Exact& e)
      : sys_(&e),
        s_(e.k.s),
        c_(e.k.c),
        c_n_(e.k.c * e.k.inv_1ps),
        zero2_(e.zero_slip2),
        mu_{e.k.mu_w, e.k.mu_s},
        f_x_{3.5, e.k.k1},
        g_x_{e.k.k1, 3.5},
        const_y_{e.k.s * e.k.c, -e.k.c},
        f_y_{e.k.kyy, e.k.k2},
        g_y_{e.k.k2, 3.5} {}

  double operator()(const SlipState& y0, const SlipState& k1, double h, double atol, Step& st) {
    using namespace dp;
    ref_x_ = Pair{sys_->cushion_ref.x, sys_->bed_ref.x};
    ref_y_ = Pair{sys_->cushion_ref.y, sys_->bed_ref.y};
    const Slips z0 = load(y0);
    const Slips f1 = load(k1);  // k1's slips
    // Sums of the stages 3 to 6, of y1 and of the error estimate (W apart).
    Slips b3 = axpy(z0, h * a31, f1);
    Slips b4 = axpy(z0, h * a41, f1);
    Slips b5 = axpy(z0, h * a51, f1);
    Slips b6 = axpy(z0, h * a61, f1);
    Slips yb = axpy(z0, h * a71, f1);
    Slips eb = scale(e1, f1);
    double yb_w = y0[kW] + (h * a71) * k1[kW];
    double eb_w = e1 * k1[kW];
    Rates r;
    Slips t = stage(axpy(z0, h * a21, f1), b3, h * a32, r);  // k2
    b4 = axpy(b4, h * a42, r.slips);
    b5 = axpy(b5, h * a52, r.slips);
    b6 = axpy(b6, h * a62, r.slips);
    t = stage(t, b4, h * a43, r);  // k3
    store(r, st.k3);
    b5 = axpy(b5, h * a53, r.slips);
    b6 = axpy(b6, h * a63, r.slips);
    yb = axpy(yb, h * a73, r.slips);
    eb = axpy(eb, e3, r.slips);
    yb_w += (h * a73) * r.w;
    eb_w += e3 * r.w;
    t = stage(t, b5, h * a54, r);  // k4
    store(r, st.k4);
    b6 = axpy(b6, h * a64, r.slips);
    yb = axpy(yb, h * a74, r.slips);
    eb = axpy(eb, e4, r.slips);
    yb_w += (h * a74) * r.w;
    eb_w += e4 * r.w;
    t = stage(t, b6, h * a65, r);  // k5
    store(r, st.k5);
    yb = axpy(yb, h * a75, r.slips);
    eb = axpy(eb, e5, r.slips);
    yb_w += (h * a75) * r.w;
    eb_w += e5 * r.w;
    const Slips z1 = stage(t, yb, h * a76, r);  // k6, and the new slips
    store(r, st.k6);
    store(z1, st.y1);
    st.y1[kW] = yb_w + (h * a76) * r.w;
    eb = axpy(eb, e6, r.slips);
    eb_w += e6 * r.w;
    stage(z1, z1, 0.0, r);  // k7 (first same as last)
    store(r, st.k7);
    eb = axpy(eb, e7, r.slips);
    eb_w += e7 * r.w;
    const double err = std::max({std::abs(eb.x[0]), std::abs(eb.x[1]), std::abs(eb.y[0]), std::abs(eb.y[1]),
                                 std::abs(eb_w)});
    return h * err / atol;
  }

 private:
  // Two doubles in one SIMD register (a GCC/Clang vector extension: SSE2 on
  // x86-64, NEON on AArch64, pairs of scalars elsewhere).
  using Pair = double __attribute__((vector_size(16)));
  struct Slips {
    Pair x;  // (s_I,x, s_C,x)
    Pair y;  // (s_I,y', s_C,y)
  };
  struct Rates {
    Slips slips;
    double w;  // dW/dP
  };

  static Pair pair(double a) { return Pair{a, a}; }
  static Slips load(const SlipState& z) {
    static_assert(kSix + 1 == kScx && kSiy + 1 == kScy, "x and y components side by side");
    return {Pair{z[kSix], z[kScx]}, Pair{z[kSiy], z[kScy]}};
  }
  static void store(const Slips& s, SlipState& z) {
    z[kSix] = s.x[0];
    z[kScx] = s.x[1];
    z[kSiy] = s.y[0];
    z[kScy] = s.y[1];
  }
  static void store(const Rates& r, SlipState& z) {
    store(r.slips, z);
    z[kW] = r.w;
  }
  // base + a d, per component.
  static Slips axpy(const Slips& base, double a, const Slips& d) {
    const Pair pa = pair(a);
    return {base.x + pa * d.x, base.y + pa * d.y};
  }
  static Slips scale(double a, const Slips& d) { return {pair(a) * d.x, pair(a) * d.y}; }

  // The rates r at the slips z (Exact::rhs), and returns base + hk r for
  // the slips of the next stage.
  Slips stage(const Slips& z, const Slips& base, double hk, Rates& r) const {
    const Pair r2 = z.x * z.x + z.y * z.y;  // (|s_I|^2, |s_C|^2)
    if (!(r2[0] > zero2_ && r2[1] > zero2_)) {
      SlipState zz{};
      store(z, zz);
      const SlipState d = sys_->rhs_general(zz);
      r = {load(d), d[kW]};
      return axpy(base, hk, r.slips);
    }
    // (7a), (7b): the friction at I opposes the slip (continued through zero
    // with the sign at the step start); (3d), (10a), (10b) at C:
    //   f = wi s_I,  g = q s_C,  q = wc (sin(theta) - cos(theta) f_y').
    const Pair along_ref = z.x * ref_x_ + z.y * ref_y_;
    const Pair mu = along_ref < 0.0 ? mu_ : -mu_;
    const Pair w = (mu / r2) * Pair{std::sqrt(r2[0]), std::sqrt(r2[1])};  // (wi, wc) = mu / |s|
    const double wi = w[0];
    const double wc = w[1];
    const double wiwc = wi * wc;
    const Pair pwi = pair(wi);
    const Pair pwc = pair(wc);
    const Pair pwiwc = pair(wiwc);
    const Pair phk = pair(hk);
    // The slip rates (mathavan_2010_equations.hpp) are a f + b g + const per component:
    // x: (7/2, k1) f_x + (k1, 7/2) g_x;  y: (sc, -c) + (kyy, k2) f_y + (k2, 7/2) g_y,
    // with f = wi s_I and g = q s_C = (wc s - wi wc c s_I,y') s_C.
    const Pair six = pair(z.x[0]);
    const Pair scx = pair(z.x[1]);
    const Pair siy = pair(z.y[0]);
    const Pair scy = pair(z.y[1]);
    const Pair c_siy = pair(c_ * z.y[0]);
    const Pair bed_x = (phk * g_x_) * scx;  // multiplies q
    const Pair bed_y = (phk * g_y_) * scy;
    const Slips next{((base.x + ((phk * f_x_) * six) * pwi) + (bed_x * s_) * pwc) - (bed_x * c_siy) * pwiwc,
                     (((base.y + phk * const_y_) + ((phk * f_y_) * siy) * pwi) + (bed_y * s_) * pwc) -
                         (bed_y * c_siy) * pwiwc};
    const double q = wc * s_ - wiwc * (c_ * z.y[0]);
    const Pair ax = pair(wi * z.x[0]);
    const Pair ay = pair(wi * z.y[0]);
    const Pair gx = pair(q * z.x[1]);
    const Pair gy = pair(q * z.y[1]);
    r.slips = {f_x_ * ax + g_x_ * gx, (const_y_ + f_y_ * ay) + g_y_ * gy};
    r.w = -c_n_ * (z.y[1] - z.y[0]);
    return next;
  }

  const Exact* sys_;
  double s_, c_, c_n_;  // c_n = cos(theta) / (1 + sin(theta))
  double zero2_;
  Pair mu_;              // (mu_w, mu_s)
  Pair ref_x_{}, ref_y_{};  // the reference slip directions at the step's start, x and y components
  Pair f_x_, g_x_;       // coefficients of the friction rates in the x rates
  Pair const_y_, f_y_, g_y_;  // and in the y rates
};

void make_dense(const SlipState& y0, const SlipState& k1, double h, Step& st) {
  using namespace dp;
  for (std::size_t i = 0; i < y0.size(); ++i) {
    const double r2 = st.y1[i] - y0[i];
    const double r3 = h * k1[i] - r2;
    st.dense[0][i] = r2;
    st.dense[1][i] = r3;
    st.dense[2][i] = r2 - h * st.k7[i] - r3;
    st.dense[3][i] =
        h * (d1 * k1[i] + d3 * st.k3[i] + d4 * st.k4[i] + d5 * st.k5[i] + d6 * st.k6[i] + d7 * st.k7[i]);
  }
}

// Dense output at the fraction t of the step: one component, and the state.
inline double interpolate(const SlipState& y0, const Step& st, double t, std::size_t i) {
  const double u = 1.0 - t;
  return y0[i] + t * (st.dense[0][i] + u * (st.dense[1][i] + t * (st.dense[2][i] + u * st.dense[3][i])));
}
SlipState interpolate(const SlipState& y0, const Step& st, double t) {
  SlipState out;
  for (std::size_t i = 0; i < y0.size(); ++i) out[i] = interpolate(y0, st, t, i);
  return out;
}

// Events that end a smooth segment (the end of compression (16c) does not: it
// changes nothing in the equations; the end of restitution (16b) ends the
// impact). Both are located separately, on the same dense output.
enum class Event : unsigned char {
  none,
  cushion_slip_zero,     // the slip at I runs through zero
  bed_slip_zero,         // the slip at C runs through zero
  cushion_slip_small,    // a free s falls to small_slip (finish its approach to zero)
  bed_slip_small,        // s' likewise
  cushion_stick_breaks,  // the friction needed to stick at I reaches mu_w
  bed_stick_breaks,      // the friction needed to stick at C reaches mu_s n_C
};

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
  double tiny_slip;  // the small-slip threshold once an approach could not be finished

  double small_threshold(const SlipRegime& g) const { return g.approach_armed ? sys->small_slip : tiny_slip; }

  double value(Event e, const SlipState& y) const {
    const Coefficients& k = sys->k;
    switch (e) {
      case Event::cushion_slip_zero: return -dot(slip_i(y), sys->cushion_ref);
      case Event::bed_slip_zero: return -dot(slip_c(y), sys->bed_ref);
      case Event::cushion_slip_small: return small_threshold(sys->cushion_regime) - length(slip_i(y));
      case Event::bed_slip_small: return small_threshold(sys->bed_regime) - length(slip_c(y));
      case Event::cushion_stick_breaks: return cushion_cone_excess(k, sys->friction(y));
      case Event::bed_stick_breaks: return bed_cone_excess(k, sys->friction(y));
      case Event::none: break;
    }
    return -1.0;
  }

  // Whether a slip's component along its reference direction could dip to
  // zero inside a step although it is positive at both ends: only if it is
  // within one step's worth of change of zero at either end.
  bool may_dip(bool at_cushion, const SlipState& y0, const SlipState& d0, const SlipState& y1, const SlipState& d1,
               double h) const {
    const Vec2 ref = at_cushion ? sys->cushion_ref : sys->bed_ref;
    auto slip = [&](const SlipState& s) { return at_cushion ? slip_i(s) : slip_c(s); };
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
// The local error per Runge-Kutta step is solve_exact's `tolerance`
// (kExactTolerance by default, mathavan_2010_equations.hpp).
struct ExactLimits {
  static constexpr double slaved_slip = 1e-3;   // a small slip may be slaved below this
  static constexpr double small_slip = 1e-6;    // a free slip closing in on zero is finished below this
  static constexpr double tiny_slip = 1e-10;    // a slip this small is zero
  static constexpr int max_attempts = 20000;    // Runge-Kutta steps, accepted or not
  static constexpr int hover_attempts = 200;    // steps in one segment before a hovering slip is set to zero
  static constexpr int max_events = 64;
  // While both contacts slip by more than loose_slip, the local tolerance of
  // a step is the solver's times their smaller slip over loose_slip, up to
  // `loosening` times, and never above kMaxExactTolerance: where the slips
  // are large the directions turn slowly and an error committed there is not
  // amplified (the steps' errors add up to about the tolerance), while near
  // zero slip, where the default 1e-8 is needed, the tolerance is the
  // solver's. On 200,000 random sliding impacts (bench_cushion_impact's
  // BM_CushionRandomAccuracy) 10x takes 16.1 steps against 17.8 at 3x,
  // worst error against the solve at 1e-11 5.1e-7 of the largest
  // incoming velocity (4.3e-7 at 3x), none beyond the accuracy goal;
  // the five-rail shot of bench_simulator 57.6k -> 54.3k instructions. (10x
  // once moved the constants fit of tests/test_constants_fit.cpp, whose
  // objective is flat along a valley where the cushion's restitution and
  // friction trade: its path, not the simulated shots; the fit's restarts
  // now reach the truth under either tolerance.) A sticking contact has
  // zero slip. Only at the default tolerance or looser: reference solves and
  // the rolling-ball table's are not loosened.
  static constexpr double loose_slip = 0.01;
  static constexpr double loosening = 10.0;
  // In the smooth middle (SmoothMiddle, below) the same loosening goes on
  // up to `middle_loosening` times further: to 30x the solver's tolerance at
  // the default (the local tolerance 3e-7 where both slips exceed 0.3 of the
  // velocity scale), to 3x at 1e-7 (the same 3e-7 there, so that 1e-7 stays
  // the cheaper setting): no event can fall inside a step there, so a step's
  // error is carried along smoothly, not turned into an event's error. On
  // the 200,000 random sliding impacts of BM_CushionRandomAccuracy the worst
  // error against the solve at 1e-11 went from 4.4e-7 to 4.8e-7 of the
  // largest incoming velocity (none beyond the goal), and on two more seeds
  // of the same draw it stayed as before (7.8e-7; and 2.8e-6 on one impact
  // of seed 30, an outlier that the solver before the smooth middle had
  // too: a step past a growing slip's radius of convergence, since bounded,
  // Exact::step_bound); the five-rail shot's sliding impact takes 9 steps
  // instead of 10.
  // (100x took 8, worst 5.6e-7.)
  static constexpr double middle_loosening = 3.0;
};


// ------------------------------------------------------------------ the smooth middle

// While both contacts slip and both slips stay well clear of zero, none of
// the events above can happen (no slip reaches zero or passes close to it,
// no contact sticks or is slaved, the directions need no reference), and the
// integration is the smooth system alone, with the ends of compression (16c)
// and restitution (16b) on the way: the smooth middle of a sliding impact,
// where most of its steps are. run_smooth_middle() integrates it with the
// same DOPRI5 steps and step-size control as the general loop below (the
// same loosened tolerance, loosened further by ExactLimits::middle_loosening),
// without its event machinery (whose per-step overhead was as large as the
// step itself: on the five-rail shot's sliding impact solve_exact took
// 18,700 instructions, 10,600 of them its 11 steps; now 12,800, 9,600 of
// them 10 steps, one rejected; callgrind), and hands the
// state back at the start of the first step that could bring a slip within
// `clearance` of zero. The general loop hands over again after an accepted
// step wherever both slips are free and clear (after a slip reversal, for
// instance), at most once per segment unless the slips have doubled.
struct SmoothMiddle {
  double c_n;         // cos(theta) / (1 + sin(theta)): dW/dP = -c_n (s_C,y - s_I,y') (16a)
  double rate_bound;  // |d s/dP| of either contact, for any slip directions
  double clearance;   // slips stay above this (scaled units)
  double atol;        // the solver's local tolerance, loosened by the slips as in the general loop:
  double loosen_per_slip;  // x clamp(smaller slip x loosen_per_slip, 1, loosen_max)
  double loosen_max;

  SmoothMiddle(const Coefficients& k, double clearance_in, double atol_in, double loosen_per_slip_in,
               double loosen_max_in)
      : c_n(k.c * k.inv_1ps), rate_bound(0.0), clearance(clearance_in), atol(atol_in),
        loosen_per_slip(loosen_per_slip_in), loosen_max(loosen_max_in) {
    // |friction rates|: mu_w at I, mu_s n_C <= mu_s (s + c mu_w) at C (3d), (8);
    // the slip rates (mathavan_2010_equations.hpp) bounded entry by entry.
    const double g = k.mu_s * (k.s + k.c * k.mu_w);
    const double kmax = std::max(std::abs(k.k1), std::abs(k.k2));
    rate_bound = std::max(k.s * k.c + std::max(3.5, k.kyy) * k.mu_w + kmax * g, k.c + kmax * k.mu_w + 3.5 * g);
  }
  static double smaller_slip2(const SlipState& y) {
    return std::min(dot(slip_i(y), slip_i(y)), dot(slip_c(y), slip_c(y)));
  }
  double smaller_slip(const SlipState& y) const { return std::sqrt(smaller_slip2(y)); }
  // The local tolerance of a step from the smaller slip r0 at its start.
  double step_tolerance(double r0) const { return atol * std::clamp(r0 * loosen_per_slip, 1.0, loosen_max); }
  // Whether the general loop at y may hand over: both contacts slip freely,
  // by more than `entry` (and twice the clearance).
  bool enters(const Exact& sys, const SlipState& y, double entry) const {
    return sys.free_slip && smaller_slip(y) > std::max(entry, 2.0 * clearance);
  }
  // Whether both slips stay above `clearance` within a step. A slip of sizes
  // r0 and r1 at the ends of a step h stays above (r0 + r1 - h rate_bound) / 2
  // (`r0` is the smaller slip at the start, r1 at the end); where that
  // bound is too coarse, the sizes at its quarters on the cubic Hermite
  // interpolant of its ends, less h rate_bound / 8 (the most a slip can
  // fall between two such points), decide.
  bool clear(const SlipState& y0, const SlipState& f0, double r0, const SlipState& y1, const SlipState& f1,
             double r1, double h) const {
    if (r0 + r1 > h * rate_bound + 2.0 * clearance) return true;
    const double margin = clearance + 0.125 * h * rate_bound;
    const double margin2 = margin * margin;
    if (!(smaller_slip2(y1) > margin2)) return false;
    std::array<double, kSlips> a, b, d;
    for (std::size_t i = 0; i < kSlips; ++i) {
      a[i] = y1[i] - y0[i];
      b[i] = h * f0[i] - a[i];
      d[i] = a[i] - h * f1[i] - b[i];
    }
    for (const double t : {0.25, 0.5, 0.75}) {
      const double u = 1.0 - t;
      SlipState z{};
      for (std::size_t i = 0; i < kSlips; ++i) z[i] = y0[i] + t * (a[i] + u * (b[i] + t * d[i]));
      if (!(smaller_slip2(z) > margin2)) return false;
    }
    return true;
  }
};

// Where the impact stands, shared by the smooth middle and the general loop.
struct Progress {
  SlipState y{};
  SlipState k1{};  // d y / dP at y
  double p = 0.0;
  double h = 0.0;
  bool compressing = true;
  double work_target = 0.0;
  bool over = false;  // restitution has ended (y is the final state)
};

// A combination sum_i w_i y_i of a step's dense output (make_dense()) as the
// quartic it is in the fraction t of the step,
//   y(t) = y0 + t (d0 + u (d1 + t (d2 + u d3))), u = 1 - t
//        = y0 + (d0 + d1) t + (d2 + d3 - d1) t^2 - (d2 + 2 d3) t^3 + d3 t^4,
// so that its root is found by Newton's method on the polynomial (three or
// four iterations where regula falsi on interpolate() took ten).
struct DenseQuartic {
  std::array<double, 5> c{};  // coefficients of t^0 .. t^4
  double value(double t) const { return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * c[4]))); }
  double slope(double t) const { return c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * 4.0 * c[4])); }
};
DenseQuartic dense_quartic(const SlipState& y0, const Step& st,
                           std::initializer_list<std::pair<std::size_t, double>> terms) {
  DenseQuartic q;
  for (const auto& [i, w] : terms) {
    const double d0 = st.dense[0][i], d1 = st.dense[1][i], d2 = st.dense[2][i], d3 = st.dense[3][i];
    q.c[0] += w * y0[i];
    q.c[1] += w * (d0 + d1);
    q.c[2] += w * (d2 + d3 - d1);
    q.c[3] -= w * (d2 + 2.0 * d3);
    q.c[4] += w * d3;
  }
  return q;
}
// The root of q in [lo, hi], given q(lo) <= 0 < q(hi): Newton's method from
// the secant's point, kept inside the bracket (bisection where a step would
// leave it), to 1e-13 of the step (as locate()).
double dense_root(const DenseQuartic& q, double lo, double hi) {
  const double q_lo = q.value(lo);
  const double q_hi = q.value(hi);
  double t = q_hi > q_lo ? lo - q_lo * (hi - lo) / (q_hi - q_lo) : 0.5 * (lo + hi);
  for (int it = 0; it < 50; ++it) {
    const double v = q.value(t);
    if (v == 0.0) break;
    (v > 0.0 ? hi : lo) = t;
    const double d = q.slope(t);
    double next = t - v / d;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double moved = std::abs(next - t);
    t = next;
    if (moved <= 1e-13 || hi - lo <= 1e-13) break;
  }
  return t;
}

// Records a state of the impact into its history (CushionImpactOptions::record_history).
struct Recorder {
  std::vector<CushionImpactSample>* history;
  const Coefficients* k;
  const Units* units;
  double j;  // the invariant line momentum (velocity_state)
  void operator()(double p, const SlipState& z) const {
    history->push_back(sample(*k, *units, p, velocity_state(*k, z, j)));
  }
};

// Runs the smooth middle from g (both contacts slipping, clear of zero) until
// the impact ends or a step would leave it; records into `history` if given.
template <class Stepper>
void run_smooth_middle(const SmoothMiddle& m, Stepper& step, double e, Progress& g, Outcome& out,
                       const Recorder* record) {
  double err_previous_root = 0.7;
  double err_previous_3_16 = 0.0;
  double h_previous = 0.0;
  bool rejected = false;
  Step st;
  double r0 = m.smaller_slip(g.y);  // at the step's start
  for (int attempts = 0; attempts < ExactLimits::max_attempts && g.p <= kMaxScaledImpulse; ++attempts) {
    const double atol_step = m.step_tolerance(r0);
    const double err = step(g.y, g.k1, g.h, atol_step, st);
    const double root4 = std::sqrt(std::sqrt(std::max(err, 1e-5)));
    if (!(err <= 1.0)) {
      g.h /= std::min(10.0, root4 / 0.75);
      rejected = true;
      continue;
    }
    const double r1 = m.smaller_slip(st.y1);
    if (!m.clear(g.y, g.k1, r0, st.y1, st.k7, r1, g.h)) return;
    ++out.steps;
    const double root8 = std::sqrt(root4);
    const double root16 = std::sqrt(root8);
    const double root_3_16 = root8 * root16;
    double factor = 0.85 * err_previous_root / root4;
    if (!rejected && h_previous > 0.0) factor *= (g.h / h_previous) * (err_previous_3_16 / root_3_16);
    double h_next = g.h * std::clamp(factor, 0.1, 5.0);
    if (rejected) h_next = std::min(h_next, g.h);
    err_previous_root = std::sqrt(root16);
    err_previous_3_16 = root_3_16;
    h_previous = g.h;
    rejected = false;

    // The ends of compression, -(1 + s) yG' = s_I,y' - s_C,y rising through
    // zero (16c), and of restitution, W reaching its target (16b), on the
    // step's dense output.
    bool dense_ready = false;
    auto dense = [&] {
      if (!dense_ready) make_dense(g.y, g.k1, g.h, st);
      dense_ready = true;
    };
    double t_from = 0.0;
    if (g.compressing && st.y1[kSiy] - st.y1[kScy] > 0.0) {
      double tc = 0.0;
      if (g.y[kSiy] - g.y[kScy] <= 0.0) {
        dense();
        tc = dense_root(dense_quartic(g.y, st, {{kSiy, 1.0}, {kScy, -1.0}}), 0.0, 1.0);
      }
      g.compressing = false;
      out.compression_impulse = g.p + g.h * tc;
      out.compression_work = tc == 0.0 ? g.y[kW] : interpolate(g.y, st, tc, kW);
      g.work_target = (1.0 - e * e) * out.compression_work;  // (16b)
      ++out.events;
      out.note(32);
      if (record && tc > 0.0) (*record)(out.compression_impulse, interpolate(g.y, st, tc));
      t_from = tc;
    }
    if (!g.compressing && st.y1[kW] > g.work_target) {
      double tr = t_from;
      if ((t_from == 0.0 ? g.y[kW] : interpolate(g.y, st, t_from, kW)) <= g.work_target) {
        dense();
        DenseQuartic w = dense_quartic(g.y, st, {{kW, 1.0}});
        w.c[0] -= g.work_target;
        tr = dense_root(w, t_from, 1.0);
      }
      if (tr >= 0.9) {
        dense();
        g.y = interpolate(g.y, st, tr);
      } else if (tr > 0.0) {
        Step last;
        step(g.y, g.k1, g.h * tr, m.atol, last);
        g.y = last.y1;
        ++out.steps;
      }
      g.p += g.h * tr;
      ++out.events;
      out.note(33);
      g.over = true;
      return;
    }
    g.y = st.y1;
    g.p += g.h;
    g.k1 = st.k7;
    r0 = r1;
    if (record) (*record)(g.p, g.y);
    g.h = h_next;
    if (!g.compressing) {
      // Aim the step in which restitution ends to end just past it (as the general loop does).
      const double gap = g.work_target - g.y[kW];
      const double w1 = g.k1[kW];
      const double w2 = -m.c_n * (g.k1[kScy] - g.k1[kSiy]);
      const double disc = w1 * w1 + 2.0 * w2 * gap;
      if (w1 > 0.0 && disc > 0.0) {
        const double rest = 2.0 * gap / (w1 + std::sqrt(disc));
        if (rest <= g.h) {
          g.h = std::min(1.02 * rest, h_next * 1.02);
        } else if (rest <= 2.0 * g.h) {
          g.h = 0.51 * rest;
        }
      }
    }
  }
}

}  // namespace

Outcome solve_exact(const Coefficients& k, const State& y0, const Units& units,
                    std::vector<CushionImpactSample>* history, double tolerance) {
  const double scale = std::max(velocity_scale(y0), 1.0);
  const double tiny_slip = ExactLimits::tiny_slip * scale;
  const double atol = tolerance * scale;
  // The step's tolerance, loosened while both slips are large (see ExactLimits::loose_slip).
  const double loosen_max =
      tolerance >= kExactTolerance ? std::max(1.0, std::min(ExactLimits::loosening, kMaxExactTolerance / tolerance)) : 1.0;
  const double loosen_per_slip = 1.0 / (ExactLimits::loose_slip * scale);
  Exact sys{};
  sys.k = k;
  sys.zero_slip = 1e-13 * scale;
  sys.zero_slip2 = sys.zero_slip * sys.zero_slip;
  sys.slaved_slip = ExactLimits::slaved_slip * scale;
  sys.small_slip = ExactLimits::small_slip * scale;
  SlipState y = slip_state(k, y0);
  const double j = line_momentum(k, y0);
  auto record = [&](double p_now) { history->push_back(sample(k, units, p_now, velocity_state(k, y, j))); };

  // Modes at a state where the flagged contacts have zero slip; a contact
  // that starts to slip from zero does so along its slaved direction.
  auto choose_modes = [&](bool cushion_zero, bool bed_zero) {
    if (cushion_zero) snap_cushion_slip(y);
    if (bed_zero) snap_bed_slip(k, y);
    sys.modes = select_modes(k, slip_i(y), slip_c(y), cushion_zero, bed_zero);
    if (cushion_zero) sys.cushion_regime = {};
    if (bed_zero) sys.bed_regime = {};
    if (cushion_zero && sys.modes.cushion == kSlip) sys.enslave(true, sys.modes.cushion_direction);
    if (bed_zero && sys.modes.bed == kSlip) sys.enslave(false, sys.modes.bed_direction);
  };
  choose_modes(length(slip_i(y)) <= tiny_slip, length(slip_c(y)) <= tiny_slip);
  if (history) record(0.0);

  Outcome out;
  out.note(64 + (sys.modes.cushion == kStick ? 1u : 0u) + (sys.modes.bed == kStick ? 2u : 0u));
  bool compressing = true;
  double work_target = 0.0;
  double p = 0.0;
  const double h_start = 0.1 * (1.0 + k.e);
  double h = h_start;
  // Step-size control: a PI controller (Gustafsson; Hairer's DOPRI5 uses
  // 0.9 err^-(0.2 - 0.75 beta) err_old^beta with beta = 0.04); here
  // 0.85 err^-1/4 err_old^1/32. Between two accepted steps it is made
  // predictive (K. Gustafsson, ACM TOMS 20 (1994) 496-517): the factor is
  // multiplied by (h / h_old) (err_old / err)^(3/16), so a step size that
  // must keep shrinking (a slip closing in on zero) is followed instead of
  // overshot and rejected. All powers are square roots. (Tuned on 2,148
  // impacts from break shots and on the benchmark grid: 14% and 6% fewer
  // steps, accepted and rejected, than the PI controller alone.)
  double err_previous_root = 0.7;  // err_old^(1/32): err_old = 1.1e-5 before the first step
  double err_previous_3_16 = 0.0;  // err_old^(3/16)
  double h_previous = 0.0;         // the last accepted step of this segment (0: none yet)
  bool rejected = false;
  sys.set_references(y);
  SlipState k1 = sys.rhs(y);
  Step st;
  FreeSlipStep free_step(sys);
  int segment_attempts = 0;
  const SmoothMiddle middle(k, ExactLimits::loose_slip * scale, atol, loosen_per_slip,
                            tolerance >= kExactTolerance ? ExactLimits::middle_loosening * loosen_max : 1.0);
  double reentry_slip = 0.0;  // the general loop hands over again only once the slips exceed this
  // The middle's step: FreeSlipStep, with the slips at the step's start as
  // the reference directions (only their sign matters there, and no slip
  // comes near zero within a step of the middle). A plain scalar step took
  // 23 % fewer instructions but 8 % more time on the five rails (the stages'
  // chains of square roots and divisions set the pace; FreeSlipStep runs
  // them side by side).
  auto middle_step = [&](const SlipState& y_start, const SlipState& k_start, double h_step, double atol_step,
                         Step& out_step) {
    sys.cushion_ref = slip_i(y_start);
    sys.bed_ref = slip_c(y_start);
    return free_step(y_start, k_start, h_step, atol_step, out_step);
  };
  // After an event: modes for the contacts whose slip reached zero, and a new segment.
  auto start_segment = [&](bool cushion_zero, bool bed_zero) {
    if (cushion_zero || bed_zero) {
      // A slip reached zero: the other contact is at zero too if it sticks or its slip is tiny.
      cushion_zero = cushion_zero || sys.modes.cushion == kStick || length(slip_i(y)) <= tiny_slip;
      bed_zero = bed_zero || sys.modes.bed == kStick || length(slip_c(y)) <= tiny_slip;
      choose_modes(cushion_zero, bed_zero);
      out.note(64 + (sys.modes.cushion == kStick ? 1u : 0u) + (sys.modes.bed == kStick ? 2u : 0u));
    }
    if (history) record(p);
    sys.set_references(y);
    k1 = sys.rhs(y);
    // A new segment: the step that closed in on the event says nothing about it.
    h = std::max(h, h_start);
    reentry_slip = 0.0;
    err_previous_root = 0.7;
    h_previous = 0.0;
    segment_attempts = 0;
  };
  // The smooth middle (SmoothMiddle): from the start, and again after an
  // accepted step of the general loop wherever both slips are free and clear.
  const Recorder record_state{history, &k, &units, j};
  auto smooth_middle = [&] {
    Progress g{y, k1, p, h, compressing, work_target, false};
    run_smooth_middle(middle, middle_step, k.e, g, out, history ? &record_state : nullptr);
    y = g.y;
    p = g.p;
    compressing = g.compressing;
    work_target = g.work_target;
    if (g.over) return true;
    // Back in the general loop: a new segment from the step that left the
    // middle, and the middle again only once the slips have doubled.
    reentry_slip = 2.0 * middle.smaller_slip(y);
    h = g.h;
    sys.set_references(y);
    k1 = sys.rhs(y);
    err_previous_root = 0.7;
    h_previous = 0.0;
    rejected = false;
    segment_attempts = 0;
    return false;
  };
  auto finish = [&] {
    out.total_impulse = p;
    out.final_state = velocity_state(k, y, j);
    if (history) record(p);
  };
  if (middle.enters(sys, y, 0.0) && smooth_middle()) {
    finish();
    return out;
  }
  for (int attempts = 1;; ++attempts) {
    if (attempts > ExactLimits::max_attempts || p > kMaxScaledImpulse) wedged();
    if (++segment_attempts > ExactLimits::hover_attempts) {
      // A free slip that could not be finished (a near miss of zero) and
      // hovers below small_slip, its direction turning back and forth, in
      // steps that barely advance P_I: it is at zero to within small_slip
      // (the Euler scheme chatters about zero there). Set it to zero and
      // choose the modes afresh, as at a slip reaching zero.
      const bool cushion_hovers = sys.modes.cushion == kSlip && !sys.cushion_regime.slaved &&
                                  !sys.cushion_regime.approach_armed && length(slip_i(y)) <= 2.0 * sys.small_slip;
      const bool bed_hovers = sys.modes.bed == kSlip && !sys.bed_regime.slaved && !sys.bed_regime.approach_armed &&
                              length(slip_c(y)) <= 2.0 * sys.small_slip;
      if (cushion_hovers || bed_hovers) {
        if (++out.events > ExactLimits::max_events) wedged();
        start_segment(cushion_hovers, bed_hovers);
        continue;
      }
    }
    h = std::min(h, sys.step_bound(y, k1));
    const double atol_step = atol * std::clamp(std::min(sys.cushion_r, sys.bed_r) * loosen_per_slip, 1.0, loosen_max);
    const double err = sys.free_slip ? free_step(y, k1, h, atol_step, st) : dopri5_step(sys, y, k1, h, atol_step, st);
    const double root4 = std::sqrt(std::sqrt(std::max(err, 1e-5)));
    if (!(err <= 1.0)) {
      h /= std::min(10.0, root4 / 0.75);
      rejected = true;
      continue;
    }
    // The earliest event inside the step, located on the dense output.
    const EventFunctions ev{&sys, tiny_slip};
    Event first = Event::none;
    double t_first = 2.0;
    bool dense_ready = false;
    auto dense = [&] {
      if (!dense_ready) make_dense(y, k1, h, st);
      dense_ready = true;
    };
    // An event whose function is g_hi > 0 at the fraction t_hi of the step
    // (the end, or a probe inside) and g_start at its start.
    auto crossing = [&](Event e, double g_start, double t_hi, double g_hi) {
      double t = 0.0;
      if (g_start <= 0.0) {
        dense();
        t = t_hi * locate([&](double tt) { return ev.value(e, interpolate(y, st, t_hi * tt)); }, g_start, g_hi);
      }
      if (t < t_first) {
        t_first = t;
        first = e;
      }
    };
    // A slip's component along its reference direction: at the step end, or
    // inside it when it may run through zero and back within the step.
    auto slip_zero = [&](Event e, bool at_cushion, Vec2 slip_start, Vec2 slip_end) {
      const Vec2 ref = at_cushion ? sys.cushion_ref : sys.bed_ref;
      double t_hi = 1.0;
      double g_hi = -dot(slip_end, ref);
      if (!(g_hi > 0.0) && ev.may_dip(at_cushion, y, k1, st.y1, st.k7, h)) {
        // The dip's deepest point is taken where the cubic Hermite
        // interpolant of the step's ends (the dense output without its
        // fourth-order term) has its interior maximum of g (a root of its
        // derivative, a quadratic), then refined on the dense output by
        // parabolic steps; g > 0 there is a crossing. (Probes of the cubic at
        // quarters of the step missed brief dips of a slip arriving along its
        // slaved direction whose rate turns back within the step: the slip
        // then passed by instead of reaching zero and sticking, an error of
        // up to 3.6e-6 of the largest incoming velocity on 200,000 random
        // impacts.)
        const std::size_t ix = at_cushion ? kSix : kScx;
        const std::size_t iy = at_cushion ? kSiy : kScy;
        // g = -(c0 + A t + B (t - t^2) + C (t^2 - t^3)) along ref.
        auto along = [&](double vx, double vy) { return vx * ref.x + vy * ref.y; };
        const double r2x = st.y1[ix] - y[ix];
        const double r2y = st.y1[iy] - y[iy];
        const double r3x = h * k1[ix] - r2x;
        const double r3y = h * k1[iy] - r2y;
        const double ca = along(r2x, r2y);
        const double cb = along(r3x, r3y);
        const double cc = along(r2x - h * st.k7[ix] - r3x, r2y - h * st.k7[iy] - r3y);
        auto g_hermite = [&](double t) { return -(ca * t + cb * (t - t * t) + cc * (t * t - t * t * t)); };  // + g(0)
        // g' = 0: 3C t^2 + 2 (B - C) t - (A + B) = 0.
        double t_peak = -1.0;
        auto consider = [&](double t) {
          if (t > 0.0 && t < 1.0 && (t_peak < 0.0 || g_hermite(t) > g_hermite(t_peak))) t_peak = t;
        };
        const double qa = 3.0 * cc;
        const double qb = 2.0 * (cb - cc);
        const double qc = -(ca + cb);
        if (std::abs(qa) > 1e-12 * (std::abs(qb) + std::abs(qc))) {
          const double disc = qb * qb - 4.0 * qa * qc;
          if (disc >= 0.0) {
            const double root = std::sqrt(disc);
            consider((-qb + root) / (2.0 * qa));
            consider((-qb - root) / (2.0 * qa));
          }
        } else if (qb != 0.0) {
          consider(-qc / qb);
        }
        if (t_peak > 0.0) {
          dense();
          auto g_at = [&](double tt) {
            return -dot(Vec2{interpolate(y, st, tt, ix), interpolate(y, st, tt, iy)}, ref);  // ev.value(e, ...)
          };
          constexpr double kSpan = 1.0 / 16.0;
          double a = std::max(0.0, t_peak - kSpan);
          double b = t_peak;
          double c = std::min(1.0, t_peak + kSpan);
          double ga = a == 0.0 ? -dot(slip_start, ref) : g_at(a);
          double gb = g_at(b);
          double gc = c == 1.0 ? g_hi : g_at(c);
          for (int it = 0; it < 4 && !(gb > 0.0); ++it) {
            const double pa = (b - a) * (gb - gc);
            const double q = (b - c) * (gb - ga);
            const double den = pa - q;
            if (!(den != 0.0)) break;
            const double tv = b - 0.5 * ((b - a) * pa - (b - c) * q) / den;
            if (!(tv > a && tv < c) || tv == b) break;
            const double gv = g_at(tv);
            if (gv > gb) {
              (tv < b ? c : a) = b;
              (tv < b ? gc : ga) = gb;
              b = tv;
              gb = gv;
            } else {
              (tv < b ? a : c) = tv;
              (tv < b ? ga : gc) = gv;
            }
          }
          if (gb > 0.0) {
            t_hi = b;
            g_hi = gb;
          }
        }
      }
      if (g_hi > 0.0) crossing(e, -dot(slip_start, ref), t_hi, g_hi);
    };
    const Modes& m = sys.modes;
    if (m.cushion == kSlip || m.bed == kSlip) {
      const Vec2 si0 = slip_i(y);
      const Vec2 sc0 = slip_c(y);
      const Vec2 si1 = slip_i(st.y1);
      const Vec2 sc1 = slip_c(st.y1);
      if (m.cushion == kSlip) slip_zero(Event::cushion_slip_zero, true, si0, si1);
      if (m.bed == kSlip) slip_zero(Event::bed_slip_zero, false, sc0, sc1);
      if (m.cushion == kSlip && !sys.cushion_regime.slaved) {
        const double threshold = ev.small_threshold(sys.cushion_regime);
        const double g_hi = threshold - length(si1);
        if (sys.cushion_r > threshold && g_hi > 0.0) {
          crossing(Event::cushion_slip_small, threshold - sys.cushion_r, 1.0, g_hi);
        }
      }
      if (m.bed == kSlip && !sys.bed_regime.slaved) {
        const double threshold = ev.small_threshold(sys.bed_regime);
        const double g_hi = threshold - length(sc1);
        if (sys.bed_r > threshold && g_hi > 0.0) {
          crossing(Event::bed_slip_small, threshold - sys.bed_r, 1.0, g_hi);
        }
      }
    }
    if (m.cushion == kStick) {
      const double g_hi = ev.value(Event::cushion_stick_breaks, st.y1);
      if (g_hi > 0.0) crossing(Event::cushion_stick_breaks, ev.value(Event::cushion_stick_breaks, y), 1.0, g_hi);
    }
    if (m.bed == kStick) {
      const double g_hi = ev.value(Event::bed_stick_breaks, st.y1);
      if (g_hi > 0.0) crossing(Event::bed_stick_breaks, ev.value(Event::bed_stick_breaks, y), 1.0, g_hi);
    }

    // A free slip "reaching zero" that is still away from zero where its
    // component along the reference vanishes is a close pass that the step
    // was too long to resolve (its direction turns through 90 degrees or more
    // within the step): taking it for a zero would set the slip to zero, an
    // error of the distance it passes at. Such a step is retried shorter. (A
    // slaved slip arrives along its slow manifold: what is left of it there
    // is the manifold's approximation error, and it is set to zero.)
    if ((first == Event::cushion_slip_zero || first == Event::bed_slip_zero) && t_first > 0.0 &&
        !(first == Event::cushion_slip_zero ? sys.cushion_regime : sys.bed_regime).slaved) {
      const SlipState ye = interpolate(y, st, t_first);
      const Vec2 slip = first == Event::cushion_slip_zero ? slip_i(ye) : slip_c(ye);
      if (!(length(slip) <= atol)) {
        h *= std::max(0.5 * t_first, 0.05);
        rejected = true;
        continue;
      }
    }
    ++out.steps;
    const double root8 = std::sqrt(root4);
    const double root16 = std::sqrt(root8);
    const double root_3_16 = root8 * root16;
    double factor = 0.85 * err_previous_root / root4;
    if (!rejected && h_previous > 0.0) factor *= (h / h_previous) * (err_previous_3_16 / root_3_16);
    double h_next = h * std::clamp(factor, 0.1, 5.0);
    if (rejected) h_next = std::min(h_next, h);
    err_previous_root = std::sqrt(root16);
    err_previous_3_16 = root_3_16;
    h_previous = h;
    rejected = false;

    // The end of compression changes nothing in the equations: it is
    // recorded where it falls and the step goes on. The end of restitution
    // ends the impact. Its state comes from the dense output if it falls near
    // the end of the step (where the dense output is as accurate as the step
    // itself; the step before aims for that, below), else from a step of the
    // exact length (the dense output is only 4th order).
    const double t_cut = first == Event::none ? 1.0 : t_first;
    auto component_at = [&](double t, std::size_t i) {
      if (t == 0.0) return y[i];
      if (t == 1.0) return st.y1[i];
      dense();
      return interpolate(y, st, t, i);
    };
    double t_from = 0.0;  // restitution from here
    if (compressing && t_cut > 0.0) {
      auto g = [&](double t) { return component_at(t, kSiy) - component_at(t, kScy); };  // -(1 + s) yG'
      const double g_cut = g(t_cut);
      if (g_cut > 0.0) {
        const double g0 = g(0.0);
        const double tc = g0 <= 0.0 ? t_cut * locate([&](double tt) { return g(t_cut * tt); }, g0, g_cut) : 0.0;
        compressing = false;
        out.compression_impulse = p + h * tc;
        out.compression_work = component_at(tc, kW);
        work_target = (1.0 - k.e * k.e) * out.compression_work;  // (16b)
        if (++out.events > ExactLimits::max_events) wedged();
        out.note(32);
        if (history && tc > 0.0) {
          dense();
          history->push_back(sample(k, units, out.compression_impulse, velocity_state(k, interpolate(y, st, tc), j)));
        }
        t_from = tc;
      }
    }
    if (!compressing && t_cut > t_from) {
      auto g = [&](double t) { return component_at(t, kW) - work_target; };
      const double g_cut = g(t_cut);
      if (g_cut > 0.0) {
        const double g0 = g(t_from);
        const double span = t_cut - t_from;
        const double tr =
            g0 <= 0.0 ? t_from + span * locate([&](double tt) { return g(t_from + span * tt); }, g0, g_cut) : t_from;
        if (tr >= 0.9) {
          dense();
          y = interpolate(y, st, tr);
        } else if (tr > 0.0) {
          Step last;
          dopri5_step(sys, y, k1, h * tr, atol, last);
          y = last.y1;
          ++out.steps;
        }
        p += h * tr;
        if (++out.events > ExactLimits::max_events) wedged();
        out.note(33);
        out.total_impulse = p;
        out.final_state = velocity_state(k, y, j);
        if (history) record(p);
        return out;
      }
    }

    if (first == Event::none) {
      y = st.y1;
      p += h;
      sys.set_references(y);
      k1 = st.k7;
      if (history) record(p);
      h = h_next;
      if (middle.enters(sys, y, reentry_slip)) {
        if (smooth_middle()) {
          finish();
          return out;
        }
        continue;
      }
      if (!compressing) {
        // Aim the step in which restitution ends to end just past that point
        // (W to second order: W' = -c yG', W'' = -c yG''), so that the point
        // falls where the dense output is as accurate as the step itself.
        const double gap = work_target - y[kW];  // > 0
        const double w1 = k1[kW];
        const double w2 = -k.c * k.inv_1ps * (k1[kScy] - k1[kSiy]);
        const double disc = w1 * w1 + 2.0 * w2 * gap;
        if (w1 > 0.0 && disc > 0.0) {
          const double rest = 2.0 * gap / (w1 + std::sqrt(disc));
          if (rest <= h) {
            h = std::min(1.02 * rest, h_next * 1.02);
          } else if (rest <= 2.0 * h) {
            h = 0.51 * rest;
          }
        }
      }
      continue;
    }

    // The state at the event: the dense output (4th order, within the step's
    // error tolerance; exact for the piecewise-linear head-on impact).
    const double he = h * t_first;
    if (t_first > 0.0) y = interpolate(y, st, t_first);
    p += he;
    if (++out.events > ExactLimits::max_events) wedged();

    bool cushion_zero = false;
    bool bed_zero = false;
    switch (first) {
      case Event::cushion_slip_small:
      case Event::bed_slip_small: {
        const bool at_cushion = first == Event::cushion_slip_small;
        SlipRegime& g = at_cushion ? sys.cushion_regime : sys.bed_regime;
        if (g.approach_armed) {
          const Vec2 slip = at_cushion ? slip_i(y) : slip_c(y);
          const Vec2 other_slip = at_cushion ? slip_c(y) : slip_i(y);
          const ContactMode other = at_cushion ? sys.modes.bed : sys.modes.cushion;
          const Vec2 w = sys.free_direction(other_slip, at_cushion ? sys.bed_ref : sys.cushion_ref);
          double dp_rest = 0.0;
          Friction impulse{};
          if (!finish_approach(k, at_cushion, slip, other, w, dp_rest, impulse)) {
            g.approach_armed = false;  // a near miss: integrate on
            break;
          }
          // Velocities are affine in the friction impulses (14); W by the trapezoid rule (16a).
          const double vy_before = scaled_normal_speed(y);
          const SlipState d = slip_rates(k, y, {impulse.cushion / dp_rest, impulse.bed / dp_rest});
          for (std::size_t i = 0; i < kSlips; ++i) y[i] += d[i] * dp_rest;
          y[kW] += -0.5 * (vy_before + scaled_normal_speed(y)) * k.inv_1ps * k.c * dp_rest;
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
        snap_cushion_slip(y);
        sys.modes.cushion = kSlip;
        sys.modes.cushion_direction = u0;
        sys.enslave(true, u0);
        break;
      }
      case Event::bed_stick_breaks: {
        const Vec2 u0 = -1.0 * unit(sys.friction(y).bed);
        snap_bed_slip(k, y);
        sys.modes.bed = kSlip;
        sys.modes.bed_direction = u0;
        sys.enslave(false, u0);
        break;
      }
      case Event::none: break;
    }
    start_segment(cushion_zero, bed_zero);
  }
}

}  // namespace cueball::mathavan_2010
