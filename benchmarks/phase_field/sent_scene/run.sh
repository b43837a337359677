#!/usr/bin/env bash
# The notched-tension scene prm/sent_coarse.prm run to complete
# fracture with the current build: statistics, screen output and the last
# output step in runs/, then report.py (force curve, energies, a picture of
# s on the slab with scripts/vtu_slice.py).
# Usage: benchmarks/phase_field/sent_scene/run.sh [NP]   (default 2 ranks;
#        ~15 min on 2 cores)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build
dir="$here/runs"
mkdir -p "$dir"
sed -e "s|set Directory = results|set Directory = $dir|" \
  -e "s|= meshes/sent_coarse.msh|= $project_root/prm/meshes/sent_coarse.msh|" \
  "$project_root/prm/sent_coarse.prm" > "$dir/scene.prm"
mpirun -np "$np" "$exe" "$dir/scene.prm" > "$dir/screen.txt" 2>&1
/usr/bin/python3 "$here/report.py" "$here"
