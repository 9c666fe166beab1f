"""simulate_many: N different shots in one call, outcomes as NumPy arrays."""

import json
import pathlib
import unittest
import warnings

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

    def test_a_tip_offset_beyond_the_miscue_limit_is_that_shots_outcome(self) -> None:
        actions = self.actions[:6].copy()
        actions[2, 3:] = (0.4, 0.4)  # 0.57 ball radii: the tip slips
        r = cueball.simulate_many(None, actions)
        np.testing.assert_array_equal(r["miscue"], [False, False, True, False, False, False])
        self.assertTrue(np.isnan(r["final_position"][2]).all())
        self.assertEqual(r["events"][2], 0)
        self.assertTrue(r["present"][2].all())  # the balls are still on the table
        # The other rows are what they are without the miscue beside them.
        alone = cueball.simulate_many(None, np.delete(actions, 2, axis=0))
        np.testing.assert_array_equal(np.delete(r["final_position"], 2, axis=0), alone["final_position"])

    def test_absent_balls_are_not_on_the_table(self) -> None:
        n = len(self.actions)
        present = np.random.default_rng(5).random((n, 10)) > 0.4
        present[:, 0] = True  # the cue ball
        rack = [b["position"] for b in cueball.simulate(None).to_dict()["scenario"]["balls"]]
        layouts = np.repeat(np.array([rack], dtype=float), n, axis=0)
        layouts[~present] = np.nan  # an absent ball's position is ignored
        one = cueball.simulate_many(None, self.actions, layouts, present=present, seed=2, noise=True)
        two = cueball.simulate_many(None, self.actions, layouts, present=present, seed=2, noise=True, threads=2)
        for key, value in one.items():
            if isinstance(value, np.ndarray):
                np.testing.assert_array_equal(value, two[key], err_msg=key)
        np.testing.assert_array_equal(one["present"], present)
        self.assertFalse(one["pocketed"][~present].any())
        self.assertTrue((one["pocket"][~present] == -1).all())
        self.assertTrue(np.isnan(one["final_position"][~present]).all())
        self.assertTrue((one["cushions"][~present] == 0).all())
        # No ball the cue ball touches first is absent.
        for k in range(n):
            if one["first_contact"][k] >= 0:
                self.assertTrue(present[k, list(one["ids"]).index(one["first_contact"][k])], k)

    def test_a_shot_played_from_the_last_ones_end(self) -> None:
        # What an RL loop does: the next layout is the last shot's final positions, its pocketed balls absent.
        first = cueball.simulate_many(None, np.array([[8.0, 0.0, 0.0, 0.0, 0.0]]))
        present = first["present"] & ~first["pocketed"]
        self.assertTrue(present[0, 0], "the break scratched: pick another action")
        layouts = np.where(present[..., None], first["final_position"], np.nan)
        second = cueball.simulate_many(None, np.array([[1.0, 45.0, 0.0, 0.0, 0.0]]), layouts, present=present)
        np.testing.assert_array_equal(second["present"], present)
        self.assertFalse(second["failure"][0])

    def test_bad_masks_name_the_field(self) -> None:
        actions = self.actions[:3]
        for present, field in [(np.ones((3, 10)), "present"), (np.ones((2, 10), dtype=bool), "present"),
                               (np.ones((3, 9), dtype=bool), "present")]:
            with self.assertRaises(cueball.InvalidArgument) as e:
                cueball.simulate_many(None, actions, present=present)
            self.assertEqual(e.exception.field, field, str(e.exception))
        no_cue = np.ones((3, 10), dtype=bool)
        no_cue[1, 0] = False
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.simulate_many(None, actions, present=no_cue, first_shot=40)
        self.assertEqual(e.exception.field, "present[41][0]")

    def test_noise_arguments(self) -> None:
        actions = np.repeat(self.actions[:1], 30, axis=0)
        plain = cueball.simulate_many(None, actions)
        none = cueball.simulate_many(None, actions, noise="none", seed=4)
        np.testing.assert_array_equal(plain["final_position"], none["final_position"])
        tournament = cueball.simulate_many(None, actions, noise="tournament", seed=4)
        self.assertGreater(np.nanstd(tournament["final_position"][:, 0, 0]), 0.0)
        sigmas = cueball.simulate_many(None, actions, noise={"aim_deg": 0.5}, seed=4)
        self.assertGreater(np.nanstd(sigmas["final_position"][:, 0, 0]), 0.0)
        with open(CUT) as f:
            quiet = json.load(f)
        quiet.pop("noise", None)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            cueball.simulate_many(quiet, actions[:2], noise=True)
        self.assertEqual(len(caught), 1)
        self.assertIn("no execution noise", str(caught[0].message))
        self.assertEqual(caught[0].filename, __file__)  # the caller's line
        for noise, field in [("loud", "noise"), ({"aim_deg": -1.0}, "noise.aim_deg"), (3, "noise")]:
            with self.assertRaises(cueball.InvalidArgument) as e:
                cueball.simulate_many(None, actions[:1], noise=noise)
            self.assertEqual(e.exception.field, field, str(e.exception))


class SimulateBatchNoiseTest(unittest.TestCase):
    def setUp(self) -> None:
        with open(CUT) as f:
            self.quiet = json.load(f)
        self.quiet.pop("noise", None)

    def test_the_scenarios_noise_when_it_is_zero_warns(self) -> None:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            r = cueball.simulate_batch(self.quiet, shots=20)
        self.assertEqual(len(caught), 1)
        self.assertTrue(issubclass(caught[0].category, UserWarning))
        self.assertEqual(r["balls"][0]["position_std"], [0.0, 0.0])  # what it warned of
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # identical shots asked for: no warning
            cueball.simulate_batch(self.quiet, shots=5, noise="none")

    def test_named_and_given_noise(self) -> None:
        tournament = cueball.simulate_batch(self.quiet, shots=60, noise="tournament", seed=3)
        self.assertGreater(tournament["balls"][0]["position_std"][0], 0.0)
        # A dict is read as the scenario's "noise" would be: the same shots as a scenario with it.
        sigmas = {"speed": 0.05, "side": 0.1}
        given = cueball.simulate_batch(self.quiet, shots=60, noise=sigmas, seed=3)
        self.assertGreater(given["balls"][0]["position_std"][0], 0.0)
        self.assertNotEqual(given["balls"], tournament["balls"])
        self.assertEqual(given["balls"], cueball.simulate_batch(dict(self.quiet, noise=sigmas), shots=60, seed=3)["balls"])
        # The scenario's own noise, by default or by name: the same shots.
        with open(CUT) as f:
            noisy = json.load(f)
        self.assertEqual(cueball.simulate_batch(noisy, shots=30, seed=1)["balls"],
                         cueball.simulate_batch(noisy, shots=30, seed=1, noise="scenario")["balls"])
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.simulate_batch(self.quiet, shots=5, noise={"aim": 1.0})
        self.assertTrue(e.exception.field.startswith("noise"), e.exception.field)


if __name__ == "__main__":
    unittest.main()
