#!/usr/bin/env bash
# The ductile notched plate (prm/ductile_notch.prm with the
# coarse copy's lengths, tests/ductile_notch_coarse.prm: l_f = 0.1 mm,
# l_p = 0.2 mm) through yield, crack initiation and the crack's run, on
#  - fixed: the ctest's mesh graded by hand (tests/meshes/
#    ductile_notch_coarse.msh, h = 0.1 mm = l_f along the crack path), and
#  - adaptive: a uniform coarse mesh of h = 0.2 mm = 2 l_f (make_sent.py 0.2
#    0.4 ... 1.0 2), refined to level 1 (h = l_f, two layers) where
#    alpha > 0.002 or s > 0.2.
# Usage: benchmarks/adaptive_refinement/ductile_notch/run.sh [NP]; then
# report.py writes results.md. Runs whose statistics are complete are kept.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-1}
require_build
coarse=$here/runs/ductile_notch_h0.2.msh
[[ -f "$coarse" ]] || /usr/bin/python3 "$project_root/prm/meshes/make_sent.py" \
  0.2 0.4 "$coarse" 1.0 2 > /dev/null

run() { # name mesh [extra entries]
  local dir=$here/runs/$1
  if run_finished "$dir"; then echo "== $1 (done)"; return; fi
  mkdir -p "$dir"
  { cat "$project_root/prm/ductile_notch.prm" \
        "$project_root/tests/ductile_notch_coarse.prm"
    printf '%s\n' "subsection Mesh" "  subsection Gmsh" "    set File name = $2" \
      "  end" "end" "subsection Load stepping" "  set End time = 0.8" "end" \
      "subsection Output" "  set Directory = $dir" "  set Interval = 0" "end"
    printf '%s\n' "${@:3}"
  } > "$dir/scene.prm"
  echo "== $1 ($(date +%H:%M))"
  run_scene "$np" "$dir"
  grep -E "Total wallclock" "$dir/screen.txt" || true
}

run fixed "$project_root/tests/meshes/ductile_notch_coarse.msh"
run adaptive "$coarse" "subsection Mesh" "  subsection Adaptive refinement" \
  "    set Enabled               = true" "    set Phase-field threshold = 0.2" \
  "    set Hardening threshold   = 0.002" "    set Maximum level         = 1" \
  "  end" "end"
/usr/bin/python3 "$here/report.py"
