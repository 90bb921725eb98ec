#!/usr/bin/env bash
# The long tier: installs what is missing, builds, and runs the
# validations at full resolution, the tests labelled "long" (tests/long_*.cpp), one at a
# time on every core. Times are recorded in docs/development.md ("Test tiers").
#   scripts/long_tier.sh [ctest arguments...]     e.g. -R Ca005 for one test
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root_dir/scripts/build.sh"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-$(nproc)}"
start=$(date +%s)
ctest --test-dir "${BUILD_DIR:-$root_dir/build}" -L long --output-on-failure -V "$@" |
  grep -E "^[0-9]+: (capsule|small|published|Jeffery|plug|pair|paper|stack|contraction|\[ *(OK|FAILED) *\])|tests passed|Failure|Expected|Which is|actual|Test +#"
echo "long tier: $(( $(date +%s) - start )) s on ${OMP_NUM_THREADS} threads"
