#!/usr/bin/python3
"""A time step of every paper scene on 2 threads beside one busy single-threaded process,
against the same step on the idle machine (bench/scenes.md): what a researcher's laptop,
which always runs something else, sees.

    /usr/bin/python3 bench/under_load.py [--cases stack_shear,...] [--warmup 2] [--steps 4]
        [--repeats 2] [--out bench/under_load.csv]

Per scene it times a step as bench/scene_steps.py does (the step's stages over warmup+steps
steps minus those over warmup steps), on 2 threads, with the threads as rouleau places them
by default (bound one per core) and free to move (OMP_PROC_BIND=false), each on the idle
machine and beside a busy loop (one process spinning on the CPU the whole time), taking
turns, each twice (the least counts). The bound it is judged by, written before any run: a step beside the busy process
takes at most 2.5 times its idle time with the default placement.
"""
import argparse
import csv
import os
import subprocess
import sys

from scene_steps import CASES, ROOT, measure

BOUND_BUSY_OVER_IDLE = 2.5
PLACEMENTS = {"default (bound)": {}, "free (OMP_PROC_BIND=false)": {"OMP_PROC_BIND": "false"}}


def busy_process():
    """One single-threaded process that spins until it is killed."""
    return subprocess.Popen([sys.executable, "-c", "while True: pass"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rouleau", default=os.path.join(ROOT, "build", "rouleau"))
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--warmup", type=int, default=2)
    parser.add_argument("--steps", type=int, default=4)
    parser.add_argument("--repeats", type=int, default=2)
    parser.add_argument("--scratch", default=os.path.join(ROOT, "build", "under_load"))
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "under_load.csv"))
    args = parser.parse_args()
    rows = []
    for case in args.cases.split(","):
        case_file = os.path.join(ROOT, "cases", case, "case.toml")
        for placement, binding in PLACEMENTS.items():
            seconds = {"idle": float("inf"), "busy": float("inf")}
            for _ in range(args.repeats):
                for load in ("idle", "busy"):
                    spinner = busy_process() if load == "busy" else None
                    try:
                        result = measure(args.rouleau, case_file, os.path.join(args.scratch, case), 2, args.warmup,
                                         args.steps, binding)
                    finally:
                        if spinner:
                            spinner.kill()
                            spinner.wait()
                    seconds[load] = min(seconds[load], result["seconds_per_step"])
            ratio = seconds["busy"] / seconds["idle"]
            rows.append({"case": case, "placement": placement, "idle_seconds_per_step": round(seconds["idle"], 4),
                         "busy_seconds_per_step": round(seconds["busy"], 4), "busy_over_idle": round(ratio, 2)})
            print(f"{case:14s} {placement:28s} idle {seconds['idle']:.3f} s  busy {seconds['busy']:.3f} s  "
                  f"ratio {ratio:.2f}", flush=True)
    with open(args.out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    default = [r for r in rows if r["placement"].startswith("default")]
    worst = max(r["busy_over_idle"] for r in default)
    print(f"default placement: largest busy/idle ratio {worst:.2f} (bound {BOUND_BUSY_OVER_IDLE}): "
          f"{'met' if worst <= BOUND_BUSY_OVER_IDLE else 'NOT MET'}")
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
