#!/usr/bin/env bash
# Hertz point contact (validation.md rung 11): the scene
# prm/hertz_sphere.prm (sphere R = 1 m on a flat foundation, both E = 1 GPa,
# nu = 0.3, quarter model) on meshes h = a/2, a/3, a/4 at the contact
# (bodies 20 a = 0.2 m wide and deep), plus h = a/3 with bodies 40 a for the
# error of the finite bodies. Per step: contact radius a, peak pressure p0
# and the approach of the two axis probes at 2 a against Hertz
# (hertz_sphere.py), run time and Newton iterations (report.py).
# Usage: benchmarks/contact/hertz_sphere/run.sh [NP]   (default 2 ranks;
#        about 7 min in all on 2 cores; a/4 alone 3.5 min)
# runs/2026-11-al-amg: the runs of November 2026 with the augmented
# Lagrangian and GMRES-AMG (28-31 Newton iterations, 78-833 s): the same
# errors to three digits as the semi-smooth Newton method on the direct
# solver now (14-17 iterations, 26-196 s).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build
mkdir -p "$here/runs/meshes"
# Cases RATIO:WIDTH[:curved]; curved: the sphere's surface given as the
# sphere (Mesh/Gmsh/Curved boundaries = 4 : 0, 0, 1), so that the mid-side
# nodes of its faces lie on it rather than on the chords (the same meshes).
for case in 2:0.2 3:0.2 3:0.4 4:0.2 2:0.2:curved 3:0.2:curved 4:0.2:curved; do
  IFS=: read -r ratio width curved <<< "$case"
  name="h$ratio-w$width${curved:+-curved}"
  mesh="$here/runs/meshes/h$ratio-w$width.msh"
  [[ -f "$mesh" ]] || /usr/bin/python3 "$project_root/prm/meshes/make_hertz_sphere.py" \
    1 0.01 "$ratio" "$width" 1.5 "$mesh" > /dev/null
  dir="$here/runs/$name"
  if run_finished "$dir"; then
    echo "== $name (done)"
    continue
  fi
  mkdir -p "$dir"
  sed -e "s|= meshes/hertz_sphere.msh|= $mesh|" -e "s|results/hertz_sphere|$dir|" \
    "$project_root/prm/hertz_sphere.prm" > "$dir/scene.prm"
  if [[ -n $curved ]]; then
    printf 'subsection Mesh\n  subsection Gmsh\n    set Curved boundaries = 4 : 0, 0, 1\n  end\nend\n' \
      >> "$dir/scene.prm"
  fi
  echo "== $name"
  run_scene "$np" "$dir"
  rm -f "$dir"/*.vtu "$dir"/*.pvtu
done
/usr/bin/python3 "$here/report.py" "$here"
