#!/usr/bin/env python3
"""Redraws docs/calibration-held-out.svg, README "Validated against a real match".

The figure: the cumulative distribution of the held-out shots' cue-ball RMSE
on the recorded three-cushion match, for the constants `cueball calibrate`
fits (han_2005 cushion, mathavan_2014 ball-ball contact, 30 training shots,
91 held out: --held-out 0.75 --seed S, one curve a seed) beside the engine's
defaults (the carom_10ft preset, mathavan_2010, coulomb_impulse: strikes
fitted, constants not, on the first seed's held-out shots), with the issue's
goal (median <= 6 cm, p90 <= 20 cm) drawn in.

    python3 tools/calibration_figure.py [--cueball build/release/cueball]
        [--shots ../shared/data/measured-three-cushion/shots.json]
        [--seeds 1 2 3] [--threads 2] [--work DIR] [--out docs/calibration-held-out.svg]

It runs the CLI (one `cueball calibrate ... --json` a seed, ~40-80 s of CPU
each, and one `--evaluate` under the defaults) and gnuplot (gnuplot-nox,
build.sh installs it), both as argument lists, never through a shell. The
reports are kept in --work (default: a fresh temporary directory, removed
afterwards); a report already there is reused, so `--work DIR` twice redraws
without recalibrating. The data and the gnuplot script are written into the
work directory under fixed names, so no path given on the command line
reaches gnuplot's script; the SVG is then copied to --out. The shots file is
read from ../shared and never copied into the repository (it has no licence);
the figure is our own results.
"""

from __future__ import annotations

import argparse
import json
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
DEFAULT_SHOTS = ROOT.parent / "shared" / "data" / "measured-three-cushion" / "shots.json"
MODELS = ["--cushion-model", "han_2005", "--ball-collision-model", "mathavan_2014"]
GOAL_MEDIAN_CM, GOAL_P90_CM = 6.0, 20.0


def run_report(argv: list[str], report: pathlib.Path) -> dict:
    """The CLI's --json report, from `report` when it is there, else by running argv."""
    if not report.exists():
        print("running:", " ".join(argv), file=sys.stderr, flush=True)
        done = subprocess.run(argv, check=True, stdout=subprocess.PIPE)
        report.write_bytes(done.stdout)
    return json.loads(report.read_text())


def held_out_cue_rmse_cm(report: dict, ids: set[str] | None = None) -> list[float]:
    """The cue-ball RMSEs (cm, sorted) of the report's held-out shots, or of the shots in `ids`."""
    values = []
    for shot in report["shots"]:
        chosen = shot["held_out"] if ids is None else str(shot["id"]) in ids
        if chosen and shot["cue_rmse"] is not None:
            values.append(100.0 * shot["cue_rmse"])
    return sorted(values)


def p90(values: list[float]) -> float:
    """The 90th percentile, linear between order statistics (as the CLI's summary)."""
    pos = 0.9 * (len(values) - 1)
    lo = int(pos)
    hi = min(lo + 1, len(values) - 1)
    return values[lo] + (pos - lo) * (values[hi] - values[lo])


def summary(values: list[float]) -> str:
    """The curve's median and p90, for its title and the log."""
    return f"median {statistics.median(values):.1f} cm, p90 {p90(values):.1f} cm"


def write_cdf(path: pathlib.Path, values: list[float]) -> None:
    """The empirical CDF as gnuplot data: value, fraction of shots at or below it."""
    n = len(values)
    path.write_text("".join(f"{v:.4f} {(i + 1) / n:.5f}\n" for i, v in enumerate(values)))


