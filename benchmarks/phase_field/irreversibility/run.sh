#!/usr/bin/env bash
# Irreversibility of the crack: the history field of psi+ alone,
# the bound s >= s_n at every phase-field DoF alone, and both
# (Coupling/Irreversibility = history | bound | history and bound, the
# default), on the coarse copy of the ductile notched plate (the ctest
# ductile_notch's scene, tests/ductile_notch_coarse.prm: h = l_f = 0.1 mm,
# l_p = 0.2 mm, g_c = 2800 J/m^2), pulled to 24 um, past the
# separation, where the history field alone lets the broken band relax.
# report.py: smallest s change, Newton iterations, cut-backs, run time and
# the differences of the force curves.
# Usage: benchmarks/phase_field/irreversibility/run.sh [NP] (default 1 rank,
# about 3 x 4 min). Finished runs are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-1}
require_build

for mode in history bound "history and bound"; do
  dir="$here/runs/${mode// /-}"
  if run_finished "$dir"; then
    echo "== $mode (done)"
    continue
  fi
  mkdir -p "$dir"
  {
    cat "$project_root/prm/ductile_notch.prm"
    cat "$project_root/tests/ductile_notch_coarse.prm"
    cat <<PRM
subsection Mesh
  subsection Gmsh
    set File name = $project_root/tests/meshes/ductile_notch_coarse.msh
  end
end
subsection Coupling
  set Irreversibility = $mode
end
subsection Load stepping
  set End time = 0.8
end
subsection Output
  set Directory = $dir
end
PRM
  } > "$dir/scene.prm"
  echo "== $mode"
  run_scene "$np" "$dir"
  grep -E "^step" "$dir/screen.txt" | tail -1 || true
done
/usr/bin/python3 "$here/report.py" "$here"
