#!/usr/bin/env bash
# Run time against error of the C0IP crack operator (manufactured solution
# and crack-energy strip), Q2/Q3, direct and AMG, on 1 rank. Writes
# results.txt. About 5 minutes.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
cmake --build "$build_dir" --target phase_field_operator -- -j"$jobs" >/dev/null
"$build_dir/phase_field_operator" | tee "$here/results.txt"
/usr/bin/python3 "$here/plot.py"
