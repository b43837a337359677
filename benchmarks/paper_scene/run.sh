#!/usr/bin/env bash
# The paper's scene (prm/block_on_plate.prm) and its variants:
# the viscosities eta_p and eta_f halved, the load step halved, the plate
# refined at the clamp (by a box, or adaptively where alpha > 0.002 or 1e-4, once
# or twice), and the plastic work crack driver. report.py
# writes results.md and the plots (force curve, energies, fields).
# Usage: benchmarks/paper_scene/run.sh [-j 2] [VARIANT...]
#   default: every variant below, one after the other on NP (2) ranks;
#   -j 2 runs two at a time on one rank each (the machine's two cores).
#   Finished runs are kept (delete runs/VARIANT to redo one). Each run
#   leaves runs/VARIANT/{scene.prm,screen.txt,statistics,solution.pvd}.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
require_build

# variant -> .prm lines appended to the scene (';' separates lines, '@'
# stands for a ';' inside a line).
fracture="subsection Body 0;subsection Fracture"
# The mesh study at 0.6 mm per step (four of the scene's steps: its load step
# error, dt_half against paper, is 5e-5 of the peak, far below the mesh's):
# the paper mesh, the plate refined once for x > 0.22 m (clamp_refined) and
# once more for x > 0.268 m (the two columns of cells at the clamp, where
# the hinge forms; 205k unknowns), single-precision factors for all three.
coarse_step="subsection Load stepping;set Time step = 4;end;subsection Linear solver;set Factorisation precision = single;end"
clamp_box="0.22,0,0 : 0.3,0.2,0.02 : 1"
hinge_box="0.268,0,0 : 0.3,0.2,0.02 : 1"
declare -A settings=(
  [paper]=""
  [eta_p_half]="subsection Body 0;subsection Plasticity;set Viscosity = 5e5;end;end"
  [eta_f_half]="$fracture;set Viscosity = 5e4;end;end"
  [dt_half]="subsection Load stepping;set Time step = 0.5;end"
  [clamp_refined]="subsection Mesh;set Local refinement boxes = $clamp_box;end"
  [paper_du0.6]="$coarse_step"
  [clamp_refined_du0.6]="$coarse_step;subsection Mesh;set Local refinement boxes = $clamp_box;end"
  [hinge_refined2_du0.6]="$coarse_step;subsection Mesh;set Local refinement boxes = $clamp_box@ $hinge_box;end"
  [block_refined]="subsection Mesh;set Local refinement boxes = 0,0,0.02 : 0.3,0.2,0.1 : 1;end"
  [clamp_adaptive]="subsection Mesh;subsection Adaptive refinement;set Enabled = true;set Hardening threshold = 0.002;set Maximum level = 1;end;end"
  [clamp_adaptive_early]="subsection Mesh;subsection Adaptive refinement;set Enabled = true;set Hardening threshold = 1e-4;set Maximum level = 1;end;end"
  [clamp_adaptive2]="subsection Mesh;subsection Adaptive refinement;set Enabled = true;set Hardening threshold = 0.002;set Maximum level = 2;end;end"
  [ductile_zeta1]="$fracture;set Crack driver = elastic plus plastic work;set Critical work density = 0;set Driver factor = 1;end;end"
  [ductile]="$fracture;set Crack driver = elastic plus plastic work;set Critical work density = 5e5;set Driver factor = 10;end;end"
  [ductile_zeta30]="$fracture;set Crack driver = elastic plus plastic work;set Critical work density = 5e5;set Driver factor = 30;end;end"
)
order=(paper eta_p_half eta_f_half ductile_zeta1 ductile ductile_zeta30 dt_half
       clamp_refined block_refined clamp_adaptive clamp_adaptive_early clamp_adaptive2
       paper_du0.6 clamp_refined_du0.6 hinge_refined2_du0.6)

parallel=1
if [[ "${1:-}" == "-j" ]]; then
  parallel=$2
  shift 2
fi
np=$((parallel > 1 ? 1 : ${NP:-2}))
jobs=("$@")
((${#jobs[@]})) || jobs=("${order[@]}")

run_variant() {
  local variant=$1 out=$here/runs/$1
  if run_finished "$out"; then
    echo "== $variant: done before"
    return
  fi
  [[ -v settings[$variant] ]] || { echo "unknown variant $variant" >&2; return 1; }
  rm -rf "$out"
  mkdir -p "$out"
  copy_scene "$project_root/prm/block_on_plate.prm" "$out/scene.prm"
  printf 'subsection Output\n  set Directory = %s\n  set Interval = 113\nend\n' \
    "$out" >> "$out/scene.prm"
  tr ';@' '\n;' <<< "${settings[$variant]}" >> "$out/scene.prm"
  echo >> "$out/scene.prm"
  echo "== $variant on $np rank(s) ($(date +%H:%M))"
  (cd "$project_root" && /usr/bin/time -f "peak memory %M KB per rank" \
    mpirun -np "$np" "$exe" "$out/scene.prm" > "$out/screen.txt" 2>&1) ||
    echo "   $variant stopped early, see $out/screen.txt"
}

for ((i = 0; i < ${#jobs[@]}; i += parallel)); do
  for ((k = i; k < i + parallel && k < ${#jobs[@]}; ++k)); do
    run_variant "${jobs[$k]}" &
  done
  wait
done
"$here/report.py"
