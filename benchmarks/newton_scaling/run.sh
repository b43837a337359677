#!/usr/bin/env bash
# Time per Newton iteration, split into assembly and linear solve, for the
# direct (MUMPS) and the AMG-preconditioned CG solver, on 1 and 2 MPI ranks,
# at increasing refinement (2.8k ... 1.04M unknowns).
# Usage: benchmarks/newton_scaling/run.sh [MAX_REFINE_AMG] [MAX_REFINE_DIRECT]
# Writes runs/<config>/statistics, then results.md and scaling.png via
# report.py. Run with the other core idle; takes about 25 minutes.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
max_amg=${1:-3}
max_direct=${2:-2}
require_build

run() { # solver refine np
  local name="$1-r$2-np$3" dir="$here/runs/$1-r$2-np$3"
  mkdir -p "$dir"
  sed -e "s/@REFINE@/$2/" -e "s/@SOLVER@/$1/" -e "s|@DIR@|$dir|" \
    "$here/scene.prm.in" > "$dir/scene.prm"
  echo "== $name"
  /usr/bin/time -f "%M" -o "$dir/max_rss_kb" \
    mpirun -np "$3" "$exe" "$dir/scene.prm" > "$dir/screen.txt" 2>&1 ||
    echo "   failed, see $dir/screen.txt"
  grep -E "^step|DoFs" "$dir/screen.txt" || true
}

for r in $(seq 0 "$max_amg"); do
  for np in 1 2; do
    run cg-amg "$r" "$np"
    if (( r <= max_direct )); then run direct "$r" "$np"; fi
  done
done
# Debian's python3 has matplotlib (install-deps.sh --plots); a python3 from
# elsewhere earlier in PATH may not.
/usr/bin/python3 "$here/report.py" "$here"
