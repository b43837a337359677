#!/usr/bin/env bash
# The energy error of an elastic impact against the time step:
# prm/bar_impact.prm (two equal bars collide, part after 2L/c) with the
# trapezoidal rule, dt = 40 ... 2.5 us, with the redistributed contact mass
# (the default) and with the consistent mass. report.py: per run the
# energy error -(energy_residual) at the end (after release) and its
# largest magnitude during the run, both over K_0, the contact's closings
# and its duration over 2L/c, Newton iterations and run time; plot.py:
# results.png.
# Usage: benchmarks/dynamics/bar_impact/run.sh [NP] (default 2 ranks,
# about 3 minutes). Finished runs are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build

for mass in redistributed consistent; do
  for dt in 4e-5 2e-5 1e-5 5e-6 2.5e-6; do
    [[ $mass == consistent && $dt == 2.5e-6 ]] && continue
    dir="$here/runs/${mass}_$dt"
    if run_finished "$dir"; then
      echo "== $mass, dt = $dt (done)"
      continue
    fi
    mkdir -p "$dir"
    echo "== $mass, dt = $dt"
    /usr/bin/time -f "%e s %M KB" -o "$dir/time.txt" \
      mpirun -np "$np" "$exe" "$project_root/prm/bar_impact.prm" \
      --set "Load stepping/Time step = $dt" \
      --set "Load stepping/Contact surface mass = $mass" \
      --set "Output/Directory = $dir" --set "Output/Interval = 0" \
      > "$dir/screen.txt" 2>&1 || echo "   stopped early, see $dir/screen.txt"
  done
done
/usr/bin/python3 "$here/report.py" "$here"
/usr/bin/python3 "$here/plot.py" "$here"
