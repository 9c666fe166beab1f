"""Tables, racks and scenarios as objects: geometry checked against the
specifications, racks against the rules, scenarios round-tripped through
JSON and pickle bit for bit, the cue's units against the scenario reader's."""

import concurrent.futures
import copy
import json
import multiprocessing
import math
import os
import pickle
import subprocess
import unittest

import numpy as np

import cueball

POOL_R = 0.028575
CLI = os.environ.get("CUEBALL_BIN")


def square_table(side=1.0, clockwise=False):
    """A pocketless square table, its four cushions anticlockwise (or not)."""
    h = 1.4 * POOL_R
    corners = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side)]
    if clockwise:
        corners.reverse()
    cushions = [cueball.CushionSegment(corners[i], corners[(i + 1) % 4], h) for i in range(4)]
    return cueball.Table(side, side, cushions, cueball.BallParameters(0.17, POOL_R), name="square")


class TableTest(unittest.TestCase):
    def test_presets_are_the_same_table_by_every_name(self):
        self.assertEqual(cueball.TABLE_PRESETS, ("pool_9ft", "snooker_12ft", "carom_10ft"))
        for name, make in zip(cueball.TABLE_PRESETS,
                              (cueball.pool_table_9ft, cueball.snooker_table_12ft, cueball.carom_table_10ft)):
            with self.subTest(name=name):
                self.assertEqual(cueball.Table.preset(name), make())
                self.assertEqual(cueball.preset_table(name), make())
                self.assertEqual(cueball.build_table(cueball.preset_table_spec(name)), make())
        self.assertNotEqual(cueball.pool_table_9ft(), cueball.snooker_table_12ft())

    def test_pool_table_follows_the_wpa_specification(self):
        t = cueball.pool_table_9ft()
        self.assertEqual((t.length, t.width), (2.54, 1.27))  # 100 x 50 in, nose to nose
        self.assertEqual(t.ball, cueball.pool_parameters().ball)
        self.assertEqual([p.name for p in t.pockets],
                         ["bottom-left", "bottom-side", "bottom-right", "top-right", "top-side", "top-left"])
        self.assertEqual(len(t.jaws), 12)
        self.assertEqual(len(t.diamonds), 18)
        names = [c.name for c in t.cushions] + [j.name for j in t.jaws]
        self.assertEqual(len(set(names)), len(names))  # unique, every part named
        self.assertIn("bottom rail, left of the side pocket", names)
        self.assertIn("top-side pocket, right jaw", names)
        for c in t.cushions:
            self.assertGreater(c.contact_height, t.ball.radius)
            self.assertLess(c.contact_height, 2 * t.ball.radius)

    def test_inward_normals_are_unit_perpendicular_and_point_onto_the_bed(self):
        t = cueball.pool_table_9ft()
        expected = {"bottom": (0.0, 1.0), "top": (0.0, -1.0), "left": (1.0, 0.0), "right": (-1.0, 0.0)}
        rails = 0
        for c in t.cushions:
            n = c.inward_normal
            d = np.subtract(c.end, c.start)
            self.assertAlmostEqual(math.hypot(*n), 1.0, delta=1e-15)
            self.assertAlmostEqual(float(np.dot(n, d)), 0.0, delta=1e-15)
            # Left of start -> end: the cross product d x n is positive.
            self.assertGreater(d[0] * n[1] - d[1] * n[0], 0.0)
            if "rail" in c.name:
                rails += 1
                np.testing.assert_allclose(n, expected[c.name.split()[0]], atol=1e-15)
                mid = np.add(c.start, c.end) / 2
                self.assertTrue(t.inside_playing_area(mid + 0.05 * np.array(n)))
                self.assertFalse(t.inside_playing_area(mid - 0.05 * np.array(n)))
        self.assertEqual(rails, 6)

    def test_json_pickle_and_copy_give_the_same_table(self):
        for name in cueball.TABLE_PRESETS:
            t = cueball.Table.preset(name)
            with self.subTest(name=name):
                self.assertEqual(cueball.Table.from_json(t.to_json()), t)
                self.assertEqual(cueball.table_from_json(cueball.table_to_json(t)), t)
                back = pickle.loads(pickle.dumps(t))
                self.assertEqual(back, t)
                self.assertEqual(back.to_json(), t.to_json())
                self.assertEqual(copy.deepcopy(t), t)
        overridden = cueball.Table.from_json('{"preset": "pool_9ft", "length": 2.24, "width": 1.12}')
        self.assertEqual((overridden.length, overridden.width), (2.24, 1.12))

    def test_a_spec_changes_the_geometry(self):
        spec = cueball.preset_table_spec("pool_9ft")
        spec.length, spec.width = 2.0, 1.0
        t = cueball.Table.from_spec(spec)
        self.assertEqual((t.length, t.width), (2.0, 1.0))
        self.assertEqual(cueball.foot_spot(t), (1.5, 0.5))
        self.assertEqual(cueball.head_string_x(t), 0.5)
        self.assertEqual(t.pockets[1].centre[0], 1.0)  # the side pocket at mid-length
        spec.corner_pockets = cueball.PocketSpec(mouth=0.01, cut_angle_deg=142.0, jaw_radius=0.00635)
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.build_table(spec)
        self.assertTrue(caught.exception.field.startswith("corner_pockets"), caught.exception.field)

    def test_a_custom_table_from_its_parts(self):
        t = square_table()
        self.assertEqual([c.name for c in t.cushions], [f"cushions[{i}]" for i in range(4)])
        self.assertEqual(t.cushions[0].inward_normal, (0.0, 1.0))
        self.assertEqual(cueball.Table.from_json(t.to_json()), t)
        self.assertEqual(pickle.loads(pickle.dumps(t)), t)
        self.assertTrue(t.ball_on_table((0.5, 0.5)))
        d = math.sqrt(t.cushions[0].contact_height * (2 * POOL_R - t.cushions[0].contact_height))
        self.assertTrue(t.ball_on_table((0.5, d)))          # touching the cushion
        self.assertFalse(t.ball_on_table((0.5, d - 1e-6)))  # overlapping it
        # A result of this table simulates: a ball rolled straight at the far cushion comes back.
        scenario = cueball.Scenario(t, [cueball.SimulationBall(0, (0.5, 0.2), (1.0, 0.0), (0.0, 1.0 / POOL_R, 0.0))])
        result = cueball.simulate(scenario)
        kinds = [cueball.EVENT_TYPES[k] for k in result.events["type"]]
        self.assertIn("ball_cushion", kinds)
        self.assertEqual(result.scenario.table, t)

    def test_a_bad_table_names_the_field(self):
        with self.assertRaises(cueball.InvalidArgument) as caught:
            square_table(clockwise=True)
        self.assertEqual(caught.exception.field, "cushions")
        h = 1.4 * POOL_R
        open_cushions = [cueball.CushionSegment((0, 0), (1, 0), h), cueball.CushionSegment((1, 0), (1, 1), h),
                         cueball.CushionSegment((1, 1), (0, 1), h)]
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.Table(1.0, 1.0, open_cushions, cueball.BallParameters(0.17, POOL_R))
        self.assertRegex(caught.exception.field, r"^cushions\[2\]")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.Table(1.0, 1.0, open_cushions, cueball.BallParameters(0.17, POOL_R), name="")
        self.assertEqual(caught.exception.field, "name")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.Table.preset("croquet")
        self.assertEqual(caught.exception.field, "preset")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.Table.from_json('{"preset": "pool_9ft", "length": -1}')
        self.assertEqual(caught.exception.field, "table.length")
        t = cueball.pool_table_9ft()
        with self.assertRaises(cueball.InvalidArgument) as caught:
            t.inside_playing_area((1.0, 0.5), margin=-1.0)
        self.assertEqual(caught.exception.field, "margin")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            t.inside_playing_area((math.nan, 0.5))
        self.assertEqual(caught.exception.field, "position")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            t.ball_on_table((1.0, 0.5), radius=0.01)  # the noses are above the ball
        self.assertEqual(caught.exception.field, "radius")
        self.assertIn("allowed", str(caught.exception))

    def test_placement_and_the_playing_area(self):
        t = cueball.pool_table_9ft()
        self.assertTrue(t.ball_on_table((1.27, 0.635)))
        self.assertFalse(t.ball_on_table(t.pockets[0].centre))  # over the hole
        self.assertTrue(t.inside_playing_area(t.pockets[0].centre))  # the throat is inside
        self.assertFalse(t.inside_playing_area((3.0, 0.6)))
        self.assertTrue(t.inside_playing_area((2.6, 0.6), margin=0.1))
        self.assertTrue(t.ball_on_table(np.array([1.27, 0.635]), radius=np.float32(0.0286)))

    def test_numpy_numbers_and_vectors_are_accepted(self):
        h = np.float32(1.4 * POOL_R)
        corners = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
        cushions = [cueball.CushionSegment(corners[i], corners[(i + 1) % 4], h) for i in range(4)]
        t = cueball.Table(np.float64(1.0), np.int64(1), cushions, cueball.BallParameters(np.float32(0.17), POOL_R))
        self.assertEqual(t.length, 1.0)
        self.assertEqual(t.cushions[1].end, (1.0, 1.0))

    def test_repr(self):
        self.assertEqual(repr(cueball.carom_table_10ft()),
                         "Table(name='carom 10 ft (UMB)', length=2.84, width=1.42, cushions=4, jaws=0, pockets=0)")
        self.assertEqual(repr(cueball.Pocket("p", (1, 2), 0.05)), "Pocket(name='p', centre=(1.0, 2.0), radius=0.05)")


