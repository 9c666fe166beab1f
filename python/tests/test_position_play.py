"""plan_shot(position=True) and plan_shot(in_hand=True) from Python: each shot's leave, the choice by
score, the placed cue ball, the CLI's plan, errors."""

import json
import os
import pathlib
import subprocess
import tempfile
import unittest

import cueball

CUT = pathlib.Path(__file__).resolve().parents[2] / "docs" / "example-cut-shot.json"


def without_python_only(plan: dict) -> dict:
    """The plan without its timing and without the Scenario objects that only Python has."""
    plan = {k: v for k, v in plan.items() if k not in ("seconds", "scenario")}
    plan["alternatives"] = [{k: v for k, v in a.items() if k != "scenario"} for a in plan["alternatives"]]
    return plan


class PositionPlayTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls) -> None:
        # Pot the 1 with the 9 next (the lowest id left after the 1).
        cls.plan = cueball.plan_shot(CUT, 1, simulations=1000, position=True)

    def test_every_shot_has_its_leave_and_the_best_score_is_played(self) -> None:
        p = self.plan["position"]
        self.assertEqual(p["next"], 9)
        # scored over the noisy successes' leaves (the mean next window there)
        self.assertGreater(p["noisy_leaves"], 0)
        self.assertLessEqual(p["noisy_leaves"], 4)
        self.assertEqual(p["score"], p["screened_probability"] * p["noisy_next_window"])
        cue_end = [b["position"] for b in self.plan["predicted"] if b["id"] == 0][0]
        self.assertEqual(tuple(p["cue_ball"]), tuple(cue_end))
        for alt in self.plan["alternatives"]:
            self.assertLessEqual(alt["position"]["score"], p["score"])
        # The leave's next probability is that of a plan of the 9 on the table the shot leaves.
        r = cueball.simulate(self.plan["scenario"])
        ids = list(r.balls["id"])
        left = {"table": "pool_9ft", "balls": [
            {"id": int(i), "position": [float(x), float(y)]}
            for i, (x, y), down in zip(ids, r.balls["position"], r.balls["pocketed"]) if not down]}
        if p["next_feasible"]:
            nxt = cueball.plan_shot(left, 9, cue_ball=0, simulations=500)
            self.assertEqual(nxt["success_probability"], p["next_success_probability"])

    def test_next_targets_given_explicitly(self) -> None:
        # 9-ball's next targets given by the rule: the same plan as the default.
        given = cueball.plan_shot(CUT, 1, simulations=1000, position=True, next_targets=[[9]])
        self.assertEqual(given["cue"], self.plan["cue"])
        self.assertEqual(given["position"], self.plan["position"])
        self.assertEqual(given["position"]["next_ball"], 9 if given["position"]["next_feasible"] else None)
        for next_targets in ([[42]], [[]], [[0]]):
            with self.subTest(next_targets=next_targets), self.assertRaises(cueball.InvalidArgument) as e:
                cueball.plan_shot(CUT, 1, simulations=1000, position=True, next_targets=next_targets)
            self.assertEqual(e.exception.field, "next_targets")
        with self.assertRaises(cueball.InvalidArgument) as e:
            cueball.plan_shot(CUT, 1, next_targets=[[9]])
        self.assertEqual(e.exception.field, "next_targets")

    def test_the_same_plan_as_the_cli(self) -> None:
        binary = os.environ.get("CUEBALL_BIN")
        if not binary:
            self.skipTest("CUEBALL_BIN not set")
        out = subprocess.run([binary, "plan-shot", str(CUT), "--ball", "1", "--simulations", "1000", "--position",
                              "--json"], check=True, capture_output=True, text=True).stdout
        cli = json.loads(out)
        for key in ("kind", "pocket", "success_probability", "cue"):
            self.assertEqual(cli[key], self.plan[key], key)
        self.assertEqual(cli["position"]["score"], self.plan["position"]["score"])
        # One writer (io/plan_json.hpp): every key and value, the leaves too, but the timing and
        # the Scenario objects only Python has.
        self.assertEqual(json.dumps(without_python_only(self.plan)), json.dumps(without_python_only(cli)))

    def test_in_hand_takes_a_region_by_name_as_the_cli_does(self) -> None:
        plan = cueball.plan_shot(CUT, 1, simulations=1000, in_hand=True, region="kitchen")
        x, _ = plan["in_hand"]["cue_ball"]
        self.assertLessEqual(x, 2.54 / 4 + 1e-9)  # behind the head string of the 9-ft table
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.plan_shot(CUT, 1, in_hand=True, region="nowhere")
        self.assertEqual(caught.exception.field, "region")
        self.assertIn("kitchen", str(caught.exception))
        binary = os.environ.get("CUEBALL_BIN")
        if binary:
            out = subprocess.run([binary, "plan-shot", str(CUT), "--ball", "1", "--simulations", "1000", "--in-hand",
                                  "--region", "kitchen", "--json"], check=True, capture_output=True, text=True).stdout
            self.assertEqual(json.loads(out)["in_hand"]["cue_ball"], list(plan["in_hand"]["cue_ball"]))

    def test_in_hand_places_the_cue_ball_inside_the_region_and_the_scenario_replays_from_there(self) -> None:
        plan = cueball.plan_shot(CUT, 1, simulations=1000, in_hand=True, region=(0.0, 1.27, 0.0, 1.27))
        x, y = plan["in_hand"]["cue_ball"]
        self.assertLessEqual(x, 1.27)
        self.assertGreaterEqual(plan["in_hand"]["spots_played"], 1)
        self.assertIn("position", plan)  # in_hand plays for position
        r = cueball.simulate(plan["scenario"])
        ids = list(r.balls["id"])
        cue = [b for b in plan["scenario"].balls if b.id == 0][0]
        self.assertEqual(tuple(cue.state.position), (x, y))
        self.assertTrue(r.balls["pocketed"][ids.index(1)])  # the planned shot pots the 1 from the spot
        binary = os.environ.get("CUEBALL_BIN")
        if binary:
            out = subprocess.run([binary, "plan-shot", str(CUT), "--ball", "1", "--simulations", "1000", "--in-hand",
                                  "--region", "0,1.27,0,1.27", "--json"], check=True, capture_output=True,
                                 text=True).stdout
            cli = json.loads(out)
            self.assertEqual(tuple(cli["in_hand"]["cue_ball"]), (x, y))
            self.assertEqual(cli["cue"], plan["cue"])
            self.assertEqual(json.dumps(without_python_only(plan)), json.dumps(without_python_only(cli)))

    def test_a_ghost_ball_valuation_is_the_clis_plan_with_fewer_runs(self) -> None:
        quick = cueball.plan_shot(CUT, 1, simulations=1000, position=True, valuation="ghost_ball")
        self.assertLess(quick["simulations"], self.plan["simulations"])
        self.assertIn(quick["position"]["next_kind"], ("direct", ""))  # the next shot: a straight pot or none
        binary = os.environ.get("CUEBALL_BIN")
        if binary:
            out = subprocess.run([binary, "plan-shot", str(CUT), "--ball", "1", "--simulations", "1000", "--position",
                                  "--valuation", "ghost_ball", "--json"], check=True, capture_output=True,
                                 text=True).stdout
            self.assertEqual(json.dumps(without_python_only(quick)), json.dumps(without_python_only(json.loads(out))))

    def test_a_game_ball_values_the_leave_by_its_combination_as_the_cli_does(self) -> None:
        # The 2 behind the 9 on the bottom-left corner's diagonal: the leave's next shot is the 9 through the 2.
        scenario = {"table": "pool_9ft", "balls": [{"id": 0, "position": [1.35, 0.75]}, {"id": 1, "position": [1.85, 0.45]},
                                                   {"id": 2, "position": [0.5, 0.5]}, {"id": 9, "position": [0.4, 0.4]}]}
        plan = cueball.plan_shot(scenario, 1, simulations=1000, position=True, valuation="ghost_ball", game_ball=9)
        plain = cueball.plan_shot(scenario, 1, simulations=1000, position=True, valuation="ghost_ball")
        self.assertEqual(plan["position"]["next_kind"], "combination")
        self.assertEqual(plan["position"]["next_ball"], 9)
        self.assertGreaterEqual(plan["position"]["score"], plain["position"]["score"])
        binary = os.environ.get("CUEBALL_BIN")
        if binary:
            with tempfile.TemporaryDirectory() as d:
                path = pathlib.Path(d) / "nine.json"
                path.write_text(json.dumps(scenario))
                out = subprocess.run([binary, "plan-shot", str(path), "--ball", "1", "--simulations", "1000", "--position",
                                      "--valuation", "ghost_ball", "--game-ball", "9", "--json"], check=True,
                                     capture_output=True, text=True).stdout
            self.assertEqual(json.dumps(without_python_only(plan)), json.dumps(without_python_only(json.loads(out))))
        with self.assertRaises(ValueError) as e:
            cueball.plan_shot(scenario, 1, simulations=1000, position=True, game_ball=9)  # windows
        self.assertIn("game_ball", str(e.exception))
        with self.assertRaises(ValueError) as e:
            cueball.plan_shot(scenario, 1, simulations=1000, valuation="ghost_ball", game_ball=9)  # no position play
        self.assertIn("game_ball", str(e.exception))
        with self.assertRaises(ValueError) as e:
            cueball.plan_shot(scenario, 1, simulations=1000, position=True, valuation="ghost_ball", game_ball=7)
        self.assertIn("game_ball", str(e.exception))

    def test_bad_input_names_the_argument(self) -> None:
        for kwargs, field in (({"position": True, "next": 7}, "next"),
                              ({"position": True, "valuation": "geometry"}, "valuation"),
                              ({"valuation": "ghost_ball"}, "valuation"),
                              ({"position": True, "next": 1}, "next"),
                              ({"next": 9}, "next"),
                              ({"position": True, "next_simulations": 10}, "next_simulations"),
                              ({"region": (0.0, 1.0, 0.0, 1.0)}, "region"),
                              ({"in_hand": True, "region": (1.0, 0.0, 0.0, 1.0)}, "region")):
            with self.assertRaises(ValueError) as e:
                cueball.plan_shot(CUT, 1, simulations=1000, **kwargs)
            self.assertIn(field, str(e.exception))


if __name__ == "__main__":
    unittest.main()
