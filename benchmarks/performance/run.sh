#!/usr/bin/env bash
# Every shipped scene of prm/ that finishes within an hour, run whole on 2
# MPI ranks: with the current defaults and no field output (variant
# default), with the scene's own output (variant output), and variants that
# measure one choice against its alternative:
#   direct    every scene on the direct solver with double-precision factors
#             (single-precision factors are the default)
#   al        two_bodies with the augmented Lagrangian enforcement
#   amg       hertz_sphere with GMRES-AMG
#   amg-elim  the same with the contact rows eliminated (Constrained rows)
#   amg-elim-pb  and the rigid-body modes of each body (Rigid-body modes)
#   constant  the constant predictor (scenes that start from the linear one)
#   newton    block_on_plate with a tangent in every Newton iteration
#   relative  linear solves to their relative tolerance instead of Newton's
#   monotone  sent_coarse with Line search memory = 1
#   linear    sent_coarse with Predictor = linear (the scene sets best linear)
#   best      ductile_notch with Predictor = best linear
# Runs of earlier code are kept under the commit they ran (runs/SCENE/<commit>)
# for a before/after; report.py names them with their commit and date.
# report.py writes results.md (wall time, Newton and linear iterations, time
# per Newton iteration split into bulk assembly / contact / linear solve /
# rest, peak memory, each scene's quantity of interest against its reference:
# a speed-up counts only where it agrees); run_times.py writes run_times.md,
# the run-time table that README.md and the prm headers point to.
# Usage: benchmarks/performance/run.sh [SCENE[:VARIANT]...]
#   default: all scenes with their variants. Finished runs are kept
#   (delete runs/SCENE/VARIANT to redo one).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
require_build

# scene -> variants; a variant is a name and .prm lines to append
# (';' separates lines); "default" and "output" append nothing ("default"
# turns the field output off).
declare -A variants=(
  [box_compression]="default output"
  [gmsh_distorted_cube]="default output"
  [necking_bar]="default output direct"
  [two_bodies]="default output relative constant al direct"
  [two_bodies_no_contact]="default output"
  [block_on_plate]="default output relative newton direct constant"
  [hertz_sphere]="default output direct amg amg-elim amg-elim-pb"
  [hertz_cylinder_2d]="default output"
  [ironing]="default output relative direct"
  [ironing_2d]="default output"
  [ductile_notch]="default output relative direct best"
  [ductile_notch_2d]="default output"
  [sent_pfm_2d]="default output"
  [sent_shear_pfm_2d]="default output"
  [block_on_strip_2d]="default output"
  [block_impact_2d]="default output"
  [sent_coarse]="default output relative constant direct monotone linear"
  [bar_impact]="default output"
)
declare -A settings=(
  [al]="subsection Contact pair 1;  set Enforcement = augmented Lagrangian;end"
  [direct]="subsection Linear solver;  set Type = direct;  set Factorisation precision = double;end"
  [amg]="subsection Linear solver;  set Type = gmres-amg;end"
  [amg-elim]="subsection Linear solver;  set Type = gmres-amg;  set Constrained rows = eliminate;end"
  [amg-elim-pb]="subsection Linear solver;  set Type = gmres-amg;  set Constrained rows = eliminate;  set Rigid-body modes = per body;end"
  [constant]="subsection Load stepping;  set Predictor = constant;end"
  [newton]="subsection Newton;  set Tangent update = every iteration;end"
  [relative]="subsection Newton;  set Linear solve accuracy = relative tolerance;end"
  [monotone]="subsection Newton;  set Line search memory = 1;end"
  [linear]="subsection Load stepping;  set Predictor = linear;end"
  [best]="subsection Load stepping;  set Predictor = best linear;end"
)
order=(box_compression gmsh_distorted_cube necking_bar two_bodies two_bodies_no_contact
       block_on_plate hertz_sphere hertz_cylinder_2d ironing ironing_2d ductile_notch ductile_notch_2d sent_pfm_2d
       sent_shear_pfm_2d block_on_strip_2d block_impact_2d
       sent_coarse
       bar_impact)

jobs=("$@")
if ((${#jobs[@]} == 0)); then
  for scene in "${order[@]}"; do
    for v in ${variants[$scene]}; do jobs+=("$scene:$v"); done
  done
fi

for job in "${jobs[@]}"; do
  scene=${job%%:*}
  variant=${job#*:}
  [[ $variant == "$job" ]] && variant=default
  out=$here/runs/$scene/$variant
  if run_finished "$out"; then
    echo "== $scene $variant: done before"
    continue
  fi
  rm -rf "$out"
  mkdir -p "$out"
  copy_scene "$project_root/prm/$scene.prm" "$out/scene.prm"
  if [[ $variant == output ]]; then
    printf 'subsection Output\n  set Directory = %s\nend\n' "$out" >> "$out/scene.prm"
  else
    printf 'subsection Output\n  set Directory = %s\n  set Interval = 0\nend\n' \
      "$out" >> "$out/scene.prm"
  fi
  if [[ $variant != default && $variant != output ]]; then
    tr ';' '\n' <<< "${settings[$variant]}" >> "$out/scene.prm"
    echo >> "$out/scene.prm"
  fi
  echo "== $scene $variant ($(date +%H:%M))"
  date -u "+run started %Y-%m-%d %H:%M UTC" > "$out/screen.txt"
  (cd "$project_root" && /usr/bin/time -f "peak memory %M KB per rank" \
     mpirun -np 2 "$exe" "$out/scene.prm") >> "$out/screen.txt" 2>&1 ||
    echo "   stopped early, see $out/screen.txt"
  # The field output was written for its cost; the run keeps its text files.
  find "$out" -maxdepth 1 -type f ! -name statistics ! -name '*.prm' \
    ! -name log.txt ! -name screen.txt -delete
  rm -rf "$out/checkpoints"
done
/usr/bin/env python3 "$here/report.py"
/usr/bin/env python3 "$here/run_times.py"
/usr/bin/python3 "$here/plot.py" || echo "   no plot (scripts/install-deps.sh --plots)"
