#!/usr/bin/python3
"""The scene benchmark (bench/scenes.md): every paper scene at its case file's resolution and
time step, a fixed number of steps on 1 and 2 threads, with the binary of a baseline revision
(the previous commit by default) and this tree's binary run in turn, so that every speed-up is
a ratio measured side by side on the same machine at the same time.

    /usr/bin/python3 bench/scene_steps.py [--baseline HEAD~1 | --baseline-binary PATH]
        [--threads 1,2] [--warmup 2] [--steps 4] [--repeats 2] [--cases aggregation,...]
        [--out bench/scene_steps.csv]

The baseline is built once per revision (the `rouleau` target only) into
build-bench/<revision>/ from `git archive`, against the same Kokkos as build/. This tree's
binaries must be built (`scripts/build.sh`): build/rouleau and build/bench/scene_operator
(the folder of --rouleau).

Per scene, thread count and binary it reports:
- seconds per step: the step's stages (forces, spread, cell stiffness, fluid solve,
  interpolate, move; not the set-up, diagnostics, output or checkpoint stages) summed over a
  run of warmup + steps steps, minus the same sum over a run of warmup steps, divided by
  steps; the least over the repeats;
- GMRES iterations per step, over the same steps;
- seconds per GMRES iteration (the fluid solve's seconds per step over its GMRES iterations)
  divided by the seconds of one application of the fluid operator on the same mesh
  (bench/scene_operator.cpp, this tree's binary, same thread count): the solve's overhead
  ratio, how many operator applications one GMRES iteration costs;
- the run's peak memory (resident set, as the run reports it) per fluid unknown;
- the answers' largest difference: after the last timed step, the largest difference between
  the two binaries' cell centroids and gaps (diagnostics.csv, μm), which must stay at the
  solver tolerance's level (a faster step may not change the result).
The targets they are judged by are written below, before any run.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile

from run_log import case_time_step, stage_times

CASES = ["aggregation", "stack_shear", "twelve_cells", "contraction", "capillary"]
# Targets, 2 threads: seconds per step at the case's resolution and time step, one GMRES
# iteration in operator applications, memory per fluid unknown.
TARGET_SECONDS_PER_STEP = {"aggregation": 0.10, "stack_shear": 0.10, "twelve_cells": 0.30, "contraction": 0.15,
                           "capillary": 0.10}
TARGET_OVERHEAD_RATIO = 5.0
TARGET_BYTES_PER_UNKNOWN = 1024.0
# Stages that are not part of a time step.
NOT_STEP_STAGES = {"mesh", "cell meshes", "fluid setup", "coupling setup", "cell diagnostics", "output", "checkpoint"}
UNKNOWNS = re.compile(r"^fluid mesh: .*?(\d+) unknowns", re.M)
PEAK_MEMORY = re.compile(r"^peak memory: ([0-9.]+) MiB", re.M)
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def thread_environment(threads, binding=None):
    """OpenMP on `threads` threads, pinned one per core unless the caller says otherwise;
    `binding` given: exactly these OMP_PROC_BIND/OMP_PLACES settings ({} = rouleau's own
    default)."""
    environment = dict(os.environ, OMP_NUM_THREADS=str(threads))
    if binding is None:
        binding = {"OMP_PROC_BIND": os.environ.get("OMP_PROC_BIND", "spread"),
                   "OMP_PLACES": os.environ.get("OMP_PLACES", "threads")}
    for variable in ("OMP_PROC_BIND", "OMP_PLACES"):
        environment.pop(variable, None)
    environment.update(binding)
    return environment


def fail(message):
    sys.exit(f"scene_steps.py: {message}")




def build_baseline(revision):
    """The rouleau binary of `revision`, built (once) from its archived tree."""
    sha = subprocess.run(["git", "-C", ROOT, "rev-parse", "--verify", revision + "^{commit}"], capture_output=True,
                         text=True).stdout.strip()
    if not sha:
        fail(f"--baseline {revision}: not a commit of this repository")
    folder = os.path.join(ROOT, "build-bench", sha[:12])
    binary = os.path.join(folder, "build", "rouleau")
    if os.path.exists(binary):
        return binary, sha[:12]
    source = os.path.join(folder, "source")
    os.makedirs(source, exist_ok=True)
    archive = subprocess.Popen(["git", "-C", ROOT, "archive", sha], stdout=subprocess.PIPE)
    subprocess.run(["tar", "-x", "-C", source], stdin=archive.stdout, check=True)
    if archive.wait() != 0:
        fail(f"git archive {sha} failed")
    prefix = subprocess.run([os.path.join(ROOT, "scripts", "bootstrap.sh")], capture_output=True, text=True,
                            check=True).stdout.strip().splitlines()[-1]
    print(f"building the baseline {sha[:12]} in {folder} (the rouleau target only)", flush=True)
    build = os.path.join(folder, "build")
    for command in (["cmake", "-S", source, "-B", build, f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_BUILD_TYPE=Release",
                     "-DROULEAU_BUILD_TESTS=OFF", "-DROULEAU_BUILD_BENCHMARKS=OFF", "-DROULEAU_BUILD_CASES=OFF"],
                    ["cmake", "--build", build, "--target", "rouleau", "-j", str(os.cpu_count() or 2)]):
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            fail(f"{' '.join(command)} failed:\n{(done.stdout + done.stderr)[-3000:]}")
    return binary, sha[:12]


def run(binary, case_file, folder, steps, threads, binding=None):
    """One run of `steps` steps: (the step stages' seconds, the fluid solve's seconds, the
    GMRES iterations of each step, the fluid unknowns, the peak memory in MiB, the last
    diagnostics row)."""
    dt = case_time_step(case_file)
    command = [binary, "run", case_file, "--out", folder, "--overwrite", "--no-progress", "--threads", str(threads),
               "--set", f"time.end_s={steps * dt!r}", "--set", "output.fields=false",
               "--set", "output.diagnostics_every_steps=1", "--set", "checkpoint.every_minutes=0"]
    done = subprocess.run(command, capture_output=True, text=True, env=thread_environment(threads, binding))
    if done.returncode != 0:
        fail(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    log = done.stdout + done.stderr
    stages = stage_times(log)
    step_seconds = sum(seconds for stage, seconds in stages.items() if stage not in NOT_STEP_STAGES)
    with open(os.path.join(folder, "diagnostics.csv")) as f:
        rows = list(csv.DictReader(f))
    gmres = {int(row["step"]): int(float(row["gmres_iterations"])) for row in rows}
    unknowns, peak = UNKNOWNS.search(log), PEAK_MEMORY.search(log)
    if not unknowns or not peak:
        fail(f"{' '.join(command)}: the log has no unknowns or peak memory line")
    return (step_seconds, stages.get("fluid solve", 0.0), gmres, int(unknowns.group(1)), float(peak.group(1)),
            rows[-1])


# The diagnostics columns whose difference between two binaries is the answers' difference
# [μm]: each cell's centroid and each pair's gap.
ANSWER_COLUMNS = re.compile(r"^(cell\d+_centroid_[xyz]_um|gap_\d+_\d+_um)$")


def answer_difference(row_a, row_b):
    """The largest |a − b| over the centroid and gap columns both rows hold [μm]; 0 for a scene
    without cells, NaN when the rows have such columns but none in common (renamed columns
    must not read as agreement)."""
    own = [c for c in row_b if ANSWER_COLUMNS.match(c) and row_b[c]]
    columns = [c for c in own if row_a.get(c)]
    if own and not columns:
        return float("nan")
    return max((abs(float(row_a[c]) - float(row_b[c])) for c in columns), default=0.0)


def measure(binary, case_file, scratch, threads, warmup, steps, binding=None):
    """Seconds per step, fluid solve seconds per step, GMRES iterations per step, unknowns and
    peak MiB over steps warmup+1 … warmup+steps."""
    short = run(binary, case_file, os.path.join(scratch, "short"), warmup, threads, binding)
    long = run(binary, case_file, os.path.join(scratch, "long"), warmup + steps, threads, binding)
    iterations = [long[2][s] for s in range(warmup + 1, warmup + steps + 1) if s in long[2]]
    return {"seconds_per_step": (long[0] - short[0]) / steps, "fluid_seconds_per_step": (long[1] - short[1]) / steps,
            "gmres_per_step": sum(iterations) / max(len(iterations), 1), "unknowns": long[3], "peak_mib": long[4],
            "last_row": long[5]}


def operator_seconds(rouleau, case_file, threads):
    binary = os.path.join(os.path.dirname(rouleau), "bench", "scene_operator")
    done = subprocess.run([binary, case_file], capture_output=True, text=True,
                          env=thread_environment(threads))
    match = re.search(r"seconds_per_application (\S+) path (\S+)", done.stdout)
    if done.returncode != 0 or not match:
        fail(f"{binary} {case_file} failed ({done.returncode}):\n{done.stderr[-2000:]}")
    return float(match.group(1)), match.group(2)


def plot(rows, threads, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    cases = list(dict.fromkeys(r["case"] for r in rows))
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    x = np.arange(len(cases))
    width = 0.8 / (2 * len(threads))
    panels = [("seconds_per_step", "seconds per step", True), ("gmres_per_step", "GMRES iterations per step", False),
              ("overhead_ratio", "one GMRES iteration / one operator application", True),
              ("bytes_per_unknown", "peak memory per fluid unknown (bytes)", True)]
    for axis, (key, title, log_scale) in zip(axes.flat, panels):
        k = 0
        for t in threads:
            for binary, hatch in (("baseline", "//"), ("new", "")):
                values = [next((float(r[key]) for r in rows if r["case"] == c and int(r["threads"]) == t
                                and r["binary"] == binary), np.nan) for c in cases]
                axis.bar(x - 0.4 + width * (k + 0.5), values, width, hatch=hatch, label=f"{binary}, {t} thread(s)",
                         color=f"C{threads.index(t)}", edgecolor="black", linewidth=0.5)
                k += 1
        if key == "seconds_per_step":
            axis.scatter(x, [TARGET_SECONDS_PER_STEP.get(c, np.nan) for c in cases], marker="_", s=600, color="red",
                         zorder=3, label="target, 2 threads")
        elif key == "overhead_ratio":
            axis.axhline(TARGET_OVERHEAD_RATIO, color="red", linewidth=1, label="target")
        elif key == "bytes_per_unknown":
            axis.axhline(TARGET_BYTES_PER_UNKNOWN, color="red", linewidth=1, label="target (at 1 M unknowns)")
        axis.set_xticks(x)
        axis.set_xticklabels(cases, rotation=15)
        axis.set_title(title, fontsize=10)
        if log_scale:
            axis.set_yscale("log")
        axis.grid(axis="y", alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--baseline", default="HEAD~1", help="the revision to compare with (default HEAD~1)")
    parser.add_argument("--baseline-binary", default="", help="a rouleau binary to compare with instead")
    parser.add_argument("--rouleau", default=os.path.join(ROOT, "build", "rouleau"))
    parser.add_argument("--threads", default="1,2")
    parser.add_argument("--warmup", type=int, default=2)
    parser.add_argument("--steps", type=int, default=4)
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "scene_steps.csv"))
    args = parser.parse_args()
    threads = [int(t) for t in args.threads.split(",")]
    if args.baseline_binary:
        baseline = os.path.abspath(args.baseline_binary)
        version = subprocess.run([baseline, "--version"], capture_output=True, text=True).stdout
        match = re.search(r"\(([0-9a-f]+(?:-dirty)?)\)", version)
        baseline_name = match.group(1) if match else baseline
    else:
        baseline, baseline_name = build_baseline(args.baseline)
    binaries = {"baseline": baseline, "new": os.path.abspath(args.rouleau)}
    this_tree = subprocess.run(["git", "-C", ROOT, "describe", "--always", "--dirty"], capture_output=True,
                               text=True).stdout.strip() or "this tree"

    rows = []
    with tempfile.TemporaryDirectory(prefix="rouleau-scene-steps-") as scratch:
        for case in args.cases.split(","):
            case_file = os.path.join(ROOT, "cases", case, "case.toml")
            for t in threads:
                best = {}
                for repeat in range(args.repeats):
                    # alternate which binary goes first, so neither always runs on a warmer machine
                    order = ("baseline", "new") if repeat % 2 == 0 else ("new", "baseline")
                    for name in order:
                        result = measure(binaries[name], case_file, os.path.join(scratch, name), t, args.warmup,
                                         args.steps)
                        print(f"{case}, {t} thread(s), {name}: {result['seconds_per_step']:.3f} s per step, "
                              f"{result['gmres_per_step']:.1f} GMRES", flush=True)
                        if name not in best or result["seconds_per_step"] < best[name]["seconds_per_step"]:
                            best[name] = result
                op_seconds, path = operator_seconds(binaries["new"], case_file, t)
                difference = answer_difference(best["baseline"]["last_row"], best["new"]["last_row"])
                for name in ("baseline", "new"):
                    r = best[name]
                    per_iteration = r["fluid_seconds_per_step"] / r["gmres_per_step"] if r["gmres_per_step"] else 0.0
                    rows.append({"case": case, "threads": t, "binary": name,
                                 "revision": baseline_name if name == "baseline" else this_tree,
                                 "unknowns": r["unknowns"], "seconds_per_step": f"{r['seconds_per_step']:.4f}",
                                 "gmres_per_step": f"{r['gmres_per_step']:.2f}",
                                 "seconds_per_gmres_iteration": f"{per_iteration:.5f}",
                                 "operator_seconds": f"{op_seconds:.6f}", "operator_path": path,
                                 "overhead_ratio": f"{per_iteration / op_seconds:.1f}",
                                 "peak_mib": f"{r['peak_mib']:.0f}",
                                 "bytes_per_unknown": f"{r['peak_mib'] * 2**20 / r['unknowns']:.0f}",
                                 "speedup": f"{best['baseline']['seconds_per_step'] / r['seconds_per_step']:.2f}",
                                 "answer_difference_um": f"{difference:.2e}"})

    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    figure = os.path.splitext(args.out)[0] + ".png"
    plot(rows, threads, figure)
    print(f"\n{args.warmup} warm-up steps, then {args.steps} timed steps, least of {args.repeats} runs; baseline "
          f"{baseline_name}; wrote {args.out} and {figure}\n")
    print("| case | threads | s/step baseline | s/step new | speed-up | target (2 threads) | GMRES/step | "
          "GMRES iteration / operator | bytes per unknown | answers' largest difference (μm) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for case in dict.fromkeys(r["case"] for r in rows):
        for t in threads:
            old = next(r for r in rows if r["case"] == case and r["threads"] == t and r["binary"] == "baseline")
            new = next(r for r in rows if r["case"] == case and r["threads"] == t and r["binary"] == "new")
            print(f"| {case} | {t} | {old['seconds_per_step']} | {new['seconds_per_step']} | {new['speedup']}× | "
                  f"{TARGET_SECONDS_PER_STEP.get(case, '')} | {old['gmres_per_step']} → {new['gmres_per_step']} | "
                  f"{old['overhead_ratio']} → {new['overhead_ratio']} | {new['bytes_per_unknown']} | "
                  f"{new['answer_difference_um']} |")


if __name__ == "__main__":
    main()
