#!/usr/bin/python3
"""What a scene does not need (bench/scenes.md): each paper case run for a few steps at
full resolution with its skips (scene.skip_unneeded_stages = true, the default; the
"variant") and without them (the "baseline"), from the same start. Prints, per case, the time per stage both ways, the
speed-up, and how far the two runs' diagnostics differ (they must agree to round-off:
every skip under that key changes nothing else).

    /usr/bin/python3 bench/scene_skips.py [--rouleau build/rouleau] [--threads 1]
        [--steps 10] [--cases aggregation,stack_shear,...] [--out bench/scene_skips.csv]

Any other pair of settings compares the same way, e.g. the two scalable preconditioners:

    /usr/bin/python3 bench/scene_skips.py --baseline 'solver.preconditioner="ilu0"' \
        --variant 'solver.preconditioner="multigrid"' --out bench/preconditioners.csv

and the variant may run under a launcher, e.g. on two MPI ranks against one (bench/mpi.md):

    /usr/bin/python3 bench/scene_skips.py --baseline 'solver.preconditioner="block_jacobi"' \
        --variant 'solver.preconditioner="block_jacobi"' \
        --variant-launcher 'mpiexec -n 2 --oversubscribe' --out bench/mpi_scenes.csv

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
import shlex
import subprocess
import sys
import tempfile
import time

from run_log import case_time_step, stage_times

CASES = ["aggregation", "stack_shear", "twelve_cells", "contraction", "capillary"]




def last_diagnostics(folder):
    with open(os.path.join(folder, "diagnostics.csv")) as f:
        rows = list(csv.DictReader(f))
    return rows[-1]


def is_work_count(column):
    """Columns that count the solver's work, its residuals or its run times, not the physical
    answer: they differ by design (the skips change how much is done, GMRES stops at a
    tolerance)."""
    if column == "wall_time_s" or (column.startswith("time_") and column != "time_s"):
        return True  # run times, not results
    return column == "step" or any(word in column for word in ("iterations", "residual", "corrected_points",
                                                                 "rebuild"))


def largest_relative_difference(a, b):
    """Over the numeric diagnostics columns whose magnitude reaches 1e-6 in their own unit
    (μm, s, pN, Pa, ...; below that a quantity is zero for this physics, and a relative
    difference of it means nothing): max |a − b| / max(|a|, |b|), and that column's values."""
    worst, where = 0.0, ""
    for key, value in a.items():
        try:
            x, y = float(value), float(b[key])
        except (TypeError, ValueError):
            continue
        if is_work_count(key) or not (math.isfinite(x) and math.isfinite(y)):
            continue
        scale = max(abs(x), abs(y))
        if scale >= 1e-6 and abs(x - y) / scale > worst:
            worst, where = abs(x - y) / scale, f"{key}: {y:.9g} vs {x:.9g}"
    return worst, where


def run(rouleau, case_file, folder, steps, threads, setting, launcher=""):
    dt = case_time_step(case_file)
    command = shlex.split(launcher) + [rouleau, "run", case_file, "--out", folder, "--no-progress", "--threads", str(threads),
               "--set", f"time.end_s={steps * dt!r}", "--set", "output.fields=false",
               "--set", "output.diagnostics_every_steps=1", "--set", setting]
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
    parser.add_argument("--baseline", default="scene.skip_unneeded_stages=false",
                        help="the --set of the reference runs (default: everything on)")
    parser.add_argument("--variant", default="scene.skip_unneeded_stages=true",
                        help="the --set of the runs compared with it (default: the scene's skips)")
    parser.add_argument("--variant-launcher", default="",
                        help="a command the variant runs under (e.g. 'mpiexec -n 2'; default: none)")
    args = parser.parse_args()

    rows = []
    with tempfile.TemporaryDirectory(prefix="rouleau-scene-skips-") as scratch:
        for case in args.cases.split(","):
            case_file = os.path.join(root, "cases", case, "case.toml")
            results = {}
            for name, setting, launcher in (("variant", args.variant, args.variant_launcher),
                                            ("baseline", args.baseline, "")):
                folder = os.path.join(scratch, f"{case}_{name}")
                results[name] = run(args.rouleau, case_file, folder, args.steps, args.threads, setting, launcher)
                print(f"{case}: {launcher + ' ' if launcher else ''}{setting}: {results[name][0]:.1f} s", flush=True)
            (wall_on, stages_on, last_on), (wall_off, stages_off, last_off) = results["variant"], results["baseline"]
            difference, column = largest_relative_difference(last_on, last_off)
            iterations = (last_off.get("gmres_iterations", ""), last_on.get("gmres_iterations", ""))
            for stage in sorted(set(stages_on) | set(stages_off)):
                on, off = stages_on.get(stage, 0.0), stages_off.get(stage, 0.0)
                rows.append({"case": case, "stage": stage, "baseline_s": off, "variant_s": on,
                             "speedup": off / on if on > 0 else float("nan")})
            rows.append({"case": case, "stage": "whole run (wall)", "baseline_s": wall_off, "variant_s": wall_on,
                         "speedup": wall_off / wall_on})
            rows.append({"case": case, "stage": "GMRES iterations, last step", "baseline_s": iterations[0],
                         "variant_s": iterations[1], "speedup": float("nan")})
            rows.append({"case": case, "stage": f"largest relative difference of the last diagnostics row ({column})",
                         "baseline_s": difference, "variant_s": difference, "speedup": float("nan")})

    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["case", "stage", "baseline_s", "variant_s", "speedup"])
        writer.writeheader()
        writer.writerows(rows)
    print(f"\n{args.steps} steps per run, {args.threads} thread(s); baseline {args.baseline}, variant "
          f"{args.variant}{' under ' + args.variant_launcher if args.variant_launcher else ''}; wrote {args.out}\n")
    print("| case | stage | baseline (s) | variant (s) | speed-up |")
    print("|---|---|---|---|---|")
    for r in rows:
        if r["stage"].startswith("largest"):
            print(f"| {r['case']} | {r['stage']} | {r['baseline_s']:.1e} | | |")
        elif r["stage"].startswith("GMRES"):
            print(f"| {r['case']} | {r['stage']} | {r['baseline_s']} | {r['variant_s']} | |")
        elif r["baseline_s"] >= 0.01 or r["variant_s"] >= 0.01:
            print(f"| {r['case']} | {r['stage']} | {r['baseline_s']:.2f} | {r['variant_s']:.2f} | {r['speedup']:.2f}× |")


if __name__ == "__main__":
    main()
