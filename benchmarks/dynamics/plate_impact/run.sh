#!/usr/bin/env bash
# The paper's scene as an impact, on the coarse mesh of the ctests
# (plate 8 x 5 x 1, block 2 x 2 x 2): prm/block_on_plate.prm with densities
# (plate 2700, block 1100 kg/m^3), the block launched at the plate at V m/s
# instead of pressed, the viscosities in physical time (eta_p = 1e3 Pa s,
# eta_f = 1e2 J/m^3 s), Time integration = Bossak (rho_inf = 1), to 2 ms,
# for dt = 20, 10, 5 us. report.py: the energy residual over K_0, the
# plastic work, the largest alpha and s, the friction dissipation, K at
# the end, Newton iterations, cut-backs and run time (results.md).
# Usage: benchmarks/dynamics/plate_impact/run.sh [V [MU [RHO [DTS]]]]
# (default 60 m/s, the scene's friction coefficient 0.2, the high-frequency
# spectral radius 1 and the steps "2e-5 1e-5 5e-6"; 2 ranks, about 3
# minutes).
# Finished runs are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
speed=${1:-60}
mu=${2:-0.2}
rho=${3:-1}
steps=${4:-2e-5 1e-5 5e-6}
tag="v$speed"
[[ $mu != 0.2 ]] && tag="${tag}_mu$mu"
[[ $rho != 1 ]] && tag="${tag}_rho$rho"
require_build

for dt in $steps; do
  dir="$here/runs/${tag}_dt$dt"
  if run_finished "$dir"; then
    echo "== $speed m/s, dt = $dt (done)"
    continue
  fi
  mkdir -p "$dir"
  copy_scene "$project_root/prm/block_on_plate.prm" "$dir/scene.prm"
  cat >> "$dir/scene.prm" <<PRM
subsection Mesh
  subsection Two bodies
    set Plate subdivisions = 8, 5, 1
    set Block subdivisions = 2, 2, 2
  end
end
subsection Body 0
  set Density = 2700
  subsection Plasticity
    set Viscosity = 1e3
  end
  subsection Fracture
    set Viscosity = 1e2
  end
end
subsection Body 1
  set Density          = 1100
  set Initial velocity = 0; 0; -$speed
end
subsection Boundary 2
  set Constrained components =
  set Displacement           = 0; 0; 0
end
subsection Contact pair 1
  set Friction coefficient = $mu
end
subsection Load stepping
  set End time          = 2e-3
  set Time step         = $dt
  set Minimum time step = 1e-9
  set Time integration  = Bossak
  set High-frequency spectral radius = $rho
  set Predictor         = constant
end
subsection Output
  set Directory = $dir
  set Interval  = 0
end
PRM
  echo "== $speed m/s, mu = $mu, rho_inf = $rho, dt = $dt"
  run_scene 2 "$dir"
done
/usr/bin/python3 "$here/report.py" "$here"
