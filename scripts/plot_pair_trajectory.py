#!/usr/bin/python3
"""Two spheres passing each other in shear: their relative trajectory, for one or more runs
of cases/sphere_pair_shear.

    scripts/plot_pair_trajectory.py OUT.png LABEL=RUN_DIR [LABEL=RUN_DIR]...   (split at the last "=")

Draws y0 − y1 against x0 − x1 (cells 0 and 1's centroids) over each run, with the
starting offset mirrored to the far side: a reversible pass (smooth spheres in Stokes
flow) ends on that line. Needs matplotlib: run it with /usr/bin/python3.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    start = None
    for spec in sys.argv[2:]:
        label, run_dir = spec.rsplit("=", 1)
        with open(os.path.join(run_dir, "diagnostics.csv")) as f:
            rows = list(csv.DictReader(f))
        dx = [float(r["cell0_centroid_x_um"]) - float(r["cell1_centroid_x_um"]) for r in rows]
        dy = [float(r["cell0_centroid_y_um"]) - float(r["cell1_centroid_y_um"]) for r in rows]
        # Up to the symmetric point and a little beyond (the periodic image is half a box away).
        end = next((k for k, x in enumerate(dx) if x >= -dx[0]), len(dx) - 1)
        ax.plot(dx[: end + 1], dy[: end + 1], label=label)
        start = (dx[0], dy[0])
    ax.plot([start[0], -start[0]], [start[1], start[1]], "k--", label="reversible: the starting offset")
    ax.set_xlabel("x0 − x1 [μm] (along the flow)")
    ax.set_ylabel("y0 − y1 [μm] (across the streamlines)")
    ax.set_title("Two stiff spheres (a = 2 μm) passing in shear")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=120)
    print(sys.argv[1])


if __name__ == "__main__":
    main()
