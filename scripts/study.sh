#!/usr/bin/env bash
# A parameter study: runs a scene for every combination of the swept values
# and collects one CSV row per run (scripts/study_report.py).
# Usage:
#   scripts/study.sh [-j N] [-o DIR] [--set "ENTRY = VALUE"]... \
#                    [--plot COLUMN:ENTRY] SCENE.prm "ENTRY = V1, V2, ..." ...
#   ENTRY   a parameter path as in the .prm, subsections joined by '/', e.g.
#           "Body 0/Fracture/Critical energy release rate = 75e3, 150e3"
#           (values are separated by ','; a value cannot contain one)
#   -j N    runs at a time (default 2: two runs on one rank each, the two
#           cores of this machine); -j 1 runs one at a time on NP (2) ranks
#   -o DIR  the study's folder (default results/study_SCENE); each run keeps
#           its results in DIR/run_K (scene.prm, screen.txt, statistics, ...)
#   --set   a fixed override for every run (repeatable), e.g.
#           --set "Output/Interval = 0" to skip the field output
#   --plot  draws COLUMN of the CSV against the swept ENTRY (repeatable)
# Writes DIR/study.csv: the swept values, peak and final force, max s, max
# alpha, crack energy, frictional dissipation, Newton iterations, wall time
# and exit code of each run. A run that fails is a row with its exit code
# (and what it reached); the study goes on. Finished runs (an exit code
# recorded) are not redone, so an interrupted study resumes
# (delete DIR/run_K to redo one).
set -uo pipefail
source "$(dirname "$0")/env.sh"
require_build

parallel=2 out="" fixed=() plots=()
while (($#)); do
  case $1 in
    -j) parallel=$2; shift 2 ;;
    -o) out=$2; shift 2 ;;
    --set) fixed+=("$2"); shift 2 ;;
    --plot) plots+=("$2"); shift 2 ;;
    -h|--help) sed -n '2,23p' "$0"; exit 0 ;;
    *) break ;;
  esac
done
(($# >= 2)) || { echo "usage: scripts/study.sh [options] SCENE.prm \"ENTRY = V1, V2\" ... (--help)" >&2; exit 1; }
scene=$1; shift
[[ -f $scene ]] || { echo "error: no scene file $scene" >&2; exit 1; }
scene=$(cd "$(dirname "$scene")" && pwd)/$(basename "$scene")
out=${out:-$project_root/results/study_$(basename "$scene" .prm)}
mkdir -p "$out"
out=$(cd "$out" && pwd)
np=$((parallel > 1 ? 1 : ${NP:-2}))

# The sweeps: names and value lists.
names=() lists=()
for sweep in "$@"; do
  [[ $sweep == *=* ]] || { echo "error: a sweep is \"ENTRY = V1, V2, ...\", got '$sweep'" >&2; exit 1; }
  names+=("$(sed 's/ *=.*//; s/^ *//' <<< "$sweep")")
  lists+=("$(sed 's/^[^=]*= *//' <<< "$sweep")")
done


# Every combination, one per line: values separated by tabs.
combinations=("")
for ((s = 0; s < ${#names[@]}; ++s)); do
  IFS=, read -ra values <<< "${lists[$s]}"
  next=()
  for c in "${combinations[@]}"; do
    for v in "${values[@]}"; do
      v=$(sed 's/^ *//; s/ *$//' <<< "$v")
      next+=("${c:+$c	}$v")
    done
  done
  combinations=("${next[@]}")
done

# The study's description for study_report.py.
{
  printf '%s\n' "${names[@]}" > "$out/swept_entries"
  printf '%s\n' "${combinations[@]}" > "$out/combinations"
}

run_one() {
  local k=$1 combination=$2 dir=$out/run_$1
  if [[ -f $dir/exit_code ]]; then
    echo "== run $k: done before (exit code $(cat "$dir/exit_code"))"
    return
  fi
  rm -rf "$dir"
  mkdir -p "$dir"
  # The scene as it is, the study's entries as --set overrides (recorded by
  # the program in the run's input.prm and parameters.prm).
  local sets=()
  for f in "${fixed[@]}"; do sets+=(--set "$f"); done
  IFS=$'\t' read -ra values <<< "$combination"
  for ((s = 0; s < ${#names[@]}; ++s)); do
    sets+=(--set "${names[$s]} = ${values[$s]}")
  done
  sets+=(--set "Output/Directory = $dir")
  copy_scene "$scene" "$dir/scene.prm"
  printf '%s\n' "${sets[@]}" | grep -v '^--set$' > "$dir/overrides"
  echo "== run $k on $np rank(s): ${combination//	/, } ($(date +%H:%M))"
  local start=$(date +%s%N)
  # From the project root, like scripts/run.sh (Output/Directory is relative
  # to where the program starts; the copy reads the scene's mesh).
  (cd "$project_root" && mpirun -np "$np" "$exe" "${sets[@]}" "$dir/scene.prm" > "$dir/screen.txt" 2>&1)
  local code=$?
  echo "$code" > "$dir/exit_code"
  echo "$((($(date +%s%N) - start) / 1000000))" > "$dir/wall_time_ms"
  ((code == 0)) || echo "   run $k ended with exit code $code (see $dir/screen.txt)"
}

n=${#combinations[@]}
echo "-- $n runs, $parallel at a time, results in $out"
for ((i = 0; i < n; i += parallel)); do
  for ((k = i; k < i + parallel && k < n; ++k)); do
    run_one "$((k + 1))" "${combinations[$k]}" &
  done
  wait
done
plot_args=()
for p in "${plots[@]}"; do plot_args+=(--plot "$p"); done
"$project_root/scripts/study_report.py" "$out" "${plot_args[@]}"
