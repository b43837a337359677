#!/usr/bin/env bash
# The paper's scene as an impact, converged in dt: prm/block_impact.prm (the
# block launched at the clamped plate, plasticity, the phase field with the
# variational driver, Coulomb friction, Bossak with rho_inf = 0.8) at V m/s
# for dt = 20, 10, 5 us (or DTS), field output
# every 50 us in the 10 us run (the pictures). report.py: results.md (per
# run the energies at the end, the residual over K_0, the largest alpha and
# s, Newton iterations, run time; the differences to the finest run);
# plot.py: force and energies over time, and run time against the
# difference in dt (results_V.png).
# With the third argument 2d: prm/block_impact_2d.prm, the same in plane
# strain (runs v<V>_dt<dt>_2d). With the fourth argument bound: the
# plasticity of prm/block_on_plate_tearing.prm (Loading condition = bound,
# the hardening field in the Bernstein basis; runs ..._bound).
# Usage: benchmarks/dynamics/block_impact/run.sh [V [DTS [2d|3d [bound]]]]
# (default 120 m/s and "2e-5 1e-5 5e-6"; 2 ranks, about 50 minutes in 3-D).
# Finished runs are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
speed=${1:-120}
steps=${2:-2e-5 1e-5 5e-6}
scene=block_impact suffix="" velocity="0; 0; -$speed"
if [[ ${3:-} == 2d ]]; then
  scene=block_impact_2d suffix=_2d velocity="0; -$speed"
fi
options=()
if [[ ${4:-} == bound ]]; then
  suffix=${suffix}_bound
  options=(--set "Body 0/Plasticity/Loading condition = bound"
    --set "Finite elements/Hardening basis = Bernstein")
fi
require_build

for dt in $steps; do
  dir="$here/runs/v${speed}_dt$dt$suffix"
  if run_finished "$dir"; then
    echo "== $speed m/s, dt = $dt (done)"
    continue
  fi
  mkdir -p "$dir"
  interval=0
  [[ $dt == 1e-5 ]] && interval=5
  echo "== $speed m/s, dt = $dt"
  /usr/bin/time -f "%e s %M KB" -o "$dir/time.txt" \
    mpirun -np 2 "$exe" "$project_root/prm/$scene.prm" \
    --set "Body 1/Initial velocity = $velocity" "${options[@]}" \
    --set "Load stepping/Time step = $dt" \
    --set "Output/Directory = $dir" --set "Output/Interval = $interval" \
    > "$dir/screen.txt" 2>&1 || echo "   stopped early, see $dir/screen.txt"
done
/usr/bin/python3 "$here/report.py" "$here"
if [[ -z ${4:-} ]]; then
  /usr/bin/python3 "$here/plot.py" "$here" "$speed" ${3:-}
fi
