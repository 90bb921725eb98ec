#!/usr/bin/env bash
# Fuzzes the parsers of input that comes from others (tests/fuzz, libFuzzer with
# AddressSanitizer and UBSan): the case-file loader and the mesh cache reader, each for
# SECONDS (default 15) from a seed corpus of real files (the cases' TOML files, the seeds
# in tests/fuzz/corpus, small mesh cache files found on this machine). Every input must
# load or be refused with a message: a crash, an uncaught exception, a hang (> 10 s per
# input), a leak or more than 2 GB of memory fails, with the reproducer saved under
# build-fuzz/findings/. Prints time, executions and corpus size per target.
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds="${1:-15}"
build_dir="${BUILD_DIR:-$root_dir/build-fuzz}"
"$root_dir/scripts/bootstrap.sh" --fuzz
mkdir -p "$build_dir"
cmake -S "$root_dir" -B "$build_dir" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DROULEAU_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$build_dir/configure.log" 2>&1 || { cat "$build_dir/configure.log" >&2; exit 1; }
cmake --build "$build_dir" -j "${ROULEAU_JOBS:-$(nproc)}" >"$build_dir/build.log" 2>&1 ||
  { tail -40 "$build_dir/build.log" >&2; exit 1; }

mesh_cache_dir="${ROULEAU_MESH_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/rouleau/meshes}"
mkdir -p "$build_dir/findings"
for target in case_file mesh_cache; do
  corpus="$build_dir/corpus/$target"
  mkdir -p "$corpus"
  cp "$root_dir/tests/fuzz/corpus/$target/"* "$corpus/"
  if [ "$target" = case_file ]; then
    for file in "$root_dir"/cases/*/*.toml; do cp "$file" "$corpus/$(basename "$(dirname "$file")")_$(basename "$file")"; done
  elif [ -d "$mesh_cache_dir" ]; then
    find "$mesh_cache_dir" -maxdepth 1 -name '*mesh-*.txt' -size -128k -exec cp {} "$corpus/" \;
  fi
  log="$build_dir/fuzz_$target.log"
  if ! "$build_dir/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
       -artifact_prefix="$build_dir/findings/$target-" "$corpus" >"$log" 2>&1; then
    tail -60 "$log" >&2
    echo "fuzz: $target: a problem was found (log $log; reproducer in $build_dir/findings)" >&2
    exit 1
  fi
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  printf 'fuzz: %s: %s s, %s executions, corpus %s files, no problem found\n' \
    "$target" "$seconds" "$executions" "$(find "$corpus" -type f | wc -l)"
done
