#!/usr/bin/env bash
# Peak resident memory per rank against the unknowns, for the direct and the
# iterative solver on 1 and 2 MPI ranks: the 3-D two bodies (elastic
# contact with friction), its first 3 steps on the shipped mesh (r0), the
# mesh refined once (r1) and the shipped mesh subdivided 3x per direction
# (k3; 2 ranks only). Each run's screen ends with the ranks' peak resident
# set (VmHWM) and the direct solver's factor entries; report.py writes
# results.md with the bytes per unknown.
# Usage: [NP="1 2"] benchmarks/scaling/memory/run.sh [CASE...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
source "$here/../two_bodies_cases.sh"
require_build

# case : ranks : extra entries ('|' separates)
cases=(
  "r0:1 2:Mesh/Global refinements = 0"
  "r1:1 2:Mesh/Global refinements = 1"
  "k3:2:Mesh/Two bodies/Plate subdivisions = 57, 39, 6|Mesh/Two bodies/Block subdivisions = 15, 15, 15"
)
solvers=(direct gmres-amg)
run_two_bodies_cases "$here" again "$@"
python3 "$here/report.py"
