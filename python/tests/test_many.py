"""simulate_many: N different shots in one call, outcomes as NumPy arrays."""

import json
import pathlib
import unittest

import numpy as np

import cueball

CUT = pathlib.Path(__file__).resolve().parents[2] / "docs" / "example-cut-shot.json"


class SimulateManyTest(unittest.TestCase):
    def setUp(self) -> None:
        rng = np.random.default_rng(3)
        n = 40
        self.actions = np.column_stack([
            rng.uniform(0.5, 6.0, n),      # speed, m/s
            rng.uniform(-180, 180, n),     # aim, deg
            rng.uniform(0, 30, n),         # elevation, deg
            rng.uniform(-0.3, 0.3, n),     # side, ball radii
            rng.uniform(-0.3, 0.3, n),     # height, ball radii
        ])

    def test_shapes_and_types(self) -> None:
        r = cueball.simulate_many(None, self.actions, threads=2)
        n, b = len(self.actions), len(r["ids"])
        self.assertEqual(b, 10)  # the built-in 9-ball break
        self.assertEqual(r["pocketed"].shape, (n, b))
        self.assertEqual(r["pocketed"].dtype, np.bool_)
        self.assertEqual(r["final_position"].shape, (n, b, 2))
        self.assertEqual(r["first_contact"].shape, (n,))
        self.assertFalse(r["final_position"].flags.writeable)
        self.assertTrue((r["events"] > 0).all())
        # A pocketed ball has its pocket's index, the others -1.
        self.assertTrue(((r["pocket"] >= 0) == r["pocketed"]).all())

    def test_same_arrays_whatever_the_threads(self) -> None:
        one = cueball.simulate_many(None, self.actions, threads=1, seed=5, noise=True)
        two = cueball.simulate_many(None, self.actions, threads=2, seed=5, noise=True)
        for key, value in one.items():
            if isinstance(value, np.ndarray):
                np.testing.assert_array_equal(value, two[key], err_msg=key)

    def test_each_shot_is_the_single_run_of_its_action(self) -> None:
        with open(CUT) as f:
            scenario = json.load(f)
        actions = self.actions[:8]
        r = cueball.simulate_many(scenario, actions)
        ids = list(r["ids"])
        for k, (speed, aim, elevation, side, height) in enumerate(actions):
            single = dict(scenario)
            single["cue"] = {"ball": scenario["cue"]["ball"], "speed": speed, "aim_deg": aim,
                             "elevation_deg": elevation, "side": side, "height": height}
            single_result = cueball.simulate(single)
            pocketed = single_result.balls["pocketed"]
            np.testing.assert_array_equal(r["pocketed"][k], pocketed)
            np.testing.assert_array_equal(r["final_position"][k][~pocketed], single_result.balls["position"][~pocketed])
            self.assertEqual(ids, list(single_result.balls["id"]))

    def test_layouts_move_the_balls(self) -> None:
        with open(CUT) as f:
            scenario = json.load(f)
        base = np.array([b["position"] for b in scenario["balls"]], dtype=float)
        layouts = np.repeat(base[None], 2, axis=0)
        layouts[1, -1] += (0.1, 0.0)  # the last ball 10 cm along x
        slow = np.array([[0.0001 + 0.01, 90.0, 0, 0, 0]] * 2)  # a tap: nothing reaches the last ball
        r = cueball.simulate_many(scenario, slow, layouts)
        np.testing.assert_allclose(r["final_position"][1, -1], layouts[1, -1])
        np.testing.assert_allclose(r["final_position"][0, -1], layouts[0, -1])

    def test_bad_input_names_the_field(self) -> None:
        for actions, field in [(np.zeros((3, 4)), "actions"), ([[0.0, 0, 0, 0, 0]], "actions[0].speed"),
                               ([[1.0, 0, 0, 0.9, 0]], "actions[0].side"), ("text", "actions")]:
            with self.assertRaises(cueball.InvalidArgument) as e:
                cueball.simulate_many(None, actions)
            self.assertTrue(e.exception.field.startswith(field), (field, e.exception.field, str(e.exception)))
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.simulate_many(None, self.actions[:1], threads=0)
        self.assertEqual(e.exception.field, "threads")
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.simulate_many(None, self.actions[:1], np.zeros((1, 3, 2)))
        self.assertTrue(e.exception.field.startswith("layouts"), e.exception.field)


if __name__ == "__main__":
    unittest.main()
