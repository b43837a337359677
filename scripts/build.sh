#!/usr/bin/env bash
# Configures (Release) and builds ductile-contact into build/ (override with BUILD_DIR).
set -euo pipefail
source "$(dirname "$0")/env.sh"
cmake -S "$project_root" -B "$build_dir" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} >/dev/null
cmake --build "$build_dir" -- -j"$jobs"
