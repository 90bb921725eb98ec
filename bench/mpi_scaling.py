#!/usr/bin/python3
"""Scaling across MPI ranks (bench/mpi.md): measured from 1 to 2 ranks here, modelled
out to 1000.

Measured (bench/mpi_scaling under mpiexec, the shear box with 1 um elements, Stokes limit,
point-block Jacobi GMRES; every figure is the median over repeats of the slowest rank):
  strong   one box of --strong elements: 1 rank x 1 thread, 1 rank x 2 threads (OpenMP),
           2 ranks x 1 thread (MPI)
  weak     --weak elements per rank: 1 rank, then 2 ranks on the box doubled in x
Columns: the distributed Stokes action (its exchanges overlapped with the interior
elements), the same action with the exchanges after the whole element loop, the halo
exchange alone (update_copies + sum_into_owners), one MPI_Allreduce of 61 doubles, and a
GMRES(30) iteration.

Model (per GMRES iteration, P ranks, a cube of elements split into P cubic blocks of
s^3 elements, s = (E/P)^(1/3)):
  compute    t_e E/P, t_e the measured time per element of one iteration on 1 rank x 1
             thread (operator, preconditioner and vector work together);
  halo       3 exchanges per action (copies; then the sums to the owners and back) to 26
             neighbours (6 faces of (s+1)^2 nodes, 12 edges of s+1, 8 corners), 4 values of
             8 bytes per node: 3 x, x = 26 alpha + 32 ((6 (s+1)^2 + 12 (s+1) + 8)) / beta;
  overlap    each of the 3 exchanges travels while a third of the interior elements
             ((s-2)^3 of them) is summed: exposed 3 max(0, x - t_a (s-2)^3 / 3),
             t_a the measured action time per element (action_s on 1 rank x 1 thread). The
             overlap needs the messages to progress while the rank computes: on GPUs the
             kernels run asynchronously while the host waits in MPI; on CPU ranks it
             takes an MPI with asynchronous progress (RDMA, or a progress thread) for
             messages above the eager limit;
  reductions 3 MPI_Allreduce per iteration (CGS2; the norm comes with the last):
             3 x 2 log2(P) alpha.
Network: a typical InfiniBand HDR100 fabric, alpha = 1.5 us latency, beta = 12 GB/s per
rank. The time per element is this machine's core; the model also gives the same ranks as
GPUs 30x faster per element (GPU_SPEEDUP; the staging of halo buffers through the host is
not counted), where communication takes over at far larger blocks.

    /usr/bin/python3 bench/mpi_scaling.py [--strong 48 24 24] [--weak 24 24 24]
        [--out bench/mpi_scaling.csv]                 (figure beside it, .png)
"""
import argparse
import csv
import io
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LATENCY_S = 1.5e-6
BANDWIDTH_B_S = 12e9
BYTES_PER_NODE = 4 * 8
GPU_SPEEDUP = 30.0


def run(binary, ranks, threads, elements, repeats):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND="false",
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    # OpenMPI binds each of up to 2 ranks to one core: a rank with more threads must not be.
    binding = ["--bind-to", "none"] if threads > 1 else []
    command = ["mpiexec", "-n", str(ranks), "--oversubscribe", *binding, binary,
               "--elements", *map(str, elements), "--repeats", str(repeats)]
    out = subprocess.run(command, env=env, capture_output=True, text=True, check=True).stdout
    lines = [l for l in out.splitlines() if l.startswith("ranks,") or l[:1].isdigit()]
    return next(csv.DictReader(io.StringIO("\n".join(lines))))


