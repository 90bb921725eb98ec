#!/usr/bin/env bash
# Installs what is missing (scripts/bootstrap.sh), configures and builds rouleau.
#   scripts/build.sh [extra CMake arguments...]          # OpenMP/Serial build in build/
#   scripts/build.sh --cuda [extra CMake arguments...]   # CUDA build (sm_80) in build-cuda/
# BUILD_DIR overrides the build folder; ROULEAU_JOBS the number of parallel jobs.
#
# The CUDA build compiles every kernel, the library, tests, benchmarks and case drivers
# with nvcc (through Kokkos' nvcc_wrapper) and the host-only files (config, CLI, I/O)
# with g++-11; its binaries need a GPU to run.
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
variant=()
build_dir="${BUILD_DIR:-$root_dir/build}"
compilers=()
if [ "${1:-}" = "--cuda" ]; then
  shift
  variant=(--cuda)
  build_dir="${BUILD_DIR:-$root_dir/build-cuda}"
  # shellcheck source=scripts/cuda-env.sh
  . "$root_dir/scripts/cuda-env.sh"
  compilers=(-DCMAKE_C_COMPILER=gcc-11 -DCMAKE_CXX_COMPILER=g++-11)
fi
kokkos_prefix=$("$root_dir/scripts/bootstrap.sh" "${variant[@]}")
mkdir -p "$build_dir"
cmake -S "$root_dir" -B "$build_dir" -DCMAKE_PREFIX_PATH="$kokkos_prefix" "${compilers[@]}" "$@" \
  >"$build_dir/configure.log" 2>&1 || { cat "$build_dir/configure.log" >&2; exit 1; }
cmake --build "$build_dir" -j "${ROULEAU_JOBS:-$(nproc)}"
