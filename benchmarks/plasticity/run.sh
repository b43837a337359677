#!/usr/bin/env bash
# Cost per quadrature point of the material updates; writes results.txt.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
cmake --build "$build_dir" --target plasticity_material_point -- -j"$jobs" >/dev/null
"$build_dir/plasticity_material_point" | tee "$here/results.txt"
