// cueball roll: a straight shot's phases (paper 001 eqs 19-24), and the full
// state at any time.
#include <cstdio>
#include <memory>
#include <optional>

#include "common.hpp"
#include "cueball/physics/cloth_motion.hpp"

namespace cueball::cli {

namespace {

struct RollFlags {
  double v0 = 0.0;
  double w0 = 0.0;
  double side = 0.0;
  std::optional<double> at;
  ParameterFlags parameters;
};

void run_roll(const RollFlags& f, std::ostream& out, std::ostream& err) {
  check_flag("--v0", f.v0, 0.0, kMaxSpeed, "initial speed along +x, m/s");
  check_flag("--w0", f.w0, -kMaxAngularSpeed, kMaxAngularSpeed, "initial topspin, rad/s");
  check_flag("--side", f.side, -kMaxAngularSpeed, kMaxAngularSpeed, "initial side spin w_z, rad/s");
  if (f.at) check_flag("--at", *f.at, 0.0, 1e6, "time since the strike, s");
  const Parameters p = resolve_parameters(f.parameters);

  const StraightShot shot = straight_shot(f.v0, f.w0, f.side, p);
  Report r("straight shot along +x (" + f.parameters.preset + " preset, SI units)");
  r.add("v0", f.v0, "m/s", "initial speed");
  r.add("w0", f.w0, "rad/s", "initial topspin (R w0 = v0: natural roll)");
  r.add("side", f.side, "rad/s", "initial side spin w_z");
  r.add("t1", shot.t1, "s", "end of sliding (eq. 19)");
  r.add("x1", shot.x1, "m", "position at end of sliding (eq. 21)");
  r.add("v1", shot.v1, "m/s", "velocity at end of sliding (eq. 20)");
  r.add("t2", shot.t2, "s", "ball at rest (eq. 22, v2 = 0)");
  r.add("x2", shot.x2, "m", "rest position (eq. 24)");
  r.add("t_spin", shot.t_spin, "s", "side spin has decayed to zero");
  if (f.at) {
    char heading[64];
    std::snprintf(heading, sizeof heading, "state at t = %g s:", *f.at);
    r.begin_section("at", heading);
    r.add("t", *f.at, "s");
    add_state(r, straight_shot_state(f.v0, f.w0, f.side, *f.at, p), p);
    r.end_section();
  }
  add_parameters(r, p);
  if (shot.v1 < 0.0) r.warn("the draw reverses the ball while it slides: x1, x2 lie behind the start");
  emit(r, f.parameters.json, out, err);
}

}  // namespace

Command add_roll_command(CLI::App& app) {
  auto flags = std::make_shared<RollFlags>();
  CLI::App* sub = app.add_subcommand(
      "roll",
      "A straight shot along +x from x = 0: when sliding ends (t1, x1, v1) and where the ball stops (t2, x2);\n"
      "with --at T, the full state at time T. Units SI. Topspin --w0 > 0 turns the ball the way it rolls\n"
      "(R w0 = v0 is natural roll, 0 a stun/centre hit, < 0 draw); --side is spin about the vertical,\n"
      "positive anticlockwise seen from above.");
  sub->add_option("--v0", flags->v0, "Initial speed along +x, m/s [0, 30]")->required();
  sub->add_option("--w0", flags->w0, "Initial topspin, rad/s (default 0: centre-ball hit)")->capture_default_str();
  sub->add_option("--side", flags->side, "Initial side spin w_z, rad/s (default 0)")->capture_default_str();
  sub->add_option("--at", flags->at, "Also print the full state at this time, s");
  add_parameter_flags(*sub, flags->parameters);
  return [flags](std::ostream& out, std::ostream& err) { run_roll(*flags, out, err); };
}

}  // namespace cueball::cli
