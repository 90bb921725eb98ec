#!/usr/bin/env python3
"""What a scene does not need (issue 8, item 5): each paper case run for a few steps at
full resolution with its skips (scene.skip_unneeded_stages = true, the default) and
without them, from the same start. Prints, per case, the time per stage both ways, the
speed-up, and how far the two runs' diagnostics differ (they must agree to round-off:
every skip under that key changes nothing else).

    /usr/bin/python3 bench/scene_skips.py [--rouleau build/rouleau] [--threads 1]
        [--steps 10] [--cases aggregation,stack_shear,...] [--out bench/scene_skips.csv]

The skips (rouleau run --explain names them): the Stokes operator as a stencil from one
reference element on a uniform box; the Morse neighbour list rebuilt only when a surface
node has moved half its skin; no inertia stage when the cells are as dense as the fluid;
the RKPM correction only where the plain window does not reproduce linear fields. (The
Stokes limit is a modelling choice, solver.stokes, and stays as the case sets it.)
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile
import time

CASES = ["aggregation", "stack_shear", "twelve_cells", "contraction", "capillary"]
TIME_STEP = re.compile(r"^dt_s\s*=\s*([0-9.eE+-]+)", re.M)
STAGE_LINE = re.compile(r"^\s{2}(\S.*?)\s{2,}([0-9.]+) s$")


def case_time_step(case_file):
    with open(case_file) as f:
        match = TIME_STEP.search(f.read())
    if not match:
        sys.exit(f"scene_skips.py: {case_file}: no time.dt_s")
    return float(match.group(1))


def stage_times(log):
    """The 'time per stage:' table at the end of a run's log, as {stage: seconds}."""
    times, inside = {}, False
    for line in log.splitlines():
        if line.startswith("time per stage:"):
            inside = True
            continue
        if inside:
            match = STAGE_LINE.match(line)
            if not match:
                break
            times[match.group(1).strip()] = float(match.group(2))
    return times


def last_diagnostics(folder):
    with open(os.path.join(folder, "diagnostics.csv")) as f:
        rows = list(csv.DictReader(f))
    return rows[-1]


def is_work_count(column):
    """Columns that count the solver's work or its residuals, not the physical answer:
    they differ by design (the skips change how much is done, GMRES stops at a tolerance)."""
    return column == "step" or any(word in column for word in ("iterations", "residual", "corrected_points",
                                                                 "rebuild"))


def largest_relative_difference(a, b):
    """Over the numeric diagnostics columns: max |a − b| / max(|a|, |b|, 1e-12), and its column."""
    worst, where = 0.0, ""
    for key, value in a.items():
        try:
            x, y = float(value), float(b[key])
        except (TypeError, ValueError):
            continue
        if is_work_count(key) or not (math.isfinite(x) and math.isfinite(y)):
            continue
        scale = max(abs(x), abs(y), 1e-12)
        if abs(x - y) / scale > worst:
            worst, where = abs(x - y) / scale, key
    return worst, where


def run(rouleau, case_file, folder, steps, threads, skip):
    dt = case_time_step(case_file)
    command = [rouleau, "run", case_file, "--out", folder, "--no-progress", "--threads", str(threads),
               "--set", f"time.end_s={steps * dt!r}", "--set", "output.fields=false",
               "--set", "output.diagnostics_every_steps=1",
               "--set", f"scene.skip_unneeded_stages={'true' if skip else 'false'}"]
    start = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"scene_skips.py: {' '.join(command)} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    return wall, stage_times(done.stdout + done.stderr), last_diagnostics(folder)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rouleau", default=os.path.join(root, "build", "rouleau"))
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--steps", type=int, default=10)
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--out", default=os.path.join(root, "bench", "scene_skips.csv"))
    args = parser.parse_args()

    rows = []
    with tempfile.TemporaryDirectory(prefix="rouleau-scene-skips-") as scratch:
        for case in args.cases.split(","):
            case_file = os.path.join(root, "cases", case, "case.toml")
            results = {}
            for skip in (True, False):
                folder = os.path.join(scratch, f"{case}_{'skips' if skip else 'everything'}")
                results[skip] = run(args.rouleau, case_file, folder, args.steps, args.threads, skip)
                print(f"{case}: {'with skips' if skip else 'everything on'}: {results[skip][0]:.1f} s", flush=True)
            (wall_on, stages_on, last_on), (wall_off, stages_off, last_off) = results[True], results[False]
            difference, column = largest_relative_difference(last_on, last_off)
            for stage in sorted(set(stages_on) | set(stages_off)):
                on, off = stages_on.get(stage, 0.0), stages_off.get(stage, 0.0)
                rows.append({"case": case, "stage": stage, "everything_s": off, "skips_s": on,
                             "speedup": off / on if on > 0 else float("nan")})
            rows.append({"case": case, "stage": "whole run (wall)", "everything_s": wall_off, "skips_s": wall_on,
                         "speedup": wall_off / wall_on})
            rows.append({"case": case, "stage": f"largest relative difference of the last diagnostics row ({column})",
                         "everything_s": difference, "skips_s": difference, "speedup": float("nan")})

    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["case", "stage", "everything_s", "skips_s", "speedup"])
        writer.writeheader()
        writer.writerows(rows)
    print(f"\n{args.steps} steps per run, {args.threads} thread(s); wrote {args.out}\n")
    print("| case | stage | everything on (s) | with skips (s) | speed-up |")
    print("|---|---|---|---|---|")
    for r in rows:
        if r["stage"].startswith("largest"):
            print(f"| {r['case']} | {r['stage']} | {r['everything_s']:.1e} | | |")
        elif r["everything_s"] >= 0.01 or r["skips_s"] >= 0.01:
            print(f"| {r['case']} | {r['stage']} | {r['everything_s']:.2f} | {r['skips_s']:.2f} | {r['speedup']:.2f}× |")


if __name__ == "__main__":
    main()
