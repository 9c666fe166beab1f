// Physical parameters of a ball on the cloth, with named presets.
//
// Conventions (see README "Units and sign conventions"): SI units throughout.
// The rolling-resistance coefficient follows paper 001 (Jaroukh 2019), which
// models it by energy: dE/dt = -mu_r m g v with E = 7/10 m v^2, so a rolling
// ball decelerates at (5/7) mu_r g. Simulators that write the rolling
// deceleration as mu_r' g use mu_r' = (5/7) mu_r; cueball's field is named
// `rolling_resistance` and `rolling_deceleration()` gives the deceleration so
// the two cannot be confused.
#pragma once

#include <array>
#include <string_view>

namespace cueball {

struct BallParameters {
  double mass = 0.0;    ///< m, kg
  double radius = 0.0;  ///< R, m
  friend bool operator==(const BallParameters&, const BallParameters&) = default;
};

struct ClothParameters {
  double sliding_friction = 0.0;    ///< mu_s, ball-cloth sliding friction (dimensionless)
  double rolling_resistance = 0.0;  ///< mu_r, paper 001's energy convention (dimensionless)
  double spin_friction = 0.0;       ///< mu_sp, vertical-spin friction: dw_z/dt = -5 mu_sp g / (2R)
  double gravity = 9.81;            ///< g, m/s^2
  friend bool operator==(const ClothParameters&, const ClothParameters&) = default;
};

struct Parameters {
  BallParameters ball;
  ClothParameters cloth;
  friend bool operator==(const Parameters&, const Parameters&) = default;
};

/// Moment of inertia of a solid sphere about its centre, I = 2/5 m R^2
/// (paper 001 prints 5/2 by a typo; its equations use 2/5).
constexpr double moment_of_inertia(const BallParameters& b) { return 0.4 * b.mass * b.radius * b.radius; }
/// Deceleration of a sliding ball, mu_s g (paper 001 eq. 2), m/s^2.
constexpr double sliding_deceleration(const Parameters& p) { return p.cloth.sliding_friction * p.cloth.gravity; }
/// Deceleration of a rolling ball, (5/7) mu_r g (paper 001, from eqs 11-12), m/s^2.
constexpr double rolling_deceleration(const Parameters& p) {
  return 5.0 / 7.0 * p.cloth.rolling_resistance * p.cloth.gravity;
}
/// Angular deceleration of spin about the vertical, 5 mu_sp g / (2R), rad/s^2.
constexpr double spin_deceleration(const Parameters& p) {
  return 2.5 * p.cloth.spin_friction * p.cloth.gravity / p.ball.radius;
}

/// The accepted range of one parameter: validation errors quote it, and the
/// CLI's --help prints it.
struct ParameterRange {
  const char* field;    ///< name in the API and in error messages, e.g. "mu_s"
  const char* meaning;  ///< what it is, in words
  const char* unit;     ///< SI unit, "" when dimensionless
  double min;
  double max;
};

inline constexpr ParameterRange kMassRange{"mass", "ball mass", "kg", 0.01, 2.0};
inline constexpr ParameterRange kRadiusRange{"radius", "ball radius", "m", 0.005, 0.1};
inline constexpr ParameterRange kSlidingFrictionRange{"mu_s", "ball-cloth sliding friction", "", 0.01, 1.0};
inline constexpr ParameterRange kRollingResistanceRange{
    "mu_r", "rolling resistance (paper 001 energy convention)", "", 1e-4, 0.1};
inline constexpr ParameterRange kSpinFrictionRange{"mu_sp", "vertical-spin friction", "", 1e-5, 0.1};
inline constexpr ParameterRange kGravityRange{"g", "gravitational acceleration", "m/s^2", 1.0, 30.0};

inline constexpr std::array<const ParameterRange*, 6> kParameterRanges{
    &kMassRange, &kRadiusRange, &kSlidingFrictionRange, &kRollingResistanceRange, &kSpinFrictionRange,
    &kGravityRange};

/// Throws InvalidArgument unless range.min <= value <= range.max (and finite);
/// the message names range.field, the value, the range, meaning and unit.
void check_range(const ParameterRange& range, double value);

/// Throws InvalidArgument naming the first parameter that is not finite or
/// lies outside its range, or mu_r >= mu_s, e.g. "mu_s = -0.1 is outside [0.01, 1] (...)".
void validate(const Parameters& p);

/// Snooker ball on a snooker cloth (Mathavan, Jackson & Parkin 2010 and 2009).
Parameters snooker_parameters();
/// WPA pool ball on a typical pool cloth (WPA specifications; Alciatore).
Parameters pool_parameters();
/// UMB carom ball on a heated carom cloth: the cloth fitted by `cueball
/// calibrate` to a recorded three-cushion match (README "Validated against
/// a recorded match"); the carom_10ft table's default.
Parameters carom_parameters();
/// A preset by name: "snooker", "pool" or "carom". Throws InvalidArgument otherwise.
Parameters preset_parameters(std::string_view name);
/// The names accepted by preset_parameters().
inline constexpr std::array<std::string_view, 3> kPresetNames{"snooker", "pool", "carom"};

}  // namespace cueball
