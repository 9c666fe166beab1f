"""cueball.calibrate (python/src/calibration.cpp): the report dict, errors naming the JSON
path, and the recorded match from ../shared when the checkout has it beside it."""
import json
import pathlib
import unittest

import cueball

SHARED = pathlib.Path(__file__).resolve().parents[2].parent / "shared" / "data" / "measured-three-cushion" / "shots.json"


def straight_shot() -> dict:
    # The white rolls along +x from (0.7, 0.71) and stops near x = 1.9; the red stays.
    t = [0.0] + [0.01 + 0.02 * k for k in range(60)] + [3.0]
    x, v = [0.7], 2.0
    pos = 0.7
    for k in range(60):
        pos += v * 0.02
        v = max(v - 0.06, 0.0)
        x.append(pos)
    x.append(pos)
    return {
        "table": "carom_10ft",
        "shots": [
            {
                "shot_id": 1,
                "cue_ball": "white",
                "balls": {
                    "white": {"t": t, "x": x, "y": [0.71] * len(t)},
                    "red": {"t": [0.0, 3.0], "x": [2.5, 2.5], "y": [1.1, 1.1]},
                },
            }
        ],
    }


class CalibrateTest(unittest.TestCase):
    def test_evaluate_returns_the_report(self) -> None:
        r = cueball.calibrate(json.dumps(straight_shot()), constants='{"table": "carom_10ft"}', evaluate=True)
        self.assertEqual(set(r), {"table", "constants", "start_constants", "summary", "constant_evaluations",
                                  "constant_iterations", "constant_restarts", "uncertainty", "seconds", "shots"})
        self.assertEqual(r["uncertainty"], {"method": "none", "replicates": 0, "constants": {}})
        self.assertEqual(r["summary"]["training"]["shots"], 1)
        shot = r["shots"][0]
        self.assertEqual(shot["id"], "1")
        self.assertLess(shot["cue_rmse"], 0.05)
        self.assertAlmostEqual(shot["strike"]["aim_deg"], 0.0, delta=1.0)
        self.assertFalse(shot["balls"]["red"]["moved_simulated"])
        self.assertEqual(r["constants"]["ball_collision"]["model"], "coulomb_impulse")

    def test_the_ball_collision_model_is_chosen(self) -> None:
        r = cueball.calibrate(json.dumps(straight_shot()), constants='{"table": "carom_10ft"}', evaluate=True,
                              ball_collision_model="mathavan_2014")
        self.assertEqual(r["constants"]["ball_collision"]["model"], "mathavan_2014")
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.calibrate(json.dumps(straight_shot()), ball_collision_model="glue")
        self.assertIn("ball_collision_model", str(e.exception))

    def test_bootstrap_and_html(self) -> None:
        doc = straight_shot()
        doc["shots"].append(json.loads(json.dumps(doc["shots"][0])))
        doc["shots"][1]["shot_id"] = 2
        r = cueball.calibrate(json.dumps(doc), held_out=0.0, max_evaluations=4, max_iterations=0, restarts=0,
                              starts=2, bootstrap=2, html=True)
        self.assertEqual(r["uncertainty"]["replicates"], 2)
        mu_r = r["uncertainty"]["constants"]["mu_r"]
        self.assertLessEqual(mu_r["p05"], mu_r["p95"])
        self.assertGreaterEqual(mu_r["std_dev"], 0.0)
        self.assertTrue(r["html"].startswith("<!DOCTYPE html>"))
        self.assertEqual(r["html"].count("<figure"), 2)
        self.assertNotIn("<script", r["html"])
        with self.assertRaises(cueball.InvalidArgument):
            cueball.calibrate(json.dumps(doc), bootstrap=-1)
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.calibrate(json.dumps(doc), spin_profile=17)
        self.assertIn("spin_profile", str(e.exception))

    def test_errors_name_the_json_path(self) -> None:
        doc = straight_shot()
        doc["shots"][0]["balls"]["red"]["x"][1] = 9.0
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.calibrate(json.dumps(doc))
        self.assertIn("shots[0].balls.red.x[1] = 9", str(e.exception))
        with self.assertRaises(cueball.InvalidArgument):
            cueball.calibrate(json.dumps(straight_shot()), held_out=0.95)
        with self.assertRaises(cueball.InvalidArgument):
            cueball.calibrate(json.dumps(straight_shot()), evaluate=True)

    @unittest.skipUnless(SHARED.exists(), "../shared/data/measured-three-cushion/shots.json is not here")
    def test_the_recorded_match(self) -> None:
        doc = json.loads(SHARED.read_text())
        doc["shots"] = doc["shots"][:3]
        r = cueball.calibrate(json.dumps(doc), constants='{"table": "carom_10ft"}', evaluate=True)
        self.assertEqual(r["summary"]["training"]["shots"], 3)
        # Default constants: the cue ball within a few decimetres (README: 11-19 cm medians).
        self.assertLess(r["summary"]["training"]["cue_rmse_median"], 0.4)


if __name__ == "__main__":
    unittest.main()
