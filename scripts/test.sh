#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest.
# Fails (non-zero exit) when any test fails.
set -euo pipefail
source "$(dirname "$0")/env.sh"
"$project_root/scripts/install-deps.sh"
"$project_root/scripts/build.sh"
cd "$build_dir"
ctest --output-on-failure -j"$(nproc)" "$@"
