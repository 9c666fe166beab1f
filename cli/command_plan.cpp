// cueball plan: paper 001's inverse problem (eqs 25-28) and its variants.
#include <memory>
#include <optional>

#include "common.hpp"
#include "cueball/physics/cloth_motion.hpp"
#include "cueball/physics/cue_strike.hpp"
#include "cueball/physics/straight_shot_inverse.hpp"

namespace cueball::cli {

namespace {

struct PlanFlags {
  double x0 = 0.0;
  std::optional<double> x1;
  double x2 = 0.0;
  double v2 = 0.0;
  bool natural_roll = false;
  std::optional<double> w0;
  std::optional<double> v0;
  CueParameters cue;
  ParameterFlags parameters;
};

void run_plan(const PlanFlags& f, std::ostream& out, std::ostream& err) {
  const int chosen = (f.x1 ? 1 : 0) + (f.natural_roll ? 1 : 0) + (f.w0 ? 1 : 0) + (f.v0 ? 1 : 0);
  if (chosen != 1)
    throw UsageError("plan needs exactly one of --x1, --natural-roll, --w0, --v0 (got " + std::to_string(chosen) + ")");
  check_flag("--x0", f.x0, -1e3, 1e3, "start, m");
  check_flag("--x2", f.x2, -1e3, 1e3, "planned point, m");
  check_flag("--v2", f.v2, 0.0, kMaxSpeed, "planned speed at x2, m/s");
  if (f.x1) check_flag("--x1", *f.x1, -1e3, 1e3, "end of sliding, m");
  if (f.w0) check_flag("--w0", *f.w0, -kMaxAngularSpeed, kMaxAngularSpeed, "initial topspin, rad/s");
  if (f.v0) check_flag("--v0", *f.v0, 0.0, kMaxSpeed, "initial speed, m/s");
  check_flag("--cue-mass", f.cue.mass, 0.1, 2.0, "cue mass, kg");
  check_flag("--cue-tip-e", f.cue.tip_restitution, 0.0, 1.0, "cue tip-ball restitution");
  const Parameters p = resolve_parameters(f.parameters);

  const ShotTarget target{f.x0, f.x2, f.v2};
  ShotPlan plan{};
  if (f.x1) plan = plan_shot_with_slide_end(target, *f.x1, p);
  if (f.natural_roll) plan = plan_natural_roll_shot(target, p);
  if (f.w0) plan = plan_shot_with_spin(target, *f.w0, p);
  if (f.v0) plan = plan_shot_with_speed(target, *f.v0, p);

  Report r("shot plan, variant " + std::string(to_string(plan.variant)) + " (" + f.parameters.preset +
           " preset, SI units)");
  r.add_text("variant", to_string(plan.variant), "member of the solution family");
  r.add("v0", plan.v0, "m/s", "initial speed (eq. 27)");
  r.add("w0", plan.w0, "rad/s", "initial topspin (eq. 28)");
  r.add("t1", plan.t1, "s", "end of sliding (eq. 19)");
  r.add("x1", plan.x1, "m", "end of sliding (eq. 21)");
  r.add("v1", plan.v1, "m/s", "speed at end of sliding (eq. 20)");
  r.add("t2", plan.t2, "s", "passes x2 at speed v2 (eq. 22)");
  if (plan.v0 > 0.0) {
    const double b = level_cue_tip_height(plan.v0, plan.w0, p.ball);
    r.add("cue_tip_height", b, "m", "level cue, tip above the ball's centre");
    r.add("cue_tip_offset", b / p.ball.radius, "R", "the same, in ball radii");
    r.add("cue_speed", level_cue_speed(plan.v0, b, p.ball, f.cue), "m/s", "cue speed for v0 at that height");
    if (!cue_tip_offset_ok(b, p.ball))
      r.warn("the tip offset " + std::to_string(b / p.ball.radius) + " R is beyond the miscue limit (" +
             std::to_string(kMiscueOffsetFraction) + " R): a level cue cannot give this spin");
  }
  add_parameters(r, p);
  emit(r, f.parameters.json, out, err);
}

}  // namespace

Command add_plan_command(CLI::App& app) {
  auto flags = std::make_shared<PlanFlags>();
  CLI::App* sub = app.add_subcommand(
      "plan",
      "Initial speed v0 and topspin w0 that bring a ball struck along a line to x2 with speed v2\n"
      "(paper 001, eqs 25-28), and the level-cue tip height that gives them. Positions in m along\n"
      "the line of the shot, increasing in the direction of travel. Choose the member of the\n"
      "family: --x1 (end of sliding, the paper's problem), --natural-roll (x1 = x0), --w0 or --v0.\n"
      "Topspin w0 > 0 turns the ball the way it rolls (R w0 = v0 is natural roll, w0 < 0 draw);\n"
      "valid plans satisfy v0 >= R w0 >= -5/2 v0. Units SI.");
  sub->add_option("--x0", flags->x0, "Start, m (default 0)")->capture_default_str();
  sub->add_option("--x1", flags->x1, "End of sliding, m (the paper's problem)");
  sub->add_option("--x2", flags->x2, "Planned point, m")->required();
  sub->add_option("--v2", flags->v2, "Planned speed at x2, m/s (default 0: stop there)")->capture_default_str();
  sub->add_flag("--natural-roll", flags->natural_roll, "The ball rolls from the start (x1 = x0)");
  sub->add_option("--w0", flags->w0, "Given topspin, rad/s; v0 and x1 follow");
  sub->add_option("--v0", flags->v0, "Given speed, m/s; w0 and x1 follow");
  sub->add_option("--cue-mass", flags->cue.mass, "Cue mass, kg")->capture_default_str();
  sub->add_option("--cue-tip-e", flags->cue.tip_restitution, "Cue tip-ball restitution")->capture_default_str();
  add_parameter_flags(*sub, flags->parameters);
  return [flags](std::ostream& out, std::ostream& err) { run_plan(*flags, out, err); };
}

}  // namespace cueball::cli
