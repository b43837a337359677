#!/usr/bin/env bash
# Strong and weak scaling on 1 and 2 ranks, measured: the 3-D two bodies
# (elastic contact with friction), its first 3 steps, with the direct solver
# and gmres-amg. Strong: the mesh refined once (138k unknowns) on 1 and 2
# ranks. Weak: the shipped mesh (19.8k) on 1 rank against the plate's and the
# block's x subdivisions doubled (2x the unknowns) on 2 ranks, and the same
# from the mesh refined once (138k on 1 rank, 2x on 2 ranks). report.py:
# results.md with the time per Newton iteration of steps 2 and 3 (no
# set-up) and the efficiencies. Run on the quiet machine (about 15 minutes).
# Usage: benchmarks/scaling/speed/run.sh [CASE...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
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
selected=("$@")
for entry in "${cases[@]}"; do
  IFS=: read -r name ranks extra <<< "$entry"
  if ((${#selected[@]})) && [[ ! " ${selected[*]} " == *" $name "* ]]; then
    continue
  fi
  for np in $ranks; do
    for solver in "${solvers[@]}"; do
      out=$here/runs/$name-$solver-np$np
      if run_finished "$out"; then
        echo "== $name $solver on $np rank(s) (done)"
        continue
      fi
      rm -rf "$out"
      mkdir -p "$out"
      args=(--set "Load stepping/End time = 3"
            --set "Linear solver/Type = $solver"
            --set "Output/Directory = $out" --set "Output/Interval = 0")
      IFS='|' read -ra entries <<< "$extra"
      for e in "${entries[@]}"; do args+=(--set "$e"); done
      echo "== $name $solver on $np rank(s)"
      (cd "$project_root" && mpirun -np "$np" "$exe" "${args[@]}" \
         "$project_root/prm/two_bodies.prm") > "$out/screen.txt" 2>&1 ||
        echo "   (failed: see $out/screen.txt)"
    done
  done
done
/usr/bin/python3 "$here/report.py"
