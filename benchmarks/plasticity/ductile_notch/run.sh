#!/usr/bin/env bash
# Ductile notched plate: the scene prm/ductile_notch.prm on
# meshes with h = 0.05 mm (the scene's) and finer along the crack path
# (prm/meshes/make_sent.py H 0.15 ... 1.0 HEIGHT with the scene's height),
# and with the volumetric switch of (17) blended over delta = 5e-4, 1e-3
# (the scene's) and 2e-3. report.py: force curve, peak force, displacement
# where the crack has crossed the ligament, plastic work and crack energy
# against run time; pictures of s and alpha.
# Usage: benchmarks/plasticity/ductile_notch/run.sh [NP] [CASE ...]
#   CASE = <h [mm]>:<delta>[:<driver>[:<time step>]], default 0.05:1e-3
#   0.05:5e-4 0.05:2e-3 0.035:1e-3 0.05:1e-3:work 0.05:1e-3:energy and the
#   time-step study 0.05:1e-3::0.02 0.05:1e-3::0.005 (the scene's time step
#   is 0.01); driver 'work' is the plastic work crack driver (Fracture/Crack
#   driver = elastic plus plastic work, w_c = 0, zeta = 1; doc/model.md
#   4.3), 'energy' the variational one (w_c = 0, the box bound alone).
#   Cases with a finished run are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
shift || true
cases=("$@")
((${#cases[@]})) || cases=(0.05:1e-3 0.05:5e-4 0.05:2e-3 0.035:1e-3 0.05:1e-3:work 0.05:1e-3:energy
                           0.05:1e-3::0.02 0.05:1e-3::0.005)
require_build
scene="$project_root/prm/ductile_notch.prm"
height=$(sed -n 's/^# Specimen height: \([0-9.]*\) mm.*/\1/p' "$scene")

for case in "${cases[@]}"; do
  IFS=: read -r h delta driver dt <<< "$case"
  name="h$h-delta$delta${driver:+-$driver}${dt:+-dt$dt}"
  dir="$here/runs/$name"
  if run_finished "$dir"; then
    echo "== $name (done)"
    continue
  fi
  mkdir -p "$dir"
  /usr/bin/python3 "$project_root/prm/meshes/make_sent.py" "$h" 0.15 "$dir/mesh.msh" 1.0 "$height" > /dev/null
  sed -e "s|set File name = .*|set File name = $dir/mesh.msh|" \
    -e "s|set Volumetric switch width  *= .*|set Volumetric switch width = $delta|" \
    -e "s|set Directory = .*|set Directory = $dir|" \
    -e "s|set Interval  = .*|set Interval = 10|" \
    "$scene" > "$dir/scene.prm"
  if [[ -n $dt ]]; then
    printf '%s\n' "subsection Load stepping" "set Time step = $dt" "end" >> "$dir/scene.prm"
  fi
  if [[ $driver == work ]]; then
    printf '%s\n' "subsection Body 1" "subsection Fracture" \
      "set Crack driver = elastic plus plastic work" \
      "set Critical work density = 0" "set Driver factor = 1" "end" "end" \
      >> "$dir/scene.prm"
  elif [[ $driver == energy ]]; then
    # The variational driver, its plastic energy degraded from the first
    # yield (w_c = 0), the box s_n <= s <= 1 alone.
    printf '%s\n' "subsection Body 1" "subsection Fracture" \
      "set Crack driver = elastic and plastic energy" \
      "set Critical work density = 0" "end" "end" \
      "subsection Coupling" "set Irreversibility = bound" "end" \
      >> "$dir/scene.prm"
  fi
  echo "== $name"
  run_scene "$np" "$dir"
  grep -E "^step" "$dir/screen.txt" | tail -1 || true
done
/usr/bin/python3 "$here/report.py" "$here"
