#!/usr/bin/env bash
# Every shipped scene of prm/ on 1, 2 and 3 MPI ranks
# (3 ranks share the 2 cores: OMPI_MCA_mpi_yield_when_idle), each up to the
# end time below (the whole scene where it is cheap, otherwise through the
# phase that exercises its physics: contact, yield, a running crack).
# report.py compares the statistics of 1 and 3 ranks with those of 2
# (every column but timings and iteration counts, to 1e-6 of the column's
# scale: tests/checkpoint/compare_statistics.py) and writes results.md.
# Usage: benchmarks/rank_invariance/run.sh [SCENE...]   (default: all)
#   Finished runs are kept (delete runs/SCENE/npN to redo one).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
require_build
export OMPI_MCA_mpi_yield_when_idle=1 OPENBLAS_NUM_THREADS=1

# scene -> end time of the comparison ("" = the scene's own).
declare -A end_time=(
  [block_on_plate]=34      # contact, friction, the plate yields from 31
  [box_compression]=""
  [ductile_notch]=0.34     # yield and the crack at the notch (s to 0.9)
  [gmsh_distorted_cube]=""
  [hertz_sphere]=0.25      # the first of 4 steps (126k unknowns)
  [ironing]=""
  [necking_bar]=""
  [sent]=0.02              # the elastic start (fine mesh, ~160k unknowns)
  [sent_coarse]=0.7        # the crack runs through (s to 0.9)
  [two_bodies]=40          # contact and friction, 6 mm
  [two_bodies_no_contact]=""
)
scenes=("$@")
((${#scenes[@]})) || scenes=($(printf '%s\n' "${!end_time[@]}" | sort))

for s in "${scenes[@]}"; do
  [[ -v end_time[$s] ]] || { echo "unknown scene $s" >&2; exit 1; }
  for np in 2 1 3; do
    out=$here/runs/$s/np$np
    if run_finished "$out"; then
      echo "== $s on $np rank(s): done before"
      continue
    fi
    rm -rf "$out"
    mkdir -p "$out"
    {
      cat "$project_root/prm/$s.prm"
      mesh_override "$project_root/prm/$s.prm"
      printf '%s\n' "subsection Output" "  set Directory = $out" \
        "  set Interval = 0" "end"
      [[ -n ${end_time[$s]} ]] && printf '%s\n' "subsection Load stepping" \
        "  set End time = ${end_time[$s]}" "end"
    } > "$out/scene.prm"
    echo "== $s on $np rank(s) ($(date +%H:%M))"
    (cd "$project_root" && mpirun --oversubscribe -np "$np" "$exe" \
      "$out/scene.prm" > "$out/screen.txt" 2>&1) ||
      echo "   stopped early, see $out/screen.txt"
  done
done
"$here/report.py"
