#!/usr/bin/env bash
# Cost of one Newton iteration in short runs of the shipped scenes: each
# scene of prm/ cut to its first steps (End time below), 2 MPI ranks.
# Usage: benchmarks/iteration_cost/run.sh LABEL [BINARY]
#   LABEL   name of this set of runs (runs/LABEL/<scene>/), e.g. a commit
#   BINARY  the ductile-contact to time (default build/ductile-contact);
#           a binary copied elsewhere finds its library through
#           LD_LIBRARY_PATH=<its folder>.
# Then report.py writes results.md from every runs/* label.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
root=$project_root
label=$1
binary=${2:-$exe}
export LD_LIBRARY_PATH=$(dirname "$binary")${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}

# scene : end time (the first steps of each)
scenes=(box_compression:1 necking_bar:0.3 two_bodies:8 sent_coarse:0.1
        ductile_notch:0.2)
for entry in "${scenes[@]}"; do
  scene=${entry%%:*}
  end=${entry##*:}
  out=$here/runs/$label/$scene
  rm -rf "$out"
  mkdir -p "$out"
  # The scene with its end time replaced, its output into $out and no
  # solution output (a subsection may be entered again).
  sed -e "s|^\( *set End time *=\).*|\1 $end|" \
      "$root/prm/$scene.prm" > "$out/scene.prm"
  mesh_override "$root/prm/$scene.prm" >> "$out/scene.prm"
  printf 'subsection Output\n  set Directory = %s\n  set Interval = 0\nend\n' \
      "$out" >> "$out/scene.prm"
  echo "== $label $scene (end time $end)"
  (cd "$root" && mpirun -np 2 "$binary" "$out/scene.prm") > "$out/screen.txt" 2>&1
  tail -n 1 "$out/statistics" | cut -c1-120
done
python3 "$here/report.py"
