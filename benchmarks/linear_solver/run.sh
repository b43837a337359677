#!/usr/bin/env bash
# The linear solvers side by side on the first steps of shipped scenes
# (19.8k, 34k and 126k unknowns), 2 MPI ranks: each variant below is a set
# of `Linear solver` entries appended to the scene. report.py writes
# results.md (time per Newton iteration in the linear solve, Newton and
# linear iterations, and the scene's last force, which must not change).
# Usage: benchmarks/linear_solver/run.sh [SCENE...]   (default: all below)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../scripts/env.sh"
root=$project_root

# scene : end time (its first steps)
declare -A end_time=([box_compression]=1 [two_bodies]=8 [sent_coarse]=0.1
                     [ductile_notch]=0.2 [hertz_sphere]=0.25)
# variant : Linear solver entries (';' separates lines)
variants=(
  "amesos-mumps:Type = direct;Direct solver = Amesos_Mumps"
  "amesos-klu:Type = direct;Direct solver = Amesos_Klu"
  "mumps-pord:Type = direct;Direct solver = mumps;Ordering = pord"
  "mumps-metis:Type = direct;Direct solver = mumps;Ordering = metis"
  "mumps-metis-ldlt:Type = direct;Direct solver = mumps;Factorisation = ldlt"
  "mumps-metis-reuse:Type = direct;Direct solver = mumps;Factorisation reuse = 60"
  "mumps-metis-single:Type = direct;Direct solver = mumps;Factorisation precision = single"
  "gmres-amg:Type = gmres-amg"
)
scenes=("$@")
((${#scenes[@]})) || scenes=(box_compression two_bodies sent_coarse ductile_notch hertz_sphere)

for scene in "${scenes[@]}"; do
  for entry in "${variants[@]}"; do
    variant=${entry%%:*}
    settings=${entry#*:}
    # LDL^T only where the tangent is symmetric (elastic, no contact).
    if [[ $variant == *ldlt* && $scene != box_compression ]]; then continue; fi
    # KLU factorises on one rank: 20 s per solve at 34k unknowns already
    # (sent_coarse); not run on the larger ductile_notch and hertz_sphere.
    if [[ $variant == amesos-klu && ( $scene == hertz_sphere ||
          $scene == ductile_notch ) ]]; then continue; fi
    out=$here/runs/$scene/$variant
    rm -rf "$out"
    mkdir -p "$out"
    sed -e "s|^\( *set End time *=\).*|\1 ${end_time[$scene]}|" \
        "$root/prm/$scene.prm" > "$out/scene.prm"
    mesh_override "$root/prm/$scene.prm" >> "$out/scene.prm"
    printf 'subsection Output\n  set Directory = %s\n  set Interval = 0\nend\n' \
        "$out" >> "$out/scene.prm"
    { echo "subsection Linear solver"
      tr ';' '\n' <<< "$settings" | sed 's/^/  set /'
      echo "end"; } >> "$out/scene.prm"
    echo "== $scene $variant"
    (cd "$root" && /usr/bin/time -f "peak memory %M KB per rank" \
       mpirun -np 2 "$exe" "$out/scene.prm") > "$out/screen.txt" 2>&1 || \
      echo "   (failed: see $out/screen.txt)"
    tail -n 1 "$out/statistics" | cut -c1-100
  done
done
python3 "$here/report.py"
