#!/usr/bin/python3
"""Figures from a rouleau run's diagnostics.csv (and its case.resolved.toml).

    scripts/plot_diagnostics.py RUN_DIR [--out FOLDER] [--plane xy|xz|yz] [--snapshots N]

Writes PNG files into RUN_DIR/figures (or FOLDER) and prints their paths; each figure is
titled with the case's name and what it shows:
  driving_pressure.png  vessels: the driving pressure against time (the paper's Fig. 17),
                        each cell's position along the vessel with the throat's extent, and
                        the cells past the throat's exit with the inflow and outflow
  gaps.png              two cells or more: each pair's gap and contact area against time
  cell_shapes.png       cells: inclination and Taylor deformation in the shear plane
  volumes.png           cells: each cell's volume relative to its first row (t = 0)
  cell_extents.png      cells: the outer surface's extent along x, y and z (a capsule's
                        length and width in a capillary along x)
  wall_stress.png       the wall shear stress and the relative apparent viscosity
  solver.png            Newton and GMRES iterations per row
  cross_sections.png    cells: the nodes within half a micrometre of a plane through the
                        cells' mean centre (--plane, default xy) at N field outputs spread
                        over the run (the paper's snapshot figures, e.g. Figs. 6 and 8-16);
                        in a vessel, with its wall in planes through its axis
Only the figures the run's columns and files allow are drawn. Needs matplotlib
(Debian's python3-matplotlib), and h5py (python3-h5py) for the cross-sections: it runs
with Debian's /usr/bin/python3, which has them after scripts/bootstrap.sh.
"""
import argparse
import csv
import glob
import math
import os
import re
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"plot_diagnostics: {path}: no data row")
    return {name: [float(r[name]) for r in rows] for name in rows[0]}


def cell_count(columns):
    count = 0
    while f"cell{count}_volume_um3" in columns:
        count += 1
    return count


class Figures:
    """Where the figures go, the paths written, and the case's name for their titles."""

    def __init__(self, folder, case_name):
        self.folder, self.case_name, self.written = folder, case_name, []


def save(figure, figures, name, title):
    path = os.path.join(figures.folder, name)
    figure.suptitle(f"{figures.case_name}: {title}" if figures.case_name else title)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)
    figures.written.append(path)


def throat_span(case):
    """The throat's start and end along x [μm], or None when the case has no vessel."""
    vessel = case.get("vessel")
    if not vessel:
        return None
    start = vessel.get("inlet_length_um", 0.0) + vessel.get("contraction_length_um", 0.0)
    return start, start + vessel.get("throat_length_um", 0.0)


def vessel_wall(case, x):
    """The vessel's radius at x [μm]: feeders, transitions (cosine or cone) and throat, as
    src/geometry/vessel_profile.cpp builds the mesh."""
    vessel = case["vessel"]
    radius, throat = vessel["radius_um"], vessel["throat_radius_um"]
    cosine = vessel.get("transition", "cosine") == "cosine"

    def transition(start, end, s):  # from `start` (s = 0) to `end` (s = 1)
        weight = 0.5 * (1.0 - math.cos(math.pi * s)) if cosine else s
        return start + (end - start) * weight

    contraction = vessel["inlet_length_um"]
    throat_start = contraction + vessel["contraction_length_um"]
    diffuser = throat_start + vessel["throat_length_um"]
    outlet = diffuser + vessel["diffuser_length_um"]
    if x < contraction or x >= outlet:
        return radius
    if x < throat_start:
        return transition(radius, throat, (x - contraction) / vessel["contraction_length_um"])
    if x < diffuser:
        return throat
    return transition(throat, radius, (x - diffuser) / vessel["diffuser_length_um"])


def plot_vessel(columns, case, figures):
    """Driving pressure (Fig. 17), each cell's position along the vessel, and the cells past
    the throat's exit with the flow rates (the contraction's diagnostics, Figs. 13-15)."""
    if "driving_pressure_Pa" not in columns:
        return
    time = columns["time_s"]
    cells = cell_count(columns)
    span = throat_span(case)
    panels = 3 if cells else 1
    figure, axes = plt.subplots(panels, 1, figsize=(7, 2.6 * panels + 0.6), sharex=True, squeeze=False)
    axes = axes[:, 0]
    axes[0].plot(time, columns["driving_pressure_Pa"], color="tab:red")
    axes[0].set_ylabel("driving pressure [Pa]\n(inlet − outlet)")
    if cells:
        for c in range(min(cells, 12)):
            axes[1].plot(time, columns[f"cell{c}_centroid_x_um"], label=f"cell {c}")
        if span and span[1] > span[0]:
            axes[1].axhspan(span[0], span[1], color="tab:gray", alpha=0.15, label="throat")
        axes[1].set_ylabel("centroid x [μm]")
        axes[1].legend(fontsize="small", ncol=4)
        if span:
            passed = [sum(columns[f"cell{c}_centroid_x_um"][i] > span[1] for c in range(cells))
                      for i in range(len(time))]
            axes[2].step(time, passed, where="post", color="black", label="cells past the throat's exit")
            axes[2].set_ylabel("cells passed")
            axes[2].set_ylim(-0.2, cells + 0.2)
        if "flow_rate_inlet_um3_s" in columns:
            rate = axes[2].twinx()
            rate.plot(time, columns["flow_rate_inlet_um3_s"], color="tab:blue", alpha=0.6, label="inflow")
            rate.plot(time, columns["flow_rate_outlet_um3_s"], "--", color="tab:green", alpha=0.6, label="outflow")
            rate.set_ylabel("flow rate [μm³/s]")
            largest = max(max(columns["flow_rate_inlet_um3_s"]), max(columns["flow_rate_outlet_um3_s"]))
            rate.set_ylim(0.0, 1.25 * largest)  # from zero: outflow and inflow agree to the solver's tolerance
            rate.legend(fontsize="small", loc="lower right")
    axes[-1].set_xlabel("time [s]")
    save(figure, figures, "driving_pressure.png", "driving pressure and cells along the vessel")


