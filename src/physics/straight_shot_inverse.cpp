// Inverse problem of paper 001 (A. Jaroukh, 2019), eqs 17-28, and its
// variants. See straight_shot_inverse.hpp for the conventions and conditions.
#include "cueball/physics/straight_shot_inverse.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cueball/physics/cloth_motion.hpp"
#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

// Positions x0, x1, x2 lie within [-1000, 1000] m, as the CLI's flags.
constexpr double kMaxPlanDistance = 1000.0;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void validate_target(const ShotTarget& t, const Parameters& p) {
  validate(p);
  require_in_range("x0", t.x0, -kMaxPlanDistance, kMaxPlanDistance, "start, m");
  require_in_range("x2", t.x2, -kMaxPlanDistance, kMaxPlanDistance, "planned point, m");
  require_finite("v2", t.v2);
  if (t.v2 < 0.0) throw InfeasibleShot("v2 >= 0", "v2 = " + num(t.v2) + " m/s is negative");
  require_in_range("v2", t.v2, 0.0, kMaxSpeed, "planned speed at x2, m/s");
  if (t.x2 < t.x0)
    throw InfeasibleShot("x2 >= x0", "x2 = " + num(t.x2) + " m lies behind the start x0 = " + num(t.x0) +
                                         " m; positions increase in the direction of travel");
  if (!(t.x2 > t.x0 || t.v2 > 0.0))
    throw InfeasibleShot("x2 > x0 or v2 > 0", "the ball would not move (x2 = x0 = " + num(t.x0) + " m, v2 = 0)");
}

// A plan beyond the speed or spin caps of the rest of the library (no ball
// can be given it, and no simulation would accept it) is an error naming the
// input that asks for it: the distance to x2 (or to x1, when the slide alone
// needs too much). `n_alone`: v0 = N/7 when Z = 0, the speed the rolling leg
// alone needs.
void check_caps(const ShotPlan& plan, PlanVariant variant, const ShotTarget& t, double n, const Parameters& p) {
  const bool fast = !(plan.v0 <= kMaxSpeed);
  const bool spun = !(std::abs(plan.w0) <= kMaxAngularSpeed);
  if (!fast && !spun) return;
  const bool slide = variant == PlanVariant::given_slide_end && n / 7.0 <= kMaxSpeed;
  const char* field = slide ? "x1" : "x2";
  std::string message = std::string(field) + " = " + num(slide ? plan.x1 : t.x2) + " m (x0 = " + num(t.x0) +
                        " m, v2 = " + num(t.v2) + " m/s) needs " +
                        (fast ? "v0 = " + num(plan.v0) + " m/s; allowed: v0 <= " + num(kMaxSpeed) + " m/s"
                              : "w0 = " + num(plan.w0) + " rad/s; allowed: |w0| <= " + num(kMaxAngularSpeed) + " rad/s");
  if (fast && variant == PlanVariant::natural_roll && t.v2 < kMaxSpeed) {
    // v0 = N / 7 with N^2 = 70 mu_r g (x2 - x0) + 49 v2^2 (eq. 25).
    const double reach = 49.0 * (kMaxSpeed * kMaxSpeed - t.v2 * t.v2) / (70.0 * p.cloth.rolling_resistance * p.cloth.gravity);
    message += " (x2 at most " + num(t.x0 + reach) + " m)";
  }
  throw InvalidArgument(field, message);
}

// From the paper's Z and N to the full plan: eqs 27, 28, 19, 20, 21, 22.
ShotPlan finish(PlanVariant variant, const ShotTarget& t, double z, double n, const Parameters& p) {
  const double mu_s_g = sliding_deceleration(p);
  const double mu_r_g = p.cloth.rolling_resistance * p.cloth.gravity;
  ShotPlan plan{};
  plan.variant = variant;
  plan.v0 = (n + 2.0 * z) / 7.0;                         // (27)
  plan.w0 = (n - 5.0 * z) / (7.0 * p.ball.radius);       // (28)
  plan.t1 = 2.0 / 7.0 * z / mu_s_g;                      // (19)
  plan.v1 = n / 7.0;                                     // (20)
  plan.x1 = t.x0 + 2.0 / 49.0 * z * (n + z) / mu_s_g;    // (21)
  plan.t2 = plan.t1 + 7.0 * (plan.v1 - t.v2) / (5.0 * mu_r_g);  // (22), brackets restored (spec §3)
  check_caps(plan, variant, t, n, p);
  return plan;
}

// N from the rolling leg, eq. 25: N = sqrt(70 mu_r g (x2 - x1) + 49 v2^2).
double rolling_leg_n(double rolling_distance, double v2, const Parameters& p) {
  return std::sqrt(70.0 * p.cloth.rolling_resistance * p.cloth.gravity * rolling_distance + 49.0 * v2 * v2);
}

}  // namespace

ShotPlan plan_shot_with_slide_end(const ShotTarget& t, double x1, const Parameters& p) {
  validate_target(t, p);
  require_in_range("x1", x1, -kMaxPlanDistance, kMaxPlanDistance, "end of sliding, m");
  if (x1 < t.x0)
    throw InfeasibleShot("x1 >= x0", "x1 = " + num(x1) + " m lies behind the start x0 = " + num(t.x0) +
                                         " m (it would need v0 < R w0, an overspun ball)");
  if (t.x2 < x1)
    throw InfeasibleShot("x2 >= x1", "the planned point x2 = " + num(t.x2) + " m lies before the end of sliding x1 = " +
                                         num(x1) + " m");
  const double n = rolling_leg_n(t.x2 - x1, t.v2, p);  // (25)
  // (26): Z^2 + N Z - 49/2 (x1 - x0) mu_s g = 0, positive root, written
  // without the cancellation of (-N + sqrt(...)) / 2.
  const double c = 49.0 * (x1 - t.x0) * sliding_deceleration(p);
  const double z = c / (n + std::sqrt(n * n + 2.0 * c));
  return finish(PlanVariant::given_slide_end, t, z, n, p);
}

