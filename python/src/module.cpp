// The module `cueball`: its docstring, version and every bind_*() of bindings.hpp.
#include "bindings.hpp"

namespace {

constexpr const char* kModuleDoc = R"(cueball: physics of billiard balls (closed forms, no time steps).

Units are SI throughout: m, s, kg, rad. The one exception is the scenario's
units, the same in its JSON, its dicts, ShotStrike (a Scenario's cue) and
simulate_many's actions: the cue's aim_deg and elevation_deg in degrees, its
side and height tip offsets in ball radii. CueStrike is SI;
CueStrike.from_units(..., radius=R) and strike.in_units(radius=R) convert as
the scenario reader does. Table frame: x, y on the bed, x along the
table, z up. A ball's position is its centre projected on the bed, its
velocity (vx, vy) lies in the bed's plane, its angular velocity is
(wx, wy, wz). Straight shots travel along +x; topspin w0 > 0 turns the ball
the way it rolls (R w0 = v0 is natural roll, 0 a stun, < 0 draw); for motion
along +x topspin is wy. Side spin wz > 0 is anticlockwise seen from above;
right english (tip to the right of centre, seen from behind the cue) gives
wz > 0. mu_r follows paper 001's energy convention: a rolling ball
decelerates at (5/7) mu_r g.

Defaults are the pool preset everywhere: functions that need the ball and
cloth take params=Parameters, default pool_parameters() (as the CLI's
--preset); the built-in scenario is the 9-ball break on the 9-ft pool table.
Pass params=snooker_parameters() for the snooker ball and cloth.

Tables, racks and scenarios are objects (Table, rack_nine_ball(), Scenario):
read-only, always valid, picklable through their JSON; simulate() takes a
Scenario wherever it takes a scenario dict, and result.scenario replays a
result bit for bit. Bad input raises cueball.InvalidArgument
(a ValueError naming the field; an argument of the wrong Python type its
subclass InvalidArgumentType, also a TypeError), an impossible plan cueball.InfeasibleShot
(ValueError), a simulation that cannot finish cueball.SimulationError
(RuntimeError).)";

}  // namespace

PYBIND11_MODULE(_cueball, m) {
  using namespace cueball_python;
  m.doc() = kModuleDoc;
  m.attr("__version__") = CUEBALL_VERSION;
  bind_errors(m);
  bind_parameters(m);
  bind_cloth_motion(m);
  bind_planner(m);
  bind_cue_strike(m);
  bind_cushion(m);
  bind_cushion_fit(m);
  bind_ball_collision(m);
  bind_table(m);
  bind_rack(m);
  bind_scenario(m);
  bind_shot_planner(m);
  bind_simulation(m);
  bind_batch(m);
  bind_calibration(m);
  bind_games(m);
  bind_rl(m);
#ifdef CUEBALL_HAVE_SIMULATE_MANY
  bind_simulate_many(m);
#endif
}
