#!/usr/bin/env bash
# The cost of a dynamic step against a quasi-static one of the same size:
# scene.prm.in (a bar of 80k unknowns, 20 steps) with Time integration =
# Bossak and quasi-static, on 2 ranks; report.py: Newton iterations per
# step, and per Newton iteration the assembly and linear-solve time
# (results.md).
# Usage: benchmarks/dynamics/cost/run.sh [NP] (default 2 ranks, about a
# minute). Finished runs are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build

for mode in Bossak quasi-static; do
  dir="$here/runs/$mode"
  if run_finished "$dir"; then
    echo "== $mode (done)"
    continue
  fi
  mkdir -p "$dir"
  sed "s/@MODE@/$mode/" "$here/scene.prm.in" > "$dir/scene.prm"
  printf 'subsection Output\n  set Directory = %s\nend\n' "$dir" >> "$dir/scene.prm"
  echo "== $mode"
  run_scene "$np" "$dir"
done
/usr/bin/python3 "$here/report.py" "$here"
