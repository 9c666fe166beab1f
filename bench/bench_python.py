#!/usr/bin/env python3
"""The built-in 9-ball break through cueball.simulate() against the library's
run_scenario() in C++, in one process (issue 12: goal within 1.3x).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_python.py [--runs 7] [--reps 300]

Each of --runs rounds times --reps calls of each, one after the other; the
medians of the times and of each round's ratio to run_scenario are printed.
"simulate()" is the call alone (the Result's arrays are built on first
access); "+ arrays" also reads events and balls; "+ to_dict()" is the JSON
form the module returned before the Result object.
"""

import argparse
import statistics
import time

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


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--reps", type=int, default=300)
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


if __name__ == "__main__":
    main()
