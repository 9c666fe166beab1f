"""cueball.rl (python/cueball/rl.py over python/src/rl.cpp): the Gymnasium-style single-learner
env, the PettingZoo-style two-player env, the vector env, their spaces, masks, rewards,
bounds and determinism, and the cross-entropy-method demo that shows learning."""

import json
import os
import unittest

import numpy as np

import cueball
from cueball import games, rl
from cueball.rl_demo import cross_entropy_method, single_ball_state


def masked_sample(space, mask, rng):
    """A random action whose discrete parts are drawn within the masks."""
    a = {"strike": rng.uniform(-1, 1, 5), "place": rng.uniform(-1, 1, 2)}
    for key in ("ball", "pocket", "decision", "push_out"):
        allowed = np.flatnonzero(mask[key])
        a[key] = int(rng.choice(allowed)) if allowed.size else 0
    return a


class SpacesTest(unittest.TestCase):
    def test_plain_spaces_have_the_gymnasium_surface(self):
        box = rl.Box(-1.0, 1.0, (3,), seed=1)
        x = box.sample()
        self.assertEqual(x.shape, (3,))
        self.assertEqual(x.dtype, np.float32)
        self.assertTrue(box.contains(x))
        self.assertFalse(box.contains(np.array([2.0, 0.0, 0.0], np.float32)))
        d = rl.Discrete(4, seed=2)
        self.assertEqual(d.n, 4)
        self.assertTrue(all(d.contains(d.sample()) for _ in range(20)))
        self.assertEqual({d.sample(np.array([0, 0, 1, 0], np.int8)) for _ in range(10)}, {2})
        self.assertFalse(d.contains(4))
        both = rl.Dict({"a": box, "b": d}, seed=3)
        self.assertTrue(both.contains(both.sample()))
        box.seed(5)
        first = box.sample()
        box.seed(5)
        np.testing.assert_array_equal(box.sample(), first)

    def test_the_layouts(self):
        for game, balls in (("nine_ball", 10), ("ten_ball", 11), ("eight_ball", 16), ("snooker", 22),
                            ("three_cushion", 3)):
            env = rl.CueballEnv(game=game, opponent="random")
            obs, info = env.reset(seed=1)
            names = rl.observation_names(game)
            self.assertEqual(obs.shape, (balls * 5 + 31,))
            self.assertEqual(len(names), obs.shape[0])
            self.assertEqual(obs.dtype, np.float32)
            self.assertTrue(env.observation_space.contains(obs), game)
            self.assertEqual(env.action_space["ball"].n, balls)
            self.assertEqual(info["action_mask"]["ball"].shape, (balls,))
            self.assertEqual(names[:3], ["ball0.x", "ball0.y", "ball0.present"])
            self.assertIn("noise.aim", names)


