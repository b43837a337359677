#!/usr/bin/env bash
# Energy balance against the load increment (issue #3): the coarse SENT of
# ../sent_scene/coarse_check.prm (the ctest sent_notch's slab, l_f = 0.1 mm,
# pulled to t = 1.2, past the separation) with Load stepping/Time step
# = 0.05, 0.025, 0.0125, 0.00625, once rate-independent (eta_f = 0: the crack
# jumps) and once with a crack viscosity (eta_f = 1e5 J/m^3 x pseudo time:
# the crack runs continuously). Two one-rank runs side by side, into
# runs/eta<eta>-dt<dt>/; then report.py writes results.md.
# Usage: benchmarks/phase_field/energy_balance/run.sh [eta:dt ...]
#        (default all eight; ~15 min on 2 cores)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
require_build
configs=("$@")
if [ ${#configs[@]} -eq 0 ]; then
  for eta in 0 1e5; do
    for dt in 0.05 0.025 0.0125 0.00625; do configs+=("$eta:$dt"); done
  done
fi
run_one() {
  local eta=${1%%:*} dt=${1##*:}
  local dir="$here/runs/eta$eta-dt$dt"
  mkdir -p "$dir"
  local dt_min
  dt_min=$(/usr/bin/python3 -c "print($dt / 64)")
  { sed -e "s|tests/meshes/sent_notch.msh|$project_root/tests/meshes/sent_notch.msh|" \
      -e "s|set Viscosity .*|set Viscosity = $eta|" \
      -e "s|set Time step .*|set Time step = $dt|" \
      -e "s|set Minimum time step .*|set Minimum time step = $dt_min|" \
      -e "s|set Verbosity = 2|set Verbosity = 1|" \
      "$here/../sent_scene/coarse_check.prm"
    printf 'subsection Output\n  set Directory = %s\nend\n' "$dir"; } > "$dir/scene.prm"
  mpirun -np 1 "$exe" "$dir/scene.prm" > "$dir/screen.txt" 2>&1 ||
    echo "run $1 failed: see $dir/screen.txt"
}
for ((i = 0; i < ${#configs[@]}; i += 2)); do
  run_one "${configs[i]}" &
  if ((i + 1 < ${#configs[@]})); then run_one "${configs[i + 1]}" & fi
  wait
done
/usr/bin/python3 "$here/report.py" "$here"
