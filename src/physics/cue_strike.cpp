// The cue strike; model, sources and equation numbers (C1)-(C7) in
// cue_strike.hpp ([LG] Leckie & Greenspan 2006, [M] Marlow 1995, [A30]
// Alciatore TP A.30).
#include "cueball/physics/cue_strike.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "cueball/core/errors.hpp"

namespace cueball {

double level_cue_tip_height(double v0, double w0, const BallParameters& ball) {
  // b = I w0 / (m v0) = 2 R^2 w0 / (5 v0)
  return 2.0 * ball.radius * ball.radius * w0 / (5.0 * v0);
}

double level_cue_speed(double v0, double tip_height, const BallParameters& ball, const CueParameters& cue) {
  const double offset = tip_height / ball.radius;
  const double effective = 1.0 + ball.mass / cue.mass + 2.5 * offset * offset;
  return v0 * effective / (1.0 + cue.tip_restitution);
}

double squirt_angle(double side_offset, double height_offset, const BallParameters& ball, const CueParameters& cue) {
  CueStrike level;
  level.speed = 1.0;
  level.side_offset = side_offset;
  level.height_offset = height_offset;
  const BallState after = strike_ball_unchecked(level, {}, ball, cue);
  return std::atan2(after.velocity.y, after.velocity.x);
}

bool cue_tip_offset_ok(double tip_height, const BallParameters& ball) {
  return std::abs(tip_height) <= kMiscueOffsetFraction * ball.radius;
}

namespace {

// sqrt rather than std::hypot (several times slower): an overflow to infinity
// for absurd offsets is still rejected as a miscue.
double tip_offset(const CueStrike& s) {
  return std::sqrt(s.side_offset * s.side_offset + s.height_offset * s.height_offset);
}

// The miscue limit, with a relative allowance of 1e-12 so that an offset
// computed to lie on the limit (e.g. (0.3 R, 0.4 R)) is not a miscue by round-off.
double miscue_limit(const BallParameters& ball) { return kMiscueOffsetFraction * ball.radius * (1.0 + 1e-12); }

}  // namespace

bool cue_tip_offset_ok(const CueStrike& strike, const BallParameters& ball) {
  return tip_offset(strike) <= miscue_limit(ball);
}

void validate(const CueStrike& s, const BallParameters& ball, const CueParameters& cue) {
  require_in_range(kMassRange.field, ball.mass, kMassRange.min, kMassRange.max, "ball mass, kg");
  require_in_range(kRadiusRange.field, ball.radius, kRadiusRange.min, kRadiusRange.max, "ball radius, m");
  require_in_range("cue_mass", cue.mass, kMinCueMass, kMaxCueMass, "cue mass, kg");
  require_in_range("cue_tip_e", cue.tip_restitution, 0.0, 1.0, "cue tip-ball restitution");
  require_in_range("cue_end_mass", cue.end_mass, 0.0, kMaxCueEndMass, "the cue shaft's end mass of squirt, kg");
  if (!(std::isfinite(s.speed) && s.speed > 0.0 && s.speed <= kMaxCueSpeed)) {
    throw InvalidArgument("speed", s.speed, "(0, " + format_number(kMaxCueSpeed) + "] m/s", "cue speed at impact");
  }
  require_finite("aim", s.aim);
  if (!(std::isfinite(s.elevation) && s.elevation >= 0.0 && s.elevation < std::numbers::pi / 2)) {
    throw InvalidArgument("elevation", s.elevation, "[0, pi/2) rad, i.e. [0, 90) degrees",
                          "cue elevation, butt raised; 0 = level");
  }
  require_finite("side_offset", s.side_offset);
  require_finite("height_offset", s.height_offset);
  const double limit = kMiscueOffsetFraction * ball.radius;
  const double offset = tip_offset(s);
  if (!(offset <= miscue_limit(ball))) {
    throw InvalidArgument("tip offset", offset,
                          "[0, " + format_number(kMiscueOffsetFraction) + " R] = [0, " + format_number(limit) + "] m",
                          "sqrt(side_offset^2 + height_offset^2): beyond it the tip slips, a miscue");
  }
}

BallState strike_ball_unchecked(const CueStrike& s, Vec2 position, const BallParameters& ball,
                                const CueParameters& cue) noexcept {
  const double m = ball.mass;
  const double radius = ball.radius;
  const double a = s.side_offset;
  const double b = s.height_offset;
  const double offset2 = a * a + b * b;  // |r x d|^2 (C2)

  // (C3): J / m = (1 + e) V / (1 + m/M_c + 5 (a^2 + b^2) / (2 R^2))
  const double j_over_m =
      (1.0 + cue.tip_restitution) * s.speed / (1.0 + m / cue.mass + 2.5 * offset2 / (radius * radius));
  // J / I = (J / m) * 5 / (2 R^2)
  const double j_over_i = j_over_m * 2.5 / (radius * radius);

  const double cos_phi = std::cos(s.aim);
  const double sin_phi = std::sin(s.aim);
  const double cos_theta = std::cos(s.elevation);
  const double sin_theta = std::sin(s.elevation);

  BallState out;
  out.position = position;
  // (C4): v = (J cos(theta) / m) u; the vertical part is absorbed by the bed.
  const double speed = j_over_m * cos_theta;
  out.velocity = {speed * cos_phi, speed * sin_phi};
  // (C5): w = (J / I) [a sin(theta) u + b (z x u) + a cos(theta) z], u = (cos phi, sin phi, 0),
  // z x u = (-sin phi, cos phi, 0).
  const double along_aim = a * sin_theta;
  out.angular_velocity = {j_over_i * (along_aim * cos_phi - b * sin_phi),
                          j_over_i * (along_aim * sin_phi + b * cos_phi), j_over_i * a * cos_theta};
  if (a != 0.0 && cue.end_mass > 0.0) {
    // Squirt (C8): J_s / m along s = (sin phi, -cos phi, 0), written with m_e
    // in the numerator so that it is exactly 0 at m_e = 0; its torque
    // (J_s / I)(b d + c e_up), d = cos(theta) u - sin(theta) z and
    // e_up = sin(theta) u + cos(theta) z.
    const double r2 = radius * radius;
    const double c = std::sqrt(std::max(0.0, r2 - offset2));
    const double js_over_m = -2.5 * j_over_m * a * c * cue.end_mass /
                             (r2 * (cue.end_mass * (1.0 + 2.5 * (1.0 - a * a / r2)) + m));
    const double js_over_i = js_over_m * 2.5 / r2;
    out.velocity = out.velocity + js_over_m * Vec2{sin_phi, -cos_phi};
    const double along = b * cos_theta + c * sin_theta;  // (b d + c e_up) . u
    const double up = c * cos_theta - b * sin_theta;     // (b d + c e_up) . z
    out.angular_velocity = out.angular_velocity + js_over_i * Vec3{along * cos_phi, along * sin_phi, up};
  }
  return out;
}

BallState strike_ball(const CueStrike& strike, Vec2 position, const BallParameters& ball, const CueParameters& cue) {
  validate(strike, ball, cue);
  // As a scenario's ball positions: the centre on the bed, within 100 m of the origin.
  require_in_range("position[0]", position.x, -100.0, 100.0, "x of the ball's centre on the bed, m");
  require_in_range("position[1]", position.y, -100.0, 100.0, "y of the ball's centre on the bed, m");
  return strike_ball_unchecked(strike, position, ball, cue);
}

void validate(const CueStrikeNoise& sigma) {
  const auto check = [](const char* field, double value) {
    if (!(std::isfinite(value) && value >= 0.0)) {
      throw InvalidArgument(field, value, "[0, infinity), finite", "standard deviation of the execution error");
    }
  };
  check("sigma speed", sigma.speed);
  check("sigma aim", sigma.aim);
  check("sigma elevation", sigma.elevation);
  check("sigma side_offset", sigma.side_offset);
  check("sigma height_offset", sigma.height_offset);
}

CueStrike with_noise(const CueStrike& strike, const CueStrikeNoise& sigma,
                     const std::array<double, 5>& standard_normals) {
  validate(sigma);
  for (std::size_t i = 0; i < standard_normals.size(); ++i) {
    if (!std::isfinite(standard_normals[i])) {
      throw InvalidArgument("standard_normals[" + std::to_string(i) + "]", standard_normals[i],
                            "any finite number", "standard-normal draw");
    }
  }
  return {strike.speed + sigma.speed * standard_normals[0], strike.aim + sigma.aim * standard_normals[1],
          strike.elevation + sigma.elevation * standard_normals[2],
          strike.side_offset + sigma.side_offset * standard_normals[3],
          strike.height_offset + sigma.height_offset * standard_normals[4]};
}

}  // namespace cueball
