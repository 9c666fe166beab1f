"""The cushion and ball-ball models by name from Python (SimulationSettings)."""
import json
import pickle
import unittest

import cueball


def cut_scenario(settings):
    return cueball.Scenario(
        cueball.pool_table_9ft(),
        [cueball.SimulationBall(0, (0.6, 0.6)), cueball.SimulationBall(1, (1.1, 0.7))],
        cueball.ShotStrike(3.0, target=1, side=0.2),
        settings=settings)


class ModelsTest(unittest.TestCase):
    def test_each_model_takes_its_own_constants(self):
        s = cueball.SimulationSettings()
        self.assertEqual((s.cushion_model, s.cushion_restitution, s.cushion_friction), ("mathavan_2010", 0.98, 0.14))
        self.assertEqual(s.ball_collision_model, "coulomb_impulse")
        han = cueball.SimulationSettings(cushion_model="han_2005")
        self.assertEqual((han.cushion_restitution, han.cushion_friction), (0.85, 0.2))
        stronge = cueball.SimulationSettings(cushion_model="stronge_compliant", cushion_friction=0.1)
        self.assertEqual((stronge.cushion_frequency_ratio, stronge.cushion_friction), (1.8, 0.1))
        m14 = cueball.SimulationSettings(ball_collision_model="mathavan_2014")
        self.assertEqual((m14.ball_collision.restitution, m14.ball_collision.friction), (0.89, 0.05))

    def test_models_change_the_shot_and_survive_json_and_pickle(self):
        outcomes = set()
        for cushion in ("mathavan_2010", "han_2005", "stronge_compliant"):
            for ball in ("coulomb_impulse", "mathavan_2014"):
                with self.subTest(cushion=cushion, ball=ball):
                    s = cut_scenario(cueball.SimulationSettings(cushion_model=cushion, ball_collision_model=ball))
                    doc = json.loads(s.to_json())
                    self.assertEqual(doc["cushion"]["model"], cushion)
                    self.assertEqual(doc["ball_collision"]["model"], ball)
                    self.assertEqual(cueball.Scenario.from_json(s.to_json()), s)
                    self.assertEqual(pickle.loads(pickle.dumps(s.settings)), s.settings)
                    r = cueball.simulate(s)
                    outcomes.add(tuple(round(float(c), 9) for c in r.balls["position"][0]))
        self.assertEqual(len(outcomes), 6)  # every pair of models ends the shot elsewhere

    def test_exact_tolerance_for_planners(self):
        loose = cueball.SimulationSettings(cushion_exact_tolerance=1e-7)
        self.assertEqual((cueball.SimulationSettings().cushion_exact_tolerance, loose.cushion_exact_tolerance), (1e-8, 1e-7))
        self.assertEqual(pickle.loads(pickle.dumps(loose)), loose)
        self.assertNotEqual(loose, cueball.SimulationSettings())
        s = cut_scenario(loose)
        self.assertEqual(json.loads(s.to_json())["cushion"]["exact_tolerance"], 1e-7)
        self.assertEqual(cueball.Scenario.from_json(s.to_json()), s)
        self.assertNotIn("exact_tolerance", json.loads(cut_scenario(cueball.SimulationSettings()).to_json())["cushion"])
        # The shot ends within a micrometre of the default's.
        a = cueball.simulate(s).balls["position"]
        b = cueball.simulate(cut_scenario(cueball.SimulationSettings())).balls["position"]
        self.assertLess(max(abs(float(x - y)) for x, y in zip(a.ravel(), b.ravel())), 1e-6)
        loose.cushion_exact_tolerance = 1e-6
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.simulate(cut_scenario(loose))
        self.assertEqual(caught.exception.field, "scenario.cushion.exact_tolerance")

    def test_single_impacts_by_model(self):
        import math
        snooker = cueball.snooker_parameters()
        exact = cueball.cushion_impact(1.0, math.pi / 4, params=snooker)
        same = cueball.cushion_rebound(1.0, math.pi / 4, params=snooker)
        self.assertEqual(same.velocity, exact.velocity)
        # Han 2005, rolling head-on: (1 - 1.85 cos^2) - 0.37 cos sin at h = 7R/5 (test_cushion_han_2005).
        han = cueball.cushion_rebound(1.0, math.pi / 2, model="han_2005")
        self.assertAlmostEqual(han.rebound_speed, 0.689644, delta=1e-6)
        stronge = cueball.cushion_rebound(1.0, math.pi / 2, 0.0, model="stronge_compliant", frequency_ratio=2.0)
        self.assertAlmostEqual(stronge.rebound_speed, 0.85, delta=1e-12)  # no slip at the equator: e V0
        with self.assertRaisesRegex(ValueError, "model = \"x\" is not known"):
            cueball.cushion_rebound(1.0, 0.5, model="x")
        # Mathavan 2014 against the paper's Table 1 at the 18.05 deg cut (as quoted by pooltool):
        # with no cloth friction it is resolve_ball_collision with a constant friction.
        p = cueball.pool_parameters()
        R = p.ball.radius
        a = cueball.BallState((0.0, 0.0), (1.0, 0.0), (0.0, 1.0 / R, 0.0))
        b = cueball.BallState((2 * R * math.cos(0.5), 2 * R * math.sin(0.5)), (0.0, 0.0), (0.0, 0.0, 0.0))
        bare = cueball.mathavan_2014_collision(a, b, p, cloth_friction=0.0)
        coulomb = cueball.resolve_ball_collision(a, b, p, cueball.BallCollisionParameters(0.89, 0.05))
        for x, y in zip(bare.a.velocity + bare.b.velocity, coulomb.a.velocity + coulomb.b.velocity):
            self.assertAlmostEqual(x, y, delta=1e-9)
        cloth = cueball.mathavan_2014_collision(a, b, p)
        self.assertGreater(abs(cloth.a.velocity[1] - bare.a.velocity[1]), 1e-4)

    def test_unknown_names_are_value_errors_naming_the_field(self):
        with self.assertRaisesRegex(ValueError, "cushion_model = \"han\" is not known; allowed: 'mathavan_2010'"):
            cueball.SimulationSettings(cushion_model="han")
        with self.assertRaisesRegex(ValueError, "ball_collision_model = \"x\" is not known"):
            cueball.SimulationSettings(ball_collision_model="x")
        s = cueball.SimulationSettings()
        with self.assertRaisesRegex(ValueError, "cushion_solver"):
            s.cushion_solver = "euler"

    def test_another_models_or_solvers_argument_is_refused_as_the_cli_refuses_its_key(self):
        # Issue 24: these were kept (and never used), so Omega = 5000 was silently accepted.
        cases = [
            (dict(cushion_frequency_ratio=5000), "cushion_frequency_ratio",
             "cushion_frequency_ratio applies to the model 'stronge_compliant' only, not to \"mathavan_2010\""),
            (dict(cushion_model="han_2005", cushion_frequency_ratio=2), "cushion_frequency_ratio", "'stronge_compliant' only"),
            (dict(cushion_paper_steps=100), "cushion_paper_steps",
             "cushion_paper_steps applies to the solver 'paper' only, not to \"exact\""),
            (dict(cushion_solver="paper", cushion_exact_tolerance=1e-7), "cushion_exact_tolerance",
             "cushion_exact_tolerance applies to the solver 'exact' only, not to \"paper\""),
            (dict(cushion_model="han_2005", cushion_solver="paper"), "cushion_solver", "'mathavan_2010' only"),
            (dict(ball_collision_model="mathavan_2014",
                  ball_collision=cueball.BallCollisionParameters(0.89, 0.05, 0.0, 1.0)), "ball_collision.friction_decay",
             "friction_decay = 1 is outside the allowed range 0"),
            # The chosen model's own values are checked when the settings are made, as the reader checks them.
            (dict(cushion_model="stronge_compliant", cushion_frequency_ratio=5000), "cushion_frequency_ratio", "(1, 1000]"),
            (dict(max_events=0), "max_events", "[1, 1000000]"),
        ]
        for kwargs, field, message in cases:
            with self.subTest(**{k: str(v) for k, v in kwargs.items()}):
                with self.assertRaises(cueball.InvalidArgument) as caught:
                    cueball.SimulationSettings(**kwargs)
                self.assertEqual(caught.exception.field, field)
                self.assertIn(message, str(caught.exception))
        s = cueball.SimulationSettings()
        with self.assertRaises(cueball.InvalidArgument) as caught:
            s.cushion_frequency_ratio = 2.5
        self.assertEqual(caught.exception.field, "cushion_frequency_ratio")
        self.assertEqual(s.cushion_frequency_ratio, 1.8)
        # Each model's and solver's own arguments are taken, and written to the scenario as its keys.
        paper = cueball.SimulationSettings(cushion_solver="paper", cushion_paper_steps=100)
        self.assertEqual(paper.cushion_paper_steps, 100)
        self.assertEqual(json.loads(cut_scenario(paper).to_json())["cushion"]["paper_steps"], 100)
        m14 = json.loads(cut_scenario(cueball.SimulationSettings(ball_collision_model="mathavan_2014")).to_json())
        self.assertNotIn("friction_decay", m14["ball_collision"])
        # cushion_rebound as the CLI's cushion --model han_2005 --frequency-ratio 2.
        with self.assertRaises(cueball.InvalidArgument) as caught:
            cueball.cushion_rebound(1.0, 0.5, model="han_2005", frequency_ratio=2)
        self.assertEqual(caught.exception.field, "frequency_ratio")
        self.assertIn("applies to the model 'stronge_compliant' only", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
