#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest.
# Fails (non-zero exit) when any test fails.
set -euo pipefail
source "$(dirname "$0")/env.sh"
"$project_root/scripts/install-deps.sh"
"$project_root/scripts/build.sh"
cd "$build_dir"
# Build the test programs first: make knows that a test run on 1 and on 2
# ranks share one program, ctest would build it twice at once (a race on
# the object file).
targets=$(make help | sed -n 's/^\.\.\. \(tests\.[A-Za-z0-9_]*\.release\)$/\1/p')
echo "building $(echo $targets | wc -w) test programs"
make -j"$(nproc)" $targets > /dev/null
ctest --output-on-failure -j"$(nproc)" "$@"
