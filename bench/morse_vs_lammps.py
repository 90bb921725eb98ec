#!/usr/bin/python3
"""The Morse pair kernel of rouleau against LAMMPS' pair_style morse on the same points.

For each cell count N and thread count T this script
  1. writes the surface nodes of bench_morse's packing of N normal red cells
     (`bench_morse --write-points=FILE --cells=N`: "x y z cell" per line, μm; nodal
     quadrature: the Gauss-point sets are 6 times larger, 36 times the pairs);
  2. writes them as a LAMMPS data file (atom_style molecular, molecule id = cell + 1,
     one atom type of mass 1, a non-periodic box with a 4 μm margin) and an input
     script: pair_style morse 3.0, pair_coeff * * 1.0 4.0 0.25 (D0, alpha, r0: the same
     law as rouleau's De, β, r0), intra-cell pairs excluded
     (neigh_modify exclude molecule/intra all, as rouleau lists only pairs of different
     cells), neighbor 0.3 bin (rouleau's skin), the list built once
     (neigh_modify every 1000000 delay 0 check no), zero velocities, timestep 0,
     fix nve, `run STEPS`: STEPS force evaluations after the one neighbour build of the
     run's setup, then `run STEPS pre no` twice (the same again, no new setup or
     build); the "Pair" row of LAMMPS' timing breakdown (average over ranks) of the
     fastest of the three blocks is the time of STEPS evaluations. STEPS = 200, fewer
     when STEPS x pairs would pass 1e8 (100 cells: 30, 1000 cells: 5), to keep the
     script within ~5 minutes. A last block rebuilds the list on every step
     (neigh_modify every 1): LAMMPS' Neigh time per build;
  3. runs rouleau's `bench_morse --benchmark_filter=BM_MorsePairs/cells:N/...` at T
     OpenMP threads (full and half list, nodes; 5 repetitions of at least 0.1 s, the
     fastest kept: the VM has slow phases of seconds that no process on it shows);
  4. prints ns per unique pair for both codes and the ratio LAMMPS / rouleau
     (with --passes 2, steps 3 and 2 are done twice for every size and thread count,
     and the faster of the two passes is kept for each number).

"Unique pairs" are the pairs of points of different cells closer than the 3 μm cut-off,
each counted once. rouleau counts them from its half list by distance (bench_morse's
`pairs` counter); LAMMPS counts them itself in the first run of each N (compute
pair/local dist, reduced to sum and average: count = sum / average, in a `run 0` before
the timed blocks), and the script stops if the two counts differ. Both codes are
normalized by the same count, so the full list's doubled work shows as a higher ns/pair.

The Debian package of LAMMPS (29 Sep 2021) has no OPENMP package (`lmp -h`: no
-sf omp styles), so its T = 2 runs use 2 MPI ranks (`mpirun -np 2`, 1 OpenMP thread
each) — LAMMPS's native parallelism — and the serial `morse` and the OPT package's
`morse/opt` (-sf opt) are both timed. Not the same work: rouleau multiplies each pair by
the area weights w_i w_j (one extra load and multiply per pair), looks the potential up
per pair of cell kinds, and its time includes the gather of the point positions from
the nodes and the skin check; LAMMPS' morse looks its coefficients up per pair of atom
types.

Other processes on the 2 cores spoil the numbers (the 2-thread ones most), so each
measurement (one bench_morse or lmp process) waits up to 60 s for an idle machine, and
is repeated (at most 3 runs, the least disturbed kept) while other processes or the
hypervisor took more than 0.1 core on average during it: the machine's busy CPU time
(/proc/stat, steal included) minus this script's and its children's (getrusage). The
output names any measurement that stayed disturbed.

Usage (from the repository root, after building bench_morse; about 4 minutes on an
idle machine, 7 with --passes 2):
  ROULEAU_MESH_CACHE=/tmp/rouleau-mesh-cache /usr/bin/python3 bench/morse_vs_lammps.py
Options: --bench PATH (default build-morse/bench/bench_morse), --work DIR (default
/tmp/rouleau-morse-vs-lammps), --cells 2,10,100,1000, --threads 1,2, --steps 200,
--pair-evaluations 1e8, --repeats 3 (LAMMPS blocks), --repetitions 5 (rouleau),
--passes 1, --neighbor-builds 2, --variants morse,morse/opt, --attempts 3,
--with-build (also time rouleau's list build, BM_NeighborListBuild: slow at 1000 cells).
"""
import argparse
import json
import os
import re
import resource
import shutil
import subprocess
import sys
import time

