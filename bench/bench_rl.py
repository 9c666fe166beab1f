#!/usr/bin/env python3
"""cueball.rl against the physics it drives, side by side in one process.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_rl.py [--steps 2000] [--tables 64] [--rounds 3]

1. CueballEnv.step (9-ball, self-play, random actions with the discrete parts
   drawn within the masks) against cueball.simulate() of the very shots those
   steps played (the recommended breaks of the resets included; prepared
   Scenario objects), per env step (issue 26: goal <= 2x).
2. VectorEnv.step of --tables tables on 1 and 2 threads: env steps a second
   (issue 26: goal >= 20,000 on 2 cores), against simulate() of the same shots
   on one thread.
Each round runs every part once, in alternating order; medians are printed.
"""

import argparse
import statistics
import time

import numpy as np

import cueball
from cueball import rl


def masked(rng, mask):
    a = {"strike": rng.uniform(-1, 1, 5), "place": rng.uniform(-1, 1, 2)}
    for key in ("ball", "pocket", "decision", "push_out"):
        allowed = np.flatnonzero(mask[key])
        a[key] = int(rng.choice(allowed)) if allowed.size else 0
    return a


def env_workload(steps, record):
    """Runs `steps` env steps; returns (seconds, shots played as Scenario objects when recording)."""
    env = rl.CueballEnv(opponent=None, render_mode="html" if record else None)
    rng = np.random.default_rng(1)
    obs, info = env.reset(seed=1)
    shots = []
    seconds = 0.0  # env.step and env.reset only (the random actions are the learner's cost)
    for _ in range(steps):
        action = masked(rng, info["action_mask"])
        start = time.perf_counter()
        obs, reward, terminated, truncated, info = env.step(action)
        seconds += time.perf_counter() - start
        if terminated or truncated:
            if record:
                shots += env._table.shots()
            start = time.perf_counter()
            obs, info = env.reset()
            seconds += time.perf_counter() - start
    if record:
        shots += env._table.shots()
    return seconds, [cueball.Scenario.from_json(s) for s in shots]


def simulate_all(shots):
    start = time.perf_counter()
    for s in shots:
        cueball.simulate(s)
    return time.perf_counter() - start


def vector_workload(tables, threads, steps):
    v = rl.VectorEnv(tables, opponent=None, threads=threads, seed=3)
    obs, info = v.reset(seed=3)
    n = 0
    start = time.perf_counter()
    while n < steps:
        obs, reward, terminated, truncated, info = v.step(v.sample_actions(info["action_mask"]))
        n += tables
    return n / (time.perf_counter() - start)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--steps", type=int, default=2000)
    p.add_argument("--tables", type=int, default=64)
    p.add_argument("--rounds", type=int, default=3)
    args = p.parse_args()
    _, shots = env_workload(args.steps, record=True)
    print(f"{args.steps} env steps played {len(shots)} shots (breaks included)")
    env_s, sim_s, v1, v2 = [], [], [], []
    for r in range(args.rounds):
        parts = [lambda: env_s.append(env_workload(args.steps, record=False)[0]),
                 lambda: sim_s.append(simulate_all(shots)),
                 lambda: v1.append(vector_workload(args.tables, 1, 20 * args.tables)),
                 lambda: v2.append(vector_workload(args.tables, 2, 20 * args.tables))]
        for part in (parts if r % 2 == 0 else parts[::-1]):
            part()
    e, s = statistics.median(env_s), statistics.median(sim_s)
    print(f"CueballEnv.step      {1e6 * e / args.steps:8.1f} us a step")
    print(f"simulate() its shots {1e6 * s / args.steps:8.1f} us a step ({len(shots) / args.steps:.2f} shots a step)")
    print(f"ratio env / simulate  {e / s:.2f}  (goal <= 2)")
    print(f"VectorEnv x{args.tables}, 1 thread  {statistics.median(v1):9.0f} env steps/s")
    print(f"VectorEnv x{args.tables}, 2 threads {statistics.median(v2):9.0f} env steps/s")
    print(f"simulate() alone, 1 thread {len(shots) / s:9.0f} shots/s")


if __name__ == "__main__":
    main()
