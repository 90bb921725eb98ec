#!/usr/bin/env bash
# Installs what is missing (scripts/bootstrap.sh), configures and builds rouleau in build/.
#   scripts/build.sh [extra CMake arguments...]
# BUILD_DIR overrides the build folder; ROULEAU_JOBS the number of parallel jobs.
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="${BUILD_DIR:-$root_dir/build}"
kokkos_prefix=$("$root_dir/scripts/bootstrap.sh")
mkdir -p "$build_dir"
cmake -S "$root_dir" -B "$build_dir" -DCMAKE_PREFIX_PATH="$kokkos_prefix" "$@" >"$build_dir/configure.log" 2>&1 ||
  { cat "$build_dir/configure.log" >&2; exit 1; }
cmake --build "$build_dir" -j "${ROULEAU_JOBS:-$(nproc)}"