import numpy as np

CUTOFF = 3.0   # μm
SKIN = 0.3     # μm
MARGIN = 4.0   # μm, box margin around the points


def run(command, env=None, log=None):
    """Runs `command`; returns its stdout; stops the script with its output if it fails."""
    result = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if log:
        with open(log, "w") as f:
            f.write(result.stdout)
    if result.returncode != 0:
        sys.exit("morse_vs_lammps: failed (%d): %s\n%s" % (result.returncode, " ".join(command), result.stdout[-4000:]))
    return result.stdout


def busy_cpu_seconds():
    """CPU seconds the whole machine spent busy (user, nice, system, irq, softirq) or
    stolen by the hypervisor since boot (/proc/stat)."""
    fields = [int(v) for v in open("/proc/stat").readline().split()[1:]]
    user, nice, system, idle, iowait, irq, softirq, steal = fields[:8]
    return (user + nice + system + irq + softirq + steal) / os.sysconf("SC_CLK_TCK")


def own_cpu_seconds():
    """CPU seconds of this script and of its finished children (and theirs)."""
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def wait_for_idle(limit=60.0):
    """Waits (at most `limit` s) until no other process uses the cores."""
    waited = 0.0
    while waited < limit:
        busy0, own0, t0 = busy_cpu_seconds(), own_cpu_seconds(), time.time()
        time.sleep(1.0)
        if (busy_cpu_seconds() - busy0 - (own_cpu_seconds() - own0)) / (time.time() - t0) < 0.05:
            return
        waited += 1.0


FOREIGN_LIMIT = 0.1  # cores: other processes using more than this spoil a measurement
DISTURBED = []       # measurements that stayed disturbed after every attempt


def measured(label, command, env, log, attempts):
    """Runs `command` until other processes (and the hypervisor) took less than
    FOREIGN_LIMIT cores on average during it, at most `attempts` times: a 2-core machine
    shared with builds and tests gives meaningless numbers otherwise. Returns the output
    of the least disturbed attempt."""
    best = None
    for attempt in range(attempts):
        wait_for_idle()
        busy0, own0, t0 = busy_cpu_seconds(), own_cpu_seconds(), time.time()
        output = run(command, env=env, log=None)
        foreign = (busy_cpu_seconds() - busy0 - (own_cpu_seconds() - own0)) / (time.time() - t0)
        if best is None or foreign < best[0]:
            best = (foreign, output)
        if foreign < FOREIGN_LIMIT:
            break
        print("  %s: other processes took %.2f cores, again" % (label, foreign), flush=True)
    if best[0] >= FOREIGN_LIMIT:
        DISTURBED.append("%s (%.2f cores)" % (label, best[0]))
    if log:
        with open(log, "w") as f:
            f.write(best[1])
    return best[1]


def write_lammps_data(points, path, cells):
    lower = points[:, :3].min(axis=0) - MARGIN
    upper = points[:, :3].max(axis=0) + MARGIN
    n = len(points)
    with open(path, "w") as f:
        f.write("rouleau bench_morse surface points, %d cells (molecule = cell + 1)\n\n" % cells)
        f.write("%d atoms\n1 atom types\n\n" % n)
        for d, name in enumerate("xyz"):
            f.write("%.6f %.6f %slo %shi\n" % (lower[d], upper[d], name, name))
        f.write("\nMasses\n\n1 1.0\n\nAtoms # molecular\n\n")
        ids = np.arange(1, n + 1)
        molecules = points[:, 3].astype(np.int64) + 1
        table = np.column_stack([ids, molecules, np.ones(n, dtype=np.int64)])
        lines = ["%d %d %d %.17g %.17g %.17g" % (a, m, t, x, y, z)
                 for (a, m, t), (x, y, z) in zip(table.tolist(), points[:, :3].tolist())]
        f.write("\n".join(lines))
        f.write("\n")


