"""Tests of cueball.Result (simulate()'s NumPy arrays) and of NumPy input.

Every array is held to the documented JSON form (to_dict(), the library's
result_to_json), and to_json() to the CLI's bytes; NumPy scalars and arrays
give the results plain Python numbers give.
"""

import json
import math
import os
import pathlib
import subprocess
import unittest

import numpy as np

import cueball

REPO = pathlib.Path(__file__).resolve().parents[2]
CLI = os.environ.get("CUEBALL_BIN")
CUT_SHOT = REPO / "docs" / "example-cut-shot.json"

TWO_BALLS = {
    "table": "pool_9ft",
    "balls": [{"id": 0, "position": [0.6, 0.6]}, {"id": 1, "position": [1.1, 0.7]}],
    "cue": {"ball": 0, "target": 1, "speed": 3.0, "side": 0.25},
}


def numpy_two_balls():
    """TWO_BALLS with NumPy scalars and arrays for every number and vector."""
    return {
        "table": "pool_9ft",
        "balls": [
            {"id": np.int64(0), "position": np.array([0.6, 0.6])},
            {"id": np.int32(1), "position": (np.float64(1.1), np.float64(0.7))},
        ],
        "cue": {"ball": np.int64(0), "target": np.int16(1), "speed": np.float32(3.0), "side": np.float32(0.25)},
    }


class ResultTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.result = cueball.simulate()  # the built-in break: 10 balls, pockets, cushions, jaws
        cls.json = cls.result.to_dict(sample_rate=20.0)
        cls.cut = cueball.simulate(CUT_SHOT)  # pockets the 1 ball

    @unittest.skipUnless(CLI, "CUEBALL_BIN is not set")
    def test_to_json_is_the_clis_output(self):
        for args, mine in [
            ([], self.result.to_json()),
            ([str(CUT_SHOT), "--sample", "30"], self.cut.to_json(sample_rate=30.0)),
            ([str(CUT_SHOT), "--sample", "30"], cueball.simulate(CUT_SHOT, sample_rate=30.0).to_json()),
        ]:
            with self.subTest(args=args):
                out = subprocess.run([CLI, "simulate", *args, "--json"], check=True, capture_output=True, text=True)
                self.assertEqual(mine, out.stdout.rstrip("\n"))
        self.assertEqual(json.loads(self.result.to_json(indent=-1)), self.result.to_dict())
        self.assertNotIn("\n", self.result.to_json(indent=-1))

    def test_cue_obstructed(self):
        # A ball right behind the cue ball on the cue's line; 1.8 m from the head rail a level cue
        # reaches no rail. The flag is the result JSON's; the shot is simulated all the same.
        def layout(behind, elevation):
            balls = [{"id": 0, "position": [1.8, 0.635]}, {"id": 1, "position": [2.1, 0.635]}]
            if behind:
                balls.append({"id": 2, "position": [1.7, 0.635]})
            return {"table": "pool_9ft", "balls": balls,
                    "cue": {"ball": 0, "target": 1, "speed": 2.0, "elevation_deg": elevation}}
        blocked = cueball.simulate(layout(True, 0.0))
        self.assertIs(blocked.cue_obstructed, True)
        self.assertIs(blocked.to_dict()["cue_obstructed"], True)
        self.assertGreater(len(blocked.events["time"]), 2)
        for behind, elevation in ((False, 0.0), (True, 60.0)):
            r = cueball.simulate(layout(behind, elevation))
            self.assertIs(r.cue_obstructed, False, (behind, elevation))
            self.assertIs(r.to_dict()["cue_obstructed"], False)
        self.assertIs(cueball.simulate({"balls": [{"id": 0, "position": [1, 0.6]}]}).cue_obstructed, False)

    def test_names_and_repr(self):
        self.assertEqual(cueball.EVENT_TYPES, ("cue_strike", "slide_to_roll", "roll_to_spin", "roll_to_rest",
                                               "spin_stop", "ball_ball", "ball_cushion", "ball_jaw", "ball_pocket"))
        self.assertEqual(cueball.PHASES, ("sliding", "rolling", "spinning", "stationary"))
        r = self.result
        self.assertEqual(repr(r), f"Result(balls=10, events={len(self.json['events'])}, end_time={self.json['end_time']!r})")
        self.assertEqual(r.end_time, self.json["end_time"])
        self.assertEqual(r.pocket_names, [p["name"] for p in self.json["table"]["pockets"]])

    def test_events_are_the_jsons(self):
        for r in (self.result, self.cut):
            ev, js = r.events, r.to_dict()["events"]
            self.assertEqual(sorted(ev), ["ball", "cushion", "jaw", "other", "pocket", "time", "type"])
            self.assertEqual(ev["time"].dtype, np.float64)
            self.assertEqual(ev["type"].dtype, np.int8)
            for key in ("ball", "other", "cushion", "jaw", "pocket"):
                self.assertEqual(ev[key].dtype, np.int32, key)
                self.assertEqual(ev[key].shape, (len(js),), key)
            for i, e in enumerate(js):
                self.assertEqual(ev["time"][i], e["time"])
                self.assertEqual(cueball.EVENT_TYPES[ev["type"][i]], e["type"])
                self.assertEqual(ev["ball"][i], e["balls"][0])
                self.assertEqual(ev["other"][i], e["balls"][1] if e["type"] == "ball_ball" else -1)
                self.assertEqual(ev["cushion"][i], e.get("cushion", -1))
                self.assertEqual(ev["jaw"][i], e.get("jaw", -1))
                pocket = ev["pocket"][i]
                self.assertEqual(r.pocket_names[pocket] if pocket >= 0 else None, e.get("pocket"))
                cushion, jaw = ev["cushion"][i], ev["jaw"][i]
                self.assertEqual(r.cushion_names[cushion] if cushion >= 0 else None, e.get("cushion_name"))
                self.assertEqual(r.jaw_names[jaw] if jaw >= 0 else None, e.get("jaw_name"))
        kinds = {cueball.EVENT_TYPES[t] for t in self.result.events["type"]}
        self.assertTrue({"cue_strike", "ball_ball", "ball_cushion"} <= kinds, kinds)
        self.assertIn("ball_pocket", {cueball.EVENT_TYPES[t] for t in self.cut.events["type"]})
        self.assertIs(self.result.events, self.result.events)  # built once

    def test_facts_are_the_jsons_and_agree_with_the_events(self):
        for r in (self.result, self.cut):
            facts = r.facts
            self.assertEqual(facts, r.to_dict()["facts"])
            self.assertIs(r.facts, facts)  # built once
            ev = r.events
            kinds = [cueball.EVENT_TYPES[t] for t in ev["type"]]
            self.assertEqual(len(facts["contacts"]), kinds.count("ball_ball"))
            self.assertEqual(len(facts["cushions"]), kinds.count("ball_cushion"))
            self.assertEqual(len(facts["jaws"]), kinds.count("ball_jaw"))
            self.assertEqual([p["ball"] for p in facts["pots"]],
                             [int(b) for b, k in zip(ev["ball"], kinds) if k == "ball_pocket"])
            self.assertEqual([p["pocket"] for p in facts["pots"]],
                             [r.pocket_names[q] for q, k in zip(ev["pocket"], kinds) if k == "ball_pocket"])
            cue = r.scenario.to_dict()["cue"]["ball"]
            first = next((int(b) if int(o) == cue else int(o) for b, o, k in zip(ev["ball"], ev["other"], kinds)
                          if k == "ball_ball" and cue in (int(b), int(o))), None)
            self.assertEqual(facts["first_contact"]["ball"], first)
        self.assertEqual(self.result.facts["first_contact"]["ball"], 1)  # the break, aimed at the 1

    def test_table_after_is_where_the_balls_stopped(self):
        after = self.cut.table_after()
        d = after.to_dict()
        self.assertNotIn("cue", d)
        balls = self.cut.balls
        left = [int(i) for i, p in zip(balls["id"], balls["pocketed"]) if not p]
        self.assertEqual([b["id"] for b in d["balls"]], left)
        for b in d["balls"]:
            k = list(balls["id"]).index(b["id"])
            self.assertEqual(tuple(b["position"]), tuple(balls["position"][k]))
            self.assertEqual(tuple(b["velocity"]), (0.0, 0.0))
        self.assertEqual(d["table"], self.cut.scenario.to_dict()["table"])

    def test_balls_are_the_jsons(self):
        for r in (self.result, self.cut):
            b, js = r.balls, r.to_dict()["balls"]
            n = len(js)
            self.assertEqual(b["position"].shape, (n, 2))
            self.assertEqual(b["velocity"].shape, (n, 2))
            self.assertEqual(b["angular_velocity"].shape, (n, 3))
            self.assertEqual(b["pocketed"].dtype, np.bool_)
            self.assertEqual(b["id"].tolist(), [x["id"] for x in js])
            self.assertEqual(b["name"], [x["name"] for x in js])
            self.assertEqual(b["pocketed"].tolist(), [x["pocketed"] for x in js])
            self.assertEqual([r.pocket_names[q] if q >= 0 else None for q in b["pocket"]], [x["pocket"] for x in js])
            self.assertEqual([None if math.isnan(t) else t for t in b["pocket_time"]], [x["pocket_time"] for x in js])
            for key in ("position", "velocity", "angular_velocity"):
                self.assertEqual(b[key].tolist(), [x[key] for x in js], key)
        self.assertEqual(self.cut.balls["pocketed"].tolist(), [False, True, False])

    def test_segments_are_the_jsons(self):
        segments, js = self.result.segments, self.json["balls"]
        self.assertEqual(len(segments), len(js))
        for mine, ball in zip(segments, js):
            k = len(ball["segments"])
            self.assertEqual(mine["time"].tolist(), [s["t"] for s in ball["segments"]])
            self.assertEqual([cueball.PHASES[p] for p in mine["phase"]], [s["phase"] for s in ball["segments"]])
            for key, width in (("position", 2), ("velocity", 2), ("angular_velocity", 3)):
                self.assertEqual(mine[key].shape, (k, width))
                self.assertEqual(mine[key].tolist(), [s[key] for s in ball["segments"]], key)

    def test_sample_is_the_jsons_samples(self):
        samples = self.json["samples"]
        s = self.result.sample(20.0)
        n_balls, n_times = len(self.json["balls"]), len(samples["times"])
        self.assertEqual(s["time"].tolist(), samples["times"])
        self.assertEqual(s["position"].shape, (n_balls, n_times, 2))
        self.assertEqual(s["velocity"].shape, (n_balls, n_times, 2))
        self.assertEqual(s["angular_velocity"].shape, (n_balls, n_times, 3))
        self.assertEqual(s["phase"].shape, (n_balls, n_times))
        for i, ball in enumerate(samples["balls"]):
            for key in ("position", "velocity", "angular_velocity"):
                self.assertEqual(s[key][i].tolist(), ball[key], key)
        same = self.result.state_at(np.array(samples["times"]))
        for key in ("position", "velocity", "angular_velocity", "phase"):
            np.testing.assert_array_equal(same[key], s[key])

    def test_state_at_follows_the_segments_with_evolve(self):
        # Independent path: the module's evolve() from the segment holding t.
        q = self.json["parameters"]
        p = cueball.Parameters(cueball.BallParameters(q["mass"], q["radius"]),
                               cueball.ClothParameters(q["mu_s"], q["mu_r"], q["mu_sp"], q["g"]))
        times = np.array([0.0, 0.05, 0.3, 1.2, 2.5, self.result.end_time, self.result.end_time + 3.0])
        states = self.result.state_at(times)
        for i, ball in enumerate(self.json["balls"]):
            for k, t in enumerate(times):
                if ball["pocketed"] and t >= ball["pocket_time"]:
                    continue
                seg = [s for s in ball["segments"] if s["t"] <= t][-1]
                expected = cueball.evolve(cueball.BallState(seg["position"], seg["velocity"],
                                                            seg["angular_velocity"]), t - seg["t"], p)
                self.assertEqual(tuple(states["position"][i, k]), expected.position)
                self.assertEqual(tuple(states["velocity"][i, k]), expected.velocity)
                self.assertEqual(tuple(states["angular_velocity"][i, k]), expected.angular_velocity)
                self.assertEqual(cueball.PHASES[states["phase"][i, k]], cueball.motion_phase(expected, p))
        # At t = 0 the cue ball slides (struck at 7 m/s); after the end every ball is at rest.
        self.assertEqual(cueball.PHASES[states["phase"][0, 0]], "sliding")
        self.assertEqual({cueball.PHASES[x] for x in states["phase"][:, -1]}, {"stationary"})
        np.testing.assert_array_equal(states["position"][:, -1], self.result.balls["position"])

    def test_pocketed_ball_stays_at_its_capture_point(self):
        t = self.cut.balls["pocket_time"][1]
        s = self.cut.state_at([t, t + 1.0])
        np.testing.assert_array_equal(s["position"][1], [self.cut.balls["position"][1]] * 2)
        self.assertEqual(s["velocity"][1].tolist(), [[0.0, 0.0]] * 2)

    def test_times_as_numbers_lists_and_other_dtypes(self):
        one = self.result.state_at(1.0)
        self.assertEqual(one["position"].shape, (10, 1, 2))
        self.assertEqual(one["time"].tolist(), [1.0])
        listed = self.result.state_at([1.0, 0.5])
        self.assertEqual(listed["position"].shape, (10, 2, 2))
        np.testing.assert_array_equal(listed["position"][:, :1], one["position"])
        ints = self.result.state_at(np.array([1, 2], dtype=np.int64))
        floats = self.result.state_at(np.array([1.0, 2.0], dtype=np.float32))
        np.testing.assert_array_equal(ints["position"], floats["position"])
        empty = self.result.state_at(np.array([]))
        self.assertEqual(empty["position"].shape, (10, 0, 2))

    def test_bad_times_and_rates(self):
        for times, field in [([-1.0], "times[0]"), ([0.0, math.nan], "times[1]"), (np.array([0.0, np.inf]), "times[1]"),
                             (np.zeros((2, 2)), "times")]:
            with self.subTest(field=field):
                with self.assertRaises(cueball.InvalidArgument) as caught:
                    self.result.state_at(times)
                self.assertEqual(caught.exception.field, field)
                self.assertIn(field, str(caught.exception))
        with self.assertRaises(TypeError):
            self.result.state_at("1.0")
        for rate in (0.0, -1.0, math.nan, 1e5):
            with self.subTest(rate=rate):
                with self.assertRaises(cueball.InvalidArgument) as caught:
                    self.result.sample(rate)
                self.assertEqual(caught.exception.field, "sample_rate")
        with self.assertRaisesRegex(cueball.InvalidArgument, "at most 200000"):
            self.result.sample(1e4)
        with self.assertRaises(cueball.InvalidArgument) as caught:
            self.result.to_dict(sample_rate=-1.0)
        self.assertEqual(caught.exception.field, "sample_rate")
        with self.assertRaises(cueball.InvalidArgument) as caught:
            self.result.to_json(indent=-2)
        self.assertEqual(caught.exception.field, "indent")

    def test_timing_hook(self):
        seconds = cueball._time_run_scenario(None, 2)
        self.assertIsInstance(seconds, float)
        self.assertGreater(seconds, 0.0)
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball._time_run_scenario(None, 0)
        self.assertEqual(caught.exception.field, "repetitions")


