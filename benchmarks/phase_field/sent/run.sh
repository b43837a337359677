#!/usr/bin/env bash
# Notched tension (SENT slab, validation.md rung 8) as a coupled [u | s]
# benchmark: peak force against run time for Q2/Q3, monolithic/staggered,
# direct (MUMPS)/iterative (GMRES + block AMG) solvers, and the peak force
# under refinement of the mesh (h) and of the load step (du).
# Usage: benchmarks/phase_field/sent/run.sh [LF_MM] [NP] [RUN ...]
#   LF_MM: phase-field length l_f in mm (default 0.05: the studies need many
#          runs; the prm/sent.prm scene uses 0.0075)
#   RUN:   only these configurations (names as in runs/lf<LF_MM>/, e.g.
#          q2-h2-monolithic-direct-dt0.05-box6), e.g. to run two 1-rank
#          jobs side by side on the two cores; the report covers all runs.
# Writes runs/<config>/{scene.prm,screen.txt,statistics}, then results.md and
# sent.png via report.py. Runs whose statistics exist are skipped (delete
# their folder to redo). Run with the other core idle.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
lf_mm=${1:-0.05}
np=${2:-2}
only=("${@:3}")
require_build
mkdir -p "$here/runs/meshes"
lf=$(/usr/bin/python3 -c "print($lf_mm * 1e-3)")
# End of loading (t = 1 is a top displacement of 1e-5 m = 0.01 mm): one step
# past the peak, which lies at t = 0.46 for l_f = 0.05 mm on every mesh
# here (dt = 0.02). With eta_f = 0 the crack turns unstable just after the
# peak (t ~ 0.499 on the coarsest mesh): monolithic Newton cannot follow the
# snap-back and would stop there after cut-backs (minimum step dt / 8),
# staggered would walk through it with many alternations; neither is part
# of the peak-force comparison. (The first runs in runs/ went to t = 0.5 and
# were stopped after the step past the peak; the report counts every run up
# to that step only.) The report marks a run whose last step is its largest
# force as incomplete.
end=${END:-0.48}

