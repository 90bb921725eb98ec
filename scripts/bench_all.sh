#!/usr/bin/env bash
# Every study of bench/README.md in one command: installs what is missing,
# builds, then runs, one at a time on an otherwise idle machine,
#   1. the kernel benchmarks (Google Benchmark; JSON into bench/results/), each with the
#      STREAM-like triad and the peak-flops loop of the same run, on 1 and on all threads;
#   2. the work–precision studies (scripts/work_precision.sh; bench/work_precision_cells);
#   3. the stability map (bench/stability.py);
#   4. the scaling study (bench/scaling.py);
#   5. each paper scene's time step against the previous commit's (bench/scene_steps.py),
#      and with and without its skips (bench/scene_skips.py);
#   6. MPI: the operator's scaling and model (bench/mpi_scaling.py), and whole
#      scenes on 2 ranks against 1 (bench/scene_skips.py under mpiexec: bench/mpi_scenes_*.csv).
# The CSVs and figures land under bench/, where the README reads them. Hours in all
# (the stability map and the scenes dominate); a step can be picked by name:
#   scripts/bench_all.sh [kernels] [work_precision] [stability] [scaling] [scenes] [mpi]
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root_dir"
scripts/build.sh
build="${BUILD_DIR:-$root_dir/build}"
steps=("$@")
[ ${#steps[@]} -eq 0 ] && steps=(kernels work_precision stability scaling scenes mpi)
all_threads=$(nproc)
export OMP_PROC_BIND=spread OMP_PLACES=threads
start=$(date +%s)
for step in "${steps[@]}"; do
  echo "bench_all: $step ($(( $(date +%s) - start )) s)"
  case "$step" in
    kernels)
      mkdir -p bench/results
      for program in bench_fluid_operator bench_neo_hookean bench_morse bench_rkpm bench_gmres bench_coupling; do
        for threads in 1 "$all_threads"; do
          OMP_NUM_THREADS=$threads "$build/bench/$program" --benchmark_min_time=0.3 --benchmark_counters_tabular=true \
            --benchmark_out="bench/results/${program}_${threads}t.json" --benchmark_out_format=json
        done
      done
      ;;
    work_precision)
      OMP_NUM_THREADS=1 OMP_PROC_BIND=false scripts/work_precision.sh "$build"
      OMP_NUM_THREADS=1 "$build/bench/work_precision_cells" --out bench/work_precision_cells_1t.csv
      /usr/bin/python3 scripts/plot_work_precision.py bench/work_precision_cells_1t.csv
      ;;
    stability) /usr/bin/python3 bench/stability.py --rouleau "$build/rouleau" --out bench/stability.csv ;;
    scaling) /usr/bin/python3 bench/scaling.py --rouleau "$build/rouleau" --threads "$all_threads" --out bench/scaling.csv ;;
    scenes)
      /usr/bin/python3 bench/scene_steps.py --rouleau "$build/rouleau"
      /usr/bin/python3 bench/scene_skips.py --rouleau "$build/rouleau" --threads "$all_threads"
      /usr/bin/python3 bench/gmres_growth.py --rouleau "$build/rouleau"
      /usr/bin/python3 bench/under_load.py --rouleau "$build/rouleau"
      ;;
    mpi)
      /usr/bin/python3 bench/mpi_scaling.py
      # One thread per rank against one rank on one thread; point-block Jacobi is the same
      # on any rank count (the contraction needs ILU(0): ILU(0) per rank on 2; the multigrid
      # becomes the multigrid per rank).
      for preconditioner in block_jacobi ilu0 multigrid; do
        cases=rbc_shear,aggregation,twelve_cells
        [ "$preconditioner" = ilu0 ] && cases=contraction
        [ "$preconditioner" = multigrid ] && cases=contraction,aggregation
        OMP_PROC_BIND=false /usr/bin/python3 bench/scene_skips.py --rouleau "$build/rouleau" --threads 1 --steps 5 \
          --cases "$cases" --baseline "solver.preconditioner=\"$preconditioner\"" \
          --variant "solver.preconditioner=\"$preconditioner\"" --variant-launcher "mpiexec -n 2 --oversubscribe" \
          --out "bench/mpi_scenes_$preconditioner.csv"
      done
      ;;
    *) echo "bench_all: unknown step '$step' (kernels, work_precision, stability, scaling, scenes, mpi)" >&2; exit 2 ;;
  esac
done
echo "bench_all: done in $(( $(date +%s) - start )) s"
