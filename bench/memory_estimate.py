#!/usr/bin/python3
"""The memory estimate that `rouleau check` and `rouleau run` make before any work,
against the peak resident memory measured over a few steps of the same case.

    bench/memory_estimate.py [--rouleau build/rouleau] [--threads 2] [--quick]
                             [--out bench/memory_estimate.csv]

Runs each case below for one time step, or one solve when it is steady (fields off; the
peak is at the first factorization), reads the estimate and the peak (getrusage's maxrss, which `rouleau run`
prints at its end as "peak memory: ... (estimated ...)") and writes one CSV row per run: case, fluid nodes, estimate, peak, estimate / peak.
Exits 1 when an estimate is off by more than 30 % (the threshold set before the runs).
--quick runs only the smaller sizes (for CI).
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UNITS = {"B": 1, "KiB": 1024, "MiB": 1024**2, "GiB": 1024**3, "TiB": 1024**4}
PEAK = re.compile(r"^peak memory: ([0-9.]+) (\w+) \(estimated ([0-9.]+) (\w+)\)$", re.M)
NODES = re.compile(r"^fluid mesh: (\d+) nodes", re.M)
TOLERANCE = 0.30

# (label, case, overrides, quick): shear boxes (periodic in x and z) at four sizes, a
# channel closed in x and y (ILU(0)'s widest level grows with the cross-section there), a
# vessel of tetrahedra, and a box with cells.
RUNS = [
    ("shear box 24^3", "shear_flow", ["domain.elements=[24,24,24]"], True),
    ("shear box 32^3", "shear_flow", ["domain.elements=[32,32,32]"], True),
    ("shear box 40^3", "shear_flow", ["domain.elements=[40,40,40]"], False),
    ("shear box 64^3", "shear_flow", ["domain.elements=[64,64,64]"], False),
    ("channel 48x24x24", "channel", ["domain.elements=[48,24,24]"], False),
    ("contraction (coarse), no cells", "contraction",
     ["cells=[]", "interaction.enabled=false", "vessel.element_size_um=1.5", "vessel.wall_element_size_um=0.75"], False),
    ("aggregation (two cells)", "aggregation", [], False),
]


def to_bytes(value, unit):
    return float(value) * UNITS[unit]


def one_step(case_file):
    """The settings that run a case's first step: a transient case to its first time step,
    a steady one as it is (one solve)."""
    import tomllib
    with open(case_file, "rb") as f:
        time = tomllib.load(f).get("time", {})
    return [] if time.get("mode") == "steady" else [f"time.end_s={time.get('dt_s', 0.01)!r}"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rouleau", default=os.path.join(ROOT, "build", "rouleau"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "memory_estimate.csv"))
    args = parser.parse_args()
    rows, worst = [], 0.0
    with tempfile.TemporaryDirectory(prefix="rouleau-memory-") as scratch:
        for label, case, overrides, quick in RUNS:
            if args.quick and not quick:
                continue
            case_file = os.path.join(ROOT, "cases", case, "case.toml")
            settings = overrides + one_step(case_file) + ["output.fields=false"]
            command = [args.rouleau, "run", case_file, "--out", os.path.join(scratch, case + str(len(rows))),
                       "--no-progress", "--threads", str(args.threads)]
            command += [a for s in settings for a in ("--set", s)]
            done = subprocess.run(command, capture_output=True, text=True)
            if done.returncode != 0:
                sys.exit(f"memory_estimate: {label}: exit {done.returncode}\n{done.stderr}")
            peak = PEAK.search(done.stderr)
            peak_bytes, estimate_bytes = to_bytes(*peak.group(1, 2)), to_bytes(*peak.group(3, 4))
            ratio = estimate_bytes / peak_bytes
            worst = max(worst, abs(ratio - 1.0))
            nodes = int(NODES.search(done.stderr).group(1))
            rows.append([label, nodes, f"{estimate_bytes / 2**20:.0f}", f"{peak_bytes / 2**20:.0f}", f"{ratio:.3f}"])
            print(f"{label:34s} {nodes:9d} nodes  estimate {estimate_bytes / 2**20:8.0f} MiB  "
                  f"peak {peak_bytes / 2**20:8.0f} MiB  estimate/peak {ratio:.3f}", flush=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["case", "fluid_nodes", "estimate_MiB", "peak_MiB", "estimate_over_peak"])
        writer.writerows(rows)
    print(f"worst |estimate/peak - 1| = {worst:.3f} (threshold {TOLERANCE}); wrote {args.out}")
    return 0 if worst <= TOLERANCE else 1


if __name__ == "__main__":
    sys.exit(main())
