"""cueball.games (python/src/games.cpp): new games, states as values (copy, ==, JSON), legal
actions, play() and its step, agents, and records that load in both the CLI and Python."""

import copy
import json
import os
import pathlib
import pickle
import subprocess
import tempfile
import unittest

import cueball
import cueball.games
from cueball import games


class GamesTest(unittest.TestCase):
    def test_a_new_game_and_its_state(self):
        config = games.default_config("nine_ball")
        self.assertEqual(config.kind, "nine_ball")
        self.assertEqual(config.table, "pool_9ft")
        s = games.new_game(config, seed=0)
        self.assertIs(cueball.games, games)
        self.assertEqual(s.kind, "nine_ball")
        self.assertEqual(s.phase, "break")
        self.assertEqual(s.ball_in_hand, "behind_head_string")
        self.assertEqual(s.on, [1])
        self.assertEqual(sorted(s.balls), list(range(10)))
        self.assertEqual(s.scores, (0, 0))
        self.assertIsNone(s.winner)
        self.assertIsInstance(s.table, cueball.Scenario)
        self.assertEqual(games.new_game("nine_ball"), s)
        legal = games.legal_actions(s)
        self.assertTrue(legal["shoot"])
        self.assertEqual(legal["on"], [1])
        self.assertEqual(legal["ball_in_hand"], "behind_head_string")

    def test_states_are_values_with_a_bit_exact_json(self):
        s = games.new_game("nine_ball")
        step = games.play(s, games.Action(speed=8.0, target=1), seed=3)
        t = step.next
        self.assertEqual(s.shots, 0)  # play() never changes its input
        self.assertEqual(t.shots, 1)
        for c in (t.copy(), copy.copy(t), copy.deepcopy(t), pickle.loads(pickle.dumps(t)),
                  games.GameState.from_json(t.to_json())):
            self.assertEqual(c, t)
            self.assertEqual(c.to_json(), t.to_json())
        self.assertNotEqual(s, t)
        d = t.to_dict()
        self.assertEqual(d["game"]["shots"], 1)
        d["game"]["to_shoot"] = 2
        with self.assertRaises(cueball.InvalidArgument) as e:
            games.GameState.from_json(json.dumps(d))
        self.assertEqual(e.exception.field, "state.game.to_shoot")

    def test_a_step_has_the_ruling_facts_result_and_next_state(self):
        s = games.new_game("nine_ball")
        step = games.play(s, games.Action(speed=1.2, target=1), seed=0)
        r = step.ruling
        self.assertEqual(r["foul"], "illegal_break")
        self.assertTrue(r["turn_over"])
        self.assertEqual(set(r), {"foul", "points", "turn_over", "game_over", "winner", "respotted", "pocketed", "push_out",
                                  "miss", "truncated", "reason"})
        self.assertEqual(step.facts["first_contact"]["ball"], 1)
        self.assertIsInstance(step.result, cueball.Result)
        self.assertEqual(step.result.facts, step.facts)
        self.assertEqual(step.next.to_shoot, 1)
        self.assertEqual(step.next.ball_in_hand, "anywhere")
        self.assertEqual(json.loads(step.to_json())["ruling"], r)
        # An illegal action names its field.
        with self.assertRaises(cueball.InvalidArgument) as e:
            games.play(step.next, games.Action(decision="pass"))
        self.assertEqual(e.exception.field, "decision")
        with self.assertRaises(cueball.InvalidArgument) as e:
            games.play(s, games.Action(speed=3.0, target=1, place=(2.0, 0.6)))
        self.assertEqual(e.exception.field, "place")
        with self.assertRaises(cueball.InvalidArgument) as e:
            games.Action(speed=20.0)
        self.assertEqual(e.exception.field, "action.speed")

    def test_actions(self):
        a = games.Action(speed=2.0, aim_deg=10.0, height=-0.2, place=(0.5, 0.6), push_out=True)
        self.assertEqual(a.place, (0.5, 0.6))
        self.assertEqual(games.Action.from_json(a.to_json()), a)
        self.assertEqual(a.to_dict()["push_out"], True)
        self.assertEqual(games.Action(decision="pass").to_dict(), {"decision": "pass"})

    def test_agents_play_whole_games_and_records_replay(self):
        record = games.play_game("nine_ball", ("random", "random"), seed=4, noise="tournament")
        self.assertEqual(record.players, ("random", "random"))
        self.assertTrue(record.end.over)
        self.assertIsNone(record.replay())
        self.assertEqual(len(record.steps), record.end.shots)
        self.assertEqual(set(record.steps[0]), {"action", "seed", "ruling", "state", "reasoning"})
        self.assertIsNone(record.steps[0]["reasoning"])  # the random agent weighs nothing
        tally = record.tally()
        self.assertEqual(sum(tally["shots"]), len(record.steps))
        text = games.records_to_json([record])
        back = games.records_from_json(text)
        self.assertEqual(games.records_to_json(back), text)
        self.assertIsNone(back[0].replay())
        self.assertGreater(record.start.config.noise["aim_deg"], 0.0)
        s = games.new_game("nine_ball")
        a = games.choose_action(record.start, agent="random", seed=0)
        self.assertEqual(a, games.choose_action(record.start, agent="random", seed=0))
        with self.assertRaises(cueball.InvalidArgument) as e:
            games.choose_action(s, agent="shark")
        self.assertEqual(e.exception.field, "agent")

    def test_a_decision_under_a_seconds_budget(self):
        game = games.play_game("nine_ball", ("planner", "ghost_ball"), seed=3, simulations=500, noise="tournament")
        after_break = game.steps[0]["state"]
        self.assertFalse(after_break.over)
        # No second round fits in 1e-9 s: the first round's 500 runs are played, as simulations=500 plays.
        timed = games.choose_action(after_break, agent="planner", seed=4, simulations=1000, seconds=1e-9)
        self.assertEqual(timed, games.choose_action(after_break, agent="planner", seed=4, simulations=500))
        with self.assertRaises(cueball.InvalidArgument) as e:
            games.choose_action(after_break, agent="planner", seconds=-1.0)
        self.assertEqual(e.exception.field, "seconds")

    def test_the_planner_agents_reasoning_is_in_the_record(self):
        game = games.play_game("nine_ball", ("planner", "ghost_ball"), seed=3, simulations=500, noise="tournament")
        first = game.steps[0]["reasoning"]
        self.assertEqual(first["summary"], "break")  # the planner breaks
        planned = [s["reasoning"] for s in game.steps if s["reasoning"] and s["reasoning"]["considered"]]
        for r in planned:
            self.assertTrue(all(c["what"] for c in r["considered"]))
            estimates = [c["estimate"] for c in r["considered"] if c["estimate"] is not None]
            self.assertTrue(all(0.0 <= p <= 1.0 for p in estimates))
        back = games.records_from_json(games.records_to_json([game]))[0]
        self.assertEqual([s["reasoning"] for s in back.steps], [s["reasoning"] for s in game.steps])
        # "strongest" is an agent name too (the safety planner with position play)
        with self.assertRaises(cueball.InvalidArgument) as e:
            games.play_game("nine_ball", ("strongest", "shark"))
        self.assertEqual(e.exception.field, "players[1]")

    @unittest.skipUnless(os.environ.get("CUEBALL_BIN"), "needs the CLI (CUEBALL_BIN)")
    def test_records_load_in_both_the_cli_and_python(self):
        binary = os.environ["CUEBALL_BIN"]
        with tempfile.TemporaryDirectory() as scratch:
            from_cli = pathlib.Path(scratch) / "cli.json"
            subprocess.run([binary, "game", "play", "--game", "nine_ball", "--players", "random,random", "--games", "2",
                            "--seed", "8", "--noise", "tournament", "--record", str(from_cli)],
                           check=True, stdout=subprocess.DEVNULL)
            records = games.records_from_json(from_cli.read_text())
            self.assertEqual(len(records), 2)
            for r in records:
                self.assertIsNone(r.replay())
            # The same seeds in Python: the same games, byte for byte.
            mine = [games.play_game("nine_ball", ("random", "random"), seed=seed, noise="tournament") for seed in (8, 9)]
            self.assertEqual(games.records_to_json(mine) + "\n", from_cli.read_text())
            from_python = pathlib.Path(scratch) / "python.json"
            from_python.write_text(games.records_to_json(mine))
            out = subprocess.run([binary, "game", "replay", str(from_python)], check=True, capture_output=True, text=True)
            self.assertIn("bit for bit", out.stdout)
            # A state written by Python is shot by the CLI, and back.
            state = pathlib.Path(scratch) / "state.json"
            state.write_text(games.new_game("nine_ball").to_json())
            shot = subprocess.run([binary, "game", "shoot", str(state), "--cue", '{"speed": 8, "target": 1}', "--json"],
                                  check=True, capture_output=True, text=True)
            step = json.loads(shot.stdout)
            mine_step = games.play(games.GameState.from_json(state.read_text()), games.Action(speed=8.0, target=1))
            self.assertEqual(games.GameState.from_json(json.dumps(step["state"])), mine_step.next)


if __name__ == "__main__":
    unittest.main()
