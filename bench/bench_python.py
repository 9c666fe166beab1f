#!/usr/bin/env python3
"""The Python module against the C++ library, side by side in one process.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_python.py
        [--runs 7] [--reps 300] [--many-shots 100000] [--threads 2] [--dask-shots 40000]

1. The built-in 9-ball break through cueball.simulate() against the library's
   run_scenario() in C++ (issue 12: goal within 1.3x). Each of --runs rounds
   times --reps calls of each, one after the other; the medians of the times
   and of each round's ratio to run_scenario are printed. "simulate()" is the
   call alone (the Result's arrays are built on first access); "+ arrays" also
   reads events and balls; "+ to_dict()" is the JSON form the module returned
   before the Result object.
2. simulate_many of --many-shots noisy breaks (the break's resolved strike as
   every row's action, noise on) against simulate_batch, the C++ batch, on the
   same shots and --threads threads (goal: >= 0.9x its throughput). Two
   rounds of half the shots each, in alternating order.
3. cueball.dask.simulate_many of --dask-shots noisy breaks on a LocalCluster of
   1 and of 2 worker processes (one thread each), against a local
   simulate_many on one thread (goal: 2 workers >= 1.7x one). 0 skips it.
"""

import argparse
import logging
import statistics
import time
import warnings

import numpy as np

import cueball


def per_call(fn, reps):
    start = time.perf_counter()
    for _ in range(reps):
        fn()
    return (time.perf_counter() - start) / reps


def with_arrays():
    r = cueball.simulate()
    r.events
    r.balls


def break_actions(shots):
    """Every row the built-in break's strike as it was resolved (aim at the 1-ball)."""
    strike = cueball.simulate().to_dict()["cue_strike"]["resolved"]
    row = [strike["speed"], strike["aim_deg"], strike["elevation_deg"], strike["side"], strike["height"]]
    return np.tile(np.array(row, dtype=np.float64), (shots, 1))


def many_vs_batch(shots, threads):
    half = max(1, shots // 2)
    actions = break_actions(half)
    rate = {"simulate_batch (C++ batch)": [], "simulate_many": []}
    for order in (0, 1):
        for name in sorted(rate, reverse=bool(order)):
            start = time.perf_counter()
            if name == "simulate_many":
                cueball.simulate_many(None, actions, threads=threads, seed=order, noise=True)
            else:
                cueball.simulate_batch(None, shots=half, threads=threads, seed=order)
            rate[name].append(half / (time.perf_counter() - start))
    print(f"{2 * half} noisy breaks on {threads} threads, two rounds of {half}")
    base = sum(rate["simulate_batch (C++ batch)"])
    for name, r in rate.items():
        print(f"  {name:26s} {sum(r) / 2:9.0f} shots/s   {sum(r) / base:5.2f}x")


def dask_workers(shots):
    from distributed import Client, LocalCluster

    import cueball.dask

    actions = break_actions(shots)
    start = time.perf_counter()
    local = cueball.simulate_many(None, actions, seed=1, noise=True)
    rows = [("local simulate_many, 1 thread", shots / (time.perf_counter() - start))]
    for workers in (1, 2):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)
            with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                              silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
                cueball.dask.simulate_many(client, None, actions[: 8 * workers], seed=1, noise=True)  # warm up
                out = cueball.dask.simulate_many(client, None, actions, seed=1, noise=True)
        assert out["final_position"].tobytes() == local["final_position"].tobytes()
        rows.append((f"cueball.dask, {workers} worker{'s' if workers > 1 else ''}", out["shots_per_second"]))
    print(f"{shots} noisy breaks through cueball.dask (LocalCluster, one thread per worker process)")
    one = rows[1][1]
    for name, rate in rows:
        print(f"  {name:30s} {rate:9.0f} shots/s   {rate / one:5.2f}x one worker")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--reps", type=int, default=300)
    ap.add_argument("--many-shots", type=int, default=100_000)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--dask-shots", type=int, default=40_000)
    args = ap.parse_args()
    cueball.simulate()  # warm up (and read the built-in break once)
    rows = {"run_scenario (C++)": [], "simulate()": [], "simulate() + arrays": [], "simulate() + to_dict()": []}
    for _ in range(args.runs):
        rows["run_scenario (C++)"].append(cueball._time_run_scenario(None, args.reps))
        rows["simulate()"].append(per_call(cueball.simulate, args.reps))
        rows["simulate() + arrays"].append(per_call(with_arrays, args.reps))
        rows["simulate() + to_dict()"].append(per_call(lambda: cueball.simulate().to_dict(), max(1, args.reps // 5)))
    base = rows["run_scenario (C++)"]
    print(f"built-in 9-ball break, medians of {args.runs} rounds of {args.reps} calls each")
    print(f"  {'':24s} {'time':>11s}   ratio to run_scenario (median of the rounds' ratios)")
    for name, times in rows.items():
        ratio = statistics.median(t / b for t, b in zip(times, base))
        print(f"  {name:24s} {statistics.median(times) * 1e3:8.3f} ms   {ratio:5.2f}x")
    if args.many_shots > 0:
        many_vs_batch(args.many_shots, args.threads)
    if args.dask_shots > 0:
        dask_workers(args.dask_shots)


if __name__ == "__main__":
    main()
