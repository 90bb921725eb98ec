#!/usr/bin/env bash
# The unit tests (ctest label "unit": kernels against serial references, parsers, I/O,
# CLI, state checks) built with AddressSanitizer and UBSan and run on one thread: any
# out-of-bounds access, use after free, leak or undefined behaviour in rouleau's code
# stops the test that hit it and fails. Kokkos itself is used as built by the bootstrap
# (not instrumented). Compiled at -O1, the level the sanitizers' documentation recommends:
# the build is most of this stage's time. On 2 cores this script took 656 s at -O1 (tests
# 159 s) against 922 s at -O3 (tests 147 s), both passing the same 194 tests.
#   scripts/sanitize.sh [extra ctest arguments...]
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="${BUILD_DIR:-$root_dir/build-sanitize}"
kokkos_prefix=$("$root_dir/scripts/bootstrap.sh")
mkdir -p "$build_dir"
cmake -S "$root_dir" -B "$build_dir" -DCMAKE_PREFIX_PATH="$kokkos_prefix" -DROULEAU_SANITIZE=ON -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DROULEAU_BUILD_BENCHMARKS=OFF -DROULEAU_BUILD_CASES=OFF >"$build_dir/configure.log" 2>&1 ||
  { cat "$build_dir/configure.log" >&2; exit 1; }
cmake --build "$build_dir" --target rouleau_unit_tests -j "${ROULEAU_JOBS:-$(nproc)}" >"$build_dir/build.log" 2>&1 ||
  { grep -E "error" "$build_dir/build.log" | head -40 >&2; tail -20 "$build_dir/build.log" >&2; exit 1; }
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:${ASAN_OPTIONS:-}"
# Leaks inside third-party libraries (Gmsh) are listed, with the reason, in tests/lsan.supp.
export LSAN_OPTIONS="suppressions=$root_dir/tests/lsan.supp:print_suppressions=0:${LSAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
OMP_NUM_THREADS=1 ctest --test-dir "$build_dir" -L unit --no-tests=error --output-on-failure "$@"
