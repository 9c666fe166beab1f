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
        for key in ("speed", "aim_deg", "elevation_deg", "side", "height", "mass", "tip_restitution"):
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
        for key in ("kind", "pocket", "success_probability", "noisy_shots", "cue", "simulations"):
            self.assertEqual(cli[key], self.plan[key], key)
        self.assertEqual(tuple(cli["aim_window_deg"]), self.plan["aim_window_deg"])

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
        with self.assertRaises(ValueError) as e:
            cueball.plan_shot(walled, 1, kinds=["kick", "jump"])
        self.assertIn("kinds", str(e.exception))
        self.assertIn("'combination'", str(e.exception))

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


if __name__ == "__main__":
    unittest.main()
