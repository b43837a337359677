#!/usr/bin/env bash
# The phase field in the Lagrange and in the Bernstein basis (Finite
# elements/Phase-field basis) on the coarse tearing scene of the ctests
# block_on_plate_tearing(_bernstein): prm/block_on_plate_tearing.prm on the
# coarse mesh (plate 8 x 5 x 1, block 2 x 2 x 2), g_c = 30 kJ/m^2, w_c = 0,
# torn by 128 mm (t = 320). report.py: the largest s at a quadrature point
# and at a DoF, Newton iterations, cut-backs, run time, the peak and end
# force, the crack energy and the worst energy balance from the third step.
# Usage: benchmarks/phase_field/bernstein/run.sh [NP] (default 2 ranks,
# about 2 x 40 s). Finished runs are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build

for basis in Lagrange Bernstein; do
  dir="$here/runs/$basis"
  if run_finished "$dir"; then
    echo "== $basis (done)"
    continue
  fi
  mkdir -p "$dir"
  {
    cat "$project_root/prm/block_on_plate_tearing.prm"
    cat <<PRM
subsection Mesh
  subsection Two bodies
    set Plate subdivisions = 8, 5, 1
    set Block subdivisions = 2, 2, 2
  end
end
subsection Finite elements
  set Phase-field basis = $basis
end
subsection Body 0
  subsection Fracture
    set Critical energy release rate = 30e3
    set Critical work density        = 0
  end
end
subsection Load stepping
  set Time step = 4
  set End time  = 320
end
subsection Output
  set Directory = $dir
  set Interval  = 0
end
PRM
  } > "$dir/scene.prm"
  echo "== $basis"
  /usr/bin/time -f "%e s %M KB" -o "$dir/time.txt" mpirun -np "$np" "$exe" "$dir/scene.prm" \
    > "$dir/screen.txt" 2>&1 || echo "   stopped early, see $dir/screen.txt"
  grep -E "^step" "$dir/screen.txt" | tail -1 || true
done
/usr/bin/python3 "$here/report.py" "$here"
