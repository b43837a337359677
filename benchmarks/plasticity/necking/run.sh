#!/usr/bin/env bash
# Necking of a round bar (validation.md rung 3): the scene
# prm/necking_bar.prm (octant model, frictionless grip) on meshes with
# 10, 20, 40 cells along the half bar (Axial subdivisions 10, 20, 40 with
# Refinements = 1: 5 cells per quarter cross-section) and 20 cells with
# Refinements = 2 (20 per quarter cross-section), with the gradient length
# l_p = 1 mm and with l_p = 0 (local plasticity), time step 0.02 (50 steps
# to 14 mm). Probes on the hull every 0.5 mm from mid-length over 12 mm
# give the radius profile r(x) at every step. report.py: peak force, neck
# radius and neck width against run time.
# Usage: benchmarks/plasticity/necking/run.sh [NP] [CASE ...]
#   CASE = <axial subdivisions>:<refinements>:<l_p [m]>[:<time step>
#   [:<hold stiffness factor>]],
#   default 10:1:1e-3 10:1:0 20:1:1e-3 20:1:0 40:1:1e-3 40:1:0 20:2:1e-3
#   (about 1, 2, 4 and 15 min per case on 2 ranks) and the time-step study
#   of the scene's mesh 20:1:1e-3:0.04 20:1:1e-3:0.01 (time step 0.02
#   unless given), and the hold of alpha at non-yielding points stiffened
#   10 times, 20:1:1e-3:0.02:10 (Plasticity/Hold stiffness factor, 1 unless
#   given). Cases with a finished run are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
shift || true
cases=("$@")
((${#cases[@]})) || cases=(10:1:1e-3 10:1:0 20:1:1e-3 20:1:0 40:1:1e-3 40:1:0 20:2:1e-3
                           20:1:1e-3:0.04 20:1:1e-3:0.01 20:1:1e-3:0.02:10)
require_build

# Hull points y = 0.9998 f(x) R, z = 0 for x = L/2 + k 0.5 mm, k = 0..24.
probes=$(/usr/bin/python3 - <<'PY'
R, L, e = 6.413e-3, 53.334e-3, 0.018
pts = []
for k in range(0, 25):
    x = 0.5 * L + k * 0.5e-3
    f = 1 - e * (1 - abs(2 * x / L - 1))
    pts.append(f"{x:.6e}, {0.9998 * f * R:.6e}, 0")
print("; ".join(pts))
PY
)

for case in "${cases[@]}"; do
  IFS=: read -r axial refine lp dt hold <<< "$case"
  name="a$axial-r$refine-lp$lp${dt:+-dt$dt}${hold:+-hold$hold}"
  dt=${dt:-0.02}
  dir="$here/runs/$name"
  if run_finished "$dir"; then
    echo "== $name (done)"
    continue
  fi
  mkdir -p "$dir"
  sed -e "s|set Axial subdivisions = .*|set Axial subdivisions = $axial|" \
    -e "s|set Refinements        = .*|set Refinements        = $refine|" \
    -e "s|set Length scale  *= .*|set Length scale = $lp|" \
    -e "s|set Time step  *= .*|set Time step = $dt|" \
    -e "s|set Directory = .*|set Directory = $dir|" \
    -e "s|set Interval  = .*|set Interval = 10|" \
    -e "s|set Probe points = .*|set Probe points = $probes|" \
    "$project_root/prm/necking_bar.prm" > "$dir/scene.prm"
  if [[ -n $hold ]]; then
    printf '%s\n' "subsection Body 0" "subsection Plasticity" \
      "set Hold stiffness factor = $hold" "end" "end" >> "$dir/scene.prm"
  fi
  echo "== $name"
  run_scene "$np" "$dir"
  grep -E "^step" "$dir/screen.txt" | tail -1 || true
done
/usr/bin/python3 "$here/report.py" "$here"
