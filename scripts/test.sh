#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest.
# Fails (non-zero exit) when any test fails.
set -euo pipefail
source "$(dirname "$0")/env.sh"
"$project_root/scripts/install-deps.sh"
"$project_root/scripts/build.sh"
cd "$build_dir"
# Build the test programs first, in parallel, so that ctest's time is the
# tests' (the harness still relinks a program before each of its runs; the
# 1-, 2- and 3-rank runs of one program share a RESOURCE_LOCK for that,
# tests/CMakeLists.txt).
make -j"$jobs" test_programs > /dev/null
ctest --output-on-failure -j"$jobs" "$@"
