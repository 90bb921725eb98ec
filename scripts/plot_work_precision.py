#!/usr/bin/python3
"""Work–precision figure from bench/work_precision's CSV: relative L2 error of velocity
and of pressure against wall time, log–log, one panel per equation set and error, one
line per element type and preconditioner (points labelled with n, elements per side).
Prints the Pareto front of each panel: the points no other point beats in both time and
error, which are the settings worth defaulting to. bench/work_precision_cells's CSV (a
`family` column) gives one panel per family, one line per cell mesh preset.

    scripts/plot_work_precision.py bench/work_precision.csv [--out bench/work_precision.png]
"""
import argparse
import csv
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def pareto_front(points, error_key):
    """The points not dominated in (seconds, error): sorted by time, each with a smaller
    error than every faster one."""
    front, best = [], float("inf")
    for p in sorted(points, key=lambda p: (p["seconds"], p[error_key])):
        if p[error_key] < best:
            front.append(p)
            best = p[error_key]
    return front


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("csv_file")
    parser.add_argument("--out", default=None, help="PNG path (default: beside the CSV)")
    args = parser.parse_args()
    with open(args.csv_file) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_work_precision.py: {args.csv_file}: no rows")
    out = args.out or os.path.splitext(args.csv_file)[0] + ".png"
    if "family" in rows[0]:
        return plot_cell_families(rows, out)
    for r in rows:
        for key in ("seconds", "velocity_error", "pressure_error"):
            r[key] = float(r[key])
        r["n"] = int(r["n"])
    equations = sorted({r["equations"] for r in rows})
    errors = [("velocity_error", "velocity"), ("pressure_error", "pressure")]
    figure, axes = plt.subplots(len(equations), 2, figsize=(11, 4.5 * len(equations)), squeeze=False)
    threads = rows[0]["threads"]
    styles = {("hexahedra", "ilu0"): ("C0", "o", "-"), ("hexahedra", "multigrid"): ("C0", "s", "--"),
              ("tetrahedra", "ilu0"): ("C3", "^", "-"), ("tetrahedra", "multigrid"): ("C3", "v", "--")}
    for i, eq in enumerate(equations):
        chosen = [r for r in rows if r["equations"] == eq and r["converged"] == "1"]
        series = defaultdict(list)
        for r in chosen:
            series[(r["element"], r["preconditioner"])].append(r)
        for j, (key, label) in enumerate(errors):
            ax = axes[i][j]
            for (element, preconditioner), points in sorted(series.items()):
                points.sort(key=lambda p: p["n"])
                color, marker, line = styles.get((element, preconditioner), ("k", "x", ":"))
                ax.loglog([p["seconds"] for p in points], [p[key] for p in points], color=color, marker=marker,
                          linestyle=line, label=f"{element}, {'ILU(0)' if preconditioner == 'ilu0' else preconditioner}")
                for p in points:
                    ax.annotate(str(p["n"]), (p["seconds"], p[key]), textcoords="offset points", xytext=(4, 3),
                                fontsize=7, color=color)
            front = pareto_front(chosen, key)
            ax.plot([p["seconds"] for p in front], [p[key] for p in front], color="0.6", linewidth=4, alpha=0.35,
                    zorder=0, label="Pareto front")
            title = "Navier–Stokes, Re = 1" if eq == "navier_stokes" else "Stokes"
            ax.set_title(f"{title}: {label} (manufactured solution)")
            ax.set_xlabel(f"wall time, setup + solve [s] ({threads} thread{'s' if threads != '1' else ''})")
            ax.set_ylabel(f"relative L2 error of {label}")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=8)
            print(f"{eq}, {label}: Pareto front " +
                  ", ".join(f"{p['element']} {p['preconditioner']} n={p['n']} ({p['seconds']:.3g} s, {p[key]:.2e})"
                            for p in front))
    figure.tight_layout()
    figure.savefig(out + ".part.png", dpi=110)
    os.replace(out + ".part.png", out)
    print(f"wrote {out}")


TITLES = {"capsule_taylor": "capsule in shear, Ca = 0.05: Taylor deformation against the published 0.27\n"
                            "(labels: n, fluid elements across x; a/h_f = 2.7, 3.6, 4.6)",
          "sphere_rotation": "stiff sphere in shear: rotation rate against Jeffery's, walls corrected\n"
                             "(labels: n, fluid elements per side)",
          "rbc_stretch": "RBC stretch at 193 pN, Mills membrane: axial diameter against Mills et al. 2004\n"
                         "(labels: -log10 of the solver tolerance)"}


def plot_cell_families(rows, out):
    """One panel per family: the error against wall time, a line per mesh preset, points
    labelled with n (fluid elements per side); prints each family's Pareto front."""
    for r in rows:
        r["seconds"], r["error"], r["n"] = float(r["seconds"]), float(r["error"]), int(r["n"])
    families = sorted({r["family"] for r in rows})
    threads = rows[0]["threads"]
    figure, axes = plt.subplots(1, len(families), figsize=(6.5 * len(families), 4.8), squeeze=False)
    for ax, family in zip(axes[0], families):
        chosen = [r for r in rows if r["family"] == family]
        for k, preset in enumerate(sorted({r["mesh_preset"] for r in chosen})):
            points = sorted((r for r in chosen if r["mesh_preset"] == preset), key=lambda r: r["n"])
            ax.loglog([p["seconds"] for p in points], [p["error"] for p in points], marker="os^v"[k % 4],
                      color=f"C{k}", label=f"{preset} cell mesh")
            for p in points:
                ax.annotate(str(p["n"]), (p["seconds"], p["error"]), textcoords="offset points", xytext=(4, 3),
                            fontsize=7, color=f"C{k}")
        front = pareto_front(chosen, "error")
        ax.plot([p["seconds"] for p in front], [p["error"] for p in front], color="0.6", linewidth=4, alpha=0.35,
                zorder=0, label="Pareto front")
        ax.set_title(TITLES.get(family, family), fontsize=10)
        ax.set_xlabel(f"wall time, setup + run [s] ({threads} thread{'s' if threads != '1' else ''})")
        ax.set_ylabel("relative error")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        print(f"{family}: Pareto front " +
              ", ".join(f"{p['mesh_preset']} n={p['n']} ({p['seconds']:.3g} s, {p['error']:.2e})" for p in front))
    figure.tight_layout()
    figure.savefig(out + ".part.png", dpi=110)
    os.replace(out + ".part.png", out)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
