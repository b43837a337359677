#!/usr/bin/env bash
# Notched tension at l_f = 0.0075 mm (prm/sent.prm's length) with
# adaptive refinement from a coarse mesh, against the mesh refined by hand
# along the crack path (benchmarks/phase_field/sent, results_lf0.0075.md:
# h = l_f/2 in a square of half-width 6 l_f around the notch tip, 143k
# unknowns). Same material, loading, solver and load steps (eta_f = 0,
# monolithic, MUMPS, dt = 0.05 with cut-backs to dt/8, to t = 0.48, one step
# past the peak).
# The coarse mesh has h = 0.06 mm = 8 l_f in the plane and is one layer of
# 0.00375 mm = l_f/2 (make_sent.py's THICKNESS): Maximum level 4 makes cells
# of h = l_f/2 in the plane where s exceeds the threshold, 16 layers thick
# (every refinement halves a cell in all three directions).
# The graded base mesh is the one refined by hand at h = l_f (a square of
# half-width 6 l_f around the notch tip, one layer of l_f cubes): Maximum
# level 1 and 2 refine it where s exceeds the threshold to h = l_f/2 (2
# layers) and l_f/4 (4 layers), the level that the meshes by hand could not
# afford (~340k unknowns in the whole square).
# Usage: benchmarks/adaptive_refinement/sent/run.sh [NP] [RUN ...]
#   RUN: names as in runs/ (e.g. level4-s0.05, graded-level2-s0.2-dtmin3.125e-4);
#   default all. Runs whose statistics are complete are kept. Then report.py
#   writes results.md and sent_adaptive.png.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
only=("${@:2}")
require_build
mkdir -p "$here/runs"
coarse=$here/runs/sent_coarse_h0.06_t0.00375.msh
[[ -f "$coarse" ]] || /usr/bin/python3 "$project_root/prm/meshes/make_sent.py" \
  0.06 0.12 "$coarse" 0.98 1 0.00375 > /dev/null
graded=$here/runs/sent_graded_h0.0075_b0.045.msh
[[ -f "$graded" ]] || /usr/bin/python3 "$project_root/prm/meshes/make_sent.py" \
  0.0075 0.045 "$graded" 0.545 > /dev/null
by_hand=$here/runs/sent_h0.00375_b0.045_x0.545.msh
[[ -f "$by_hand" ]] || /usr/bin/python3 "$project_root/prm/meshes/make_sent.py" \
  0.00375 0.045 "$by_hand" 0.545 > /dev/null

# run_scene_on MESH NAME DTMIN [PRM LINES]: the scene of
# benchmarks/phase_field/sent on MESH with the minimum step DTMIN and the
# lines appended, in runs/NAME (skipped when done or not asked for).
run_scene_on() {
  local mesh=$1 name=$2 dtmin=$3 extra=${4:-} dir
  if ((${#only[@]})) && [[ " ${only[*]} " != *" $name "* ]]; then return; fi
  dir=$here/runs/$name
  if run_finished "$dir"; then
    echo "== $name (done)"
    return
  fi
  mkdir -p "$dir"
  sed -e "s|@MESH@|$mesh|" -e "s|@LF@|7.5e-06|" -e "s|@DEGREE@|2|" \
    -e "s|@STRATEGY@|monolithic|" -e "s|@DEPTH@|0|" -e "s|@SOLVER@|direct|" \
    -e "s|@PFPREC@|amg|" -e "s|@DT@|0.05|" -e "s|@DTMIN@|$dtmin|" \
    -e "s|@END@|0.48|" -e "s|@ETA@|0|" -e "s|@DIR@|$dir|" \
    "$project_root/benchmarks/phase_field/sent/scene.prm.in" > "$dir/scene.prm"
  printf '%s' "$extra" >> "$dir/scene.prm"
  echo "== $name ($(date +%H:%M))"
  run_scene "$np" "$dir"
  grep -E "Total wallclock" "$dir/screen.txt" || true
}

run() { # base level threshold [minimum time step]
  local base=$1 level=$2 threshold=$3 dtmin=${4:-0.00625} name mesh
  mesh=$coarse
  name="level$level-s$threshold${4:+-dtmin$4}"
  if [[ "$base" == graded ]]; then
    mesh=$graded
    name="graded-$name"
  fi
  run_scene_on "$mesh" "$name" "$dtmin" "subsection Mesh
  subsection Adaptive refinement
    set Enabled                 = true
    set Phase-field threshold   = $threshold
    set Maximum level           = $level
    set Maximum passes per step = 6
  end
end
"
}

run coarse 4 0.05   # stopped at t = 0.3: 174k DoFs, more than the mesh by hand
run coarse 4 0.2
run coarse 4 0.2 3.125e-4   # the reference's minimum step: closes in on the limit point
# From the mesh by hand at h = l_f, with the reference's minimum step:
run graded 2 0.2 3.125e-4   # h = l_f/4 where s > 0.2
run graded 2 0.1 3.125e-4   # the same where s > 0.1: the threshold's effect
run graded 1 0.2 3.125e-4   # h = l_f/2 where s > 0.2 (against the mesh by hand)
# The reference itself (benchmarks/phase_field/sent's h = l_f/2 mesh by hand,
# run there with the code of November) again with this code, for its wall
# time beside the adaptive runs.
run_scene_on "$by_hand" by-hand-h2-session36 3.125e-4
/usr/bin/python3 "$here/report.py"
