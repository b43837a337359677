#!/usr/bin/env bash
# Issue #24: every shipped scene that finishes within an hour, run whole on
# 2 MPI ranks with the current defaults, once more with double-precision
# MUMPS factors (variant direct: every scene on the direct solver; single-
# precision factors are the default since session 43), the contact
# scenes with the augmented Lagrangian (the enforcement before the
# semi-smooth Newton method), hertz_sphere with GMRES-AMG
# (variant amg, its default before session 35), and the scenes whose default is the linear
# predictor since session 36 (sent_coarse) or 37 (two_bodies,
# block_on_plate) with the constant one (variant constant), and
# block_on_plate with a tangent in every Newton iteration (variant newton,
# its default before its chord steps of session 38), and the scenes that
# stop their linear solves at Newton's tolerances (block_on_plate,
# ductile_notch, sent_coarse, two_bodies, ironing) with solves to their
# relative tolerance (variant relative, their default before session 39),
# and sent_coarse with a monotone line search (variant monotone: Line
# search memory = 1, the default, which the scene sets to 5 since session
# 41), and sent_coarse with Predictor = linear (variant linear: the scene's
# choice before session 42, which sets best linear) and ductile_notch with
# Predictor = best linear (variant best).
# Runs of earlier code are kept under another variant name (e.g.
# runs/SCENE/2026-12-02) for a before/after.
# report.py writes results.md: wall time, Newton and linear iterations, time
# per Newton iteration split into bulk assembly / contact / linear solve /
# rest, peak memory, and each scene's quantity of interest against its
# reference (a speed-up counts only where it agrees).
# Usage: benchmarks/performance/run.sh [SCENE[:VARIANT]...]
#   default: all scenes below with their variants. Finished runs are kept
#   (delete runs/SCENE/VARIANT to redo one).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
require_build

# scene -> variants; a variant is a name and .prm lines to append
# (';' separates lines), "default" appends nothing.
declare -A variants=(
  [box_compression]="default"
  [necking_bar]="default direct"
  [two_bodies]="default relative constant al direct"
  [block_on_plate]="default relative newton direct constant"
  [hertz_sphere]="default direct amg"
  [ironing]="default relative direct"
  [ductile_notch]="default relative direct best"
  [sent_coarse]="default relative constant direct monotone linear"
)
declare -A settings=(
  [al]="subsection Contact pair 1;  set Enforcement = augmented Lagrangian;end"
  [direct]="subsection Linear solver;  set Type = direct;  set Factorisation precision = double;end"
  [amg]="subsection Linear solver;  set Type = gmres-amg;end"
  [constant]="subsection Load stepping;  set Predictor = constant;end"
  [newton]="subsection Newton;  set Tangent update = every iteration;end"
  [relative]="subsection Newton;  set Linear solve accuracy = relative tolerance;end"
  [monotone]="subsection Newton;  set Line search memory = 1;end"
  [linear]="subsection Load stepping;  set Predictor = linear;end"
  [best]="subsection Load stepping;  set Predictor = best linear;end"
)
order=(box_compression necking_bar two_bodies block_on_plate hertz_sphere ironing ductile_notch sent_coarse)

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
  cp "$project_root/prm/$scene.prm" "$out/scene.prm"
  printf 'subsection Output\n  set Directory = %s\n  set Interval = 0\nend\n' \
    "$out" >> "$out/scene.prm"
  if [[ $variant != default ]]; then
    tr ';' '\n' <<< "${settings[$variant]}" >> "$out/scene.prm"
    echo >> "$out/scene.prm"
  fi
  echo "== $scene $variant ($(date +%H:%M))"
  (cd "$project_root" && /usr/bin/time -f "peak memory %M KB per rank" \
     mpirun -np 2 "$exe" "$out/scene.prm") > "$out/screen.txt" 2>&1 ||
    echo "   stopped early, see $out/screen.txt"
done
python3 "$here/report.py"
/usr/bin/python3 "$here/plot.py" || echo "   no plot (scripts/install-deps.sh --plots)"
