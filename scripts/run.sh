#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job on 2 MPI ranks:
# the paper's scene, prm/block_on_plate.prm, or the scene given (run times:
# benchmarks/performance/run_times.md).
# Usage: scripts/run.sh [FILE.prm]     (NP=4 scripts/run.sh for 4 ranks)
# Leaves in the scene's Output/Directory (results/block_on_plate for the
# default): statistics, log.txt, solution.pvd (ParaView), plot.png (forces,
# energies, Newton iterations against time), force_displacement.png (the
# default scene: the force on the block's top against its displacement),
# and s.png and alpha.png: the crack phase field and the hardening variable
# on the deformed bodies after the last step.
set -euo pipefail
source "$(dirname "$0")/env.sh"
"$project_root/scripts/install-deps.sh" --plots
"$project_root/scripts/build.sh"
prm=${1:-$project_root/prm/block_on_plate.prm}
cd "$project_root"
mpirun -np "${NP:-2}" "$exe" "$prm"

# The results folder: Output/Directory of the scene as run.
results=$(sed -n 's/^ *set Directory *= *\(.*[^ ]\) *$/\1/p' "$prm" | tail -1)
results=${results:-results}
plots="$project_root/scripts"
"$plots/plot.py" "$results"
if [[ -z "${1:-}" ]]; then
  "$plots/plot.py" "$results" F2_z contact1_force_z --x u2_z --abs \
    --out "$results/force_displacement.png" \
    --title "block on plate: force on the block's top face"
fi
# The fields the scene has (s, alpha: its statistics report max_s,
# max_alpha), else the von Mises stress.
fields=()
for f in s alpha; do
  head -1 "$results/statistics" | grep -qw "max_$f" && fields+=("$f")
done
((${#fields[@]})) || fields=(von_mises_kirchhoff)
xvfb-run -a "$plots/render_fields.py" "$results" "${fields[@]}"
echo "-- results in $results"