def plot_gaps(columns, figures):
    pairs = sorted(name[len("gap_"):-len("_um")] for name in columns if name.startswith("gap_"))
    if not pairs:
        return
    time = columns["time_s"]
    figure, (gap_axis, area_axis) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for pair in pairs:
        label = "cells " + pair.replace("_", "–")
        gap_axis.plot(time, columns[f"gap_{pair}_um"], label=label)
        area_axis.plot(time, columns[f"contact_area_{pair}_um2"], label=label)
    gap_axis.set_ylabel("gap [μm]")
    gap_axis.set_yscale("log")
    area_axis.set_ylabel("contact area [μm²]")
    area_axis.set_xlabel("time [s]")
    if len(pairs) <= 12:
        gap_axis.legend(fontsize="small")
    save(figure, figures, "gaps.png", "gaps and contact areas between cells")


def plot_cells(columns, figures):
    cells = cell_count(columns)
    if cells == 0:
        return
    time = columns["time_s"]
    figure, (angle_axis, deformation_axis) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for c in range(cells):
        angle_axis.plot(time, columns[f"cell{c}_inclination_deg"], label=f"cell {c}")
        deformation_axis.plot(time, columns[f"cell{c}_taylor_deformation"], label=f"cell {c}")
    angle_axis.set_ylabel("inclination [°]")
    deformation_axis.set_ylabel("Taylor deformation")
    deformation_axis.set_xlabel("time [s]")
    if cells <= 12:
        angle_axis.legend(fontsize="small")
    save(figure, figures, "cell_shapes.png", "inclination and Taylor deformation in the shear plane")

    figure, axis = plt.subplots(figsize=(7, 4))
    for c in range(cells):
        volume = columns[f"cell{c}_volume_um3"]
        axis.plot(time, [v / volume[0] - 1.0 for v in volume], label=f"cell {c}")
    axis.set_ylabel("relative volume change\n(V − V₀) / V₀")
    axis.set_xlabel("time [s]")
    if cells <= 12:
        axis.legend(fontsize="small")
    save(figure, figures, "volumes.png", "each cell's enclosed volume")


def plot_extents(columns, figures):
    cells = cell_count(columns)
    if cells == 0 or "cell0_extent_x_um" not in columns:
        return
    time = columns["time_s"]
    figure, axis = plt.subplots(figsize=(7, 4))
    for c in range(min(cells, 12)):
        for direction, style in (("x", "-"), ("y", "--"), ("z", ":")):
            axis.plot(time, columns[f"cell{c}_extent_{direction}_um"], style, color=f"C{c % 10}",
                      label=f"cell {c} along {direction}")
    axis.set_ylabel("extent of the outer surface [μm]")
    axis.set_xlabel("time [s]")
    axis.legend(fontsize="small", ncol=3)
    save(figure, figures, "cell_extents.png", "extents of the cells' outer surfaces")


def plot_walls(columns, figures):
    names = [n for n in ("wall_shear_stress_y_min_Pa", "wall_shear_stress_y_max_Pa", "mean_wall_shear_stress_Pa")
             if n in columns and any(math.isfinite(v) for v in columns[n])]
    if not names:
        return
    time = columns["time_s"]
    figure, (stress_axis, viscosity_axis) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    readable = {"wall_shear_stress_y_min_Pa": "wall at y min", "wall_shear_stress_y_max_Pa": "wall at y max",
                "mean_wall_shear_stress_Pa": "mean over the vessel wall"}
    for name in names:
        stress_axis.plot(time, columns[name], label=readable[name])
    stress_axis.set_ylabel("wall shear stress [Pa]")
    stress_axis.legend(fontsize="small")
    viscosity = columns["relative_apparent_viscosity"]
    viscosity_axis.plot(time, viscosity)
    if not any(math.isfinite(v) for v in viscosity):  # walls at rest: no shear rate to divide by
        viscosity_axis.text(0.5, 0.5, "not defined: no imposed shear rate", transform=viscosity_axis.transAxes,
                            ha="center", va="center", color="gray")
    viscosity_axis.set_ylabel("relative apparent viscosity\nτ_w / (μ γ̇)")
    viscosity_axis.set_xlabel("time [s]")
    save(figure, figures, "wall_stress.png", "wall shear stress and relative apparent viscosity")


