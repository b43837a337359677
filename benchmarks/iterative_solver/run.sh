#!/usr/bin/env bash
# Krylov iterations per linear solve against the mesh: each case below is a
# shipped scene's first steps on its mesh refined r = 0, 1, ... times
# (Mesh/Global refinements), solved with each variant of `Linear solver`
# entries; 1 MPI rank (the times are those of one core; on more ranks the
# aggregates, and the Gauss-Seidel smoother, change with the partition, and
# so do the counts). report.py writes results.md: unknowns,
# Newton iterations, Krylov iterations per solve (mean and largest), linear
# solve time per Newton iteration and the scene's last force, which must be
# the same for every variant of a case and refinement.
# Usage: [VARIANTS="v ..."] [NP=n] [REFINEMENTS="r ..."]
#        benchmarks/iterative_solver/run.sh [CASE...]
#   (default: all cases, variants and each case's refinements)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
require_build

# case : scene file : End time : refinements : extra entries ('|' separates)
cases=(
  "strip_elastic:block_on_strip_2d:4:0 1 2 3 4:Body 0/Fracture = false|Body 0/Plasticity = false"
  "strip:block_on_strip_2d:4:0 1 2 3:"
  "ductile_notch_2d:ductile_notch_2d:0.04:0 1 2:"
  "hertz_cylinder_2d:hertz_cylinder_2d:0.5:0:"
  "two_bodies:two_bodies:3:0 1:"
  "two_bodies_k3:two_bodies:3:0:Mesh/Two bodies/Plate subdivisions = 57, 39, 6|Mesh/Two bodies/Block subdivisions = 15, 15, 15"
  "two_bodies_k4:two_bodies:3:0:Mesh/Two bodies/Plate subdivisions = 76, 52, 8|Mesh/Two bodies/Block subdivisions = 20, 20, 20"
)
# variant : Linear solver entries ('|' separates)
variants=(
  "direct:Type = direct"
  "gmres-amg:Type = gmres-amg"
  "gmres-amg-sgs:Type = gmres-amg|AMG smoother = symmetric Gauss-Seidel"
  "gmres-amg-sgs-r400:Type = gmres-amg|AMG smoother = symmetric Gauss-Seidel|GMRES restart = 400"
  "gmres-amg-pf-direct:Type = gmres-amg|Phase-field preconditioner = direct"
  "gmres-amg-elim:Type = gmres-amg|Constrained rows = eliminate"
  "gmres-amg-pb:Type = gmres-amg|Rigid-body modes = per body"
  "gmres-amg-sgs-pb:Type = gmres-amg|AMG smoother = symmetric Gauss-Seidel|Rigid-body modes = per body"
  "gmres-amg-sgs-r400-pb:Type = gmres-amg|AMG smoother = symmetric Gauss-Seidel|GMRES restart = 400|Rigid-body modes = per body"
  "gmres-amg-pf-direct-pb:Type = gmres-amg|Phase-field preconditioner = direct|Rigid-body modes = per body"
  "gmres-amg-elim-pb:Type = gmres-amg|Constrained rows = eliminate|Rigid-body modes = per body"
)
selected=("$@")
# VARIANTS="a b": only these variants (default: all); NP=n: on n ranks
# (default 1; the runs are named ...-npn).
only=(${VARIANTS:-})
np=${NP:-1}
suffix=""
((np > 1)) && suffix="-np$np"

for entry in "${cases[@]}"; do
  IFS=: read -r name scene end refinements extra <<< "$entry"
  if ((${#selected[@]})) && [[ ! " ${selected[*]} " == *" $name "* ]]; then
    continue
  fi
  for r in ${REFINEMENTS:-$refinements}; do
    for v in "${variants[@]}"; do
      variant=${v%%:*}
      settings=${v#*:}
      if ((${#only[@]})) && [[ ! " ${only[*]} " == *" $variant "* ]]; then
        continue
      fi
      # The phase-field preconditioners only differ with s unknowns.
      if [[ $variant == gmres-amg-pf-direct* && ( $name == strip_elastic ||
            $name == hertz_cylinder_2d || $name == two_bodies* ) ]]; then
        continue
      fi
      # Constraint rows come from contact only, and one body has one set
      # of rigid-body modes.
      if [[ ( $variant == gmres-amg-elim* || $variant == *-pb ) &&
            $name == ductile_notch_2d ]]; then
        continue
      fi
      out=$here/runs/$name/r$r-$variant$suffix
      rm -rf "$out"
      mkdir -p "$out"
      args=(--set "Mesh/Global refinements = $r"
            --set "Load stepping/End time = $end"
            --set "Output/Directory = $out" --set "Output/Interval = 0"
            --set "Output/Verbosity = 2")
      IFS='|' read -ra entries <<< "$extra"
      for e in "${entries[@]}"; do [[ -n $e ]] && args+=(--set "$e"); done
      IFS='|' read -ra entries <<< "$settings"
      for e in "${entries[@]}"; do args+=(--set "Linear solver/$e"); done
      echo "== $name r$r $variant$suffix"
      (cd "$project_root" && mpirun -np "$np" "$exe" "${args[@]}" \
         "$project_root/prm/$scene.prm") > "$out/screen.txt" 2>&1 ||
        echo "   (failed: see $out/screen.txt)"
    done
  done
done
python3 "$here/report.py"