def write_lammps_input(path, data, steps, count_pairs, repeats, neighbor_builds):
    lines = [
        "units lj",
        "atom_style molecular",
        "boundary f f f",
        "read_data %s" % data,
        "pair_style morse %g" % CUTOFF,
        "pair_coeff * * 1.0 4.0 0.25",
        "neighbor %g bin" % SKIN,
        "neigh_modify exclude molecule/intra all",
        "neigh_modify every 1000000 delay 0 check no",
        "velocity all set 0.0 0.0 0.0",
        "timestep 0.0",
        "fix 1 all nve",
    ]
    if count_pairs:
        lines += [
            "compute pairs all pair/local dist",
            "compute pair_sum all reduce sum c_pairs",
            "compute pair_average all reduce ave c_pairs",
            "thermo_style custom step pe c_pair_sum c_pair_average",
            "thermo_modify norm no format float %.17g",
            "run 0",
            "uncompute pair_sum",
            "uncompute pair_average",
            "uncompute pairs",
        ]
    lines += [
        "thermo_style custom step pe",
        "thermo %d" % steps,
        "run %d" % steps,
    ]
    # the same evaluations again without a new setup (no neighbour build): the fastest
    # of the blocks is kept, as rouleau keeps the fastest repetition
    lines += ["run %d pre no" % steps] * (repeats - 1)
    if neighbor_builds:
        # a list build on every step: the Neigh row over the builds
        lines += ["neigh_modify every 1 delay 0 check no", "run %d" % neighbor_builds]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def parse_lammps_log(text, steps, count_pairs, neighbor_builds):
    """The fastest timed block's Pair (avg over ranks) and loop time, the Neigh time per
    build of the last block, and the pair count of the run 0."""
    blocks = []
    for section in text.split("Loop time of ")[1:]:
        m = re.match(r"([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", section)
        rows = dict((name, float(avg)) for name, avg in
                    re.findall(r"^(\w+)\s*\|\s*[0-9.eE+-]+\s*\|\s*([0-9.eE+-]+)\s*\|", section, re.M))
        if m and "Pair" in rows:
            blocks.append({"loop": float(m.group(1)), "procs": int(m.group(2)), "steps": int(m.group(3)),
                           "atoms": int(m.group(4)), "pair_avg": rows["Pair"], "neigh_avg": rows.get("Neigh", 0.0)})
    timed = [b for b in blocks if b["steps"] == steps]
    if not timed:
        sys.exit("morse_vs_lammps: no timing breakdown in the LAMMPS log")
    result = dict(min(timed, key=lambda b: b["pair_avg"]))
    result["pair_blocks"] = [b["pair_avg"] for b in timed]
    if neighbor_builds:
        result["neigh_per_build"] = blocks[-1]["neigh_avg"] / neighbor_builds
    if count_pairs:
        # the thermo line of the run 0: step pe sum average
        m = re.search(r"Step\s+PotEng\s+c_pair_sum\s+c_pair_average\s*\n\s*0\s+(\S+)\s+(\S+)\s+(\S+)", text)
        if not m:
            sys.exit("morse_vs_lammps: no pair count in the LAMMPS log")
        total, average = float(m.group(2)), float(m.group(3))
        result["pairs"] = int(round(total / average)) if average > 0 else 0
    return result


def run_lammps(work, cells, threads, variant, steps, count_pairs, repeats, neighbor_builds, attempts):
    data = os.path.join(work, "points_%d.data" % cells)
    script = os.path.join(work, "in_%d_%s_%s" % (cells, variant.replace("/", "_"), "count" if count_pairs else "time"))
    log = os.path.join(work, "log_%d_%d_%s.lammps" % (cells, threads, variant.replace("/", "_")))
    write_lammps_input(script, data, steps, count_pairs, repeats, neighbor_builds)
    # the log on stdout (-screen), so that `measured` keeps the least disturbed attempt's
    command = ["lmp", "-nocite", "-log", "none", "-in", script]
    if variant.endswith("/opt"):
        command += ["-sf", "opt"]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    if threads > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none", "-np", str(threads)] + command
    text = measured("LAMMPS %s, %d cells, %d ranks" % (variant, cells, threads), command, env, log, attempts)
    return parse_lammps_log(text, steps, count_pairs, neighbor_builds)


