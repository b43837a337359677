#!/usr/bin/env bash
# The paper's two bodies with frictional contact (prm/two_bodies.prm):
# the block pressed onto the plate for 113 steps. Runs the scene with the
# current build and the augmented Lagrangian (the enforcement of the
# frozen-operator run) into runs/consistent and writes results.md and
# two_bodies.png with report.py, next to the committed run with frozen
# mortar operators (runs/frozen-operators: code of commit 68b66c7, before
# the consistent linearisation). The scene's own enforcement, semi-smooth
# Newton, is timed in benchmarks/performance.
# Usage: benchmarks/contact/two_bodies/run.sh [NP]   (default 2 ranks; ~2 min)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build
dir="$here/runs/consistent"
mkdir -p "$dir"
sed -e "s|results/two_bodies|$dir|" "$project_root/prm/two_bodies.prm" > "$dir/scene.prm"
printf '%s\n' "subsection Contact pair 1" "set Enforcement = augmented Lagrangian" "end" \
  >> "$dir/scene.prm"
mpirun -np "$np" "$exe" "$dir/scene.prm" > "$dir/screen.txt" 2>&1
/usr/bin/python3 "$here/report.py" "$here"
