#!/usr/bin/env bash
# Usage: expect_error.sh MPIEXEC NP EXECUTABLE FILE.prm
# Passes when `EXECUTABLE --validate FILE.prm` on NP ranks exits with code 1
# and prints, exactly once, a message matching the regular expression on the
# first line of FILE.prm ("# expect: REGEX").
set -u
mpiexec=$1 np=$2 exe=$3 prm=$4
if [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
expect=$(head -n 1 "$prm" | sed -n 's/^# expect: //p')
[[ -n "$expect" ]] || { echo "FAIL: $prm has no '# expect:' first line"; exit 1; }

out=$("$mpiexec" -np "$np" "$exe" --validate "$prm" 2>&1)
code=$?
echo "$out"
if [[ $code -ne 1 ]]; then
  echo "FAIL: exit code $code, expected 1"
  exit 1
fi
n=$(grep -c -E -- "$expect" <<<"$out")
if [[ $n -ne 1 ]]; then
  echo "FAIL: expected exactly one line matching '$expect', found $n"
  exit 1
fi
if grep -q -E "^(Message|Formula|Token|Position|Errc): " <<<"$out"; then
  echo "FAIL: a library's own report came before the message"
  exit 1
fi
if grep -q -E "Stacktrace|An error occurred in line|Aborting|signal" <<<"$out"; then
  echo "FAIL: the message must not be a crash report"
  exit 1
fi
echo "PASS"
