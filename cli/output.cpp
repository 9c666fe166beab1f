#include "output.hpp"

namespace cueball::cli {

void add_state(Report& r, const BallState& s, const Parameters& p) {
  r.add_text("phase", to_string(motion_phase(s, p)), "motion phase");
  r.add("position", {s.position.x, s.position.y}, "m", "centre of the ball on the bed");
  r.add("velocity", {s.velocity.x, s.velocity.y}, "m/s");
  r.add("angular_velocity", {s.angular_velocity.x, s.angular_velocity.y, s.angular_velocity.z}, "rad/s");
  const Vec2 u = slip_velocity(s, p.ball.radius);
  r.add("slip_velocity", {u.x, u.y}, "m/s", "u = v + R z^ x w at the cloth");
}

void add_parameters(Report& r, const Parameters& p) {
  r.begin_section("parameters", "parameters:");
  r.add("mass", p.ball.mass, "kg");
  r.add("radius", p.ball.radius, "m");
  r.add("mu_s", p.cloth.sliding_friction, "", "sliding friction");
  r.add("mu_r", p.cloth.rolling_resistance, "", "rolling resistance, paper 001 convention");
  r.add("mu_sp", p.cloth.spin_friction, "", "vertical-spin friction");
  r.add("g", p.cloth.gravity, "m/s^2");
  r.end_section();
}

}  // namespace cueball::cli