class CueballEnvTest(unittest.TestCase):
    def test_deterministic_for_a_seed_and_bounded(self):
        runs = []
        for _ in range(2):
            env = rl.CueballEnv(noise="tournament", max_shots=30)
            rng = np.random.default_rng(0)
            obs, info = env.reset(seed=7)
            trace = [obs]
            for _ in range(40):
                obs, reward, terminated, truncated, info = env.step(masked_sample(env.action_space,
                                                                                   info["action_mask"], rng))
                trace.append(obs)
                trace.append(np.array([reward, terminated, truncated]))
                if terminated or truncated:
                    obs, info = env.reset()
            runs.append(np.concatenate(trace))
        np.testing.assert_array_equal(runs[0], runs[1])

    def test_the_learner_acts_and_the_opponent_replies(self):
        env = rl.CueballEnv(opponent="ghost_ball", seat=1)
        obs, info = env.reset(seed=3)
        self.assertEqual(info["to_shoot"], 1)
        self.assertEqual(info["seat"], 1)
        rng = np.random.default_rng(1)
        for _ in range(30):
            obs, reward, terminated, truncated, info = env.step(masked_sample(env.action_space,
                                                                               info["action_mask"], rng))
            self.assertEqual(info["players"][0], 1)
            if terminated or truncated:
                self.assertIn(reward, (-1.0, 0.0, 1.0))
                break
            self.assertEqual(info["to_shoot"], 1)

    def test_an_illegal_action_is_a_foul_reported_in_info(self):
        env = rl.CueballEnv(opponent=None, reward={"illegal": -1.0, "fouls": -0.5})
        obs, info = env.reset(seed=2)
        player = info["to_shoot"]
        obs, reward, terminated, truncated, info = env.step({"strike": np.zeros(5), "decision": 4})
        self.assertTrue(info["illegal"].startswith("decision"), info["illegal"])
        self.assertEqual(info["rulings"][0]["foul"], "miscue")
        self.assertEqual(reward, -1.5)
        self.assertEqual(info["to_shoot"], 1 - player)
        self.assertEqual(obs[rl.observation_names().index("ball_in_hand")], 1.0)

    def test_a_callable_opponent_and_a_given_position(self):
        calls = []

        def opponent(obs, info):
            calls.append(info["player"])
            return {"strike": [0.0, 0.3, -1.0, 0.0, 0.0], "ball": int(np.flatnonzero(info["action_mask"]["ball"])[0])}

        env = rl.CueballEnv(opponent=opponent, seat=0)
        env.reset(seed=4, options={"state": single_ball_state(np.random.default_rng(0))})
        self.assertEqual(env.state.to_shoot, 0)
        for _ in range(10):
            obs, reward, terminated, truncated, info = env.step({"strike": [-0.6, 0.9, -1.0, 0.0, 0.0]})
            if terminated or truncated:
                break
            self.assertEqual(env.state.to_shoot, 0)
        self.assertTrue(set(calls) <= {1})

    def test_noise_drawn_per_episode_is_shown(self):
        env = rl.CueballEnv(noise={"base": "tournament", "scale": [0.0, 2.0]})
        aims = set()
        i = rl.observation_names().index("noise.aim")
        for k in range(5):
            obs, info = env.reset(seed=k)
            aims.add(round(info["noise"]["aim_deg"], 9))
            self.assertAlmostEqual(float(obs[i]), info["noise"]["aim_deg"] / 0.125, places=5)
            self.assertLessEqual(info["noise"]["aim_deg"], 0.25 + 1e-12)
        self.assertEqual(len(aims), 5)

    def test_the_mirror_and_render(self):
        env = rl.CueballEnv(opponent="random", render_mode="html")
        obs, info = env.reset(seed=5)
        action = {"strike": np.array([0.1, 0.2, -1, 0.3, 0.1]), "place": np.array([0.2, 0.4]), "ball": 1,
                  "pocket": 0, "decision": 0, "push_out": 0}
        mobs, maction = env.mirror(obs, action)
        ys = [i for i, n in enumerate(rl.observation_names()) if n.endswith(".y")]
        np.testing.assert_array_equal(mobs[ys], -obs[ys])
        self.assertEqual(maction["pocket"], 5)  # bottom-left <-> top-left
        self.assertEqual(maction["strike"][1], -0.2)
        env.step(action)
        page = env.render()
        self.assertTrue(page.lstrip().lower().startswith("<!doctype html"))
        self.assertIn('"game"', page)
        self.assertIsNone(rl.CueballEnv().render())

    def test_the_strongest_agent_by_name(self):
        # Three-cushion's strongest is carom_search, here at 30 runs a
        # decision (its own budget takes minutes under the sanitizers); the
        # opponent breaks and replies until the learner is to act.
        env = rl.CueballEnv(game="three_cushion", opponent="strongest", seat=1, simulations=30)
        obs, info = env.reset(seed=2)
        self.assertEqual(info["to_shoot"], 1)
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        self.assertTrue(terminated or truncated or info["to_shoot"] == 1)
        self.assertIn("strongest", rl.OPPONENTS)
        with self.assertRaises(cueball.InvalidArgument) as e:
            rl.CueballEnv(opponent="strongest", simulations=0)
        self.assertIn("opponent.simulations", str(e.exception))
        with self.assertRaises(cueball.InvalidArgument) as e:
            rl.CueballEnv(opponent="shark")
        self.assertIn("strongest", str(e.exception))

    def test_an_opponent_on_a_time_budget(self):
        # opponent_seconds: the planner opponent plans in rounds within its
        # budget (AgentOptions::seconds), so at a million runs a plan (hours
        # a decision without the budget) it still replies until the learner
        # is to act; a callable, self-play or a value out of range are refused.
        env = rl.CueballEnv(opponent="planner", seat=1, simulations=1_000_000, opponent_seconds=0.05)
        obs, info = env.reset(seed=4)
        self.assertEqual(info["to_shoot"], 1)
        opponent_shots = 0
        for _ in range(20):
            obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
            self.assertTrue(terminated or truncated or info["to_shoot"] == 1)
            opponent_shots += info["players"].count(0)
            if terminated or truncated or opponent_shots > 0:
                break
        self.assertGreater(opponent_shots, 0)
        vec = rl.VectorEnv(2, opponent="ghost_ball", opponent_seconds=0.05, threads=1)
        self.assertEqual(vec.reset()[0].shape[0], 2)
        for kwargs in ({"opponent_seconds": -1.0}, {"opponent_seconds": 4000.0},
                       {"opponent": None, "opponent_seconds": 0.1},
                       {"opponent": lambda obs, info: {}, "opponent_seconds": 0.1}):
            with self.assertRaises(cueball.InvalidArgument) as e:
                rl.CueballEnv(**kwargs)
            self.assertIn("opponent_seconds", str(e.exception))
            self.assertEqual(len(str(e.exception).splitlines()), 1)

    def test_bad_options_name_the_option(self):
        for kwargs, word in (({"game": "pool"}, "game"), ({"opponent": "shark"}, "opponent"),
                             ({"reward": "money"}, "reward"), ({"max_shots": 0}, "max_shots"),
                             ({"action": "joystick"}, "action"), ({"noise": "loud"}, "noise"),
                             ({"max_speed": 20.0}, "max_speed"), ({"render_mode": "human"}, "render_mode")):
            with self.assertRaises(cueball.InvalidArgument) as e:
                rl.CueballEnv(**kwargs)
            self.assertIn(word, str(e.exception))
            self.assertEqual(len(str(e.exception).splitlines()), 1)


