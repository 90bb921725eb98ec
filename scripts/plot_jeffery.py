#!/usr/bin/python3
"""A spheroid's turning in shear against Jeffery's orbit, for one or more runs of
cases/spheroid_shear (or any run with one spheroid between moving walls).

    scripts/plot_jeffery.py OUT.png LABEL=RUN_DIR [LABEL=RUN_DIR]...   (split at the last "=")

Draws the symmetry axis's angle φ (from the gradient axis toward the flow) against the
strain γ̇t for each run beside Jeffery's (1922) tan φ = r tan(γ̇ r t / (r² + 1)), r the
body's axis ratio, and prints each run's period error and RMS angle error (the measures
of src/analysis/jeffery_orbit.hpp). The axis ratio and the shear rate come from each run's
case.resolved.toml. Needs matplotlib (Debian's python3-matplotlib): run it with
/usr/bin/python3.
"""
import csv
import math
import os
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def case_of(run_dir):
    with open(os.path.join(run_dir, "case.resolved.toml"), "rb") as f:
        case = tomllib.load(f)
    kind = case["cell_kinds"][case["cells"][0]["kind"]]
    domain = case["domain"]
    height = domain["upper_um"][1] - domain["lower_um"][1]
    rate = (case["boundary"]["y_max"]["velocity_um_s"][0] - case["boundary"]["y_min"]["velocity_um_s"][0]) / height
    return kind["axis_ratio"], rate


def jeffery(t, r, rate, start):
    """φ(t) of the orbit through `start` at t = 0, continuous in t."""
    phase0 = math.atan2(math.sin(start) / r, math.cos(start))
    phase0 += 2 * math.pi * round((start - phase0) / (2 * math.pi))
    phase = phase0 + rate * r / (r * r + 1) * t
    angle = math.atan2(r * math.sin(phase), math.cos(phase))
    return angle + 2 * math.pi * round((phase - angle) / (2 * math.pi))


def axis_angles(inclinations_deg, r):
    """Unwrapped inclinations (modulo π) turned into the symmetry axis's angle."""
    angles, previous = [], None
    for degrees in inclinations_deg:
        theta = math.radians(degrees)
        if previous is not None:
            theta = previous + math.remainder(theta - previous, math.pi)
        previous = theta
        angles.append(-theta if r < 1 else math.pi / 2 - theta)
    return angles


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    reference_drawn = set()
    for spec in sys.argv[2:]:
        label, run_dir = spec.rsplit("=", 1)
        r, rate = case_of(run_dir)
        with open(os.path.join(run_dir, "diagnostics.csv")) as f:
            rows = list(csv.DictReader(f))
        times = [float(row["time_s"]) for row in rows]
        angles = axis_angles([float(row["cell0_inclination_deg"]) for row in rows], r)
        start = angles[0]
        errors = [math.degrees(a - jeffery(t - times[0], r, rate, start)) for t, a in zip(times, angles)]
        rms = math.sqrt(sum(e * e for e in errors) / len(errors))
        half = None
        for k in range(1, len(times)):
            if angles[k] >= start + math.pi:
                before, after = angles[k - 1] - start - math.pi, angles[k] - start - math.pi
                half = times[k - 1] + (times[k] - times[k - 1]) * (-before) / (after - before)
                break
        period = 2 * math.pi * (r + 1 / r) / rate
        error = f"{100 * (2 * half / period - 1):+.1f} %" if half else "no half turn"
        print(f"{label}: c/a = {r:.3g}, period error {error}, RMS {rms:.1f} deg")
        ax.plot([rate * t for t in times], [math.degrees(a) for a in angles], label=f"{label} (period {error})")
        key = (round(r, 6), rate)
        if key not in reference_drawn:
            reference_drawn.add(key)
            fine = [times[-1] * k / 400 for k in range(401)]
            ax.plot([rate * t for t in fine], [math.degrees(jeffery(t, r, rate, start)) for t in fine], "k--",
                    label=f"Jeffery 1922, c/a = {r:.3g}")
    ax.set_xlabel("strain γ̇t")
    ax.set_ylabel("symmetry axis from the gradient axis φ [deg]")
    ax.set_title("A stiff spheroid in shear against Jeffery's orbit")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(out)


if __name__ == "__main__":
    main()
