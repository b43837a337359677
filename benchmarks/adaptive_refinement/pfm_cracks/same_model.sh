#!/usr/bin/env bash
# pfm-cracks' notched tension with our model matched to its own
# (prm/sent_pfm_2d.prm: plane strain, second-order phase field with
# l_f = its eps = 0.0441942 mm, no energy split, Q1, its 89 load steps) on
# its uniform meshes of levels 4, 5 and 6 (h = 0.5 mm / 2^L; its runs g4,
# g5 and g6 of run.sh are uniform at these levels up to their peaks), one
# run at a time on one rank, beside nothing else. report.py puts the peaks
# and the costs next to pfm-cracks' and draws the force curves
# (same_model.png).
# Then the same scene with our fourth-order phase field beside it
# (ours-at4-gL: l_f = eps/2 = 0.0220971 mm, the same transition zone, Q2,
# the C0IP default penalty) on levels 4 and 5.
# Its notched shear the same way (shear-gL: prm/sent_shear_pfm_2d.prm,
# small-strain linear elasticity with the spectral split, on levels 4, 5
# and 6; run.sh's s5 and s6 are pfm-cracks on the same uniform meshes).
# Usage: benchmarks/adaptive_refinement/pfm_cracks/same_model.sh [RUN...]
#   RUN: at2-g4 at2-g5 at2-g6 at4-g4 at4-g5 shear-g4 shear-g5 shear-g6
#   shear4-g4 (the shear with the fourth-order phase field, as at4)
#   (default: all)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
require_build
runs=("$@")
((${#runs[@]})) || runs=(at2-g4 at2-g5 at2-g6 at4-g4 at4-g5 shear-g4 shear-g5 shear-g6 shear4-g4)

fourth_order='subsection Finite elements
  set Polynomial degree = 2
end
subsection Body 1
  subsection Fracture
    set Regularisation = fourth order
    set Length scale   = 2.20971e-5
  end
end'

for run in "${runs[@]}"; do
  dir=$here/runs/ours-$run
  level=${run#*-g}
  if run_finished "$dir"; then
    echo "== ours-$run (done)"
    continue
  fi
  rm -rf "$dir"
  mkdir -p "$dir"
  h=$(python3 -c "print(0.5 / 2**$level)")
  scene=sent_pfm_2d.prm tags=free
  [[ $run == shear* ]] && scene=sent_shear_pfm_2d.prm tags=shear
  python3 "$project_root/prm/meshes/make_sent.py" "$h" 0.5 "$dir/mesh.msh" 1.0 1.0 0 $tags
  { cat "$project_root/prm/$scene"
    printf 'subsection Mesh\n  subsection Gmsh\n    set File name = %s\n  end\nend\n' "$dir/mesh.msh"
    printf 'subsection Output\n  set Directory = %s\nend\n' "$dir"
    [[ $run == at4-* || $run == shear4-* ]] && echo "$fourth_order"
    # pfm-cracks' 200 steps (the shipped scene stops at 125)
    [[ $run == shear* ]] && printf 'subsection Load stepping\n  set End time = 200\nend\n'
  } > "$dir/scene.prm"
  echo "== ours-$run ($(date +%H:%M))"
  run_scene 1 "$dir"
  rm -f "$dir/mesh.msh"
done
/usr/bin/python3 "$here/report.py"