ShotPlan plan_natural_roll_shot(const ShotTarget& t, const Parameters& p) {
  validate_target(t, p);
  return finish(PlanVariant::natural_roll, t, 0.0, rolling_leg_n(t.x2 - t.x0, t.v2, p), p);
}

ShotPlan plan_shot_with_spin(const ShotTarget& t, double w0, const Parameters& p) {
  validate_target(t, p);
  require_in_range("w0", w0, -kMaxAngularSpeed, kMaxAngularSpeed, "initial topspin, rad/s");
  const double rho = p.ball.radius * w0;  // R w0
  const double ks = 1.0 / (49.0 * sliding_deceleration(p));
  const double kr = 1.0 / (70.0 * p.cloth.rolling_resistance * p.cloth.gravity);
  // Total distance D(Z) = 2 ks Z (N + Z) + kr (N^2 - 49 v2^2) with N = 7 rho + 5 Z
  // (eqs 21 and 24 with 17, 18): a Z^2 + b Z + c, increasing for Z >= 0, N >= 0.
  const double a = 12.0 * ks + 25.0 * kr;
  const double b = 14.0 * ks * rho + 70.0 * kr * rho;
  const double c = 49.0 * kr * (rho * rho - t.v2 * t.v2);
  const auto distance = [&](double z) { return (a * z + b) * z + c; };
  // Smallest admissible Z: Z >= 0 (x1 >= x0) and N >= 7 v2 (x2 >= x1).
  const double z_min_slide = 0.0;
  const double z_min_roll = 7.0 * (t.v2 - rho) / 5.0;
  const double d = t.x2 - t.x0;
  if (z_min_roll > z_min_slide) {
    if (distance(z_min_roll) > d)
      throw InfeasibleShot("x2 >= x1", "with w0 = " + num(w0) + " rad/s the ball is still sliding at x2; the shortest "
                           "distance that reaches v2 = " + num(t.v2) + " m/s rolling is " + num(distance(z_min_roll)) + " m");
  } else if (distance(z_min_slide) > d) {
    throw InfeasibleShot("x1 >= x0", "w0 = " + num(w0) + " rad/s is more topspin than natural roll allows over " +
                                         num(d) + " m (it would need v0 < R w0; at most w0 = " +
                                         num(plan_natural_roll_shot(t, p).w0) + " rad/s)");
  }
  // Larger root of a Z^2 + b Z + (c - d) = 0, in the form without cancellation.
  const double disc = std::sqrt(b * b + 4.0 * a * (d - c));
  const double z = b >= 0.0 ? 2.0 * (d - c) / (b + disc) : (-b + disc) / (2.0 * a);
  return finish(PlanVariant::given_spin, t, z, 7.0 * rho + 5.0 * z, p);
}

ShotPlan plan_shot_with_speed(const ShotTarget& t, double v0, const Parameters& p) {
  validate_target(t, p);
  require_in_range("v0", v0, 0.0, kMaxSpeed, "initial speed, m/s");
  if (v0 < t.v2)
    throw InfeasibleShot("v0 >= v2", "v0 = " + num(v0) + " m/s is slower than the planned v2 = " + num(t.v2) + " m/s");
  const double ks = 1.0 / (49.0 * sliding_deceleration(p));
  const double kr = 1.0 / (70.0 * p.cloth.rolling_resistance * p.cloth.gravity);
  // With N = 7 v0 - 2 Z, eqs 21 + 24 give D(Z) = D0 + k Z (7 v0 - Z) with
  // D0 = 49 kr (v0^2 - v2^2) (natural roll) and k = 2 ks - 4 kr < 0 when
  // mu_r < 1.4 mu_s (validate() ensures mu_r < mu_s): D decreases with Z.
  const double d0 = 49.0 * kr * (v0 * v0 - t.v2 * t.v2);
  const double k = 2.0 * ks - 4.0 * kr;
  const double z_max = 3.5 * (v0 - t.v2);  // N = 7 v2: sliding ends exactly at x2
  const double d = t.x2 - t.x0;
  if (d > d0)
    throw InfeasibleShot("x1 >= x0", "v0 = " + num(v0) + " m/s falls short of x2 even with natural roll (reaches " +
                                         num(d0) + " m); it would need overspin, v0 < R w0");
  const double d_min = d0 + k * z_max * (7.0 * v0 - z_max);
  if (d < d_min)
    throw InfeasibleShot("x2 >= x1", "v0 = " + num(v0) + " m/s is too fast: with the most draw allowed the ball is "
                                         "still sliding at x2 (the shortest reach is " + num(d_min) + " m)");
  // Z (7 v0 - Z) = q, smaller root (Z <= 7 v0 / 2), without cancellation.
  const double q = (d - d0) / k;
  const double z = 2.0 * q / (7.0 * v0 + std::sqrt(std::max(0.0, 49.0 * v0 * v0 - 4.0 * q)));
  return finish(PlanVariant::given_speed, t, z, 7.0 * v0 - 2.0 * z, p);
}

const char* to_string(PlanVariant v) {
  switch (v) {
    case PlanVariant::given_slide_end: return "given_slide_end";
    case PlanVariant::natural_roll: return "natural_roll";
    case PlanVariant::given_spin: return "given_spin";
    case PlanVariant::given_speed: return "given_speed";
  }
  return "unknown";
}

}  // namespace cueball
