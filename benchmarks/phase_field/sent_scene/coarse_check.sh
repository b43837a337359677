#!/usr/bin/env bash
# The coarse check of README.md: coarse_check.prm (the ctest sent_notch's
# scene pulled past the separation) once with `history and bound` and once
# with `history` alone, into coarse/<mode>/; prints Newton iterations per
# step, how often the bound was engaged, and the energy residual with and
# without the history driving work. About 1 minute per run on one rank.
# Usage: benchmarks/phase_field/sent_scene/coarse_check.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
require_build
for mode in "history and bound" "history"; do
  dir="$here/coarse/${mode// /-}"
  mkdir -p "$dir"
  { sed -e "s|tests/meshes/sent_notch.msh|$project_root/tests/meshes/sent_notch.msh|" \
      -e "s|set Irreversibility = .*|set Irreversibility = $mode|" "$here/coarse_check.prm"
    printf 'subsection Output\n  set Directory = %s\nend\n' "$dir"; } > "$dir/scene.prm"
  mpirun -np 1 "$exe" "$dir/scene.prm" > "$dir/screen.txt" 2>&1
  echo "== $mode: $(grep -c 'its bound is engaged' "$dir/screen.txt") steps engaged the bound"
  /usr/bin/python3 - "$dir/statistics" <<'PY'
import sys
sys.path.insert(0, sys.argv[1].rsplit("/benchmarks/", 1)[0] + "/benchmarks")
from runs_io import read_statistics
rows = read_statistics(sys.argv[1])
print(" t      its  max s   residual/W_ext  (residual + history work)/W_ext")
for r in rows[1:]:
    W = r["external_work"]
    print(f" {r['time']:.3f}  {int(r['newton_iterations']):3d}  {r['max_s']:.3f}  {r['energy_residual'] / W:+.4f}"
          f"          {(r['energy_residual'] + r['history_driving_work']) / W:+.4f}")
print(f" total Newton iterations {sum(int(r['newton_iterations']) for r in rows)}")
PY
done
