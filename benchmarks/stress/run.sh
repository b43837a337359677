#!/usr/bin/env bash
# Runs that push the solver, on the coarse copy of the
# paper's scene (prm/block_on_plate.prm with the plate 8 x 5 x 1 and the
# block 2 x 2 x 2 Q2 cells, 0.6 mm per step: tests/block_on_plate.cc) and
# variants of it. Each run must either reach its end time (cut-backs and
# regrowth counted) or stop cleanly with exit code 2 and readable results;
# none may crash, hang (a time limit: TIMEOUT seconds, then SIGTERM, which
# ends the run after its step with exit code 3) or write NaN into the
# results. report.py writes results.md.
# Usage: benchmarks/stress/run.sh [CASE...]   (default: all; NP ranks, 2)
#   Finished runs are kept (delete runs/CASE to redo one).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
require_build
timeout=${TIMEOUT:-1800}

# case -> .prm lines appended to the coarse scene (';' separates lines).
ductile="subsection Body 0;subsection Fracture;set Crack driver = elastic plus plastic work;set Critical work density = 5e5;set Driver factor = 10;end;end"
steps() { echo "subsection Load stepping;set Time step = $1;set End time = $2;end"; }
declare -A settings=(
  # 10x the coarse scene's 0.6 mm per step: 6 mm steps to 18 mm.
  [large_step]="$(steps 40 120)"
  # The rate-independent limit of the crack (eta_f = 0) with the plastic
  # work driver, pressed until the plate tears (18 mm).
  [eta_f_zero]="$ductile;subsection Body 0;subsection Fracture;set Viscosity = 0;end;end;$(steps 4 120)"
  # eta_p a millionth of the paper's (1 Pa s instead of 1e6).
  [eta_p_small]="subsection Body 0;subsection Plasticity;set Viscosity = 1;end;end;$(steps 4 120)"
  # A block 1e4 times softer than the plate (nu = 0.45 kept).
  [moduli_1e4]="subsection Body 1;set Shear modulus = 2.6455e6;set Bulk modulus = 25.57e6;end;$(steps 4 120)"
  [friction_1]="subsection Contact pair 1;set Friction coefficient = 1;end;$(steps 4 120)"
  [friction_10]="subsection Contact pair 1;set Friction coefficient = 10;end;$(steps 4 120)"
  # l_f at the cell size of the coarse plate (mean edge 32.5 mm) and a
  # quarter of it (below the node spacing: warned), both tearing.
  [lf_h]="$ductile;subsection Body 0;subsection Fracture;set Length scale = 32.5e-3;end;subsection Plasticity;set Length scale = 32.5e-3;end;end;$(steps 4 120)"
  [lf_quarter_h]="$ductile;subsection Body 0;subsection Fracture;set Length scale = 8.1e-3;end;subsection Plasticity;set Length scale = 8.1e-3;end;end;$(steps 4 120)"
  # The plate held in z on its other faces (a rigid support), the block
  # pressed 45 mm, beyond its 40 mm height: its elements must invert.
  [invert]="subsection Boundary conditions;set Boundary ids = 1, 2, 0;end;subsection Boundary 0;set Constrained components = z;end;$(steps 20 300)"
  # The block moved next to the clamp (x from 0.24 to 0.28 m) and the
  # plastic work driver with a lower critical work: the plate tears along
  # the clamp, beside and under the contact zone.
  [crack_in_contact]="subsection Mesh;subsection Two bodies;set Block centre = 0.26, 0.1;end;end;$ductile;subsection Body 0;subsection Fracture;set Critical work density = 1e5;end;end;$(steps 4 200)"
)
order=(large_step eta_f_zero eta_p_small moduli_1e4 friction_1 friction_10
       lf_h lf_quarter_h invert crack_in_contact)
jobs=("$@")
((${#jobs[@]})) || jobs=("${order[@]}")
np=${NP:-2}

for c in "${jobs[@]}"; do
  out=$here/runs/$c
  if [[ -f $out/exit_code ]]; then
    echo "== $c: done before (exit code $(cat "$out/exit_code"))"
    continue
  fi
  [[ -v settings[$c] ]] || { echo "unknown case $c" >&2; exit 1; }
  rm -rf "$out"
  mkdir -p "$out"
  {
    cat "$project_root/prm/block_on_plate.prm"
    printf '%s\n' "subsection Mesh" "  subsection Two bodies" \
      "    set Plate subdivisions = 8, 5, 1" "    set Block subdivisions = 2, 2, 2" \
      "  end" "end" "subsection Output" "  set Directory = $out" \
      "  set Interval = 5" "end"
    tr ';' '\n' <<< "${settings[$c]}"
    echo
  } > "$out/scene.prm"
  echo "== $c on $np rank(s) ($(date +%H:%M))"
  start=$(date +%s%N)
  (cd "$project_root" && timeout --signal=TERM --kill-after=120 "$timeout" \
    mpirun -np "$np" "$exe" "$out/scene.prm" > "$out/screen.txt" 2>&1)
  code=$?
  echo "$code" > "$out/exit_code"
  echo "$((($(date +%s%N) - start) / 1000000))" > "$out/wall_time_ms"
  echo "   exit code $code"
done
"$here/report.py"
