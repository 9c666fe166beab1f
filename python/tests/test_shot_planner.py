"""plan_shot from Python: the CLI's plan, the Scenario that replays it, errors."""

import json
import os
import pathlib
import subprocess
import unittest

import numpy as np

import cueball

DOCS = pathlib.Path(__file__).resolve().parents[2] / "docs"
CUT = DOCS / "example-cut-shot.json"
BLOCKED = DOCS / "example-blocked.json"


def without_python_only(plan: dict) -> dict:
    """The plan without its timing and without the Scenario objects that only Python has."""
    plan = {k: v for k, v in plan.items() if k not in ("seconds", "scenario")}
    plan["alternatives"] = [{k: v for k, v in a.items() if k != "scenario"} for a in plan["alternatives"]]
    return plan


class PlanShotTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        cls.plan = cueball.plan_shot(CUT, 9, simulations=1500, seed=2)

    def test_the_plan_pots_when_replayed(self) -> None:
        p = self.plan
        self.assertEqual((p["kind"], p["pocket"]), ("direct", "top-left"))
        self.assertIsInstance(p["scenario"], cueball.Scenario)
        r = cueball.simulate(p["scenario"])
        nine = list(r.balls["id"]).index(9)
        self.assertTrue(r.balls["pocketed"][nine])
        self.assertEqual(r.pocket_names[r.balls["pocket"][nine]], "top-left")
        self.assertFalse(r.balls["pocketed"][list(r.balls["id"]).index(0)])  # no scratch
        # The cue in the scenario's units is the scenario's cue.
        cue = p["scenario"].to_dict()["cue"]
        for key in ("speed", "aim_deg", "elevation_deg", "side", "height", "mass", "tip_restitution", "end_mass"):
            self.assertEqual(cue[key], p["cue"][key], key)
        lo, hi = p["aim_window_deg"]
        self.assertLess(lo, p["cue"]["aim_deg"])
        self.assertLess(p["cue"]["aim_deg"], hi)
        self.assertLessEqual(p["simulations"], 1500)
        self.assertAlmostEqual(p["success_standard_error"],
                               np.sqrt(p["success_probability"] * (1 - p["success_probability"]) / p["noisy_shots"]))

    def test_the_same_plan_as_the_cli(self) -> None:
        binary = os.environ.get("CUEBALL_BIN")
        if not binary:
            self.skipTest("CUEBALL_BIN not set")
        out = subprocess.run([binary, "plan-shot", str(CUT), "--ball", "9", "--simulations", "1500", "--seed", "2",
                              "--json"], check=True, capture_output=True, text=True).stdout
        cli = json.loads(out)
        # One writer (io/plan_json.hpp): the same keys and values, in the same types, but for
        # the timing and the Scenario objects Python adds.
        self.assertEqual(json.dumps(without_python_only(self.plan)), json.dumps(without_python_only(cli)))
        self.assertEqual(self.plan["aim_window_deg"], cli["aim_window_deg"])
        self.assertNotIn("combination_cut_deg", self.plan)  # a combination's only, as in the CLI
        self.assertNotIn("cushion", self.plan)  # a bank's or kick's only

    def test_deterministic_for_a_seed(self) -> None:
        again = cueball.plan_shot(CUT, 9, simulations=1500, seed=2)
        self.assertEqual(again["cue"], self.plan["cue"])
        self.assertEqual(again["success_probability"], self.plan["success_probability"])

    def test_a_bank_when_every_direct_line_is_blocked(self) -> None:
        with self.assertRaises(cueball.NoFeasibleShot) as e:
            cueball.plan_shot(BLOCKED, 1, kinds=["direct"], simulations=500)
        self.assertIn("blocked", str(e.exception))
        bank = cueball.plan_shot(BLOCKED, 1, simulations=1000)
        self.assertEqual(bank["kind"], "bank")
        self.assertIsInstance(bank["cushion"], str)
        r = cueball.simulate(bank["scenario"])
        self.assertTrue(r.balls["pocketed"][list(r.balls["id"]).index(1)])

    def test_a_kick_when_every_straight_path_of_the_cue_ball_is_blocked(self) -> None:
        walled = {"table": "pool_9ft", "balls": [
            {"id": 0, "position": [1.0, 0.4]}, {"id": 1, "position": [1.9, 0.9]},
            {"id": 2, "position": [1.479139, 0.597551]}, {"id": 3, "position": [1.45, 0.65]},
            {"id": 4, "position": [1.420861, 0.702449]}]}
        with self.assertRaises(cueball.NoFeasibleShot):
            cueball.plan_shot(walled, 1, simulations=500)
        kick = cueball.plan_shot(walled, 1, kinds=["kick"], simulations=1000)
        self.assertEqual(kick["kind"], "kick")
        self.assertEqual(len(kick["cushions"]), 1)
        self.assertEqual(kick["cushion"], kick["cushions"][0])
        self.assertIsNone(kick["intermediate_ball"])
        r = cueball.simulate(kick["scenario"])
        ids = list(r.balls["id"])
        self.assertTrue(r.balls["pocketed"][ids.index(1)])
        self.assertFalse(r.balls["pocketed"][ids.index(0)])
        via = cueball.plan_shot(walled, 1, kinds=["combination"], simulations=1000)["intermediate_ball"]
        through = cueball.plan_shot(walled, 1, kinds=["combination"], ball_on=via, simulations=1000)
        self.assertEqual(through["intermediate_ball"], via)
        self.assertTrue(all(a["intermediate_ball"] == via for a in through["alternatives"]))
        with self.assertRaises(cueball.NoFeasibleShot):
            cueball.plan_shot(walled, 1, kinds=["combination"], ball_on=1, simulations=500)
        with self.assertRaises(ValueError) as e:
            cueball.plan_shot(walled, 1, ball_on=42)
        self.assertIn("ball_on = 42", str(e.exception))
        with self.assertRaises(ValueError) as e:
            cueball.plan_shot(walled, 1, kinds=["kick", "jump"])
        self.assertIn("kinds", str(e.exception))
        self.assertIn("'combination'", str(e.exception))

    def test_a_called_pocket_counts_a_pot_only_in_the_shots_own_pocket(self) -> None:
        # The C++ test's layout (ACallShotCountsAPotOnlyInTheShotsOwnPocket), where the noise sends the 1
        # into two pockets: the same strike, estimated on the same draws, lower with the call.
        places = [(0, 0.9637952625759938, 0.2051678989520107), (1, 1.9107061147082365, 0.4468972208536196),
                  (2, 0.47856410301977315, 0.8823697581870137), (3, 0.4788933752081283, 0.45139904709695194),
                  (4, 2.339371941354914, 0.09099373819723446)]
        layout = cueball.Scenario.from_json(json.dumps(
            {"table": "pool_9ft", "balls": [{"id": i, "position": [x, y]} for i, x, y in places]}))
        plans = {p: cueball.plan_shot(layout, 1, pocket=p, seed=17, simulations=1000) for p in ("any", "called")}
        self.assertEqual(plans["any"]["cue"], plans["called"]["cue"])
        self.assertLess(plans["called"]["success_probability"], plans["any"]["success_probability"])

    def test_bad_input_names_the_field(self) -> None:
        for kwargs, field in (({"simulations": 10}, "simulations"), ({"noise": "loud"}, "noise"),
                              ({"kinds": ["masse"]}, "kinds"), ({"kinds": []}, "kinds"),
                              ({"pocket": "nowhere"}, "pocket")):
            with self.subTest(field=field), self.assertRaises(cueball.InvalidArgument) as e:
                cueball.plan_shot(CUT, 9, **kwargs)
            self.assertEqual(e.exception.field, field)
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.plan_shot(CUT, 42)
        self.assertEqual(e.exception.field, "target")
        for kwargs, field in (({"targets": [1, 42]}, "targets"), ({"targets": [0, 1]}, "targets"),
                              ({"targets": [9, 9]}, "targets"), ({"targets": []}, "targets"),
                              ({"target": 1, "targets": [9]}, "targets"), ({}, "target")):
            with self.subTest(kwargs=kwargs), self.assertRaises(cueball.InvalidArgument) as e:
                cueball.plan_shot(CUT, **kwargs)
            self.assertEqual(e.exception.field, field)
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.plan_shot(CUT, targets=[1, 42])
        self.assertIn("targets[1] = 42 is not the id of a ball on the table", str(e.exception))

    def test_targets_pots_the_only_pottable_legal_target(self) -> None:
        # With direct shots only, of the 1, 3 and 4 of the blocked example only the 3 pots.
        with self.assertRaises(cueball.NoFeasibleShot):
            cueball.plan_shot(BLOCKED, targets=[1, 4], kinds=["direct"], simulations=1000)
        plan = cueball.plan_shot(BLOCKED, targets=[1, 3, 4], kinds=["direct"], simulations=1000)
        self.assertEqual(plan["target"], 3)
        r = cueball.simulate(plan["scenario"])
        three = list(r.balls["id"]).index(3)
        self.assertTrue(r.balls["pocketed"][three])
        # One target is the plan of that target.
        alone = cueball.plan_shot(BLOCKED, 3, kinds=["direct"], simulations=1000)
        self.assertEqual(alone["cue"], plan["cue"])
        self.assertEqual(alone["target"], 3)

    def test_noise_as_a_dict_of_sigmas(self) -> None:
        # The scenario's "noise" keys and units; missing keys are 0.
        none = cueball.plan_shot(CUT, 9, noise="none", simulations=1000)
        self.assertEqual(none["success_probability"], 1.0)
        self.assertEqual(cueball.plan_shot(CUT, 9, noise={}, simulations=1000)["success_probability"], 1.0)
        wide = cueball.plan_shot(CUT, 9, noise={"aim_deg": 2.0}, simulations=1000)
        self.assertLess(wide["success_probability"], 0.6)
        self.assertEqual(wide["scenario"].noise["aim_deg"], 2.0)
        self.assertEqual(wide["scenario"].noise["speed"], 0.0)
        # NumPy numbers are numbers.
        same = cueball.plan_shot(CUT, 9, noise={"aim_deg": np.float64(2.0)}, simulations=1000)
        self.assertEqual(same["success_probability"], wide["success_probability"])

    def test_noise_dict_is_the_clis_sigma_flags(self) -> None:
        binary = os.environ.get("CUEBALL_BIN")
        if not binary:
            self.skipTest("CUEBALL_BIN not set")
        sigmas = {"speed": 0.05, "aim_deg": 0.3, "elevation_deg": 0.2, "side": 0.02, "height": 0.03}
        plan = cueball.plan_shot(CUT, 9, noise=sigmas, simulations=1000, seed=4)
        out = subprocess.run([binary, "plan-shot", str(CUT), "--ball", "9", "--simulations", "1000", "--seed", "4",
                              "--noise", "none", "--sigma-speed", "0.05", "--sigma-aim", "0.3",
                              "--sigma-elevation", "0.2", "--sigma-side", "0.02", "--sigma-height", "0.03", "--json"],
                             check=True, capture_output=True, text=True).stdout
        cli = json.loads(out)
        for key in ("success_probability", "noisy_shots", "cue"):
            self.assertEqual(cli[key], plan[key], key)
        self.assertLess(plan["success_probability"], 1.0)

    def test_elevation_noise_at_a_level_cue_keeps_the_sample(self) -> None:
        # From here the level cue reaches no rail (test_cli_plan_shot_html.cpp's layout); elevation
        # noise around 0 is reflected at the limit, so the pot stays near sure.
        layout = {"table": "pool_9ft", "balls": [{"id": 0, "position": [1.55, 0.70]},
                                                 {"id": 1, "position": [2.214, 0.944]},
                                                 {"id": 9, "position": [0.8, 1.0]}]}
        plan = cueball.plan_shot(layout, 1, noise={"elevation_deg": 1.0}, simulations=1000)
        self.assertEqual(plan["cue"]["elevation_deg"], 0.0)
        self.assertGreater(plan["success_probability"], 0.95)

    def test_bad_noise_names_the_key(self) -> None:
        for noise, field in (({"aim_deg": 50}, "noise.aim_deg"), ({"loud": 1}, "noise.loud"),
                             ({"speed": -0.1}, "noise.speed"), ({"side": float("nan")}, "noise.side")):
            with self.subTest(noise=noise), self.assertRaises(cueball.InvalidArgument) as e:
                cueball.plan_shot(CUT, 9, noise=noise)
            self.assertEqual(e.exception.field, field)
        with self.assertRaises(TypeError):
            cueball.plan_shot(CUT, 9, noise=3)


if __name__ == "__main__":
    unittest.main()
