#!/usr/bin/env bash
# Hertz line contact (validation.md rung 11): contact
# half-width a and peak pressure p0 against the closed forms
# a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a) for the load P the run
# carries, against run time, for h = a/2, a/4, a/8 at the contact, dual
# and standard multiplier bases. a and p0 come from a least-squares fit of
# p^2 = p0^2 (1 - x^2 / a^2) to the nodal pressures (report.py).
# The same in plane strain (Dimension = 2, line3 contact faces, runs
# h<r>-<basis>_2d) for h = a/2 ... a/16: the slab and the plane have the
# same discrete solution, so a row of one equals the other's (to the
# solver's tolerance), at a fraction of the time.
# Runs *_curved: the indenter's surface given to the program as a circle
# (2-D) or a cylinder (slab), Mesh/Gmsh/Curved boundaries, so that its
# mid-side nodes lie on the circle instead of on the chords between the
# vertices (h^2/(8R) inside it); the same meshes.
# Usage: benchmarks/contact/hertz/run.sh [NP]   (default 2 ranks)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build
mkdir -p "$here/runs/meshes"
# run_case RATIO BASIS SUFFIX: the run h<RATIO>-<BASIS><SUFFIX> (SUFFIX
# starting with _2d: plane strain, its own mesh and scene_2d.prm.in; with
# _stiff: an indenter three times stiffer, E = 3 GPa; ending in _curved: the
# indenter's surface given as a circle or a cylinder).
run_case() {
  local ratio=$1 basis=$2 suffix=$3
  local g2=3.846153846153846e8 k2=8.333333333333334e8
  [[ $suffix == *_stiff* ]] && g2=1.153846153846154e9 k2=2.5e9
  local plain=${suffix%_curved}
  plain=${plain%_stiff}
  local template=scene$plain.prm.in
  local mesh="$here/runs/meshes/hertz_h$ratio$plain.msh"
  local curved=""
  if [[ $suffix == *_curved ]]; then
    curved="4 : 0, 1, 0 : 0, 0, 1"
    [[ $plain == _2d ]] && curved="4 : 0, 1"
  fi
  [[ -f "$mesh" ]] || /usr/bin/python3 "$here/../../../prm/meshes/make_hertz.py" \
    1 0.01 "$ratio" 0.3 "$mesh" ${plain:+2d} > /dev/null
  local dir="$here/runs/h$ratio-$basis$suffix"
  if [[ -f "$dir/statistics" ]]; then echo "== h = a/$ratio, $basis$suffix (done)"; return; fi
  mkdir -p "$dir"
  # The semi-smooth Newton method condenses with the dual basis's
  # diagonal D; the standard basis runs with the augmented Lagrangian.
  local enforcement="semi-smooth Newton"
  [[ $basis == standard ]] && enforcement="augmented Lagrangian"
  sed -e "s|@MESH@|$mesh|" -e "s|@DIR@|$dir|" -e "s|@BASIS@|$basis|" \
    -e "s|@ENFORCEMENT@|$enforcement|" -e "s|@G2@|$g2|" -e "s|@K2@|$k2|" \
    -e "s|@CURVED@|$curved|" \
    "$here/$template" > "$dir/scene.prm"
  echo "== h = a/$ratio, $basis$suffix"
  run_scene "$np" "$dir"
  rm -f "$dir"/*.vtu "$dir"/*.pvtu
}
for ratio in 2 4 8; do
  for basis in dual standard; do run_case $ratio $basis ""; done
done
for ratio in 2 4 8 16; do
  for basis in dual standard; do run_case $ratio $basis _2d; done
done
# Dissimilar materials (1/E* = (1 - nu^2) (1/E_1 + 1/E_2)), dual basis.
for ratio in 4 8 16; do run_case $ratio dual _2d_stiff; done
# The indenter's surface as a circle (cylinder): the same meshes.
for ratio in 2 4 8; do run_case $ratio dual _curved; done
for ratio in 2 4 8 16; do
  for basis in dual standard; do run_case $ratio $basis _2d_curved; done
  run_case $ratio dual _2d_stiff_curved
done
/usr/bin/python3 "$here/report.py" "$here"
