"""Tests of the Python module cueball (standard library only).

Run by ctest (test `python`) with PYTHONPATH set to the module's build
directory and CUEBALL_BIN to the CLI, or by hand:

    PYTHONPATH=build/release/python CUEBALL_BIN=build/release/cueball \
        /usr/bin/python3 -m unittest discover -s python/tests -v

The physics tests check the closed forms of paper 001 through the bindings
(units, signs, the 5/7 rule); the whole-shot tests hold the module to the
CLI's own output, byte for byte once parsed.
"""

import json
import math
import os
import pathlib
import pickle
import re
import subprocess
import tempfile
import threading
import unittest

import cueball

REPO = pathlib.Path(__file__).resolve().parents[2]
CLI = os.environ.get("CUEBALL_BIN")
CUT_SHOT = REPO / "docs" / "example-cut-shot.json"


def run_cli(*args):
    """The CLI's --json output, parsed."""
    out = subprocess.run([CLI, *args, "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


def break_with(**changes):
    """The built-in 9-ball break as a dict, with top-level keys replaced."""
    scenario = {"table": "pool_9ft", "rack": {"type": "nine_ball"}, "cue": {"ball": 0, "target": 1, "speed": 7.0}}
    scenario.update(changes)
    return scenario


class ModuleTest(unittest.TestCase):
    def test_version_is_the_projects(self):
        text = (REPO / "CMakeLists.txt").read_text()
        self.assertEqual(cueball.__version__, re.search(r"project\(cueball VERSION ([0-9.]+)", text).group(1))

    def test_exception_classes(self):
        self.assertTrue(issubclass(cueball.InvalidArgument, ValueError))
        self.assertTrue(issubclass(cueball.InfeasibleShot, ValueError))
        self.assertTrue(issubclass(cueball.SimulationError, RuntimeError))
        self.assertEqual(cueball.InvalidArgument.__module__, "cueball")


class ParametersTest(unittest.TestCase):
    def test_presets_and_fields(self):
        p = cueball.snooker_parameters()
        self.assertEqual(p.ball.mass, 0.1406)
        self.assertEqual(p.ball.radius, 0.02625)
        self.assertEqual(cueball.preset_parameters("pool"), cueball.pool_parameters())
        self.assertEqual(cueball.preset_parameters("carom"), cueball.carom_parameters())
        self.assertNotEqual(cueball.pool_parameters(), p)
        # Nested fields are references: assigning through them changes p.
        p.ball.mass = 0.2
        p.cloth.sliding_friction = 0.3
        self.assertEqual((p.ball.mass, p.cloth.sliding_friction), (0.2, 0.3))
        cueball.validate(p)

    def test_keyword_constructors_repr_and_pickle(self):
        p = cueball.Parameters(
            ball=cueball.BallParameters(mass=0.17, radius=0.028575),
            cloth=cueball.ClothParameters(sliding_friction=0.2, rolling_resistance=0.01, spin_friction=0.01),
        )
        self.assertEqual(p.cloth.gravity, 9.81)
        self.assertEqual(eval(repr(p), vars(cueball)), p)
        self.assertEqual(pickle.loads(pickle.dumps(p)), p)
        self.assertEqual(cueball.rolling_deceleration(p), 5 / 7 * 0.01 * 9.81)
        self.assertEqual(cueball.sliding_deceleration(p), 0.2 * 9.81)
        self.assertAlmostEqual(cueball.moment_of_inertia(p.ball), 0.4 * 0.17 * 0.028575**2, delta=1e-18)

    def test_validate_names_the_field(self):
        p = cueball.pool_parameters()
        p.ball.mass = -0.1
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.validate(p)
        self.assertEqual(caught.exception.field, "mass")
        self.assertIn("mass = -0.1", str(caught.exception))
        self.assertIn("[0.01, 2]", str(caught.exception))
        p = cueball.pool_parameters()
        p.cloth.sliding_friction = math.nan
        with self.assertRaisesRegex(cueball.InvalidArgument, r"mu_s = nan is not a finite number") as caught:
            cueball.validate(p)
        self.assertEqual(caught.exception.field, "mu_s")
        with self.assertRaises(cueball.InvalidArgument):
            cueball.preset_parameters("croquet")

    def test_parameter_ranges(self):
        self.assertEqual(set(cueball.PARAMETER_RANGES), {"mass", "radius", "mu_s", "mu_r", "mu_sp", "g"})
        self.assertEqual(cueball.PARAMETER_RANGES["mass"]["unit"], "kg")
        self.assertEqual(cueball.PARAMETER_RANGES["mu_s"]["min"], 0.01)


class ClothMotionTest(unittest.TestCase):
    p = cueball.pool_parameters()

    def test_stun_shot_rolls_at_five_sevenths(self):
        # A centre-ball (stun) hit: u0 = v0, sliding lasts 2|u0| / (7 mu_s g) (eq. 8) and
        # leaves the ball rolling at v1 = v0 - 2/7 u0 = 5/7 v0 (eq. 9).
        v0 = 1.5
        state = cueball.BallState(position=(0.3, 0.4), velocity=(v0, 0.0))
        self.assertEqual(cueball.motion_phase(state, self.p), "sliding")
        self.assertEqual(cueball.slip_velocity(state, self.p), (v0, 0.0))
        t1, kind = cueball.next_transition(state, self.p)
        self.assertEqual(kind, "sliding_ends")
        self.assertAlmostEqual(t1, 2 * v0 / (7 * self.p.cloth.sliding_friction * self.p.cloth.gravity), delta=1e-15)
        rolling = cueball.evolve(state, t1, self.p)
        self.assertEqual(cueball.motion_phase(rolling, self.p), "rolling")
        self.assertAlmostEqual(rolling.velocity[0], 5 / 7 * v0, delta=1e-12)
        self.assertEqual(rolling.velocity[1], 0.0)
        # Rolling: R w_y = v (topspin is w_y for motion along +x), no slip.
        self.assertAlmostEqual(self.p.ball.radius * rolling.angular_velocity[1], rolling.velocity[0], delta=1e-12)
        ux, uy = cueball.slip_velocity(rolling, self.p)
        self.assertLess(math.hypot(ux, uy), 1e-12)

    def test_oblique_slip_time_and_velocity(self):
        # Spin that does not match the velocity: the slip u0 sets both the time to roll
        # 2|u0| / (7 mu_s g) and the rolling velocity v0 - 2/7 u0 (eq. 9), in any direction.
        state = cueball.BallState(velocity=(0.8, -0.6), angular_velocity=(20.0, -35.0, 4.0))
        u0 = cueball.slip_velocity(state, self.p)
        R = self.p.ball.radius
        self.assertEqual(u0, (0.8 - R * -35.0, -0.6 + R * 20.0))
        t1 = 2 * math.hypot(*u0) / (7 * self.p.cloth.sliding_friction * self.p.cloth.gravity)
        self.assertAlmostEqual(cueball.phase_end_time(state, self.p), t1, delta=1e-15)
        after = cueball.evolve(state, t1, self.p)
        for axis in range(2):
            self.assertAlmostEqual(after.velocity[axis], state.velocity[axis] - 2 / 7 * u0[axis], delta=1e-12)
        # Side spin decays linearly at 5 mu_sp g / (2R) meanwhile.
        self.assertAlmostEqual(after.angular_velocity[2], 4.0 - cueball.spin_deceleration(self.p) * t1, delta=1e-12)

    def test_straight_shot_closed_forms(self):
        # Rolling covers 7 v1^2 / (10 mu_r g) (eq. 24 with v2 = 0) and takes 7 v1 / (5 mu_r g).
        v0 = 2.0
        shot = cueball.straight_shot(v0, params=self.p)
        mu_r_g = self.p.cloth.rolling_resistance * self.p.cloth.gravity
        self.assertAlmostEqual(shot.v1, 5 / 7 * v0, delta=1e-12)
        self.assertAlmostEqual(shot.x2 - shot.x1, 7 * shot.v1**2 / (10 * mu_r_g), delta=1e-9)
        self.assertAlmostEqual(shot.t2 - shot.t1, 7 * shot.v1 / (5 * mu_r_g), delta=1e-9)
        self.assertEqual(shot.t_spin, 0.0)
        # The same through evolve(): at rest at x2, stationary, with energy lost on the way.
        start = cueball.BallState(velocity=(v0, 0.0))
        end = cueball.evolve(start, 100.0, self.p)
        self.assertAlmostEqual(end.position[0], shot.x2, delta=1e-9)
        self.assertEqual(cueball.motion_phase(end, self.p), "stationary")
        self.assertEqual(cueball.next_transition(end, self.p), (math.inf, "none"))
        self.assertEqual(cueball.kinetic_energy(end, self.p), 0.0)
        self.assertAlmostEqual(cueball.kinetic_energy(start, self.p), 0.5 * self.p.ball.mass * v0**2, delta=1e-15)
        mid = cueball.straight_shot_state(v0, t=shot.t1, params=self.p)
        self.assertAlmostEqual(mid.position[0], shot.x1, delta=1e-12)

    def test_side_spin_sign_and_decay(self):
        shot = cueball.straight_shot(1.0, 0.0, 5.0, params=self.p)
        self.assertAlmostEqual(shot.t_spin, 5.0 / cueball.spin_deceleration(self.p), delta=1e-12)
        later = cueball.straight_shot_state(1.0, 0.0, 5.0, t=0.1, params=self.p)
        self.assertGreater(later.angular_velocity[2], 0.0)  # never reverses

    def test_ball_state_is_a_value(self):
        s = cueball.BallState((1, 2), [3, 4], (5, 6, 7))
        self.assertEqual(s.position, (1.0, 2.0))
        s.velocity = (0.5, -0.5)
        self.assertEqual(s.velocity, (0.5, -0.5))
        self.assertEqual(pickle.loads(pickle.dumps(s)), s)
        self.assertEqual(eval(repr(s), vars(cueball)), s)
        with self.assertRaises(TypeError):
            s.angular_velocity = (1, 2)

    def test_bad_input_raises(self):
        with self.assertRaisesRegex(cueball.InvalidArgument, "velocity must be finite") as caught:
            cueball.evolve(cueball.BallState(velocity=(math.nan, 0.0)), 1.0, self.p)
        self.assertEqual(caught.exception.field, "velocity")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.evolve(cueball.BallState(), -1.0, self.p)
        self.assertEqual(caught.exception.field, "dt")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.evolve(cueball.BallState(), math.inf, self.p)
        self.assertEqual(caught.exception.field, "dt")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.straight_shot(math.nan)
        self.assertEqual(caught.exception.field, "v0")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.motion_phase(cueball.BallState(velocity=(31.0, 0.0)), self.p)
        self.assertEqual(caught.exception.field, "speed")
        bad = cueball.pool_parameters()
        bad.cloth.gravity = -9.81
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.evolve(cueball.BallState(), 1.0, bad)
        self.assertEqual(caught.exception.field, "g")


class PlannerTest(unittest.TestCase):
    p = cueball.snooker_parameters()

    def check_round_trip(self, plan, x0, x2, v2):
        """Strike as planned, evolve: the ball passes x2 at speed v2 at t2, rolling from x1."""
        start = cueball.BallState(position=(x0, 0.0), velocity=(plan.v0, 0.0), angular_velocity=(0.0, plan.w0, 0.0))
        at_t1 = cueball.evolve(start, plan.t1, self.p)
        self.assertAlmostEqual(at_t1.position[0], plan.x1, delta=1e-9)
        self.assertAlmostEqual(at_t1.velocity[0], plan.v1, delta=1e-9)
        at_t2 = cueball.evolve(start, plan.t2, self.p)
        self.assertAlmostEqual(at_t2.position[0], x2, delta=1e-9)
        self.assertAlmostEqual(at_t2.velocity[0], v2, delta=1e-9)
        self.assertEqual(at_t2.position[1], 0.0)

    def test_every_variant_reaches_the_target(self):
        x0, x2, v2 = 0.25, 1.75, 0.2
        plans = [
            cueball.plan_shot_with_slide_end(x1=0.55, x2=x2, v2=v2, x0=x0, params=self.p),
            cueball.plan_natural_roll_shot(x2=x2, v2=v2, x0=x0, params=self.p),
            cueball.plan_shot_with_spin(w0=-20.0, x2=x2, v2=v2, x0=x0, params=self.p),
            cueball.plan_shot_with_speed(v0=1.5, x2=x2, v2=v2, x0=x0, params=self.p),
        ]
        variants = [plan.variant for plan in plans]
        self.assertEqual(variants, ["given_slide_end", "natural_roll", "given_spin", "given_speed"])
        for plan in plans:
            with self.subTest(variant=plan.variant):
                self.check_round_trip(plan, x0, x2, v2)
        self.assertAlmostEqual(plans[0].x1, 0.55, delta=1e-12)
        self.assertAlmostEqual(plans[1].v0, self.p.ball.radius * plans[1].w0, delta=1e-12)
        self.assertEqual(plans[2].w0, -20.0)
        self.assertEqual(plans[3].v0, 1.5)

    def test_the_clis_plan(self):
        # README: cueball plan --x1 0.3 --x2 1.5 --v2 0.2 (the pool preset, both defaults).
        plan = cueball.plan_shot_with_slide_end(x1=0.3, x2=1.5, v2=0.2)
        self.assertAlmostEqual(plan.v0, 1.20526, delta=1e-5)
        self.assertAlmostEqual(plan.w0, -41.1638, delta=1e-4)
        if CLI:
            cli = run_cli("plan", "--x1", "0.3", "--x2", "1.5", "--v2", "0.2")
            for key in ("v0", "w0", "t1", "x1", "v1", "t2"):
                self.assertEqual(getattr(plan, key), cli[key], key)

    def test_infeasible_plan_names_the_condition(self):
        with self.assertRaises(cueball.InfeasibleShot) as caught:
            cueball.plan_shot_with_spin(w0=400.0, x2=0.3)
        self.assertEqual(caught.exception.condition, "x1 >= x0")
        self.assertIn("validity condition x1 >= x0 fails", str(caught.exception))
        self.assertIsInstance(caught.exception, ValueError)
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.plan_natural_roll_shot(x2=math.nan)
        self.assertEqual(caught.exception.field, "x2")
        with self.assertRaises(TypeError):  # keyword-only
            cueball.plan_natural_roll_shot(1.0)

    def test_plans_stay_within_the_clis_ranges_and_the_speed_cap(self):
        # Once plan_natural_roll_shot(x2=1e9) returned v0 = 15,811 m/s without a word.
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.plan_natural_roll_shot(x2=1e9)
        self.assertEqual(caught.exception.field, "x2")
        self.assertIn("[-1000, 1000]", str(caught.exception))
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.plan_natural_roll_shot(x2=999.0, v2=29.0)
        self.assertEqual(caught.exception.field, "x2")
        self.assertIn("v0 <= 30 m/s", str(caught.exception))
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.plan_shot_with_spin(w0=0.0, x2=999.0, v2=29.0)
        self.assertEqual(caught.exception.field, "x2")


class CueStrikeTest(unittest.TestCase):
    p = cueball.pool_parameters()

    def test_level_cue_at_two_fifths_rolls_naturally(self):
        R = self.p.ball.radius
        strike = cueball.CueStrike(speed=2.0, aim=math.pi / 2, height_offset=0.4 * R)
        ball = cueball.strike_ball(strike, position=(0.5, 0.6), params=self.p)
        self.assertEqual(ball.position, (0.5, 0.6))
        self.assertAlmostEqual(ball.velocity[0], 0.0, delta=1e-15)
        self.assertGreater(ball.velocity[1], 0.0)
        self.assertLess(math.hypot(*cueball.slip_velocity(ball, self.p)), 1e-12)
        self.assertEqual(cueball.motion_phase(ball, self.p), "rolling")
        # The ball's speed: (1 + e) V / (1 + m/M + 5 b^2 / (2 R^2)) (C6), inverted by level_cue_speed.
        self.assertAlmostEqual(cueball.level_cue_speed(ball.velocity[1], 0.4 * R, self.p), 2.0, delta=1e-12)
        self.assertAlmostEqual(cueball.level_cue_tip_height(1.0, 1.0 / R, self.p), 0.4 * R, delta=1e-15)

    def test_right_english_gives_anticlockwise_spin(self):
        R = self.p.ball.radius
        right = cueball.strike_ball(cueball.CueStrike(speed=2.0, side_offset=0.3 * R), params=self.p)
        left = cueball.strike_ball(cueball.CueStrike(speed=2.0, side_offset=-0.3 * R), params=self.p)
        self.assertGreater(right.angular_velocity[2], 0.0)
        self.assertEqual(left.angular_velocity[2], -right.angular_velocity[2])

    def test_miscue_and_bad_strikes(self):
        R = self.p.ball.radius
        strike = cueball.CueStrike(speed=2.0, side_offset=0.4 * R, height_offset=0.4 * R)
        self.assertFalse(cueball.cue_tip_offset_ok(strike, self.p))
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.strike_ball(strike, params=self.p)
        self.assertEqual(caught.exception.field, "tip offset")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.strike_ball(cueball.CueStrike(speed=math.nan), params=self.p)
        self.assertEqual(caught.exception.field, "speed")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.strike_ball(cueball.CueStrike(speed=1.0), params=self.p, cue=cueball.CueParameters(mass=5.0))
        self.assertEqual(caught.exception.field, "cue_mass")
        # Once a NaN state: the position was not checked.
        for position, field in [((math.nan, 0.0), "position[0]"), ((0.0, math.inf), "position[1]"), ((1e9, 0.0), "position[0]")]:
            with self.subTest(position=position):
                with self.assertRaises(cueball.InvalidArgument) as caught:
                    cueball.strike_ball(cueball.CueStrike(speed=1.0), position=position, params=self.p)
                self.assertEqual(caught.exception.field, field)


class CushionImpactTest(unittest.TestCase):
    def test_the_readmes_impact(self):
        # cueball cushion --v0 1 --alpha 45 --sidespin-k -1 --preset snooker (the paper's ball, rolling in).
        p = cueball.snooker_parameters()
        R = p.ball.radius
        r = cueball.cushion_impact(1.0, math.radians(45), sidespin=-1.0 / R, params=p)
        self.assertAlmostEqual(r.rebound_speed, 0.839646, delta=1e-6)
        self.assertAlmostEqual(math.degrees(r.rebound_angle), 54.3466, delta=1e-4)
        self.assertAlmostEqual(r.rebound_speed, math.hypot(*r.velocity), delta=1e-15)
        self.assertLess(r.velocity[1], 0.0)  # away from the cushion
        if CLI:
            cli = run_cli("cushion", "--v0", "1", "--alpha", "45", "--sidespin-k", "-1", "--preset", "snooker")
            self.assertAlmostEqual(r.rebound_speed, cli["speed"], delta=1e-12)
            self.assertAlmostEqual(math.degrees(r.rebound_angle), cli["angle"], delta=1e-9)
            for mine, theirs in zip(r.velocity[:2] + r.angular_velocity, cli["v"] + cli["w"]):
                self.assertAlmostEqual(mine, theirs, delta=1e-12)
            self.assertAlmostEqual(r.compression_impulse, cli["impulse_compression"], delta=1e-12)
            self.assertAlmostEqual(r.total_impulse, cli["impulse_total"], delta=1e-12)
            self.assertAlmostEqual(r.compression_work, cli["work_compression"], delta=1e-12)

    def test_head_on_rolling_ball_stays_in_its_plane(self):
        # (cos(pi/2) is 6e-17 in doubles, hence the tolerance.)
        r = cueball.cushion_impact(1.0, math.pi / 2, params=cueball.snooker_parameters())
        self.assertAlmostEqual(r.velocity[0], 0.0, delta=1e-15)
        self.assertAlmostEqual(r.angular_velocity[2], 0.0, delta=1e-12)
        self.assertAlmostEqual(math.degrees(r.rebound_angle), 90.0, delta=1e-12)
        # The paper's head-on rolling rebound with its own constants: about 0.91 V0 (cushion_impact.hpp).
        self.assertAlmostEqual(r.rebound_speed, 0.911, delta=2e-3)
        self.assertGreater(r.total_impulse, r.compression_impulse)
        self.assertLess(r.compression_work, 0.0)
        self.assertFalse(r.beyond_rigid_cushion_limit)

    def test_sidespin_mirrors(self):
        # Head-on with side spin +S or -S: mirror images in the plane X = 0.
        plus = cueball.cushion_impact(1.2, math.pi / 2, topspin=0.0, sidespin=20.0)
        minus = cueball.cushion_impact(1.2, math.pi / 2, topspin=0.0, sidespin=-20.0)
        self.assertNotEqual(plus.velocity[0], 0.0)
        self.assertAlmostEqual(plus.velocity[0], -minus.velocity[0], delta=1e-12)
        self.assertAlmostEqual(plus.velocity[1], minus.velocity[1], delta=1e-12)
        self.assertAlmostEqual(plus.angular_velocity[2], -minus.angular_velocity[2], delta=1e-12)
        self.assertAlmostEqual(plus.rebound_speed, minus.rebound_speed, delta=1e-12)
        self.assertAlmostEqual(plus.rebound_angle, math.pi - minus.rebound_angle, delta=1e-12)

    def test_paper_solver_and_history(self):
        exact = cueball.cushion_impact(1.0, math.radians(30), history=True)
        paper = cueball.cushion_impact(1.0, math.radians(30), solver="paper", paper_steps=5000)
        self.assertAlmostEqual(exact.rebound_speed, paper.rebound_speed, delta=1e-3)
        self.assertGreater(len(exact.history), 2)
        self.assertEqual(exact.history[0].normal_impulse, 0.0)
        self.assertAlmostEqual(exact.history[-1].normal_impulse, exact.total_impulse, delta=1e-12)
        self.assertEqual(paper.history, [])

    def test_exact_tolerance_and_rolling_table(self):
        # A rolling ball is looked up in the rolling-ball table (no Runge-Kutta steps) unless
        # rolling_table=False or a tighter tolerance asks for the solve; all agree far inside 1e-6.
        looked_up = cueball.cushion_impact(1.2, math.radians(40), sidespin=15.0)
        self.assertEqual(looked_up.solver_steps, 0)
        solved = cueball.cushion_impact(1.2, math.radians(40), sidespin=15.0, rolling_table=False)
        reference = cueball.cushion_impact(1.2, math.radians(40), sidespin=15.0, exact_tolerance=1e-11)
        for r in (solved, reference):
            self.assertGreater(r.solver_steps, 0)
            for a, b in zip(r.velocity, looked_up.velocity):
                self.assertAlmostEqual(a, b, delta=1e-6)
        self.assertEqual(cueball.cushion_impact(1.2, math.radians(40), sidespin=15.0).velocity, looked_up.velocity)
        for bad in (1e-6, 1e-12, math.nan):
            with self.assertRaises(cueball.InvalidArgument) as caught:
                cueball.cushion_impact(1.0, 1.0, exact_tolerance=bad)
            self.assertEqual(caught.exception.field, "exact_tolerance")

    def test_bad_input(self):
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.cushion_impact(math.nan, 1.0)
        self.assertEqual(caught.exception.field, "V0")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.cushion_impact(1.0, 2.0)  # radians: beyond pi/2
        self.assertEqual(caught.exception.field, "alpha")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.cushion_impact(1.0, 1.0, solver="euler")
        self.assertEqual(caught.exception.field, "solver")
        with self.assertRaises(cueball.InvalidArgument):
            cueball.cushion_impact(1.0, 1.0, restitution=1.5)

    def test_ranges_are_the_clis(self):
        # The CLI's bounds: speed up to 30 m/s, spins up to 3000 rad/s, at most 1e8 Euler steps
        # (1e9 steps once ran for minutes).
        for kwargs, field in [
            (dict(speed=31.0, angle=1.0), "V0"),
            (dict(speed=1.0, angle=1.0, topspin=1e9), "w_T"),
            (dict(speed=1.0, angle=1.0, sidespin=-1e9), "w_S"),
            (dict(speed=1.0, angle=1.0, solver="paper", paper_steps=10**9), "paper_steps"),
            (dict(speed=1.0, angle=1.0, paper_steps=0), "paper_steps"),
        ]:
            with self.subTest(field=field):
                with self.assertRaises(cueball.InvalidArgument) as caught:
                    cueball.cushion_impact(**kwargs)
                self.assertEqual(caught.exception.field, field)


class SimulateTest(unittest.TestCase):
    @unittest.skipUnless(CLI, "CUEBALL_BIN is not set")
    def test_the_builtin_break_is_the_clis(self):
        self.assertEqual(cueball.simulate().to_dict(), run_cli("simulate"))

    @unittest.skipUnless(CLI, "CUEBALL_BIN is not set")
    def test_a_scenario_file_with_samples_is_the_clis(self):
        mine = cueball.simulate(CUT_SHOT, sample_rate=30.0).to_dict()
        self.assertEqual(mine, run_cli("simulate", str(CUT_SHOT), "--sample", "30"))
        self.assertEqual(mine["samples"]["rate_hz"], 30.0)

    def test_dict_string_and_path_agree_and_reruns_are_identical(self):
        text = CUT_SHOT.read_text()
        from_text = cueball.simulate(text).to_dict()
        self.assertEqual(cueball.simulate(json.loads(text)).to_dict(), from_text)
        self.assertEqual(cueball.simulate(CUT_SHOT).to_dict(), from_text)
        self.assertEqual(cueball.simulate(str(CUT_SHOT)).to_dict(), from_text)  # a str that is not JSON is a path
        self.assertEqual(cueball.simulate("  \n" + text).to_dict(), from_text)  # JSON text after blanks
        self.assertEqual(cueball.simulate(text).to_dict(), from_text)  # bit-identical rerun
        pockets = {b["name"]: b["pocket"] for b in from_text["balls"]}
        self.assertEqual(pockets["1"], "top-right")
        self.assertEqual(from_text["events"][0]["type"], "cue_strike")

    def test_final_states_follow_from_the_segments(self):
        # Each ball's last trajectory segment, evolved with the cloth closed forms to the
        # end of the shot, lands on its final position: the result's segments and the
        # module's evolve() are the same physics.
        result = cueball.simulate().to_dict()
        q = result["parameters"]
        p = cueball.Parameters(
            cueball.BallParameters(q["mass"], q["radius"]),
            cueball.ClothParameters(q["mu_s"], q["mu_r"], q["mu_sp"], q["g"]),
        )
        for ball in result["balls"]:
            if ball["pocketed"]:
                continue
            last = ball["segments"][-1]
            state = cueball.BallState(last["position"], last["velocity"], last["angular_velocity"])
            self.assertEqual(cueball.motion_phase(state, p), last["phase"])
            end = cueball.evolve(state, result["end_time"] - last["t"], p)
            for mine, theirs in zip(end.position, ball["position"]):
                self.assertAlmostEqual(mine, theirs, delta=1e-9)

    def test_bad_scenarios_name_the_field(self):
        cases = [
            (break_with(cue={"ball": 0, "target": 1, "speed": math.nan}), "scenario.cue.speed", "not a finite number"),
            (break_with(parameters={"preset": "pool", "mass": -0.1}), "scenario.parameters.mass", "-0.1"),
            ('{"table": "pool_9ft",', "scenario", "malformed JSON"),
            (break_with(spin=3), "scenario.spin", "not a known key"),
            (
                {"balls": [{"id": 0, "position": [1.0, 0.5]}, {"id": 1, "position": [1.02, 0.5]}]},
                "scenario.balls[1].position",
                "overlap",
            ),
        ]
        for scenario, field, words in cases:
            with self.subTest(field=field):
                with self.assertRaises(cueball.InvalidArgument) as caught:
                    cueball.simulate(scenario)
                self.assertEqual(caught.exception.field, field)
                self.assertIn(field, str(caught.exception))
                self.assertIn(words, str(caught.exception))
                self.assertIsInstance(caught.exception, ValueError)
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate(sample_rate=-1.0)
        self.assertEqual(caught.exception.field, "sample_rate")
        with self.assertRaises(TypeError):
            cueball.simulate(42)
        with self.assertRaises(FileNotFoundError):
            cueball.simulate(pathlib.Path(tempfile.gettempdir()) / "no-such-cueball-scenario.json")

    def test_recursive_and_deep_dicts_raise_instead_of_crashing(self):
        # Once a segfault: the NaN check recursed without a limit.
        looped = {"table": "pool_9ft"}
        looped["rack"] = looped
        deep = {}
        node = deep
        for _ in range(100000):
            node["x"] = {}
            node = node["x"]
        listed = []
        listed.append(listed)
        for scenario, field, words in [
            (looped, "scenario.rack", "contains itself"),
            (deep, "scenario.x.x.x", "nests deeper than 64"),
            ({"balls": listed}, "scenario.balls", "contains itself"),
        ]:
            with self.subTest(words=words):
                with self.assertRaises(cueball.InvalidArgument) as caught:
                    cueball.simulate(scenario)
                self.assertIn(field, caught.exception.field)
                self.assertIn(words, str(caught.exception))
        # A dict shared (not circular) is fine.
        ball = {"id": 0, "position": [0.5, 0.5]}
        shared = {"balls": [ball], "cue": {"ball": 0, "aim_deg": 0, "speed": 1.0}, "noise": {}}
        self.assertEqual(len(cueball.simulate(shared).to_dict()["balls"]), 1)

    def test_strict_json_and_bounded_resources(self):
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate('{"max_events": 5, "max_events": 6}')
        self.assertEqual(caught.exception.field, "scenario.max_events")
        self.assertIn("given twice", str(caught.exception))
        with self.assertRaisesRegex(cueball.InvalidArgument, "NUL byte"):
            cueball.simulate('{"max_events": 5}\x00{"x": 1}')
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate("/dev/zero")
        self.assertIn("larger than the 16777216 bytes", str(caught.exception))
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate(break_with(max_events=10**8))
        self.assertEqual(caught.exception.field, "scenario.max_events")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate(None, sample_rate=1e4)
        self.assertEqual(caught.exception.field, "sample_rate")
        self.assertIn("at most 200000", str(caught.exception))
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate({"parameters": {"radius": 0.05}})
        self.assertEqual(caught.exception.field, "scenario.parameters.radius")

    def test_event_limit_is_a_simulation_error(self):
        with self.assertRaises(cueball.SimulationError):
            cueball.simulate(break_with(max_events=5))


class BatchTest(unittest.TestCase):
    KEYS = ["shots", "simulated", "miscues", "failures", "speed_reflected", "elevation_reflected", "seconds",
            "shots_per_second", "events_per_shot", "pocketed_probability", "balls"]

    @staticmethod
    def without_timing(result):
        return {k: v for k, v in result.items() if k not in ("seconds", "shots_per_second")}

    def test_deterministic_whatever_the_threads(self):
        one = cueball.simulate_batch(CUT_SHOT, shots=400, threads=1, seed=3)
        two = cueball.simulate_batch(CUT_SHOT, shots=400, threads=2, seed=3)
        self.assertEqual(list(one), self.KEYS)
        self.assertEqual(self.without_timing(one), self.without_timing(two))
        other_seed = cueball.simulate_batch(CUT_SHOT, shots=400, seed=4)
        self.assertNotEqual(self.without_timing(one), self.without_timing(other_seed))
        self.assertEqual(one["shots"], 400)
        self.assertEqual(one["simulated"] + one["miscues"] + one["failures"], 400)
        self.assertEqual(sorted(one["pocketed_probability"]), [0, 1, 9])
        self.assertGreater(one["pocketed_probability"][1], 0.3)  # the cut drops most of the time (README: 0.62)
        self.assertEqual([b["id"] for b in one["balls"]], [0, 1, 9])

    @unittest.skipUnless(CLI, "CUEBALL_BIN is not set")
    def test_the_same_as_the_clis_batch(self):
        mine = cueball.simulate_batch(CUT_SHOT, shots=300, threads=2, seed=1)
        cli = run_cli("batch", str(CUT_SHOT), "--shots", "300", "--threads", "2", "--seed", "1")
        self.assertEqual(list(cli), self.KEYS)
        # One writer (io/batch_json.hpp): the same text but for the timing, ints and floats
        # alike; only pocketed_probability's keys are the ids as ints in Python.
        self.assertEqual(json.dumps(self.without_timing(mine)), json.dumps(self.without_timing(cli)))
        cli["pocketed_probability"] = {int(k): v for k, v in cli["pocketed_probability"].items()}
        self.assertEqual(self.without_timing(mine), self.without_timing(cli))

    def test_bad_options(self):
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate_batch(shots=0)
        self.assertEqual(caught.exception.field, "shots")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate_batch(threads=1000)
        self.assertEqual(caught.exception.field, "threads")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate_batch({"rack": {"type": "nine_ball"}})
        self.assertEqual(caught.exception.field, "cue")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate_batch(shots=10**10)  # beyond a C int: still the range error
        self.assertEqual(caught.exception.field, "shots")
        self.assertIn("[1, 100000000]", str(caught.exception))

    def test_a_workers_error_is_raised_in_the_caller(self):
        # jaws[0] fits the table's ball but is too high for the parameters' smaller
        # ball: found only when a shot runs, in a worker thread.
        table = cueball.simulate(break_with(max_events=1000)).to_dict()["table"]
        table["jaws"][0]["contact_height"] = 0.056
        scenario = break_with(table=table, parameters={"radius": 0.0275}, noise={"speed": 0.1})
        with self.assertRaises(cueball.InvalidArgument) as single:
            cueball.simulate(scenario)
        for threads in (1, 2, 4):
            with self.assertRaises(cueball.InvalidArgument) as caught:
                cueball.simulate_batch(scenario, shots=200, threads=threads)
            self.assertEqual(caught.exception.field, single.exception.field, threads)
            self.assertEqual(str(caught.exception), str(single.exception), threads)

    def test_noisy_strikes_are_reflected_into_their_limits(self):
        at_the_cap = break_with(cue={"ball": 0, "target": 1, "speed": 12.0}, noise={"speed": 0.3, "elevation_deg": 1})
        r = cueball.simulate_batch(at_the_cap, shots=64, threads=2, seed=4)
        self.assertEqual(r["miscues"], 0)
        self.assertEqual(r["simulated"] + r["failures"], 64)
        self.assertTrue(16 < r["speed_reflected"] < 48, r["speed_reflected"])
        self.assertTrue(16 < r["elevation_reflected"] < 48, r["elevation_reflected"])
        beyond = cueball.simulate_batch(break_with(noise={"height": 0.5}), shots=64, seed=4)
        self.assertGreater(beyond["miscues"], 5)
        self.assertEqual(beyond["speed_reflected"], 0)

    def test_python_threads_run_concurrently(self):
        # simulate() and simulate_batch() release the GIL: the same work from four Python
        # threads at once gives the results of one thread.
        expected_batch = self.without_timing(cueball.simulate_batch(shots=100, seed=9))
        expected_shot = cueball.simulate(CUT_SHOT).to_dict()
        results, errors = [], []

        def work():
            try:
                batch = cueball.simulate_batch(shots=100, seed=9)
                results.append((self.without_timing(batch), cueball.simulate(CUT_SHOT).to_dict()))
            except Exception as e:  # reported below
                errors.append(e)

        threads = [threading.Thread(target=work) for _ in range(4)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(errors, [])
        self.assertEqual(results, [(expected_batch, expected_shot)] * 4)


if __name__ == "__main__":
    unittest.main()
