#!/usr/bin/env bash
# Contact cost against the number of contact faces:
# the patch test of tests/contact_patch with N x N slave faces (upper cube)
# on (3N/4) x (3N/4) master faces, swirled meshes, 2 load steps. Prints,
# per N, the slave faces, unknowns, the time of one contact search (once
# per load step) and of one contact integration + assembly (every Newton
# iteration and line-search trial), and the pressure spread (patch test).
# Usage: [SIZES="4 8 16 24 32"] benchmarks/contact/scaling/run.sh [NP]
#        (default 2 ranks, N = 4 8 16 24)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build
mkdir -p "$here/runs"
for n in ${SIZES:-4 8 16 24}; do
  low=$(( (3 * n + 3) / 4 ))
  dir="$here/runs/n$n"
  if run_finished "$dir"; then
    echo "== N = $n (done)"; continue
  fi
  mkdir -p "$dir"
  mesh="$dir/patch.msh"
  /usr/bin/python3 "$here/../../../tests/meshes/make_contact_patch.py" "$low" "$n" 10 "$mesh" > /dev/null
  # MUMPS: GMRES with the block AMG did not converge well enough for the
  # line search on the contact tangent at N = 24.
  solver=direct
  sed -e "s|@MESH@|$mesh|" -e "s|@DIR@|$dir|" -e "s|@SOLVER@|$solver|" \
    "$here/scene.prm.in" > "$dir/scene.prm"
  echo "== N = $n (master $low), $solver"
  run_scene "$np" "$dir"
  rm -f "$mesh"
done
/usr/bin/python3 "$here/report.py" "$here"
