#include "cueball/core/parameters.hpp"

#include <cmath>
#include <string>

#include "cueball/core/errors.hpp"

namespace cueball {

namespace {

constexpr double kStandardGravity = 9.81;  // m/s^2, as in paper 000

// Vertical-spin deceleration 5-15 rad/s^2 is measured (Alciatore, "Technical
// Proof A.14"-era notes); presets use the middle, 10 rad/s^2, and invert
// dw_z/dt = 5 mu_sp g / (2R) for mu_sp.
constexpr double spin_friction_for(double angular_deceleration, double radius) {
  return 2.0 * radius * angular_deceleration / (5.0 * kStandardGravity);
}

// A rolling deceleration a (m/s^2) in paper 001's convention: a = 5/7 mu_r g.
constexpr double rolling_resistance_for(double deceleration) { return 7.0 * deceleration / (5.0 * kStandardGravity); }

}  // namespace

void check_range(const ParameterRange& r, double value) {
  if (std::isfinite(value) && value >= r.min && value <= r.max) return;  // no message built on success
  std::string meaning = r.meaning;
  if (*r.unit != '\0') meaning += std::string(", ") + r.unit;
  require_in_range(r.field, value, r.min, r.max, meaning.c_str());
}

void validate(const Parameters& p) {
  check_range(kMassRange, p.ball.mass);
  check_range(kRadiusRange, p.ball.radius);
  check_range(kSlidingFrictionRange, p.cloth.sliding_friction);
  check_range(kRollingResistanceRange, p.cloth.rolling_resistance);
  check_range(kSpinFrictionRange, p.cloth.spin_friction);
  check_range(kGravityRange, p.cloth.gravity);
  if (!(p.cloth.rolling_resistance < p.cloth.sliding_friction)) {
    throw InvalidArgument("mu_r", "mu_r = " + std::to_string(p.cloth.rolling_resistance) +
                                      " must be smaller than mu_s = " + std::to_string(p.cloth.sliding_friction) +
                                      " (rolling resistance below sliding friction)");
  }
}

Parameters snooker_parameters() {
  Parameters p;
  p.ball.mass = 0.1406;     // kg: Mathavan, Jackson & Parkin 2010, section 3.2
  p.ball.radius = 0.02625;  // m: same source (52.5 mm ball, WPBSA)
  // Mean of high-speed-camera measurements 0.178-0.245, ibid. section 3.2.
  p.cloth.sliding_friction = 0.212;
  // Measured rolling deceleration 0.124-0.126 m/s^2 (Mathavan, Jackson &
  // Parkin 2009, Am. J. Phys. 77(9)); 0.125 m/s^2 = 5/7 mu_r g.
  p.cloth.rolling_resistance = rolling_resistance_for(0.125);
  p.cloth.spin_friction = spin_friction_for(10.0, p.ball.radius);
  p.cloth.gravity = kStandardGravity;
  return p;
}

Parameters pool_parameters() {
  Parameters p;
  p.ball.mass = 0.170;       // kg: WPA, 5.5-6 oz; 6 oz is the common ball
  p.ball.radius = 0.028575;  // m: WPA, 2.25 in diameter
  p.cloth.sliding_friction = 0.2;  // Alciatore: 0.15-0.4, typical 0.2
  // Alciatore's rolling-resistance deceleration coefficient 0.005-0.015,
  // typical 0.01: deceleration 0.01 g = 5/7 mu_r g.
  p.cloth.rolling_resistance = rolling_resistance_for(0.01 * kStandardGravity);
  p.cloth.spin_friction = spin_friction_for(10.0, p.ball.radius);
  p.cloth.gravity = kStandardGravity;
  return p;
}

Parameters carom_parameters() {
  Parameters p;
  p.ball.mass = 0.210;         // kg: UMB, 205-220 g
  p.ball.radius = 0.0615 / 2;  // m: UMB, 61-61.5 mm
  // Fitted by `cueball calibrate` (mathavan_2010 cushion) to 30 shots of a
  // recorded three-cushion match on a heated cloth, tested on 91 others
  // (README "Calibrating from tracked shots"): a heated carom cloth rolls
  // about twice as far as a pool cloth (mu_r 0.014).
  p.cloth.sliding_friction = 0.216;
  p.cloth.rolling_resistance = 0.0077;
  p.cloth.spin_friction = 0.012;
  p.cloth.gravity = kStandardGravity;
  return p;
}

Parameters preset_parameters(std::string_view name) {
  if (name == "snooker") return snooker_parameters();
  if (name == "pool") return pool_parameters();
  if (name == "carom") return carom_parameters();
  throw InvalidArgument("preset", "preset = '" + std::string(name) + "' is not known; allowed: snooker, pool, carom");
}

}  // namespace cueball
