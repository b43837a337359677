#!/usr/bin/env bash
# Usage: expect_warning.sh MPIEXEC NP EXECUTABLE FILE.prm
# Passes when `EXECUTABLE --validate FILE.prm` on NP ranks accepts the file
# (exit code 0) and prints exactly as many lines starting with "Warning:" as
# the second line of FILE.prm says ("# warnings: N"), each matching the
# regular expression on its first line ("# expect: REGEX"): a warning is
# printed once (rank 0), and a file that needs none gets none.
set -u
mpiexec=$1 np=$2 exe=$3 prm=$4
if [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
expect=$(sed -n '1s/^# expect: //p' "$prm")
count=$(sed -n '2s/^# warnings: //p' "$prm")
[[ -n "$expect" && -n "$count" ]] ||
  { echo "FAIL: $prm needs '# expect:' and '# warnings:' first lines"; exit 1; }

out=$("$mpiexec" -np "$np" "$exe" --validate "$prm" 2>&1)
code=$?
echo "$out"
[[ $code -eq 0 ]] || { echo "FAIL: exit code $code, expected 0"; exit 1; }
n=$(grep -c "^Warning:" <<<"$out")
[[ $n -eq $count ]] || { echo "FAIL: $n warnings, expected $count"; exit 1; }
m=$(grep "^Warning:" <<<"$out" | grep -c -E -- "$expect")
[[ $m -eq $count ]] || { echo "FAIL: $((count - m)) warnings do not match '$expect'"; exit 1; }
echo "PASS"
