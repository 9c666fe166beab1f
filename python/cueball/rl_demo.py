"""A learner that shows cueball.rl is learnable: the cross-entropy method on a single-ball drill.

The drill (``single_ball_state``): a 9-ball table with the cue ball and the 1 at random
spots (the 9 parked by the head rail, out of the way), the 1 to pot, no opponent. The
learner plays ``CueballEnv(action='target', reward='pots', opponent=None)``: the target is
the 1, the pocket the one with the smallest cut (``easiest_pocket``, from the observation),
and what it learns is the rest of the strike, five numbers in [-1, 1]: the cut offset from
the ghost-ball aim, the speed, the elevation, the side and the height.

The cross-entropy method (R. Y. Rubinstein, "The cross-entropy method for combinatorial and
continuous optimization", Methodol. Comput. Appl. Probab. 1 (1999) 127-190; as a policy
search: I. Szita, A. Lorincz, "Learning Tetris using the noisy cross-entropy method", Neural
Comput. 18 (2006) 2936-2941): a Gaussian over the five numbers; each iteration draws a
population, plays each member on a few drills, keeps the elite fraction by pot rate and
refits the Gaussian to it (with a little added noise, as Szita and Lorincz do). NumPy only.

    python3 -m cueball.rl_demo            # a longer run, printing its curve
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from . import games
from .rl import CueballEnv

# The balls' radius and the 9-ft table's bed, m (the pool_9ft preset).
_R = 0.028575
_LENGTH, _WIDTH = 2.54, 1.27


def _pockets() -> list[tuple[float, float]]:
    """The pool_9ft table's pocket centres, in the table's order (the action's pocket index)."""
    if not _POCKETS:
        table = games.new_game("nine_ball", 0).to_dict()["table"]
        _POCKETS.extend((float(p["centre"][0]), float(p["centre"][1])) for p in table["pockets"])
    return _POCKETS


_POCKETS: list[tuple[float, float]] = []


def single_ball_state(rng: np.random.Generator) -> Any:
    """A drill: the cue ball and the 1 at random spots at least 0.25 m apart, the 9 parked by the head rail."""
    d = games.new_game("nine_ball", 0).to_dict()
    while True:
        cue = rng.uniform([0.2, 0.15], [_LENGTH - 0.2, _WIDTH - 0.15])
        one = rng.uniform([0.2, 0.15], [_LENGTH - 0.2, _WIDTH - 0.15])
        if np.hypot(*(cue - one)) > 0.25 and min(np.hypot(*(p - np.array([0.06, 0.06]))) for p in (cue, one)) > 0.3:
            break
    still = {"angular_velocity": [0.0, 0.0, 0.0], "velocity": [0.0, 0.0]}
    d["balls"] = [dict(still, id=0, name="cue", position=[float(cue[0]), float(cue[1])]),
                  dict(still, id=1, name="1", position=[float(one[0]), float(one[1])]),
                  dict(still, id=9, name="9", position=[0.06, 0.06])]
    g = d["game"]
    g.update(phase="play", ball_in_hand=None, on=[1], push_out_available=False)
    return games.GameState.from_json(json.dumps(d))


def easiest_pocket(observation: NDArray[np.float32], ball: int = 1) -> int:
    """The pocket with the smallest cut from the cue ball to `ball` (the observation's ball x, y)."""
    def xy(i: int) -> NDArray[np.float64]:
        f = observation[i * 5: i * 5 + 2].astype(np.float64)
        return np.array([(f[0] + 1.0) * _LENGTH / 2.0, (f[1] + 1.0) * _WIDTH / 2.0])
    cue, obj = xy(0), xy(ball)
    best, best_cos = 0, -2.0
    for i, p in enumerate(_pockets()):
        to_pocket = np.array(p) - obj
        to_ball = obj - cue
        c = float(to_pocket @ to_ball / (np.linalg.norm(to_pocket) * np.linalg.norm(to_ball) + 1e-12))
        if c > best_cos:
            best, best_cos = i, c
    return best


def pot_rate(env: CueballEnv, strike: NDArray[np.float64], drills: list[Any]) -> float:
    """The share of `drills` on which `strike` (the five numbers) pots the 1."""
    pots = 0
    for state in drills:
        obs, _ = env.reset(options={"state": state})
        _, reward, _, _, _ = env.step({"strike": strike, "ball": 1, "pocket": easiest_pocket(obs)})
        pots += reward > 0
    return pots / len(drills)


def cross_entropy_method(iterations: int = 8, population: int = 24, drills_per_member: int = 6, elite: float = 0.25,
                         seed: int = 0, noise: Any = None) -> list[dict[str, float]]:
    """Runs the method and returns its curve: per iteration the population's mean pot rate,
    the elite's, and the pot rate of the Gaussian's mean on fresh drills (`evaluation`);
    iteration 0 is the uniform random policy before any learning."""
    rng = np.random.default_rng(seed)
    env = CueballEnv(game="nine_ball", opponent=None, action="target", reward="pots", noise=noise)
    env.reset(seed=seed)
    mean = np.zeros(5)
    std = np.full(5, 0.6)
    n_elite = max(2, int(math.ceil(elite * population)))

    def fresh(n: int) -> list[Any]:
        return [single_ball_state(rng) for _ in range(n)]

    evaluation = fresh(3 * drills_per_member * 4)
    random_members = rng.uniform(-1.0, 1.0, (population, 5))
    random_rates = [pot_rate(env, m, fresh(drills_per_member)) for m in random_members]
    curve = [{"iteration": 0.0, "population": float(np.mean(random_rates)), "elite": float(np.mean(random_rates)),
              "evaluation": float(np.mean(random_rates))}]
    for it in range(1, iterations + 1):
        members = np.clip(rng.normal(mean, std, (population, 5)), -1.0, 1.0)
        drills = fresh(drills_per_member)  # the same drills for every member: a fair comparison
        rates = np.array([pot_rate(env, m, drills) for m in members])
        order = np.argsort(-rates, kind="stable")[:n_elite]
        mean = members[order].mean(axis=0)
        std = members[order].std(axis=0) + 0.05 / it  # Szita and Lorincz's decreasing extra noise
        curve.append({"iteration": float(it), "population": float(rates.mean()), "elite": float(rates[order].mean()),
                      "evaluation": pot_rate(env, mean, evaluation)})
    return curve


if __name__ == "__main__":
    for point in cross_entropy_method(iterations=20, population=40, drills_per_member=10, seed=1):
        print(" ".join(f"{k}={v:.3f}" for k, v in point.items()), flush=True)
