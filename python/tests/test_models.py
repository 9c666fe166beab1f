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

    def test_unknown_names_are_value_errors_naming_the_field(self):
        with self.assertRaisesRegex(ValueError, "cushion_model = \"han\" is not known; allowed: 'mathavan_2010'"):
            cueball.SimulationSettings(cushion_model="han")
        with self.assertRaisesRegex(ValueError, "ball_collision_model = \"x\" is not known"):
            cueball.SimulationSettings(ball_collision_model="x")
        s = cueball.SimulationSettings()
        with self.assertRaisesRegex(ValueError, "cushion_solver"):
            s.cushion_solver = "euler"


if __name__ == "__main__":
    unittest.main()