def model(elements, ranks, seconds_per_element, action_seconds_per_element, speedup=1.0):
    """(compute, halo without overlap, halo exposed with overlap, reductions) per iteration [s]."""
    side = (elements / ranks) ** (1 / 3)
    compute = seconds_per_element * elements / ranks / speedup
    if ranks == 1:
        return compute, 0.0, 0.0, 0.0
    nodes = 6 * (side + 1) ** 2 + 12 * (side + 1) + 8
    exchange = 26 * LATENCY_S + BYTES_PER_NODE * nodes / BANDWIDTH_B_S
    halo = 3 * exchange
    interior = action_seconds_per_element * max(0.0, side - 2) ** 3 / speedup
    halo_exposed = 3 * max(0.0, exchange - interior / 3)
    reductions = 3 * 2 * math.log2(ranks) * LATENCY_S
    return compute, halo, halo_exposed, reductions


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "bench", "mpi_scaling"))
    parser.add_argument("--strong", type=int, nargs=3, default=[48, 24, 24])
    parser.add_argument("--weak", type=int, nargs=3, default=[24, 24, 24])
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "mpi_scaling.csv"))
    args = parser.parse_args()

    rows = []
    for ranks, threads in ((1, 1), (1, 2), (2, 1)):
        rows.append(dict(study="strong", **run(args.binary, ranks, threads, args.strong, args.repeats)))
    weak_2 = [2 * args.weak[0], args.weak[1], args.weak[2]]
    rows.append(dict(study="weak", **run(args.binary, 1, 1, args.weak, args.repeats)))
    rows.append(dict(study="weak", **run(args.binary, 2, 1, weak_2, args.repeats)))

    base = rows[0]
    seconds_per_element = float(base["iteration_s"]) / float(base["elements_per_rank"])
    action_seconds_per_element = float(base["action_s"]) / float(base["elements_per_rank"])
    for row in rows:
        row["speedup_vs_1_rank_1_thread"] = ""
    for row in rows[:3]:
        row["speedup_vs_1_rank_1_thread"] = f"{float(base['iteration_s']) / float(row['iteration_s']):.3f}"
    rows[4]["speedup_vs_1_rank_1_thread"] = f"{float(rows[3]['iteration_s']) / float(rows[4]['iteration_s']):.3f}"

    print(f"{'study':7} {'ranks':>5} {'thr':>3} {'unknowns':>9} {'action ms':>9} {'no overlap':>10} "
          f"{'exchange ms':>11} {'allreduce us':>12} {'iteration ms':>12} {'speed-up':>8}")
    for r in rows:
        print(f"{r['study']:7} {r['ranks']:>5} {r['threads']:>3} {r['unknowns']:>9} "
              f"{1e3 * float(r['action_s']):9.3f} {1e3 * float(r['action_after_loop_s']):10.3f} "
              f"{1e3 * float(r['exchange_s']):11.3f} "
              f"{1e6 * float(r['allreduce_s']):12.2f} {1e3 * float(r['iteration_s']):12.3f} "
              f"{r['speedup_vs_1_rank_1_thread']:>8}")

    # The model: strong scaling of a 10^7-unknown box (2.5e6 elements), weak scaling at the
    # measured weak block per rank, out to 1000 ranks.
    model_rows = []
    strong_elements = 2.5e6
    weak_elements = args.weak[0] * args.weak[1] * args.weak[2]
    for ranks in (1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1000):
        for study, elements in (("model strong 1e7 unknowns", strong_elements),
                                ("model weak", weak_elements * ranks)):
            compute, halo, exposed, reductions = model(elements, ranks, seconds_per_element,
                                                       action_seconds_per_element)
            total = compute + halo + reductions
            overlapped = compute + exposed + reductions
            # the same ranks as GPUs, GPU_SPEEDUP times faster per element, same network
            gpu_compute, _, gpu_exposed, _ = model(elements, ranks, seconds_per_element,
                                                   action_seconds_per_element, GPU_SPEEDUP)
            gpu_total = gpu_compute + halo + reductions
            gpu_overlapped = gpu_compute + gpu_exposed + reductions
            model_rows.append(dict(study=study, ranks=ranks, elements=int(elements), compute_s=compute, halo_s=halo,
                                   halo_exposed_s=exposed, reductions_s=reductions, iteration_s=total,
                                   communication_fraction=(halo + reductions) / total,
                                   overlapped_iteration_s=overlapped,
                                   overlapped_communication_fraction=(exposed + reductions) / overlapped,
                                   gpu_iteration_s=gpu_total,
                                   gpu_communication_fraction=(halo + reductions) / gpu_total,
                                   gpu_halo_exposed_s=gpu_exposed,
                                   gpu_overlapped_iteration_s=gpu_overlapped,
                                   gpu_overlapped_communication_fraction=(gpu_exposed + reductions) / gpu_overlapped))
    print(f"\nmodel ({seconds_per_element * 1e9:.0f} ns per element per iteration, alpha {LATENCY_S * 1e6} us, "
          f"beta {BANDWIDTH_B_S / 1e9} GB/s)")
    for m in model_rows:
        if m["ranks"] in (1, 8, 64, 512, 1000):
            print(f"  {m['study']:26} P={m['ranks']:5d}: iteration {1e3 * m['iteration_s']:9.3f} ms, "
                  f"communication {100 * m['communication_fraction']:5.1f} % "
                  f"({100 * m['overlapped_communication_fraction']:5.1f} % overlapped); as GPU ranks "
                  f"{1e3 * m['gpu_iteration_s']:8.3f} ms, communication {100 * m['gpu_communication_fraction']:5.1f} % "
                  f"({100 * m['gpu_overlapped_communication_fraction']:5.1f} % overlapped, "
                  f"{1e3 * m['gpu_overlapped_iteration_s']:8.3f} ms)")

    measured_fields = list(rows[0].keys())
    model_fields = list(model_rows[0].keys())
    with open(args.out + ".tmp", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=measured_fields + [k for k in model_fields if k not in measured_fields])
        writer.writeheader()
        for r in rows + model_rows:
            writer.writerow(r)
    os.replace(args.out + ".tmp", args.out)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, study, title in ((axes[0], "model strong 1e7 unknowns", "strong: 10^7 unknowns"),
                             (axes[1], "model weak", f"weak: {weak_elements} elements per rank")):
        ms = [m for m in model_rows if m["study"] == study]
        ranks = [m["ranks"] for m in ms]
        ax.loglog(ranks, [m["iteration_s"] for m in ms], "k-", label="model: total")
        ax.loglog(ranks, [m["compute_s"] for m in ms], "b--", label="compute")
        ax.loglog(ranks[1:], [m["halo_s"] + m["reductions_s"] for m in ms[1:]], "r:", label="communication")
        ax.loglog(ranks[1:], [m["halo_exposed_s"] + m["reductions_s"] for m in ms[1:]], "r-", alpha=0.5,
                  label="communication left exposed by the overlap (CPU ranks)")
        ax.loglog(ranks, [m["gpu_overlapped_iteration_s"] for m in ms], "g-.", label="GPU ranks, overlapped: total")
        ax.loglog(ranks[1:], [m["gpu_halo_exposed_s"] + m["reductions_s"] for m in ms[1:]], "g:",
                  label="GPU ranks: communication left exposed")
        ax.set_xlabel("ranks")
        ax.set_ylabel("s per GMRES iteration")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    measured_weak = rows[3:5]
    axes[1].loglog([int(r["ranks"]) for r in measured_weak], [float(r["iteration_s"]) for r in measured_weak], "ko",
                   label="measured here")
    for ax in axes:
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.splitext(args.out)[0] + ".png", dpi=120)
    print(f"wrote {args.out} and {os.path.splitext(args.out)[0]}.png")


if __name__ == "__main__":
    sys.exit(main())
