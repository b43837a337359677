#!/usr/bin/env bash
# The undershoot of alpha below 0 next to the hinge under mesh refinement:
# prm/block_on_plate.prm (the paper's scene) pressed to 9.6 mm (t = 64,
# steps of 0.6 mm) on three meshes, plate 8 x 5 x 1, 16 x 10 x 2 and
# 24 x 15 x 3 Q2 cells (block 2, 4, 6 per edge): h, h/2, h/3, with the
# pointwise switch (runs h1 ... h3), and with Plasticity/Loading condition =
# bound, alpha in the Lagrange basis (h1_bound ...) and in the Bernstein
# basis (h1_bound_bernstein ...; doc/model.md section 3.2). The smallest
# alpha at a quadrature point (min_alpha) against the largest (max_alpha),
# the plastic dissipation D_p and the smallest local one.
# Usage: benchmarks/paper_scene/alpha_undershoot/run.sh [NP] (default 2
# ranks; about 8 min in all). Finished runs are skipped.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
np=${1:-2}
require_build

for variant in "" "_bound" "_bound_bernstein"; do
  options=()
  case "$variant" in
    _bound) options=(--set "Body 0/Plasticity/Loading condition = bound") ;;
    _bound_bernstein)
      options=(--set "Body 0/Plasticity/Loading condition = bound"
               --set "Finite elements/Hardening basis = Bernstein") ;;
  esac
  for mesh in "h1:8, 5, 1:2, 2, 2" "h2:16, 10, 2:4, 4, 4" "h3:24, 15, 3:6, 6, 6"; do
    IFS=: read -r name plate block <<< "$mesh"
    dir="$here/runs/$name$variant"
    if run_finished "$dir"; then
      echo "== $name$variant (done)"
      continue
    fi
    mkdir -p "$dir"
    mpirun -np "$np" "$exe" "$project_root/prm/block_on_plate.prm" \
      --set "Mesh/Two bodies/Plate subdivisions = $plate" \
      --set "Mesh/Two bodies/Block subdivisions = $block" \
      --set "Load stepping/Time step = 4" --set "Load stepping/End time = 64" \
      --set "Output/Directory = $dir" --set "Output/Interval = 0" \
      "${options[@]}" \
      > "$dir/screen.txt" 2>&1 || echo "   stopped early, see $dir/screen.txt"
  done
done
for variant in "" "_bound" "_bound_bernstein"; do
  for name in h1 h2 h3; do
    /usr/bin/python3 - "$here/runs/$name$variant/statistics" "$name$variant" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip() and not l.startswith('#')]
h = rows[0]; d = [list(map(float, r)) for r in rows[1:]]
col = lambda k: [r[h.index(k)] for r in d]
lo, hi = min(col('min_alpha')), max(col('max_alpha'))
print(f"{sys.argv[2]}: min_alpha {lo:.4g}, max_alpha {hi:.4g} ({-100 * lo / hi:.2f} %), "
      f"D_p {col('plastic_dissipation')[-1]:.4g} J of W_p {col('plastic_work')[-1]:.4g} J, "
      f"smallest local D_p {min(col('min_plastic_dissipation')):.3g} J/m^3, "
      f"end force {col('F2_z')[-1]:.6g} N")
PY
  done
done