run() { # degree h_over_lf strategy solver dt [box_over_lf]
  # Without box_over_lf the fine band (half-width 3 l_f) runs along the
  # whole crack path; with it only a square of half-width box_over_lf * l_f
  # around the notch tip is fine (enough for the peak force, see README).
  # strategy staggered_andersonM: staggered with Anderson depth M.
  local degree=$1 ratio=$2 strategy=$3 solver=$4 dt=$5 box=${6:-}
  local depth=0 prm_strategy=$3 prm_solver=$4 pf_prec=amg
  # solver gmres-amg-slu: GMRES + block AMG with a sparse LU of the s block
  # (Linear solver/Phase-field preconditioner = direct) instead of its AMG.
  if [[ "$solver" == gmres-amg-slu ]]; then
    prm_solver=gmres-amg
    pf_prec=direct
  fi
  if [[ "$strategy" == *_anderson* ]]; then
    depth=${strategy##*_anderson}
    prm_strategy=${strategy%%_anderson*}
  fi
  local h_mm band_mm x_end mesh name dir
  h_mm=$(/usr/bin/python3 -c "print($lf_mm / $ratio)")
  if [[ -n "$box" ]]; then
    band_mm=$(/usr/bin/python3 -c "print($box * $lf_mm)")
    x_end=$(/usr/bin/python3 -c "print(0.5 + $band_mm)")
  else
    band_mm=$(/usr/bin/python3 -c "print(3 * $lf_mm)")
    x_end=1
  fi
  mesh="$here/runs/meshes/sent_h${h_mm}_b${band_mm}_x${x_end}.msh"
  [[ -f "$mesh" ]] || /usr/bin/python3 "$here/../../../prm/meshes/make_sent.py" \
    "$h_mm" "$band_mm" "$mesh" "$x_end" > /dev/null
  name="q${degree}-h${ratio}-${strategy}-${solver}-dt${dt}${box:+-box$box}"
  if ((${#only[@]})) && [[ " ${only[*]} " != *" $name "* ]]; then return; fi
  dir="$here/runs/lf${lf_mm}/$name"
  if [[ -f "$dir/statistics" ]]; then
    echo "== $name (done)"; return
  fi
  mkdir -p "$dir"
  sed -e "s|@MESH@|$mesh|" -e "s|@LF@|$lf|" -e "s|@DEGREE@|$degree|" \
    -e "s|@STRATEGY@|$prm_strategy|" -e "s|@DEPTH@|$depth|" -e "s|@SOLVER@|$prm_solver|" -e "s|@PFPREC@|$pf_prec|" -e "s|@DT@|$dt|" -e "s|@DTMIN@|${DTMIN:-$(/usr/bin/python3 -c "print($dt / 8)")}|" \
    -e "s|@END@|$end|" -e "s|@ETA@|${ETA:-0}|" -e "s|@DIR@|$dir|" \
    "$here/scene.prm.in" > "$dir/scene.prm"
  echo "== $name"
  run_scene "$np" "$dir"
  grep -E "DoFs|Total wallclock" "$dir/screen.txt" || true
}

if [[ "$lf_mm" == "0.0075" ]]; then
  # The l_f of prm/sent.prm (rung 8). Q2, monolithic, GMRES + block AMG (the
  # fastest combination at l_f = 0.05 mm), fine square around the notch tip:
  # its size (6 vs 10 l_f) must not matter, then h and du.
  # At this l_f the crack turns unstable before the force has a smooth
  # maximum: the peak is the limit point where monolithic Newton stops.
  # Steps are halved down to 3.125e-4 (dt/64 at dt = 0.02) to bracket it
  # (the report gives the bracket: last converged and first failed load).
  end=${END:-0.7}
  export DTMIN=3.125e-4
  run 2 1 monolithic gmres-amg 0.02 6
  # h = l_f/2 with GMRES: ~200 GMRES iterations per Newton step, stopped
  # at t = 0.45 (before its limit point) after 5300 s; redone with MUMPS
  # (faster at this size on a one-element slab) and dt = 0.05: with eta_f
  # = 0 the pre-peak path does not depend on the step (checked at h = l_f
  # by dt = 0.05 against 0.02) and the bisection brackets the limit point.
  run 2 2 monolithic gmres-amg 0.02 6
  run 2 2 monolithic direct 0.05 6
  run 2 1 monolithic direct 0.05 6
  run 2 1 monolithic direct 0.05 10
  run 2 1 monolithic gmres-amg 0.01 6
  /usr/bin/python3 "$here/report.py" "$here" "$lf_mm"
  exit 0
fi

dt=0.02
# Every method at h = l_f (Q2); the monolithic ones also at h = l_f / 2 (Q2)
# and h = l_f (Q3). Staggered runs cost 6-12x more and are not repeated on
# the finer meshes; the accelerated staggered scheme runs once (direct).
for solver in gmres-amg direct; do
  for strategy in monolithic staggered; do run 2 1 "$strategy" "$solver" "$dt"; done
  run 2 2 monolithic "$solver" "$dt"
done
run 3 1 monolithic gmres-amg "$dt"
# Staggered with Anderson acceleration of the phase field (depth 5).
run 2 1 staggered_anderson5 direct "$dt"
# Reference (finest mesh), then the load step at h = l_f (the time
# discretisation error does not depend on h to leading order).
run 2 4 monolithic gmres-amg "$dt"
for d in 0.04 0.01 0.005; do run 2 1 monolithic gmres-amg "$d"; done
# The s block by a sparse LU inside the block preconditioner: GMRES
# iterations no longer grow with l_f/h through the C0IP s block.
for ratio in 1 2 4; do run 2 "$ratio" monolithic gmres-amg-slu "$dt"; done

/usr/bin/python3 "$here/report.py" "$here" "$lf_mm"
