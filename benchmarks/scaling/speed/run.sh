#!/usr/bin/env bash
# Strong and weak scaling on 1 and 2 ranks, measured: the 3-D two bodies
# (elastic contact with friction), its first 3 steps, with the direct solver
# and gmres-amg. Strong: the mesh refined once (138k unknowns) on 1 and 2
# ranks. Weak: the shipped mesh (19.8k) on 1 rank against the plate's and the
# block's x subdivisions doubled (2x the unknowns) on 2 ranks, and the same
# from the mesh refined once (138k on 1 rank, 2x on 2 ranks). report.py:
# results.md with the time per Newton iteration of steps 2 and 3 (no
# set-up) and the efficiencies. Run on the quiet machine (about 15 minutes).
# Usage: [NP="1 2"] benchmarks/scaling/speed/run.sh [CASE...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
source "$here/../two_bodies_cases.sh"
require_build

plate=(19 13 2) block=(5 5 5)
mesh() { # refinements, x factor
  echo "Mesh/Global refinements = $1|Mesh/Two bodies/Plate subdivisions = $((plate[0] * $2)), ${plate[1]}, ${plate[2]}|Mesh/Two bodies/Block subdivisions = $((block[0] * $2)), ${block[1]}, ${block[2]}"
}
# case : ranks : extra entries ('|' separates)
cases=(
  "r0x1:1:$(mesh 0 1)"
  "r0x2:2:$(mesh 0 2)"
  "r1x1:1 2:$(mesh 1 1)"
  "r1x2:2:$(mesh 1 2)"
)
solvers=(direct gmres-amg)
run_two_bodies_cases "$here" keep "$@"
/usr/bin/python3 "$here/report.py"
