#!/usr/bin/env bash
# Usage: expect_give_up.sh MPIEXEC NP EXECUTABLE (run in a scratch folder)
# Passes when give_up.prm ends with exit code 2, says why once, and leaves
# readable results behind.
set -u
mpiexec=$1 np=$2 exe=$3
here=$(cd "$(dirname "$0")" && pwd)
if [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
rm -rf give_up_results
out=$("$mpiexec" -np "$np" "$exe" "$here/give_up.prm" 2>&1)
code=$?
echo "$out"
fail() { echo "FAIL: $*"; exit 1; }
[[ $code -eq 2 ]] || fail "exit code $code, expected 2"
[[ $(grep -c "Minimum time step' = 0.5" <<<"$out") -eq 1 ]] || fail "no single give-up message"
grep -q "step 1 at t = 1 failed" <<<"$out" || fail "the failed step is not reported"
[[ -s give_up_results/statistics ]] || fail "statistics missing"
head -n 1 give_up_results/statistics | grep -q "F5_z" || fail "statistics header missing"
[[ $(wc -l < give_up_results/statistics) -eq 2 ]] || fail "statistics must hold the header and step 0"
grep -q "Minimum time step" give_up_results/log.txt || fail "log.txt lacks the message"
[[ -s give_up_results/solution_00000.pvtu && -s give_up_results/solution.pvd ]] || fail "step-0 output missing"
echo PASS
