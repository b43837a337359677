#!/usr/bin/env bash
# Usage: expect_faults.sh MPIEXEC NP EXECUTABLE (run in a scratch folder)
# Numerical faults are caught where they happen and
# named; the step is cut back; when the fault persists down to the minimum
# step the run stops with exit code 2 and readable results:
#  - inverted.prm: an inverted element (J <= 0), named with J, the cell's
#    position and the body;
#  - nan_displacement.prm: a prescribed displacement that is NaN, named
#    with the boundary condition and the time;
#  - nan_traction.prm: a residual that is not finite (a NaN traction),
#    named with the cell's position and the body;
#  - linear_failure.prm: a failed linear solve (GMRES limited to one
#    iteration), named with the iterations and the residual reached;
#  - stall.prm: a box pushed flat with a minimum step of 1e-12: failed
#    steps alternate with ever smaller accepted ones; the run gives up
#    after 20 failures within 1e-3 of t (Maximum failures without
#    progress) instead of creeping towards t = 0.5 for ever.
# (A linear solve that returns NaN or Inf is also caught, "the linear solve
# returned an update that is not finite"; no input provokes it reliably.)
set -u
mpiexec=$1 np=$2 exe=$3
here=$(cd "$(dirname "$0")" && pwd)
if [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
fail() { echo "FAIL: $*"; exit 1; }
expect() { # NAME "MESSAGE" ...: exit code 2, each message, results readable
  local name=$1
  shift
  rm -rf "${name}_results"
  local out code
  out=$("$mpiexec" -np "$np" "$exe" "$here/$name.prm" 2>&1)
  code=$?
  echo "$out" | grep "failed\|Error"
  [[ $code -eq 2 ]] || fail "$name: exit code $code, expected 2"
  for message in "$@"; do
    grep -qF -- "$message" <<< "$out" || fail "$name: no '$message'"
  done
  [[ $(grep -c -E "Minimum time step|Maximum failures without progress" \
    <<< "$out") -eq 1 ]] ||
    fail "$name: no single give-up message"
  head -n 1 "${name}_results/statistics" | grep -q "F5_z" ||
    fail "$name: statistics unreadable"
  python3 - "${name}_results/statistics" <<'EOT' ||
import math, sys
rows = [line.split() for line in open(sys.argv[1]) if line.strip()]
sys.exit(any(not math.isfinite(float(v)) for row in rows[1:]
             for v in row))
EOT
    fail "$name: NaN or Inf in the statistics"
  return 0
}
expect inverted "step 1 at t = 1 failed" "an element inverts (J = -" \
  "in the cell at (0.5 0.5 0.5) m of body 0 'body'"
expect nan_displacement "step 4 at t = 0.4 failed" \
  "the prescribed displacement of 'Boundary 5' is NaN at t = 0.4)"
expect nan_traction "step 4 at t = 0.4 failed" \
  "the residual is not finite (NaN or Inf) in the cell at (0.5 0.5 0.5) m of body 0 'body'"
expect linear_failure "step 1 at t = 1 failed" \
  "the iterative linear solver did not converge in 1 iterations (residual"
expect stall "Error: the load stepping stalls: 20 failed steps since t = 0.49" \
  "an element inverts (J = -"
echo PASS
