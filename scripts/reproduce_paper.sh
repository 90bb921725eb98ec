#!/usr/bin/env bash
# Reproduces the paper (Figs. 6-17): installs what is missing (with ParaView and Xvfb for
# the pictures), builds, runs the scenes of scripts/paper_scenes.toml into runs/paper/
# (continuing stopped runs from their checkpoints), renders them and writes docs/paper.md
# and docs/paper_checks.csv. Hours: each scene's expected time is in paper_scenes.toml,
# the measured ones in runs/paper/times.csv and docs/paper.md.
#   scripts/reproduce_paper.sh [--only ID,ID...] [--report-only] [--no-render]
set -euo pipefail
root_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root_dir/scripts/bootstrap.sh" --paraview >/dev/null
"$root_dir/scripts/build.sh"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-$(nproc)}"
exec /usr/bin/python3 "$root_dir/scripts/reproduce_paper.py" "$@"