class NumpyInputTest(unittest.TestCase):
    def test_numpy_in_a_dict_scenario(self):
        plain = cueball.simulate(TWO_BALLS).to_dict()
        self.assertEqual(cueball.simulate(numpy_two_balls()).to_dict(), plain)
        # An np.float32 that is not exact in binary stands for its own (widened) value.
        f32 = np.float32(2.9)
        with_f32 = json.loads(json.dumps(TWO_BALLS))
        with_f32["cue"]["speed"] = float(f32)
        mine = dict(TWO_BALLS, cue=dict(TWO_BALLS["cue"], speed=f32))
        self.assertEqual(cueball.simulate(mine).to_dict(), cueball.simulate(with_f32).to_dict())
        # A whole array of positions, and np.bool_ / 0-d arrays.
        arr = dict(TWO_BALLS, balls=[{"id": i, "position": p} for i, p in enumerate(np.array([[0.6, 0.6], [1.1, 0.7]]))])
        self.assertEqual(cueball.simulate(arr).to_dict(), plain)
        zero_d = dict(TWO_BALLS, max_events=np.array(100000))
        self.assertEqual(cueball.simulate(zero_d).to_dict(), plain)
        self.assertEqual(cueball.simulate_batch(numpy_two_balls(), shots=20, seed=np.uint64(2))["balls"],
                         cueball.simulate_batch(TWO_BALLS, shots=20, seed=2)["balls"])

    def test_numpy_nan_in_a_scenario_names_the_field(self):
        bad = dict(TWO_BALLS, balls=[{"id": 0, "position": np.array([0.6, np.nan])}, TWO_BALLS["balls"][1]])
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate(bad)
        self.assertEqual(caught.exception.field, "scenario.balls[0].position[1]")
        bad32 = dict(TWO_BALLS, cue=dict(TWO_BALLS["cue"], speed=np.float32("inf")))
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate(bad32)
        self.assertEqual(caught.exception.field, "scenario.cue.speed")

    def test_numpy_in_free_functions(self):
        p = cueball.pool_parameters()
        plain = cueball.BallState((1.1, 0.7), (1.5, 0.0), (0.0, 10.0, 2.0))
        mine = cueball.BallState(np.array([1.1, 0.7]), np.array([1.5, 0.0], dtype=np.float32),
                                 np.array([0, 10, 2], dtype=np.int64))
        self.assertEqual(mine, plain)
        self.assertEqual(cueball.evolve(mine, np.float64(0.5), p), cueball.evolve(plain, 0.5, p))
        self.assertEqual(cueball.evolve(mine, np.int64(2), p), cueball.evolve(plain, 2.0, p))
        self.assertEqual(repr(cueball.straight_shot(np.float32(1.5), np.int64(3), params=p)),
                         repr(cueball.straight_shot(1.5, 3.0, params=p)))
        self.assertEqual(cueball.BallParameters(np.float32(0.25), np.float64(0.028575)),
                         cueball.BallParameters(float(np.float32(0.25)), 0.028575))
        strike = cueball.CueStrike(speed=np.float32(2.0), side_offset=np.float64(0.01))
        self.assertEqual(cueball.strike_ball(strike, position=np.array([0.5, 0.5]), params=p),
                         cueball.strike_ball(cueball.CueStrike(2.0, side_offset=0.01), position=(0.5, 0.5), params=p))
        self.assertEqual(repr(cueball.cushion_impact(np.float64(1.0), np.float32(0.5), sidespin=np.int64(3))),
                         repr(cueball.cushion_impact(1.0, float(np.float32(0.5)), sidespin=3.0)))
        self.assertEqual(repr(cueball.plan_natural_roll_shot(x2=np.float64(1.0), v2=np.float32(0.25))),
                         repr(cueball.plan_natural_roll_shot(x2=1.0, v2=0.25)))
        self.assertEqual(cueball.simulate(CUT_SHOT, sample_rate=np.float32(30)).to_json(),
                         cueball.simulate(CUT_SHOT, sample_rate=30.0).to_json())
        a = cueball.simulate_batch(CUT_SHOT, shots=np.int64(30), threads=np.int32(2), seed=np.uint64(1))
        b = cueball.simulate_batch(CUT_SHOT, shots=30, threads=2, seed=1)
        self.assertEqual(a["balls"], b["balls"])
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.evolve(cueball.BallState(velocity=np.array([np.nan, 0.0])), 1.0, p)
        self.assertEqual(caught.exception.field, "velocity")
        with self.assertRaises(TypeError):
            cueball.BallState(position=np.array([1.0, 2.0, 3.0]))


if __name__ == "__main__":
    unittest.main()
