"""Arguments of the wrong Python type and strings with lone surrogates (issue 24):
InvalidArgument naming the argument in one line, never pybind11's four-line
TypeError or a RuntimeError/UnicodeEncodeError."""
import pickle
import unittest

import numpy as np

import cueball
from cueball import _cueball


class WrongTypesTest(unittest.TestCase):
    def assert_named(self, call, field, *parts):
        with self.assertRaises(cueball.InvalidArgument) as caught:
            call()
        error = caught.exception
        self.assertEqual(error.field, field)
        self.assertNotIn("\n", str(error))
        self.assertNotIn("incompatible", str(error))
        for part in parts:
            self.assertIn(part, str(error))
        return error

    def test_wrong_types_in_the_main_entry_points_name_the_argument(self):
        ball = cueball.SimulationBall(0, (1.0, 0.6))
        cases = [
            (lambda: cueball.simulate(sample_rate="fast"), "sample_rate", "sample_rate = 'fast' is a str; allowed: float"),
            (lambda: cueball.simulate(42), "scenario", "scenario = 42 is an int"),
            (lambda: cueball.plan_shot(None, "1"), "target", "target = '1' is a str; allowed: int"),
            (lambda: cueball.plan_shot(None, 1, simulations=4000.0), "simulations", "is a float; allowed: int"),
            (lambda: cueball.plan_shot(None, 1, noise=3), "noise", "noise = 3 is an int"),
            (lambda: cueball.plan_shot(None, 1, pocket=1.5), "pocket", "pocket = 1.5 is a float"),
            (lambda: cueball.SimulationSettings(max_events="many"), "max_events", "max_events = 'many' is a str"),
            (lambda: cueball.SimulationSettings(cushion_restitution="high"), "cushion_restitution",
             "cushion_restitution = 'high' is a str; allowed: float or None"),
            (lambda: cueball.Scenario(3, [ball]), "table", "table = 3 is an int"),
            (lambda: cueball.Scenario("pool_9ft", [cueball.BallState()]), "balls", "balls[0] = BallState("),
            (lambda: cueball.Scenario("pool_9ft", [ball], cue=3.0), "cue", "cue = 3.0 is a float; allowed: ShotStrike or None"),
            (lambda: cueball.ShotStrike(speed="fast"), "speed", "speed = 'fast' is a str; allowed: float"),
            (lambda: cueball.SimulationBall(0, (1.0, "a")), "position", "position = (1.0, 'a') is a tuple"),
            (lambda: cueball.SimulationBall(0, (1.0, 0.5, 0.1)), "position", "of length 3, not 2"),
            (lambda: cueball.Scenario.from_json(3), "text", "text = 3 is an int; allowed: str"),
            (lambda: cueball.simulate(None).state_at("1.0"), "times", "times = '1.0' is a str"),
            (lambda: setattr(cueball.BallState(), "angular_velocity", (1, 2)), "angular_velocity", "of length 2, not 3"),
        ]
        for call, field, message in cases:
            with self.subTest(field=field, message=message):
                error = self.assert_named(call, field, message)
                self.assertIsInstance(error, cueball.InvalidArgumentType)
                self.assertIsInstance(error, TypeError)  # as before, and as Python's own
                self.assertIsInstance(error, ValueError)

    def test_a_call_of_the_wrong_shape_stays_a_one_line_type_error(self):
        for call, message in [
            (lambda: cueball.ShotStrike(sped=3.0), "ShotStrike() got an unexpected keyword argument 'sped'"),
            (lambda: cueball.ShotStrike(), "ShotStrike() missing required argument 'speed'"),
            (lambda: cueball.plan_natural_roll_shot(1.0), "plan_natural_roll_shot() takes at most 0 positional"),
        ]:
            with self.subTest(message=message):
                with self.assertRaises(TypeError) as caught:
                    call()
                self.assertNotIsInstance(caught.exception, cueball.InvalidArgument)
                self.assertIn(message, str(caught.exception))
                self.assertNotIn("\n", str(caught.exception))

    def test_what_pybind11_converts_still_converts(self):
        self.assertEqual(cueball.ShotStrike(3, side=np.float64(0.1), ball=np.int64(0)).speed, 3.0)
        self.assertEqual(cueball.SimulationBall(0, np.array([1.0, 0.6])).state.position, (1.0, 0.6))
        s = cueball.SimulationSettings(max_events=np.int32(500))
        self.assertEqual(s.max_events, 500)
        # The package's functions are the extension's, and pickle by reference as before.
        self.assertIs(cueball.simulate, _cueball.simulate)
        self.assertIs(pickle.loads(pickle.dumps(cueball.simulate)), cueball.simulate)
        self.assertEqual(cueball.simulate.__name__, "simulate")
        self.assertTrue(cueball.simulate.__doc__.startswith("simulate("))

    def test_a_lone_surrogate_is_named_where_it_was_given(self):
        surrogate = "\ud800"
        text = '{"balls": [{"id": 0, "name": "' + surrogate + '", "position": [1, 0.6]}]}'
        cases = [
            (lambda: cueball.SimulationBall(0, (1.0, 0.6), name=surrogate), "name", "U+D800 at index 0"),
            (lambda: cueball.simulate(text), "scenario", "U+D800 at index 30"),
            (lambda: cueball.Scenario.from_json(text), "text", "U+D800"),
            (lambda: cueball.simulate({"balls": [{"id": 0, "name": surrogate, "position": [1, 0.6]}]}),
             "scenario.balls[0].name", "scenario.balls[0].name has a lone UTF-16 surrogate"),
            (lambda: cueball.plan_shot(None, 1, pocket="top" + surrogate), "pocket", "U+D800 at index 3"),
            (lambda: cueball.plan_shot(None, 1, noise=surrogate), "noise", "U+D800"),
            (lambda: cueball.Scenario("pool_9ft" + surrogate, []), "table", "U+D800"),
            (lambda: setattr(cueball.SimulationBall(0, (1.0, 0.6)), "name", "\udc00"), "name", "U+DC00"),
        ]
        for call, field, part in cases:
            with self.subTest(field=field):
                self.assert_named(call, field, "lone UTF-16 surrogate", part, "allowed: valid Unicode text")


class PlanInputTest(unittest.TestCase):
    def test_the_missing_cue_ball_and_a_region_off_the_table_are_named_as_written(self):
        # Issue 24: reported as 'cue_ball' (a name the scenario never has) and as NoFeasibleShot.
        scenario = {"balls": [{"id": 3, "position": [1, 0.6]}, {"id": 4, "position": [1.5, 0.6]}]}
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.plan_shot(scenario, 4)
        self.assertEqual(caught.exception.field, "scenario.cue.ball")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.plan_shot(scenario, 4, cue_ball=7)
        self.assertEqual(caught.exception.field, "cue_ball")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.plan_shot(None, 1, in_hand=True, region=[5, 6, 5, 6])
        self.assertEqual(caught.exception.field, "region")
        self.assertIn("wholly off the playing surface", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