class RackTest(unittest.TestCase):
    table = cueball.pool_table_9ft()
    R = table.ball.radius

    def positions(self, rack):
        return {b.id: np.array(b.position) for b in rack}

    def closest_pair(self, rack):
        p = np.array([b.position for b in rack])
        d = np.linalg.norm(p[:, None, :] - p[None, :, :], axis=-1)
        return d[np.triu_indices(len(rack), 1)].min()

    def test_nine_ball_follows_the_rules(self):
        rack = cueball.rack_nine_ball(self.table)
        self.assertEqual([b.id for b in rack][0], 0)
        self.assertEqual(sorted(b.id for b in rack), list(range(10)))
        at = self.positions(rack)
        np.testing.assert_array_equal(at[1], cueball.foot_spot(self.table))
        np.testing.assert_allclose(at[9], np.mean([at[i] for i in range(1, 10)], axis=0), atol=1e-12)  # the centre
        self.assertLess(at[0][0], cueball.head_string_x(self.table))  # behind the head string
        self.assertAlmostEqual(self.closest_pair(rack), 2 * self.R, delta=1e-12)  # frozen

    def test_eight_ball_and_snooker(self):
        rack = cueball.rack_eight_ball(self.table)
        self.assertEqual(len(rack), 16)
        at = self.positions(rack)
        apex = np.array(cueball.foot_spot(self.table))
        np.testing.assert_allclose(at[1], apex, atol=1e-15)
        # The 8 in the centre of the third row: two rows (sqrt(3) R each, frozen) behind the apex.
        np.testing.assert_allclose(at[8], apex + (2 * math.sqrt(3) * self.R, 0.0), atol=1e-12)
        self.assertEqual({len([b for b in rack if abs(b.position[0] - at[8][0]) < 1e-9])}, {3})
        snooker = cueball.snooker_table_12ft()
        balls = cueball.rack_snooker(snooker)
        self.assertEqual(len(balls), 22)
        spots = cueball.snooker_spots(snooker)
        by_name = {b.name: b.position for b in balls}
        for colour in ("yellow", "green", "brown", "blue", "pink", "black"):
            self.assertEqual(by_name[colour], getattr(spots, colour), colour)
        self.assertAlmostEqual(spots.blue[0], snooker.length / 2, delta=1e-12)
        self.assertAlmostEqual(spots.yellow[1], snooker.width / 2 - spots.d_radius, delta=1e-12)
        self.assertAlmostEqual(self.closest_pair([b for b in balls if b.name.startswith("red")]),
                               2 * snooker.ball.radius, delta=1e-12)

    def test_random_gaps_are_seeded_and_never_overlap(self):
        options = cueball.RackOptions(gap_sigma=0.001, seed=7)
        a = cueball.rack_nine_ball(self.table, options)
        self.assertEqual(a, cueball.rack_nine_ball(self.table, cueball.RackOptions(0.001, 7)))
        self.assertNotEqual(a, cueball.rack_nine_ball(self.table, cueball.RackOptions(0.001, 8)))
        self.assertGreaterEqual(self.closest_pair(a), 2 * self.R - 1e-12)
        self.assertGreater(self.closest_pair(a), 2 * self.R)
        self.assertEqual(pickle.loads(pickle.dumps(a)), a)
        self.assertEqual(pickle.loads(pickle.dumps(options)), options)

    def test_bad_racks_name_the_field(self):
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.rack_nine_ball(self.table, cueball.RackOptions(gap_sigma=0.01))
        self.assertEqual(caught.exception.field, "gap_sigma")
        self.assertIn("0.005", str(caught.exception))
        spec = cueball.preset_table_spec("carom_10ft")
        spec.length, spec.width = 0.5, 0.25
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.rack_eight_ball(cueball.build_table(spec))
        self.assertEqual(caught.exception.field, "rack")


