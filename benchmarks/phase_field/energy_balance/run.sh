#!/usr/bin/env bash
# Energy balance against the load increment: the coarse SENT of
# ../sent_scene/coarse_check.prm (the ctest sent_notch's slab, l_f = 0.1 mm,
# pulled to t = 1.2, past the separation) with Load stepping/Time step
# = 0.05 ... 0.00625, once rate-independent (eta_f = 0: the crack jumps
# past a limit point; Coupling/Strategy = monolithic-staggered, whose
# staggered retry walks to the cracked state where monolithic Newton stops)
# and once with a crack viscosity (eta_f = 1e5 J/m^3 x pseudo time: the crack
# runs continuously; Delta t down to 0.00078125, since s crosses 0 -> 1 at a
# point within ~0.007 of pseudo time). Two one-rank runs side by side, into
# runs/eta<eta>-dt<dt>/ (a finished run is not redone); then report.py writes
# results.md and energy_balance.png.
# Usage: benchmarks/phase_field/energy_balance/run.sh [eta:dt ...]
#        (default all ten; ~25 min on 2 cores)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
require_build
configs=("$@")
if [ ${#configs[@]} -eq 0 ]; then
  for dt in 0.05 0.025 0.0125 0.00625; do configs+=("0:$dt"); done
  for dt in 0.05 0.025 0.0125 0.00625 0.003125 0.0015625 0.00078125; do
    configs+=("1e5:$dt")
  done
fi
run_one() {
  local eta=${1%%:*} dt=${1##*:}
  local dir="$here/runs/eta$eta-dt$dt"
  if run_finished "$dir"; then return; fi
  mkdir -p "$dir"
  local strategy=monolithic
  if [ "$eta" = 0 ]; then strategy=monolithic-staggered; fi
  local dt_min
  dt_min=$(/usr/bin/python3 -c "print($dt / 64)")
  { sed -e "s|tests/meshes/sent_notch.msh|$project_root/tests/meshes/sent_notch.msh|" \
      -e "s|set Viscosity .*|set Viscosity = $eta|" \
      -e "s|set Time step .*|set Time step = $dt|" \
      -e "s|set Minimum time step .*|set Minimum time step = $dt_min|" \
      -e "s|set Verbosity = 2|set Verbosity = 1|" \
      -e "s|subsection Coupling|subsection Coupling\n  set Strategy = $strategy|" \
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
