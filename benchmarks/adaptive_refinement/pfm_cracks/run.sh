#!/usr/bin/env bash
# pfm-cracks (github.com/tjhei/cracks), built here from
# its source against Debian's deal.II 9.4.1, runs its own adaptive Miehe
# notched-tension file (parameters_miehe_tension_adaptive.prm: 2-D, eps =
# 0.0442 = 4 h of level 6) as shipped (g4: level 4 uniform, two adaptive
# levels), and with the uniform start one and two levels finer (g5, g6:
# Global pre-refinement steps 5 and 6, Adaptive refinement cycles 1 and 0;
# the finest level and so eps stay the same), to see its peak converge
# under h at fixed eps; then ours (../sent's level-4 run) on one rank. One
# run at a time on one core. report.py writes
# results.md from the screen logs and puts the time to a converged peak
# next to ours (benchmarks/adaptive_refinement/sent).
# Its notched shear (parameters_miehe_shear_adaptive.prm: eps = 2 h of
# level 5 = 0.0442 mm, the spectral split, 200 steps of 1e-4 mm) as shipped
# (s4: level 4, one adaptive level) and uniform on levels 5 and 6 (s5, s6:
# no adaptive cycle, Eps reg = 0.0441942 mm, the shipped value) for
# same_model.sh's shear runs on the same meshes.
# Usage: benchmarks/adaptive_refinement/pfm_cracks/run.sh [g4 g5 g6 s4 s5 s6]
#   The source and build go to work/ (not committed; PFM_DIR overrides);
#   PFM_GIT names another place to clone from (a local mirror, say).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
work=${PFM_DIR:-$here/work}
commit=8470f9514562e9119a0e205bafaa6e02bb7728e8
runs=("$@")
((${#runs[@]})) || runs=(g4 g5 g6)

if [[ ! -x "$work/build/cracks" ]]; then
  mkdir -p "$work"
  [[ -d "$work/src/.git" ]] || git clone -q "${PFM_GIT:-https://github.com/tjhei/cracks.git}" "$work/src"
  git -C "$work/src" checkout -q "$commit"
  # The README asks for deal.II 9.5; the code builds and runs with 9.4.1
  # (its own miehe_tension test matches its reference to 0.2 %).
  sed -i 's/FIND_PACKAGE(deal.II 9.5.0/FIND_PACKAGE(deal.II 9.4.0/' "$work/src/CMakeLists.txt"
  # Its printed bulk energy degrades the whole psi(E) even where the stress
  # is decomposed (the shear test); energy_split.patch prints g psi^+ +
  # psi^-, the energy of its equations, and changes nothing else.
  git -C "$work/src" apply "$here/energy_split.patch"
  cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  make -C "$work/build" -j"$jobs" cracks > "$work/build/make.log"
fi

for run in "${runs[@]}"; do
  level=${run#[gs]}
  dir=$here/runs/$run
  if grep -qs "Total wallclock" "$dir/screen.log"; then
    echo "== $run (done)"
    continue
  fi
  mkdir -p "$dir"
  case $run in
    g?) sed -e "s/\(set Global pre-refinement steps[[:space:]]*=\).*/\1 $level/" \
            -e "s/\(set Adaptive refinement cycles[[:space:]]*=\).*/\1 $((6 - level))/" \
            "$work/src/parameters_miehe_tension_adaptive.prm" > "$dir/parameters.prm" ;;
    s4) cp "$work/src/parameters_miehe_shear_adaptive.prm" "$dir/parameters.prm" ;;
    s?) sed -e "s/\(set Global pre-refinement steps[[:space:]]*=\).*/\1 $level/" \
            -e "s/\(set Adaptive refinement cycles[[:space:]]*=\).*/\1 0/" \
            -e "s/\(set Eps reg[[:space:]]*=\).*/\1 0.0441942/" \
            "$work/src/parameters_miehe_shear_adaptive.prm" > "$dir/parameters.prm" ;;
    *) echo "run.sh: unknown run '$run' (g4 g5 g6 s4 s5 s6)" >&2; exit 1 ;;
  esac
  echo "== $run ($(date +%H:%M))"
  (cd "$dir" && /usr/bin/time -f "%e s wall, %M KB" -o time.txt \
    mpirun -np 1 "$work/build/cracks" parameters.prm > screen.log 2>&1) ||
    echo "   $run stopped early, see $dir/screen.log"
  rm -rf "$dir/output"
done
# Ours beside it: ../sent's level-4 run (s > 0.2) again, on one rank.
ours=$here/runs/ours-level4-s0.2
if ! run_finished "$ours"; then
  mkdir -p "$ours"
  sed -e "s|/runs/level4-s0.2|/../pfm_cracks/runs/ours-level4-s0.2|" \
    "$here/../sent/runs/level4-s0.2/scene.prm" > "$ours/scene.prm"
  echo "== ours-level4-s0.2 ($(date +%H:%M))"
  run_scene 1 "$ours"
fi
/usr/bin/python3 "$here/report.py"
