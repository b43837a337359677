#!/usr/bin/env bash
# Ironing (prm/ironing.prm, validation.md rung 13): runs the scene with the
# current build into runs/ and writes results.md and ironing.png with
# report.py (force curves against the die's travel, their step-to-step
# smoothness, friction / normal force).
# Usage: benchmarks/contact/ironing/run.sh [NP]   (default 1 rank; ~8 min)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-1}
require_build
dir="$here/runs"
mkdir -p "$dir"
sed -e "s|results/ironing|$dir|" -e "s|= meshes/ironing.msh|= $project_root/prm/meshes/ironing.msh|" \
  "$project_root/prm/ironing.prm" > "$dir/scene.prm"
mpirun -np "$np" "$exe" "$dir/scene.prm" > "$dir/screen.txt" 2>&1
/usr/bin/python3 "$here/report.py" "$here"