def simulate_json(scenario):
    """A worker's job: a scenario in, its result's JSON out."""
    return cueball.simulate(scenario).to_json()


def break_noise():
    return {"speed": 0.1, "aim_deg": 0.2, "side": 0.02, "height": 0.02}


class ScenarioTest(unittest.TestCase):
    def test_the_default_scenario_is_the_pool_break(self):
        s = cueball.default_scenario()
        self.assertEqual(s, cueball.Scenario.default())
        self.assertEqual(s.table, cueball.pool_table_9ft())
        self.assertEqual(s.parameters, cueball.pool_parameters())
        self.assertEqual(s.settings.ball_collision, cueball.ball_collision_alciatore())
        self.assertEqual(s.cue, cueball.ShotStrike(7.0, target=1))
        self.assertEqual(s.cue_parameters, cueball.CueParameters())
        self.assertEqual([b.id for b in s.balls], [0, 1, 2, 3, 4, 9, 5, 6, 7, 8])
        # Made from its parts: the same scenario.
        t = cueball.pool_table_9ft()
        parts = cueball.Scenario(t, cueball.rack_nine_ball(t), cueball.ShotStrike(7.0, target=1), noise=break_noise())
        self.assertEqual(parts.to_json(), s.to_json())

    def test_result_scenario_replays_the_result_bit_for_bit(self):
        first = cueball.simulate()
        self.assertIsInstance(first.scenario, cueball.Scenario)
        again = cueball.simulate(first.scenario)
        self.assertEqual(again.to_json(), first.to_json())
        s = cueball.default_scenario()
        self.assertEqual(cueball.simulate(s).to_json(), first.to_json())
        self.assertIs(cueball.simulate(s).scenario, s)
        replay = cueball.Scenario.from_document(first.to_json())
        self.assertEqual(replay, s)
        self.assertEqual(cueball.scenario_from_document(first.to_json(indent=-1)), s)

    def test_json_and_pickle_round_trips_are_exact(self):
        cut = cueball.Scenario(
            cueball.pool_table_9ft(),
            [cueball.SimulationBall(0, (0.6, 0.6)), cueball.SimulationBall(1, (1.1, 0.7), name="object")],
            cueball.ShotStrike(3.3, aim_deg=12.345678901234567, elevation_deg=3.1, side=0.1234567, height=-0.3),
            settings=cueball.SimulationSettings(cueball.pool_parameters(), cushion_friction=0.2, max_events=5000),
            cue_parameters=cueball.CueParameters(0.5, 0.8))
        for s in (cueball.default_scenario(), cut):
            with self.subTest(s=repr(s)):
                text = s.to_json()
                self.assertEqual(cueball.Scenario.from_json(text).to_json(), text)
                self.assertEqual(cueball.scenario_to_json(s, -1), s.to_json(indent=-1))
                back = pickle.loads(pickle.dumps(s))
                self.assertEqual(back, s)
                self.assertEqual(hash(back), hash(s))
                self.assertEqual(cueball.simulate(back).to_json(), cueball.simulate(s).to_json())
                self.assertEqual(copy.deepcopy(s), s)
        self.assertEqual(cut.cue.aim_deg, 12.345678901234567)
        self.assertEqual(cut.cue.side, 0.1234567)
        self.assertEqual(cut.balls[1].name, "object")
        self.assertEqual(cut.balls[0].name, "0")
        self.assertEqual(cut.settings.cushion_friction, 0.2)
        self.assertEqual(cut.settings.max_events, 5000)
        self.assertEqual(cut.cue_parameters, cueball.CueParameters(0.5, 0.8))
        self.assertEqual(cut.to_dict()["cue"]["mass"], 0.5)

    def test_scenarios_and_tables_go_to_worker_processes(self):
        # What Dask or multiprocessing does: pickle, send, unpickle in another interpreter.
        s = cueball.default_scenario()
        with concurrent.futures.ProcessPoolExecutor(1, mp_context=multiprocessing.get_context("spawn")) as pool:
            remote = pool.submit(simulate_json, s).result(timeout=120)
            table = pool.submit(copy.copy, s.table).result(timeout=120)
        self.assertEqual(remote, cueball.simulate(s).to_json())
        self.assertEqual(table, cueball.pool_table_9ft())

    def test_what_a_scenario_or_table_gives_out_are_copies(self):
        s = cueball.default_scenario()
        text = s.to_json()
        s.settings.max_events = 5
        s.settings.parameters.ball.mass = 1.0
        s.balls[0].id = 99
        s.table.ball.radius = 0.05
        s.cue_parameters.mass = 1.5
        self.assertEqual(s.to_json(), text)
        t = cueball.pool_table_9ft()
        t.ball.mass = 1.0
        self.assertEqual(t, cueball.pool_table_9ft())
        with self.assertRaises(AttributeError):
            t.cushions[0].name = "x"

    def test_a_rolling_ball_stops_where_the_closed_form_says(self):
        p = cueball.pool_parameters()
        v, x0 = 0.5, 0.3
        ball = cueball.SimulationBall(0, (x0, 0.635), (v, 0.0), (0.0, v / p.ball.radius, 0.0))
        result = cueball.simulate(cueball.Scenario("pool_9ft", [ball]))
        stop = x0 + v * v / (2 * cueball.rolling_deceleration(p))
        self.assertAlmostEqual(result.balls["position"][0][0], stop, delta=1e-9)
        self.assertAlmostEqual(result.end_time, v / cueball.rolling_deceleration(p), delta=1e-9)

    def test_the_cue_in_the_scenarios_units_is_cue_strike_from_units(self):
        s = cueball.Scenario("pool_9ft", [cueball.SimulationBall(0, (0.7, 0.6)), cueball.SimulationBall(1, (1.9, 0.6))],
                             cueball.ShotStrike(4.0, aim_deg=7.5, elevation_deg=5.0, side=-0.25, height=0.3))
        R = s.parameters.ball.radius
        strike = cueball.CueStrike.from_units(4.0, 7.5, 5.0, -0.25, 0.3, radius=R)
        self.assertEqual(strike.aim, 7.5 * math.pi / 180)
        self.assertEqual(strike.side_offset, -0.25 * R)
        struck = cueball.strike_ball(strike, (0.7, 0.6), params=s.parameters)
        first = cueball.simulate(s).segments[0]
        self.assertEqual(tuple(first["velocity"][0]), struck.velocity)  # bit for bit
        self.assertEqual(tuple(first["angular_velocity"][0]), struck.angular_velocity)
        back = strike.in_units(radius=R)
        self.assertEqual(set(back), {"speed", "aim_deg", "elevation_deg", "side", "height"})
        for key, value in (("aim_deg", 7.5), ("elevation_deg", 5.0), ("side", -0.25), ("height", 0.3)):
            self.assertAlmostEqual(back[key], value, delta=1e-14)
        # The default radius is the default (pool) ball's.
        self.assertEqual(cueball.CueStrike.from_units(1.0, side=0.5).side_offset, 0.5 * POOL_R)

    def test_settings_default_to_the_tables_preset(self):
        snooker = cueball.Scenario("snooker_12ft", cueball.rack_snooker(cueball.snooker_table_12ft()))
        self.assertEqual(snooker.parameters, cueball.snooker_parameters())
        self.assertIsNone(snooker.cue)
        given = cueball.Scenario(cueball.pool_table_9ft(), [cueball.SimulationBall(0, (1.0, 0.6))],
                                 settings=cueball.SimulationSettings(ball_collision=cueball.ball_collision_frictionless(1.0)))
        self.assertEqual(given.settings.ball_collision, cueball.ball_collision_frictionless(1.0))
        self.assertEqual(given.parameters, cueball.pool_parameters())

    def test_batches_take_a_scenario_as_they_take_its_dict(self):
        s = cueball.default_scenario()
        self.assertEqual(s.noise, {"speed": 0.1, "aim_deg": 0.2, "elevation_deg": 0.0, "side": 0.02, "height": 0.02})
        by_object = cueball.simulate_batch(s, shots=20, seed=3)
        by_dict = cueball.simulate_batch(s.to_dict(), shots=20, seed=3)
        for key in ("pocketed_probability", "balls", "simulated", "miscues"):
            self.assertEqual(by_object[key], by_dict[key], key)
        actions = np.array([[6.0, 0.0, 0.0, 0.0, 0.0], [8.0, 1.0, 0.0, 0.1, -0.2]])
        many_object = cueball.simulate_many(s, actions)
        many_dict = cueball.simulate_many(s.to_json(), actions)
        np.testing.assert_array_equal(many_object["final_position"], many_dict["final_position"])

    def test_bad_parts_raise_naming_the_json_path(self):
        t = cueball.pool_table_9ft()
        cases = [
            (dict(balls=[cueball.SimulationBall(0, (100.0, 100.0))]), "scenario.balls[0].position"),
            (dict(balls=[cueball.SimulationBall(0, (1.0, 0.6))], cue=cueball.ShotStrike(20.0)), "scenario.cue.speed"),
            (dict(balls=[cueball.SimulationBall(0, (1.0, 0.6))], cue=cueball.ShotStrike(2.0, side=0.6)),
             "scenario.cue.side"),
            (dict(balls=[cueball.SimulationBall(0, (1.0, 0.6))], cue=cueball.ShotStrike(2.0, aim_deg=3.0, target=1)),
             "scenario.cue.target"),
            (dict(balls=[cueball.SimulationBall(0, (1.0, 0.6), velocity=(math.inf, 0.0))]),
             "scenario.balls[0].velocity[0]"),
            (dict(balls=[cueball.SimulationBall(0, (1.0, 0.6))], cue_parameters=cueball.CueParameters()),
             "cue_parameters"),
            (dict(balls=[cueball.SimulationBall(0, (1.0, 0.6))], noise={"speed": -1.0}), "scenario.noise.speed"),
        ]
        for kwargs, field in cases:
            with self.subTest(field=field):
                with self.assertRaises(cueball.InvalidArgument) as caught:
                    cueball.Scenario(t, **kwargs)
                self.assertEqual(caught.exception.field, field)
        with self.assertRaises(TypeError):
            cueball.Scenario(t, [cueball.BallState()])
        with self.assertRaises(TypeError):
            cueball.simulate(42)

    def test_numpy_in_the_parts(self):
        ball = cueball.SimulationBall(np.int64(0), np.array([0.6, 0.6]), velocity=np.array([0.0, 0.0]))
        other = cueball.SimulationBall(1, (np.float32(1.1), np.float64(0.7)))
        s = cueball.Scenario("pool_9ft", [ball, other], cueball.ShotStrike(np.float32(3.0), target=np.int64(1)),
                             noise={"speed": np.float64(0.05)})
        plain = cueball.Scenario("pool_9ft", [cueball.SimulationBall(0, (0.6, 0.6)),
                                              cueball.SimulationBall(1, (float(np.float32(1.1)), 0.7))],
                                 cueball.ShotStrike(3.0, target=1), noise={"speed": 0.05})
        self.assertEqual(s, plain)

    def test_repr(self):
        self.assertEqual(repr(cueball.default_scenario()),
                         "Scenario(table='pool 9 ft (WPA)', balls=10, cue=ShotStrike(speed=7.0, aim_deg=0.0, "
                         "elevation_deg=0.0, side=0.0, height=0.0, ball=0, target=1))")