def run_rouleau(bench, work, cells, threads, repetitions, with_build, attempts):
    """bench_morse's BM_MorsePairs (and BM_NeighborListBuild) at `cells`: the fastest
    repetition of each."""
    out = os.path.join(work, "rouleau_%d_%d.json" % (cells, threads))
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND="false")
    pattern = "BM_MorsePairs/cells:%d/list:[01]/quadrature:0" % cells
    if with_build:
        pattern += "|BM_NeighborListBuild/cells:%d/list:[01]/quadrature:0" % cells
    # JSON on stdout, so that `measured` keeps the least disturbed attempt's
    text = measured("rouleau, %d cells, %d threads" % (cells, threads),
                    [bench, "--benchmark_filter=%s" % pattern, "--benchmark_repetitions=%d" % repetitions,
                     "--benchmark_min_time=0.1", "--benchmark_format=json"], env, out, attempts)
    report = json.loads(text[text.index("{"):])
    rows = {}
    for b in report["benchmarks"]:
        if b.get("run_type", "iteration") != "iteration":
            continue
        if b.get("error_occurred"):
            sys.exit("morse_vs_lammps: %s: %s" % (b["name"], b.get("error_message")))
        m = re.match(r"BM_(MorsePairs|NeighborListBuild)/cells:(\d+)/list:(\d)/quadrature:0", b["name"])
        key = ("list" if m.group(1) == "MorsePairs" else "build", int(m.group(3))) if m else None
        if key and (key not in rows or b["real_time"] < rows[key]["real_time"]):
            rows[key] = b
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bench", default="build-morse/bench/bench_morse")
    parser.add_argument("--work", default="/tmp/rouleau-morse-vs-lammps")
    parser.add_argument("--cells", default="2,10,100,1000")
    parser.add_argument("--threads", default="1,2")
    parser.add_argument("--steps", type=int, default=200, help="most LAMMPS evaluations per timed block")
    parser.add_argument("--pair-evaluations", type=float, default=1e8,
                        help="fewer evaluations when evaluations x unique pairs would exceed this")
    parser.add_argument("--repeats", type=int, default=3, help="timed blocks per LAMMPS run")
    parser.add_argument("--repetitions", type=int, default=5, help="repetitions of each rouleau benchmark")
    parser.add_argument("--neighbor-builds", type=int, default=2,
                        help="LAMMPS: time this many list builds after the pair blocks (0: none)")
    parser.add_argument("--passes", type=int, default=1,
                        help="measure everything this many times, keep the fastest (2: about twice as long)")
    parser.add_argument("--attempts", type=int, default=3,
                        help="runs of a measurement at most, while other processes disturb it")
    parser.add_argument("--with-build", action="store_true", help="rouleau: also run BM_NeighborListBuild")
    parser.add_argument("--variants", default="morse,morse/opt")
    args = parser.parse_args()
    cell_counts = [int(c) for c in args.cells.split(",")]
    thread_counts = [int(t) for t in args.threads.split(",")]
    variants = args.variants.split(",")
    if not shutil.which("lmp"):
        sys.exit("morse_vs_lammps: no lmp (apt-get install -y lammps)")
    os.makedirs(args.work, exist_ok=True)
    print("load average at start: %s" % " ".join(open("/proc/loadavg").read().split()[:3]), flush=True)
    started = time.time()
    points_per_cells, pair_counts, results = {}, {}, {}
    for cells in cell_counts:
        points_file = os.path.join(args.work, "points_%d.txt" % cells)
        run([args.bench, "--write-points=%s" % points_file, "--cells=%d" % cells])
        points = np.loadtxt(points_file, ndmin=2)
        points_per_cells[cells] = len(points)
        write_lammps_data(points, os.path.join(args.work, "points_%d.data" % cells), cells)
    # Each pass measures every size and thread count; the fastest of the passes is kept
    # (the VM has slow phases lasting seconds, --passes 2 sees past most of them).
    for measurement_pass in range(args.passes):
        for cells in cell_counts:
            for threads in thread_counts:
                rouleau = run_rouleau(args.bench, args.work, cells, threads, args.repetitions, args.with_build,
                                      args.attempts)
                pairs = int(rouleau[("list", 0)]["pairs"])
                steps = max(5, min(args.steps, int(args.pair_evaluations / pairs)))
                lammps = {}
                for v, variant in enumerate(variants):
                    count = cells not in pair_counts
                    lammps[variant] = run_lammps(args.work, cells, threads, variant, steps, count, args.repeats,
                                                 args.neighbor_builds if v == 0 else 0, args.attempts)
                    if count:
                        pair_counts[cells] = lammps[variant]["pairs"]
                        if pair_counts[cells] != pairs:
                            sys.exit("morse_vs_lammps: %d cells: LAMMPS counts %d unique pairs, rouleau %d"
                                     % (cells, pair_counts[cells], pairs))
                    if lammps[variant]["atoms"] != points_per_cells[cells]:
                        sys.exit("morse_vs_lammps: LAMMPS lost atoms")
                key = (cells, threads)
                if key not in results:
                    results[key] = (pairs, rouleau, lammps, steps)
                else:
                    kept = results[key]
                    for k, b in rouleau.items():
                        if b["real_time"] < kept[1][k]["real_time"]:
                            kept[1][k] = b
                    for variant, result in lammps.items():
                        old = kept[2][variant]
                        if "neigh_per_build" in result:
                            result["neigh_per_build"] = min(result["neigh_per_build"], old["neigh_per_build"])
                        if result["pair_avg"] > old["pair_avg"]:
                            neigh = result.get("neigh_per_build")
                            result = dict(old)
                            if neigh is not None:
                                result["neigh_per_build"] = neigh
                        kept[2][variant] = result
                print("  pass %d: %d cells, %d threads done (%.0f s so far)"
                      % (measurement_pass + 1, cells, threads, time.time() - started), flush=True)
    rows = [(cells, points_per_cells[cells], results[(cells, threads)][0], threads) + results[(cells, threads)][1:]
            for cells in cell_counts for threads in thread_counts]
    print()
    print("ns per unique pair (pairs of points of different cells closer than %g um; LAMMPS counted the same"
          " pairs: %s)" % (CUTOFF, "checked"))
    print("fastest of %d pass(es); rouleau: fastest of %d repetitions (0.1 s each at least); LAMMPS: 'Pair' time (average over ranks) /"
          " (evaluations x unique pairs), fastest of %d blocks; threads = OpenMP threads for rouleau, MPI ranks"
          " for LAMMPS" % (args.passes, args.repetitions, args.repeats))
    header = ["cells", "points", "unique pairs", "threads", "rouleau full", "rouleau half"]
    header += ["LAMMPS %s" % v for v in variants] + ["LAMMPS loop*", "LAMMPS/rouleau"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for cells, points, pairs, threads, rouleau, lammps, steps in rows:
        full = rouleau[("list", 0)]["ns/pair"]
        half = rouleau[("list", 1)]["ns/pair"]
        lammps_ns = {v: lammps[v]["pair_avg"] / (lammps[v]["steps"] * pairs) * 1e9 for v in variants}
        best = min(variants, key=lambda v: lammps_ns[v])
        loop_ns = lammps[best]["loop"] / (lammps[best]["steps"] * pairs) * 1e9
        text = [str(cells), str(points), str(pairs), str(threads), "%.2f" % full, "%.2f" % half]
        text += ["%.2f" % lammps_ns[v] for v in variants]
        text += ["%.2f" % loop_ns, "%.2f" % (lammps_ns[best] / min(full, half))]
        print("| " + " | ".join(text) + " |")
    print("* LAMMPS loop: the fastest variant's whole loop time (pair + comm + integration + output) per"
          " evaluation and pair; LAMMPS/rouleau: the faster LAMMPS variant's Pair time over rouleau's faster list.")
    if args.neighbor_builds:
        print()
        print("neighbour-list build, ms (rouleau: BM_NeighborListBuild with --with-build, r_c + skin;"
              " LAMMPS %s: Neigh time per build, half list)" % variants[0])
        print("| cells | threads | rouleau full list | rouleau half list | LAMMPS |")
        print("|---|---|---|---|---|")
        for cells, points, pairs, threads, rouleau, lammps, steps in rows:
            builds = ["%.1f" % rouleau[("build", h)]["real_time"] if ("build", h) in rouleau else "-" for h in (0, 1)]
            print("| %d | %d | %s | %s | %.1f |" % (cells, threads, builds[0], builds[1],
                                                    lammps[variants[0]]["neigh_per_build"] * 1e3))
    print("evaluations per LAMMPS block: %s; total %.0f s"
          % (", ".join("%d cells: %d" % (r[0], r[6]) for r in rows if r[3] == thread_counts[0]),
             time.time() - started))
    if DISTURBED:
        print("disturbed by other processes after every attempt (least disturbed kept): " + "; ".join(DISTURBED))
    else:
        print("no measurement was disturbed by other processes (< %.1f cores on average)" % FOREIGN_LIMIT)


if __name__ == "__main__":
    main()
