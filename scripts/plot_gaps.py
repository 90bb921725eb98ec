#!/usr/bin/python3
"""The gaps between neighbouring cells of a stack over one or more runs, side by side.

    scripts/plot_gaps.py OUT.png [--shear-rate G] [--separations] LABEL=RUN_DIR [LABEL=RUN_DIR]...
                                                                           (split at the last "=")

Draws every column gap_i_(i+1)_um of each run's diagnostics.csv (the least distance
between neighbouring cells' outer surfaces) against time, or against the strain G t with
--shear-rate G [1/s], on a logarithmic axis (films of 1e-4 to a few um). With
--separations it draws instead the change of each neighbour pair's vertical separation,
the difference of their centroids' y less its first value, on a linear axis (the paper's
Fig. 8: cells that "keep their vertical separations"). One colour per run, one line style
per pair. Needs matplotlib: run it with /usr/bin/python3.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    args = sys.argv[1:]
    if len(args) < 2:
        sys.exit(__doc__)
    out = args.pop(0)
    shear_rate, separations = None, False
    while args and args[0].startswith("--"):
        option = args.pop(0)
        if option == "--shear-rate" and args:
            shear_rate = float(args.pop(0))
        elif option == "--separations":
            separations = True
        else:
            sys.exit(__doc__)
    if not args:
        sys.exit(__doc__)
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    styles = ["-", "--", ":", "-."]
    for colour, spec in enumerate(args):
        label, run_dir = spec.rsplit("=", 1)
        with open(os.path.join(run_dir, "diagnostics.csv")) as f:
            rows = list(csv.DictReader(f))
        t = [float(r["time_s"]) * (shear_rate or 1.0) for r in rows]
        pairs = sorted(k for k in rows[0] if k.startswith("gap_") and int(k.split("_")[2]) == int(k.split("_")[1]) + 1)
        for i, column in enumerate(pairs):
            a, b = column.split("_")[1:3]
            if separations:
                dy = [float(r[f"cell{b}_centroid_y_um"]) - float(r[f"cell{a}_centroid_y_um"]) for r in rows]
                values = [d - dy[0] for d in dy]
            else:
                values = [max(float(r[column]), 1e-5) for r in rows]
            ax.plot(t, values, styles[i % len(styles)], color=f"C{colour}", lw=1.4, label=f"{label}: cells {a}-{b}")
    if separations:
        ax.axhline(0.0, color="k", lw=0.6)
        ax.set_ylabel("change of the vertical separation (µm)")
    else:
        ax.set_yscale("log")
        ax.set_ylabel("gap between neighbouring cells (µm)")
    ax.set_xlabel("strain γ̇t" if shear_rate else "time (s)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=1, loc="best")
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print(out)


if __name__ == "__main__":
    main()