class DefaultsTest(unittest.TestCase):
    """One rule: the pool preset by default everywhere (python/README.md, "Units and defaults")."""

    def test_every_default_is_the_pool_preset(self):
        pool = cueball.pool_parameters()
        self.assertEqual(cueball.default_scenario().parameters, pool)
        self.assertEqual(cueball.default_scenario().table.ball, pool.ball)
        self.assertEqual(cueball.SimulationSettings().parameters, pool)  # C++'s SimulationSettings{} too
        self.assertEqual(repr(cueball.straight_shot(1.5)), repr(cueball.straight_shot(1.5, params=pool)))
        self.assertEqual(cueball.plan_natural_roll_shot(x2=1.5, v2=0.2).v0,
                         cueball.plan_natural_roll_shot(x2=1.5, v2=0.2, params=pool).v0)
        strike = cueball.CueStrike(2.0, side_offset=0.01)
        self.assertEqual(cueball.strike_ball(strike), cueball.strike_ball(strike, params=pool))
        a, b = cueball.BallState((0, 0), (1, 0)), cueball.BallState((2 * pool.ball.radius, 0))
        self.assertEqual(cueball.resolve_ball_collision(a, b).normal_impulse,
                         cueball.resolve_ball_collision(a, b, pool).normal_impulse)
        impact = cueball.cushion_impact(1.0, 1.0)
        self.assertEqual(impact.rebound_speed, cueball.cushion_impact(1.0, 1.0, params=pool).rebound_speed)
        self.assertNotEqual(impact.rebound_speed,
                            cueball.cushion_impact(1.0, 1.0, params=cueball.snooker_parameters()).rebound_speed)

    @unittest.skipUnless(CLI, "CUEBALL_BIN not set")
    def test_the_cli_has_the_same_defaults(self):
        pool = cueball.pool_parameters()
        for command in (["roll", "--v0", "1.5"], ["plan", "--x2", "1.5", "--natural-roll"]):
            with self.subTest(command=command[0]):
                out = json.loads(subprocess.run([CLI, *command, "--json"], check=True, capture_output=True,
                                                text=True).stdout)
                q = out["parameters"]
                self.assertEqual(cueball.Parameters(cueball.BallParameters(q["mass"], q["radius"]),
                                                    cueball.ClothParameters(q["mu_s"], q["mu_r"], q["mu_sp"], q["g"])),
                                 pool)
        cli = json.loads(subprocess.run([CLI, "cushion", "--v0", "1", "--alpha", "45", "--json"], check=True,
                                        capture_output=True, text=True).stdout)
        self.assertAlmostEqual(cli["speed"], cueball.cushion_impact(1.0, math.radians(45)).rebound_speed, delta=1e-12)


if __name__ == "__main__":
    unittest.main()