class TwoPlayerEnvTest(unittest.TestCase):
    def test_aec_games_to_the_end(self):
        env = rl.TwoPlayerEnv(max_shots=80)
        rng = np.random.default_rng(3)
        for game in range(3):
            env.reset(seed=9 + game)
            self.assertEqual(env.agents, ["player_0", "player_1"])
            totals = {"player_0": 0.0, "player_1": 0.0}
            for _ in range(400):
                if not env.agents:
                    break
                agent = env.agent_selection
                obs, reward, terminated, truncated, info = env.last()
                totals[agent] += reward
                if terminated or truncated:
                    env.step(None)
                    continue
                self.assertEqual(obs.shape, env.observation_space(agent).shape)
                env.step(masked_sample(env.action_space(agent), info["action_mask"], rng))
            self.assertEqual(env.agents, [])
            self.assertAlmostEqual(totals["player_0"] + totals["player_1"], 0.0)

    def test_a_player_who_pots_keeps_the_table(self):
        # A straight-in on the 1 into the bottom-right pocket: player 0 pots it and shoots again.
        d = games.new_game("nine_ball", 0).to_dict()
        still = {"angular_velocity": [0.0, 0.0, 0.0], "velocity": [0.0, 0.0]}
        d["balls"] = [dict(still, id=0, name="cue", position=[1.6, 0.6]), dict(still, id=1, name="1", position=[2.1, 0.35]),
                      dict(still, id=9, name="9", position=[0.5, 1.0])]
        d["game"].update(phase="play", ball_in_hand=None, on=[1])
        env = rl.TwoPlayerEnv(action="target", reward=["win", "pots"])
        env.reset(seed=1, options={"state": games.GameState.from_json(json.dumps(d))})
        self.assertEqual(env.agent_selection, "player_0")
        env.step({"strike": [-0.6, 0.0, -1.0, 0.0, 0.0], "ball": 1, "pocket": 2})
        self.assertEqual(env.rewards["player_0"], 1.0)
        self.assertEqual(env.agent_selection, "player_0")  # turns do not alternate on every shot
        self.assertEqual(env.state.on, [9])


class VectorEnvTest(unittest.TestCase):
    def test_threads_do_not_change_the_results_and_tables_reset_themselves(self):
        out = []
        for threads in (1, 2):
            v = rl.VectorEnv(5, opponent="random", threads=threads, seed=11)
            obs, info = v.reset(seed=11)
            rng = np.random.default_rng(2)
            trace = [obs]
            ended = 0
            for _ in range(15):
                actions = {"strike": rng.uniform(-1, 1, (5, 5)), "place": rng.uniform(-1, 1, (5, 2)),
                           "ball": np.ones(5, np.int64)}
                obs, reward, terminated, truncated, info = v.step(actions)
                self.assertEqual(obs.shape, (5, v.single_observation_space.shape[0]))
                done = terminated | truncated
                np.testing.assert_array_equal(info["_final_observation"], done)
                ended += int(done.sum())
                trace += [obs, reward, info["final_observation"][done]]
            self.assertGreater(ended, 0)
            out.append(np.concatenate([np.asarray(t, np.float64).ravel() for t in trace]))
        np.testing.assert_array_equal(out[0], out[1])

    def test_masked_random_actions_and_bad_shapes(self):
        v = rl.VectorEnv(3, game="snooker", opponent=None, seed=1)
        obs, info = v.reset()
        self.assertEqual(info["action_mask"]["ball"].shape, (3, 22))
        for _ in range(5):
            obs, reward, terminated, truncated, info = v.step(v.sample_actions(info["action_mask"]))
        self.assertFalse(info["illegal"].any())
        with self.assertRaises(cueball.InvalidArgument):
            v.step({"strike": np.zeros((2, 5))})
        with self.assertRaises(cueball.InvalidArgument):
            rl.VectorEnv(2, opponent=lambda o, i: {})


@unittest.skipIf(os.environ.get("CUEBALL_SANITIZED"), "numerics, run by the Release suite (the sanitizer build checks memory)")
class LearningTest(unittest.TestCase):
    def test_the_cross_entropy_method_learns_to_pot(self):
        curve = cross_entropy_method(iterations=10, population=30, drills_per_member=8, seed=0)
        random_policy, learned = curve[0]["evaluation"], curve[-1]["evaluation"]
        self.assertLess(random_policy, 0.15)
        self.assertGreater(learned, random_policy + 0.25)


if __name__ == "__main__":
    unittest.main()