def gnuplot_script(curves: list[tuple[str, str]], shots: int) -> str:
    """The plot of the data files `curves` (file name, title) over `shots` shots; file names fixed here."""
    plots = [f"'{name}' using 1:2 with steps lw 2 title \"{title}\"" for name, title in curves]
    return "\n".join([
        "set terminal svg size 800,560 font 'sans,13' background rgb 'white'",
        "set output 'figure.svg'",
        "set termoption noenhanced",
        "set logscale x",
        "set xrange [0.5:100]",
        "set yrange [0:1]",
        "set xtics (0.5, 1, 2, 5, 10, 20, 50, 100)",
        "set ytics 0.1",
        "set grid xtics ytics lc rgb '#dddddd'",
        "set xlabel 'cue-ball RMSE of a held-out shot (cm)'",
        f"set ylabel 'fraction of the {shots} held-out shots'",
        "set key outside below left Left reverse maxcols 1",
        f"set arrow from {GOAL_MEDIAN_CM},0 to {GOAL_MEDIAN_CM},0.5 nohead dt 2 lw 1.5 lc rgb '#cc0000'",
        f"set arrow from 0.5,0.5 to {GOAL_MEDIAN_CM},0.5 nohead dt 2 lw 1.5 lc rgb '#cc0000'",
        f"set arrow from {GOAL_P90_CM},0 to {GOAL_P90_CM},0.9 nohead dt 2 lw 1.5 lc rgb '#cc0000'",
        f"set arrow from 0.5,0.9 to {GOAL_P90_CM},0.9 nohead dt 2 lw 1.5 lc rgb '#cc0000'",
        f"set label 'goal: median {GOAL_MEDIAN_CM:g} cm' at {GOAL_MEDIAN_CM * 1.08},0.45 tc rgb '#cc0000'",
        f"set label 'goal: p90 {GOAL_P90_CM:g} cm' at {GOAL_P90_CM * 1.08},0.85 tc rgb '#cc0000'",
        "plot " + ", \\\n     ".join(plots),
        "",
    ])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cueball", type=pathlib.Path, default=ROOT / "build" / "release" / "cueball",
                        help="the cueball binary (default: build/release/cueball)")
    parser.add_argument("--shots", type=pathlib.Path, default=DEFAULT_SHOTS,
                        help="the recorded match's tracked shots (default: ../shared/...)")
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3], help="held-out draws, one curve each")
    parser.add_argument("--threads", type=int, default=2, help="the CLI's --threads")
    parser.add_argument("--work", type=pathlib.Path, help="keep (and reuse) the reports and the plot's files here")
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "docs" / "calibration-held-out.svg",
                        help="the SVG to write")
    args = parser.parse_args()
    if not args.shots.is_file():
        print(f"calibration_figure: the shots file {args.shots} is not there (--shots)", file=sys.stderr)
        return 2
    if shutil.which("gnuplot") is None:
        print("calibration_figure: gnuplot is not installed (apt-get install gnuplot-nox)", file=sys.stderr)
        return 2
    work = args.work or pathlib.Path(tempfile.mkdtemp(prefix="cueball-calibration-figure-"))
    work.mkdir(parents=True, exist_ok=True)
    try:
        cli = [str(args.cueball), "calibrate", str(args.shots), "--threads", str(args.threads), "--json"]
        curves = []
        first_ids: set[str] = set()
        for seed in args.seeds:
            report = run_report(cli + MODELS + ["--held-out", "0.75", "--seed", str(seed)], work / f"seed{seed}.json")
            values = held_out_cue_rmse_cm(report)
            if not first_ids:
                first_ids = {str(s["id"]) for s in report["shots"] if s["held_out"]}
            write_cdf(work / f"seed{seed}.dat", values)
            curves.append((f"seed{seed}.dat", f"fitted on 30 shots, --seed {seed}: {summary(values)}"))
            print(f"seed {seed}: {summary(values)} over {len(values)} shots")
        (work / "defaults.scenario.json").write_text('{"table": "carom_10ft"}\n')
        defaults = run_report(cli + ["--evaluate", "--constants", str(work / "defaults.scenario.json")],
                              work / "defaults.json")
        values = held_out_cue_rmse_cm(defaults, first_ids)
        write_cdf(work / "defaults.dat", values)
        curves.append(("defaults.dat", f"defaults, not fitted: {summary(values)}"))
        print(f"defaults, --seed {args.seeds[0]}'s held-out shots: {summary(values)} over {len(values)} shots")
        (work / "figure.gp").write_text(gnuplot_script(curves, len(values)))
        subprocess.run(["gnuplot", "figure.gp"], check=True, cwd=work)
        shutil.copyfile(work / "figure.svg", args.out)
        print(f"wrote {args.out}")
    finally:
        if args.work is None:
            shutil.rmtree(work)
    return 0


if __name__ == "__main__":
    sys.exit(main())
