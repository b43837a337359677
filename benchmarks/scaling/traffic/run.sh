#!/usr/bin/env bash
# The messages and bytes each MPI rank sends per Newton iteration, measured:
# libmpi_traffic.so (mpi_traffic.c, built here with mpicc) is preloaded into
# every rank and counts the point-to-point messages and the collective calls
# of the whole process (ours, deal.II's, Trilinos', MUMPS's Fortran ones)
# with their bytes. Each case runs to two end times; the difference of the
# counts over the difference of the Newton iterations is the traffic of one
# Newton iteration of the later steps (assembly, contact, linear solve, line
# search), without the set-up. The 3-D two bodies (elastic frictional
# contact) on the shipped mesh (r0) and refined once (r1), with the direct
# solver and gmres-amg, on 2 and 4 ranks (4 share the 2 cores: the counts do
# not depend on the speed). report.py writes results.md.
# Usage: [NP="2 4"] benchmarks/scaling/traffic/run.sh [CASE...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
require_build

library=$here/runs/libmpi_traffic.so
mkdir -p "$here/runs"
mpicc -shared -fPIC -O2 -o "$library" "$here/mpi_traffic.c" -ldl

# case : refinements : end times (the second later)
cases=("r0:0:2 3" "r1:1:2 3")
solvers=(direct gmres-amg)
selected=("$@")
for entry in "${cases[@]}"; do
  IFS=: read -r name refinements ends <<< "$entry"
  if ((${#selected[@]})) && [[ ! " ${selected[*]} " == *" $name "* ]]; then
    continue
  fi
  for np in ${NP:-2 4}; do
    for solver in "${solvers[@]}"; do
      for end in $ends; do
        out=$here/runs/$name-$solver-np$np-t$end
        rm -rf "$out"
        mkdir -p "$out"
        echo "== $name $solver on $np ranks to t = $end"
        (cd "$project_root" &&
           MPI_TRAFFIC_OUTPUT=$out/traffic.txt \
           mpirun --oversubscribe -np "$np" -x MPI_TRAFFIC_OUTPUT \
             -x LD_PRELOAD="$library" "$exe" \
             --set "Mesh/Global refinements = $refinements" \
             --set "Load stepping/End time = $end" \
             --set "Linear solver/Type = $solver" \
             --set "Output/Directory = $out" --set "Output/Interval = 0" \
             "$project_root/prm/two_bodies.prm") > "$out/screen.txt" 2>&1 ||
          echo "   (failed: see $out/screen.txt)"
      done
    done
  done
done
python3 "$here/report.py"
