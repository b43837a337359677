#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job on 2 MPI ranks.
# Usage: scripts/run.sh [FILE.prm]   (default: prm/box_compression.prm); results go to results/
set -euo pipefail
source "$(dirname "$0")/env.sh"
"$project_root/scripts/install-deps.sh"
"$project_root/scripts/build.sh"
prm=${1:-$project_root/prm/box_compression.prm}
cd "$project_root"
mpirun -np ${NP:-2} "$build_dir/ductile-contact" "$prm"
