#!/usr/bin/python3
"""Scaling (bench/scaling.md): time per step against problem size, per stage, with the
slope of log(time) against log(size) fitted for the whole step and for each stage. A
stage whose fitted slope exceeds 1.2 is flagged "grows faster than linear".

Two families, each run with `rouleau run` for a few steps:

  fluid   the empty shear box of cases/shear_flow (40 x 20 x 20 um, periodic in x and z,
          moving walls at y = +/-10 um; Stokes limit, uniform box: the stencil operator and
          the multigrid preconditioner) refined as domain.elements = [2n, n, n], at about
          1e4 x 10^(k/2) fluid unknowns (4 per node) up to --max-unknowns (default 1.2e6,
          so the largest is 1.0e6). Memory is about 4.5 kB per unknown: 1e7 needs ~45 GB,
          and sizes the machine's available memory cannot hold are skipped. (The setup
          grew like n^2.4 until ILU(0)'s triangular-solve schedule became O(nnz): 98 s at
          3.8e5 unknowns then, 3.6 s now.)
          Time step 1e-5 s instead of the case's 0.05 s: the box's diffusion time is
          3.4e-4 s, so every step is a real solve of the developing flow (at 0.05 s the
          flow is steady after two steps and later steps take 1-7 GMRES iterations).
  cells   N = 1, 8, 64 (--many-cells: also 512) normal red cells (paper mesh preset,
          1238 nodes each; volume_modulus_Pa = 150 as in the paper's scenes; the built-in
          density of 1100 kg/m3, so the inertia/buoyancy stage runs) on a k x k x k lattice
          with the spacing of cases/twelve_cells: disc axes along y, stacks 3.96 um between
          centres along y, rims 0.5 um apart in x and z, so that every cell has Morse
          neighbours within the 3 um cut-off. The Morse interaction is on and the coupling
          is semi-implicit, as in the paper's scenes (dt = 1e-3 s, shear rate 3 1/s, GMRES
          to 1e-6). The box is fixed within a study: it holds the largest lattice asked for
          (1 um of plasma beyond it in x and z, 2 um to the walls in y) at h_f of about
          1.5 um (the scenes use 1 um), so that the fluid stays small (35 k unknowns for 64
          cells, 212 k for 512) and the same while the cells grow. Smaller N fill the
          centre of that lattice. The case is written to a temporary TOML file. Up to 32
          cells (output.cell_gaps_max_cells) every diagnostics row measures the gap of
          every pair of cells, brute force (about 30 ms per pair on one core); with more
          cells the gaps are left out.

Each run makes --steps steps (default 6, even) with a diagnostics row at the middle and at
the end. The first half is warm-up: step 1 (backward Euler) and step 2 (BDF2) each build
the preconditioner, step 1 builds the Morse neighbour list. Reported per step (second
half only unless marked):
  step         the whole step, from the rows' wall_time_s, less the cell-gap
               diagnostics of the middle row (one fluid diagnostics row per half-run stays in);
  STAGE        each stage of the run's diagnostics columns (time_<stage>_s), second half;
  cell stiffness (semi-implicit)   from the run log's "time per stage" (no column): the
               mean over all steps, warm-up included;
per diagnostics row: cell diagnostics (gaps and contact areas of every pair of cells);
per run: the setup stages of the log (mesh, fluid setup, cell meshes, coupling setup).
Peak memory (the run's maximum resident set) and the run's wall time are in the CSV.

    /usr/bin/python3 bench/scaling.py [--rouleau build/rouleau] [--threads 2] [--steps 6]
        [--quick] [--max-unknowns 1.2e6] [--many-cells] [--out bench/scaling.csv]
                                                             (figure beside it, .png)

--quick: fluid at 1e4, 3e4, 1e5 unknowns and 1, 8 cells (in the 8-cell box); 40 s on one
thread. Exit code 1 if a run failed.
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

import numpy as np

from run_log import stage_times

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FLUID_CASE = os.path.join(ROOT, "cases", "shear_flow", "case.toml")
FLUID_TIME_STEP_S = 1e-5
# Peak resident memory of the fluid runs, measured: 118 MB at 1.5e4 unknowns, 562 MB at
# 1.15e5, 1.72 GB at 3.8e5 (one thread): about 4.4 kB per unknown.
MEMORY_PER_UNKNOWN_B = 4.5e3
MEMORY_BASE_B = 80e6

# The cell lattice of cases/twelve_cells: disc axes along y (orientation [90, 0, 0]).
LATTICE_SPACING_UM = (8.32, 3.96, 8.32)
PLASMA_MARGIN_UM = (1.0, 2.0, 1.0)  # beyond the lattice cells: to the periodic sides, to the walls
CELL_BOX_ELEMENT_UM = 1.5
CELL_SHEAR_RATE = 3.0
CELL_TIME_STEP_S = 1e-3

UNKNOWNS = re.compile(r"fluid mesh: .*?(\d+) unknowns")
SETUP_STAGES = ("mesh", "fluid setup", "cell meshes", "coupling setup")
PER_ROW_STAGES = ("cell diagnostics",)
LOG_ONLY_STEP_STAGES = ("cell stiffness (semi-implicit)",)  # per step, but no diagnostics column
WHOLE_STEP = "step"
PER_STEP, PER_STEP_ALL, PER_ROW, PER_RUN = "per step", "per step (all steps)", "per row", "per run"
FASTER_THAN_LINEAR = 1.2
MIN_FIT_SECONDS = 1e-4  # below this a stage time is timer noise; left out of the fits


def fluid_unknowns(n):
    """Unknowns of the shear box at elements [2n, n, n]: periodic in x and z, walls in y."""
    return 4 * (2 * n) * (n + 1) * n


def fluid_sizes(max_unknowns, quick):
    """The n of each fluid run: about 1e4 × 10^(k/2) unknowns, up to max_unknowns."""
    sizes, k = [], 0
    while True:
        target = 1e4 * 10 ** (k / 2)
        n = max(2, round((target / 8) ** (1 / 3)))
        if fluid_unknowns(n) > max_unknowns or (quick and len(sizes) == 3):
            return sizes
        sizes.append(n)
        k += 1


def cell_counts(quick, many):
    return [1, 8] if quick else [1, 8, 64] + ([512] if many else [])


def lattice_side(count):
    side = round(count ** (1 / 3))
    if side ** 3 != count:
        sys.exit(f"scaling.py: {count} cells do not fill a cube lattice")
    return side


def cells_case_toml(count, box_side, steps):
    """A shear box holding a box_side³ lattice of cells, with `count` of them at its centre."""
    extent = [box_side * s + 2 * m for s, m in zip(LATTICE_SPACING_UM, PLASMA_MARGIN_UM)]
    elements = [math.ceil(e / CELL_BOX_ELEMENT_UM) for e in extent]
    wall_speed = CELL_SHEAR_RATE * extent[1] / 2
    side = lattice_side(count)
    lines = [
        f"# Written by bench/scaling.py: {count} normal cells of a {box_side}^3 lattice box.",
        "[case]", f'name = "scaling_{count}_cells"',
        "[fluid]", "density_kg_m3 = 1025", "viscosity_Pa_s = 1.2e-3",
        "[domain]", f"lower_um = {[-e / 2 for e in extent]!r}", f"upper_um = {[e / 2 for e in extent]!r}",
        f"elements = {elements!r}"]
    for side_name in ("x_min", "x_max", "z_min", "z_max"):
        lines += [f"[boundary.{side_name}]", 'type = "periodic"']
    for side_name, sign in (("y_min", -1), ("y_max", 1)):
        lines += [f"[boundary.{side_name}]", 'type = "wall"', f"velocity_um_s = [{sign * wall_speed!r}, 0.0, 0.0]"]
    lines += ["[cell_kinds.normal]", "volume_modulus_Pa = 150",
              "[interaction]", "enabled = true",
              "[solver]", "gmres_rtol = 1e-6",
              "[coupling]", 'scheme = "semi_implicit"',
              "[time]", 'scheme = "bdf2"', f"dt_s = {CELL_TIME_STEP_S!r}", f"end_s = {steps * CELL_TIME_STEP_S!r}",
              "[output]", "fields = false", f"diagnostics_every_steps = {steps // 2}",
              "[checkpoint]", "every_minutes = 0"]
    offset = (side - 1) / 2
    for i in range(side):
        for j in range(side):
            for k in range(side):
                center = [(a - offset) * s for a, s in zip((i, j, k), LATTICE_SPACING_UM)]
                lines += ["[[cells]]", 'kind = "normal"', f"center_um = {center!r}",
                          "orientation_deg = [90.0, 0.0, 0.0]"]
    return "\n".join(lines) + "\n"


def available_memory_bytes():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) * 1024
    return float("inf")


def run_rouleau(rouleau, case_file, folder, threads, settings):
    """Runs one case; returns (exit code, log text, peak resident memory in MB, wall seconds)."""
    command = [rouleau, "run", case_file, "--out", folder, "--overwrite", "--no-progress", "--threads", str(threads)]
    command += [a for s in settings for a in ("--set", s)]
    # Beside the run's folder: a run starts only in an empty folder (or empties it).
    log_path = folder.rstrip("/") + ".log"
    start = time.monotonic()
    with open(log_path, "w") as log:
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
    wall = time.monotonic() - start
    with open(log_path) as f:
        text = f.read()
    return process.returncode, text, usage.ru_maxrss / 1024.0, wall


def stage_column(stage):
    """The diagnostics column of a stage, as src/run/run_diagnostics.cpp names it."""
    return "time_" + re.sub(r"[^0-9a-z]", "_", stage.lower()) + "_s"


def measure(folder, log, steps):
    """{(stage, basis): seconds} of one finished run, and the last step's GMRES iterations."""
    with open(os.path.join(folder, "diagnostics.csv")) as f:
        rows = list(csv.DictReader(f))
    middle = next(r for r in rows if int(r["step"]) == steps // 2)
    last = rows[-1]
    measured = steps - steps // 2
    totals = stage_times(log)
    gaps_per_row = sum(totals.get(s, 0.0) for s in PER_ROW_STAGES) / len(rows)
    # The window between the rows holds the middle row's diagnostics (its wall time is read first).
    window = float(last["wall_time_s"]) - float(middle["wall_time_s"])
    times = {(WHOLE_STEP, PER_STEP): (window - gaps_per_row) / measured}
    for stage, seconds in totals.items():
        if stage_column(stage) in last:
            times[(stage, PER_STEP)] = float(last[stage_column(stage)]) / measured
        elif stage in LOG_ONLY_STEP_STAGES:
            times[(stage, PER_STEP_ALL)] = seconds / steps
        elif stage in PER_ROW_STAGES:
            times[(stage, PER_ROW)] = seconds / len(rows)
        elif stage in SETUP_STAGES:
            times[(stage, PER_RUN)] = seconds
    return times, last.get("gmres_iterations", "")


def slope(sizes, seconds):
    """Least-squares slope of log(seconds) against log(size) over the points above the
    noise floor, and the slope between the two largest of them (None when < 2 points)."""
    points = [(x, y) for x, y in zip(sizes, seconds) if y >= MIN_FIT_SECONDS]
    if len(points) < 2:
        return None, None
    x, y = np.log([p[0] for p in points]), np.log([p[1] for p in points])
    return float(np.polyfit(x, y, 1)[0]), float((y[-1] - y[-2]) / (x[-1] - x[-2]))


def runs(args):
    """(family, size, label, case file or None, settings, cell count) of every run, in order."""
    planned = []
    for n in fluid_sizes(args.max_unknowns, args.quick):
        settings = [f"domain.elements=[{2 * n},{n},{n}]", f"time.dt_s={FLUID_TIME_STEP_S!r}",
                    f"time.end_s={args.steps * FLUID_TIME_STEP_S!r}", "output.fields=false",
                    f"output.diagnostics_every_steps={args.steps // 2}", "checkpoint.every_minutes=0"]
        planned.append(("fluid", fluid_unknowns(n), f"elements [{2 * n},{n},{n}]", FLUID_CASE, settings, 0))
    counts = cell_counts(args.quick, args.many_cells)
    for count in counts:
        planned.append(("cells", count, f"{count} cells", None, [], count))
    return planned, lattice_side(max(counts))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rouleau", default=os.path.join(ROOT, "build", "rouleau"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--steps", type=int, default=6, help="steps per run, even; the first half is warm-up")
    parser.add_argument("--quick", action="store_true", help="three fluid sizes up to 1e5 unknowns, 1 and 8 cells")
    parser.add_argument("--max-unknowns", type=float, default=1.2e6, help="largest fluid size (default 1.2e6)")
    parser.add_argument("--many-cells", action="store_true", help="add 512 cells")
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "scaling.csv"))
    args = parser.parse_args()
    if args.steps < 4 or args.steps % 2:
        sys.exit("scaling.py: --steps must be even and at least 4 (the first half is warm-up)")

    planned, box_side = runs(args)
    rows, failures = [], 0
    with tempfile.TemporaryDirectory(prefix="rouleau-scaling-") as scratch:
        for family, size, label, case_file, settings, count in planned:
            folder = os.path.join(scratch, f"{family}_{size}")
            if family == "fluid":
                need = MEMORY_BASE_B + MEMORY_PER_UNKNOWN_B * size
                if need > 0.9 * available_memory_bytes():
                    print(f"{family} {label}: skipped, needs about {need / 1e9:.1f} GB", flush=True)
                    continue
            else:
                case_file = os.path.join(scratch, f"cells_{count}.toml")
                with open(case_file, "w") as f:
                    f.write(cells_case_toml(count, box_side, args.steps))
            code, log, memory_mb, wall = run_rouleau(args.rouleau, case_file, folder, args.threads, settings)
            if code != 0:
                failures += 1
                print(f"{family} {label}: FAILED with exit code {code}:\n{log[-2000:]}", flush=True)
                continue
            times, iterations = measure(folder, log, args.steps)
            unknowns = int(UNKNOWNS.search(log).group(1))
            for (stage, basis), seconds in times.items():
                rows.append({"family": family, "size": unknowns if family == "fluid" else count,
                             "fluid_unknowns": unknowns, "cells": count, "stage": stage, "basis": basis,
                             "seconds": seconds, "gmres_iterations_last_step": iterations,
                             "peak_memory_MB": round(memory_mb, 1), "run_wall_s": round(wall, 2)})
            print(f"{family} {label}: {unknowns} fluid unknowns, {times[(WHOLE_STEP, PER_STEP)]:.3f} s per step, "
                  f"peak memory {memory_mb:.0f} MB, run {wall:.1f} s", flush=True)

    if not rows:
        sys.exit("scaling.py: no run finished")
    add_slopes(rows)
    part = args.out + ".part"
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(part, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    os.replace(part, args.out)
    print_tables(rows, args)
    plot(rows, os.path.splitext(args.out)[0] + ".png", args)
    print(f"wrote {args.out} and its .png; {len(planned)} runs, {failures} failed")
    return 1 if failures else 0


def series(rows):
    """{(family, stage, basis): [(size, seconds), ...] by size}, in the order first seen."""
    found = {}
    for r in rows:
        found.setdefault((r["family"], r["stage"], r["basis"]), []).append((r["size"], r["seconds"]))
    return {key: sorted(points) for key, points in found.items()}


def worth_showing(basis, points):
    """Stages shown in the table and the figure (all are in the CSV): above the noise floor
    somewhere, and setup stages only when they take 10 ms or more."""
    return max(p[1] for p in points) >= (1e-2 if basis == PER_RUN else MIN_FIT_SECONDS)


def add_slopes(rows):
    slopes = {key: slope([p[0] for p in points], [p[1] for p in points]) for key, points in series(rows).items()}
    for r in rows:
        fitted, last = slopes[(r["family"], r["stage"], r["basis"])]
        r["slope"] = "" if fitted is None else round(fitted, 3)
        r["slope_last_two"] = "" if last is None else round(last, 3)


def print_tables(rows, args):
    print(f"\n{args.threads} thread(s), {args.steps} steps per run (per step: the second half); seconds")
    for family, size_name in (("fluid", "unknowns"), ("cells", "cells")):
        mine = [r for r in rows if r["family"] == family]
        if not mine:
            continue
        sizes = sorted({r["size"] for r in mine})
        print(f"\n| {family}: stage | basis | " + " | ".join(f"{s:g} {size_name}" for s in sizes) +
              " | slope | slope, last two | |")
        print("|---|---|" + "---|" * len(sizes) + "---|---|---|")
        for (fam, stage, basis), points in series(rows).items():
            if fam != family or not worth_showing(basis, points):
                continue
            by_size = dict(points)
            first = next(r for r in mine if r["stage"] == stage and r["basis"] == basis)
            fitted = first["slope"]
            flag = "grows faster than linear" if fitted != "" and fitted > FASTER_THAN_LINEAR else ""
            values = " | ".join(f"{by_size[s]:.4g}" if s in by_size else "–" for s in sizes)
            slopes = f"{fitted} | {first['slope_last_two']}" if fitted != "" else "– | –"
            print(f"| {stage} | {basis} | {values} | {slopes} | {flag} |")
        for s in sizes:
            r = next(r for r in mine if r["size"] == s)
            fluid = f", {r['fluid_unknowns']} fluid unknowns" if family == "cells" else ""
            print(f"  {s:g} {size_name}{fluid}: GMRES iterations (last step) {r['gmres_iterations_last_step']}, "
                  f"peak memory {r['peak_memory_MB']:.0f} MB, run {r['run_wall_s']:.1f} s")


def plot(rows, path, args):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import NullFormatter
    figure, axes = plt.subplots(1, 2, figsize=(14, 6))
    styles = {PER_STEP: "-", PER_STEP_ALL: "-.", PER_ROW: ":", PER_RUN: "--"}
    colors = iter(plt.cm.tab10.colors * 3)
    for ax, family, xlabel in ((axes[0], "fluid", "fluid unknowns"), (axes[1], "cells", "cells (normal RBCs)")):
        for (fam, stage, basis), points in series(rows).items():
            points = [p for p in points if p[1] >= MIN_FIT_SECONDS]
            if fam != family or len(points) < 2 or not worth_showing(basis, points):
                continue
            fitted = next(r["slope"] for r in rows if (r["family"], r["stage"], r["basis"]) == (fam, stage, basis))
            x, y = zip(*points)
            whole = stage == WHOLE_STEP
            ax.plot(x, y, styles[basis], marker="o", linewidth=2.5 if whole else 1.2,
                    color="k" if whole else next(colors), label=f"{stage} ({basis}), slope {fitted:.2f}")
            if whole:
                ax.plot([x[0], x[-1]], [y[0], y[0] * x[-1] / x[0]], color="0.5", linestyle=(0, (2, 2)), linewidth=1,
                        label="slope 1 through the first step time")
        sizes = sorted({r["size"] for r in rows if r["family"] == family})
        ax.set_xscale("log")
        ax.set_yscale("log")
        if sizes:
            ax.set_xticks(sizes)
            ax.set_xticklabels([f"{s:.3g}" for s in sizes])
            ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_xlabel(xlabel)
        ax.set_ylabel("seconds")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    axes[0].set_title(f"empty shear box, refined ({args.threads} thread(s))")
    axes[1].set_title(f"cells in a fixed box, semi-implicit, Morse on ({args.threads} thread(s))")
    figure.tight_layout()
    figure.savefig(path + ".part.png", dpi=100)
    os.replace(path + ".part.png", path)


if __name__ == "__main__":
    sys.exit(main())
