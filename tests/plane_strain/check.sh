#!/usr/bin/env bash
# Usage: check.sh MPIEXEC NP PROGRAM NAME
#
# Runs tests/plane_strain/NAME.prm (Dimension = 2) and NAME_slab.prm (the
# same scene as a 3-D slab with u_z = 0 on both faces; for a plane-stress
# NAME.prm a slab whose stress state has P_33 = 0) with PROGRAM, the
# 3-D program, which hands the 2-D input to its plane-strain build. Passes
# when both finish, every statistics column agrees
# (compare_plane_strain.py), and the printed quantities of interest are
# those of NAME.output (5 significant digits).
set -euo pipefail
mpiexec=$1 np=$2 program=$3 name=$4
here=$(cd "$(dirname "$0")" && pwd)
if [ "$(id -u)" = 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
work=${name}.np${np}
rm -rf "$work" && mkdir -p "$work" && cd "$work"
for scene in "$name" "${name}_slab"; do
  if ! "$mpiexec" -np "$np" "$program" --set "Output/Directory = $scene" \
      "$here/$scene.prm" > "$scene.screen" 2>&1; then
    echo "FAIL: $scene.prm did not finish:"
    tail -20 "$scene.screen"
    exit 1
  fi
done
qois=$(sed -n 's/^# QOI: //p' "$here/$name.prm")
thickness=$(sed -n 's/^# SLAB THICKNESS: //p' "$here/$name.prm")
python3 "$here/compare_plane_strain.py" "${name}_slab/statistics" \
  "$name/statistics" "$thickness" $qois > output
cat output
diff -u "$here/$name.output" output