def plot_solver(columns, figures):
    figure, axis = plt.subplots(figsize=(7, 3.5))
    solved = [i for i, step in enumerate(columns["step"]) if step > 0]  # step 0 is the start: no solve
    steps = [columns["step"][i] for i in solved]
    axis.plot(steps, [columns["gmres_iterations"][i] for i in solved], label="GMRES iterations")
    axis.plot(steps, [columns["newton_iterations"][i] for i in solved], label="Newton iterations")
    axis.set_xlabel("step")
    axis.set_ylabel("iterations per step")
    axis.legend(fontsize="small")
    save(figure, figures, "solver.png", "solver iterations")


def plot_cross_sections(run_dir, case, plane, snapshots, figures):
    """Cell nodes near a plane at `snapshots` field outputs, one panel each, coloured by cell."""
    try:
        import h5py
    except ImportError:
        print("plot_diagnostics: no h5py (python3-h5py): cross-sections skipped", file=sys.stderr)
        return
    files = sorted(glob.glob(os.path.join(run_dir, "fields_[0-9]*.h5")),
                   key=lambda path: int(re.findall(r"(\d+)\.h5$", path)[0]))
    with_cells = []
    for path in files:
        with h5py.File(path, "r") as f:
            if "cells" in f:
                with_cells.append(path)
    if not with_cells:
        return
    count = min(snapshots, len(with_cells))
    chosen = [with_cells[round(i * (len(with_cells) - 1) / max(count - 1, 1))] for i in range(count)]
    axes_of = {"xy": (0, 1, 2), "xz": (0, 2, 1), "yz": (1, 2, 0)}
    first, second, normal = axes_of[plane]
    names = "xyz"
    along_vessel = bool(case.get("vessel")) and normal != 0  # the whole vessel in each panel: stacked
    if along_vessel:
        figure, panels = plt.subplots(count, 1, figsize=(10, 1.9 * count + 0.4), squeeze=False, sharex=True)
        panels = panels[:, 0]
    else:
        figure, panels = plt.subplots(1, count, figsize=(3.2 * count, 3.4), squeeze=False)
        panels = panels[0]
    centre = None
    for panel, path in zip(panels, chosen):
        with h5py.File(path, "r") as f:
            x = f["cells/coordinates"][()]
            cell = f["cells/cell_id"][()]
            time = float(f["time"][0])
        # The plane through the cells' mean centre: fixed at the first snapshot in a vessel
        # (its axis), followed from snapshot to snapshot in a box, where an aggregate can
        # drift along the vorticity direction (the twelve cells moved 5-9 um in z over 3 s).
        if centre is None or not along_vessel:
            centre = x[:, normal].mean()
        near = abs(x[:, normal] - centre) < 0.5
        panel.scatter(x[near, first], x[near, second], c=cell[near] % 10, cmap="tab10", vmin=0, vmax=9, s=3)
        if along_vessel:  # a plane through the vessel's axis (x): its wall
            length = sum(case["vessel"][k] for k in ("inlet_length_um", "contraction_length_um",
                                                     "throat_length_um", "diffuser_length_um", "outlet_length_um"))
            wall_x = [length * i / 400 for i in range(401)]
            wall_r = [vessel_wall(case, x) for x in wall_x]
            panel.plot(wall_x, wall_r, color="black", linewidth=0.8)
            panel.plot(wall_x, [-r for r in wall_r], color="black", linewidth=0.8)
        panel.set_aspect("equal")
        panel.set_title(f"t = {time:.4g} s", fontsize="small")
        panel.set_xlabel(f"{names[first]} [μm]")
        panel.set_ylabel(f"{names[second]} [μm]")
    save(figure, figures, "cross_sections.png", f"cell nodes within 0.5 μm of the {names[first]}{names[second]} plane")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dir")
    parser.add_argument("--out", help="folder for the figures (default RUN_DIR/figures)")
    parser.add_argument("--plane", choices=["xy", "xz", "yz"], default="xy",
                        help="the cross-sections' plane (default xy)")
    parser.add_argument("--snapshots", type=int, default=4, help="cross-sections drawn (default 4)")
    arguments = parser.parse_args(argv)
    columns = read_columns(os.path.join(arguments.run_dir, "diagnostics.csv"))
    case = {}
    resolved = os.path.join(arguments.run_dir, "case.resolved.toml")
    if os.path.exists(resolved):
        with open(resolved, "rb") as f:
            case = tomllib.load(f)
    folder = arguments.out or os.path.join(arguments.run_dir, "figures")
    os.makedirs(folder, exist_ok=True)
    figures = Figures(folder, case.get("case", {}).get("name", ""))
    plot_vessel(columns, case, figures)
    plot_gaps(columns, figures)
    plot_cells(columns, figures)
    plot_extents(columns, figures)
    plot_walls(columns, figures)
    plot_solver(columns, figures)
    plot_cross_sections(arguments.run_dir, case, arguments.plane, arguments.snapshots, figures)
    for path in figures.written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
