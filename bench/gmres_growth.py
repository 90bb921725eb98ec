#!/usr/bin/python3
"""How the GMRES iterations of a coupled step grow with the number of cells and with their
stiffness (bench/scenes.md): the four-cell stack's scene (cases/stack_shear: 0.5 1/s,
h_f = 1 um, the semi-implicit coupling, the Morse interaction, dt = 2e-3 s) in one larger
box, 40 x 20 x 40 um (134,400 unknowns), holding 1, 4, 12 and 64 cells (a single cell, then
columns of four stacked cells 3.96 um apart, as in the paper's rouleaux), and the four-cell
column with a membrane ten times stiffer.

    /usr/bin/python3 bench/gmres_growth.py [--steps 12] [--threads 1] [--out bench/gmres_growth.csv]

GMRES iterations do not depend on the machine's load, so this study may run beside other
work (it is not a timing). Per variant it reports the iterations of every step and their mean
over steps 3 to the last (the first two steps start the flow and the cells' response). The
bounds it is judged by are written below, before any run.
"""
import argparse
import csv
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASE = os.path.join(ROOT, "cases", "stack_shear", "case.toml")
# Bounds: the mean iterations per step may differ by at most this factor between any two cell
# counts, and between the normal and the ten times stiffer membrane.
BOUND_CELL_COUNT = 1.5
BOUND_STIFFNESS = 2.0
NORMAL_MEMBRANE_SHEAR_MODULUS = 4.2  # pN/um, the default of cell kind "normal"
BOX = ["domain.lower_um=[-20.0, -10.0, -20.0]", "domain.upper_um=[20.0, 10.0, 20.0]", "domain.elements=[40, 20, 40]"]
STACK_HEIGHTS = [-5.94, -1.98, 1.98, 5.94]  # um, four cells 3.96 um apart across the shear plane


def columns(xs, zs):
    """Columns of four stacked cells (discs facing y) at every (x, z)."""
    return [(x, y, z) for x in xs for z in zs for y in STACK_HEIGHTS]


# 1 cell; one column; three columns side by side along the flow 8.32 um apart (the paper's
# twelve-cell aggregate); sixteen columns, 4 along the flow by 4 along the vorticity.
ARRANGEMENTS = {1: [(0.0, 0.0, 0.0)], 4: columns([0.0], [0.0]), 12: columns([-8.32, 0.0, 8.32], [0.0]),
                64: columns([-12.48, -4.16, 4.16, 12.48], [-15.0, -5.0, 5.0, 15.0])}


def cells_setting(centres):
    cells = ", ".join(f'{{kind = "normal", center_um = [{x}, {y}, {z}], orientation_deg = [90.0, 0.0, 0.0]}}'
                      for x, y, z in centres)
    return f"cells=[{cells}]"


def run(rouleau, folder, steps, threads, settings):
    command = [rouleau, "run", CASE, "--out", folder, "--overwrite", "--no-progress", "--threads", str(threads),
               "--set", f"time.end_s={steps * 2.0e-3!r}", "--set", "output.fields=false",
               "--set", "output.diagnostics_every_steps=1", "--set", "output.cell_gaps_max_cells=0",
               "--set", "checkpoint.every_minutes=0"]
    for setting in BOX + settings:
        command += ["--set", setting]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"gmres_growth.py: {' '.join(command)} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    with open(os.path.join(folder, "diagnostics.csv")) as f:
        rows = [row for row in csv.DictReader(f) if int(row["step"]) > 0]
    return [int(float(row["gmres_iterations"])) for row in rows]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rouleau", default=os.path.join(ROOT, "build", "rouleau"))
    parser.add_argument("--steps", type=int, default=12)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--scratch", default=os.path.join(ROOT, "build", "gmres_growth"))
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "gmres_growth.csv"))
    args = parser.parse_args()
    if args.steps < 3:
        sys.exit("gmres_growth.py: --steps must be at least 3")
    variants = [(f"{n} cells", n, 1.0) for n in ARRANGEMENTS] + [("4 cells, membrane x10", 4, 10.0)]
    rows = []
    for label, count, stiffness in variants:
        settings = [cells_setting(ARRANGEMENTS[count]),
                    f"cell_kinds.normal.membrane_shear_modulus_pN_um={NORMAL_MEMBRANE_SHEAR_MODULUS * stiffness}"]
        folder = os.path.join(args.scratch, f"{count}_cells_x{stiffness:g}")
        iterations = run(args.rouleau, folder, args.steps, args.threads, settings)
        mean = sum(iterations[2:]) / len(iterations[2:])
        rows.append({"variant": label, "cells": count, "membrane_stiffness_factor": stiffness,
                     "gmres_mean_steps_3_on": round(mean, 2), "gmres_per_step": " ".join(map(str, iterations))})
        print(f"{label:24s} mean {mean:6.2f}  per step {iterations}", flush=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    by_count = [r["gmres_mean_steps_3_on"] for r in rows if r["membrane_stiffness_factor"] == 1.0]
    stiff = next(r["gmres_mean_steps_3_on"] for r in rows if r["membrane_stiffness_factor"] != 1.0)
    normal = next(r["gmres_mean_steps_3_on"] for r in rows if r["cells"] == 4 and r["membrane_stiffness_factor"] == 1.0)
    count_ratio, stiffness_ratio = max(by_count) / min(by_count), stiff / normal
    print(f"cell counts: largest / smallest mean = {count_ratio:.2f} (bound {BOUND_CELL_COUNT}): "
          f"{'met' if count_ratio <= BOUND_CELL_COUNT else 'NOT MET'}")
    print(f"membrane x10 / x1 = {stiffness_ratio:.2f} (bound {BOUND_STIFFNESS}): "
          f"{'met' if stiffness_ratio <= BOUND_STIFFNESS else 'NOT MET'}")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
