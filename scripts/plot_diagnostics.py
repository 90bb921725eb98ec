#!/usr/bin/env python3
"""Figures from a rouleau run's diagnostics.csv (and its case.resolved.toml).

    scripts/plot_diagnostics.py RUN_DIR [--out FOLDER] [--plane xy|xz|yz] [--snapshots N]

Writes PNG files into RUN_DIR/figures (or FOLDER) and prints their paths:
  driving_pressure.png  vessels: the driving pressure against time (the paper's Fig. 17),
                        with the first cell's axial position and the throat's extent
  gaps.png              two cells or more: each pair's gap and contact area against time
  cell_shapes.png       cells: inclination and Taylor deformation in the shear plane
  volumes.png           cells: each cell's volume relative to its first row
  cell_extents.png      cells: the outer surface's extent along x, y and z (a capsule's
                        length and width in a capillary along x)
  wall_stress.png       the wall shear stress and the relative apparent viscosity
  solver.png            Newton and GMRES iterations per row
  cross_sections.png    cells: the nodes within half a micrometre of a plane through the
                        cells' mean centre (--plane, default xy) at N field outputs spread
                        over the run (the paper's snapshot figures, e.g. Figs. 6 and 8-16)
Only the figures the run's columns and files allow are drawn. Needs matplotlib
(Debian's python3-matplotlib), and h5py (python3-h5py) for the cross-sections.
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


def save(figure, folder, name, written):
    path = os.path.join(folder, name)
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)
    written.append(path)


def plot_vessel(columns, case, folder, written):
    if "driving_pressure_Pa" not in columns:
        return
    time = columns["time_s"]
    figure, axis = plt.subplots(figsize=(7, 4))
    axis.plot(time, columns["driving_pressure_Pa"], color="tab:red", label="driving pressure")
    axis.set_xlabel("time [s]")
    axis.set_ylabel("driving pressure (inlet − outlet) [Pa]", color="tab:red")
    if "cell0_centroid_x_um" in columns:
        position = axis.twinx()
        position.plot(time, columns["cell0_centroid_x_um"], color="tab:blue")
        position.set_ylabel("cell 0 centroid x [μm]", color="tab:blue")
        vessel = case.get("vessel", {})
        start = vessel.get("inlet_length_um", 0.0) + vessel.get("contraction_length_um", 0.0)
        end = start + vessel.get("throat_length_um", 0.0)
        if end > start:
            position.axhspan(start, end, color="tab:blue", alpha=0.08, label="throat")
    axis.set_title(f"{case.get('case', {}).get('name', '')}: driving pressure")
    save(figure, folder, "driving_pressure.png", written)


def plot_gaps(columns, folder, written):
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
    save(figure, folder, "gaps.png", written)


def plot_cells(columns, folder, written):
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
    save(figure, folder, "cell_shapes.png", written)

    figure, axis = plt.subplots(figsize=(7, 4))
    for c in range(cells):
        volume = columns[f"cell{c}_volume_um3"]
        axis.plot(time, [v / volume[0] - 1.0 for v in volume], label=f"cell {c}")
    axis.set_ylabel("relative volume change")
    axis.set_xlabel("time [s]")
    save(figure, folder, "volumes.png", written)


def plot_extents(columns, folder, written):
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
    save(figure, folder, "cell_extents.png", written)


def plot_walls(columns, folder, written):
    names = [n for n in ("wall_shear_stress_y_min_Pa", "wall_shear_stress_y_max_Pa", "mean_wall_shear_stress_Pa")
             if n in columns and any(math.isfinite(v) for v in columns[n])]
    if not names:
        return
    time = columns["time_s"]
    figure, (stress_axis, viscosity_axis) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for name in names:
        stress_axis.plot(time, columns[name], label=name)
    stress_axis.set_ylabel("wall shear stress [Pa]")
    stress_axis.legend(fontsize="small")
    viscosity_axis.plot(time, columns["relative_apparent_viscosity"])
    viscosity_axis.set_ylabel("relative apparent viscosity")
    viscosity_axis.set_xlabel("time [s]")
    save(figure, folder, "wall_stress.png", written)


def plot_solver(columns, folder, written):
    figure, axis = plt.subplots(figsize=(7, 3.5))
    axis.plot(columns["step"], columns["gmres_iterations"], label="GMRES iterations")
    axis.plot(columns["step"], columns["newton_iterations"], label="Newton iterations")
    axis.set_xlabel("step")
    axis.legend(fontsize="small")
    save(figure, folder, "solver.png", written)


def plot_cross_sections(run_dir, plane, snapshots, folder, written):
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
    figure, panels = plt.subplots(1, count, figsize=(3.2 * count, 3.4), squeeze=False)
    centre = None
    for panel, path in zip(panels[0], chosen):
        with h5py.File(path, "r") as f:
            x = f["cells/coordinates"][()]
            cell = f["cells/cell_id"][()]
            time = float(f["time"][0])
        if centre is None:  # the plane through the cells' mean centre at the first snapshot
            centre = x[:, normal].mean()
        near = abs(x[:, normal] - centre) < 0.5
        panel.scatter(x[near, first], x[near, second], c=cell[near] % 10, cmap="tab10", vmin=0, vmax=9, s=3)
        panel.set_aspect("equal")
        panel.set_title(f"t = {time:.4g} s", fontsize="small")
        panel.set_xlabel(f"{names[first]} [μm]")
        panel.set_ylabel(f"{names[second]} [μm]")
    save(figure, folder, "cross_sections.png", written)


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
    written = []
    plot_vessel(columns, case, folder, written)
    plot_gaps(columns, folder, written)
    plot_cells(columns, folder, written)
    plot_extents(columns, folder, written)
    plot_walls(columns, folder, written)
    plot_solver(columns, folder, written)
    plot_cross_sections(arguments.run_dir, arguments.plane, arguments.snapshots, folder, written)
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
