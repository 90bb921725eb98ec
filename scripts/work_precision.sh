#!/usr/bin/env bash
# The work–precision study (bench/work_precision.md): every point a real solve, the CSV
# and the log–log figure written under bench/. Arguments go to bench/work_precision
# (--sizes 4,8,16 or --quick for a short run). Threads: OMP_NUM_THREADS (default 1).
#   scripts/work_precision.sh [build-dir] [work_precision arguments...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
if [[ $# -gt 0 && -d "$1" ]]; then build=$1; shift; fi
cmake --build "$build" --target work_precision -j2 >/dev/null
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} OMP_PROC_BIND=${OMP_PROC_BIND:-false}
"$build/bench/work_precision" --out "bench/work_precision_${OMP_NUM_THREADS}t.csv" "$@"
/usr/bin/python3 scripts/plot_work_precision.py "bench/work_precision_${OMP_NUM_THREADS}t.csv"
