# Sourced by the other scripts: common settings.
# mpirun refuses to run as root unless told; only set this when we really are root.
if [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
# One OpenBLAS thread per MPI rank: the ranks already use the cores.
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
# Parallel make and ctest jobs: all cores (plain `nproc` obeys OMP_NUM_THREADS
# and would say 1).
jobs=$(nproc --all)
# Open MPI binds each rank to a core, counting from core 0 in every mpirun: two
# 1-rank runs at once (benchmarks with -j 2, a run beside a test) then share
# core 0 and leave core 1 idle. Let the scheduler place the ranks.
export OMPI_MCA_hwloc_base_binding_policy=none
# A run that ends with a non-zero exit code (bad input, a run that gives up)
# has written its output; mpirun need not wait 2 s before it returns.
export OMPI_MCA_odls_base_sigkill_timeout=0
# Open MPI in containers: avoid probing for fast interconnects that are not there.
export OMPI_MCA_btl_vader_single_copy_mechanism=none
project_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$project_root/build}
# The application; benchmark scripts call require_build before running it.
# Installed (cmake --install), the scripts live in PREFIX/share/ductile-contact
# and the program in PREFIX/bin.
exe="$build_dir/ductile-contact"
if [[ -z ${BUILD_DIR:-} && ! -x $exe && -x $project_root/../../bin/ductile-contact ]]; then
  exe=$(cd "$project_root/../../bin" && pwd)/ductile-contact
fi
require_build() {
  [[ -x "$exe" ]] || { echo "build first: scripts/build.sh" >&2; exit 1; }
}
# Benchmark runs: DIR/scene.prm on NP ranks, screen output in DIR/screen.txt.
# run_finished DIR: the run in DIR ended with its timer table (not redone).
run_finished() {
  [[ -f "$1/statistics" ]] && grep -q "Total wallclock" "$1/screen.txt" 2>/dev/null
}
# run_scene NP DIR: runs it; a run that stops early is reported, not fatal.
run_scene() {
  mpirun -np "$1" "$exe" "$2/scene.prm" > "$2/screen.txt" 2>&1 ||
    echo "   stopped early, see $2/screen.txt"
}
# mesh_override SRC: for a scene file SRC with a relative Mesh/Gmsh/File name
# (relative to SRC's folder), the subsection that sets it again as an absolute
# path, for copies of SRC in other folders (nothing if there is none).
mesh_override() {
  local mesh
  mesh=$(sed -n 's/^[[:space:]]*set File name[[:space:]]*=[[:space:]]*\([^#[:space:]]*\).*/\1/p' "$1" | tail -1)
  if [[ -n $mesh && $mesh != /* ]]; then
    printf 'subsection Mesh\n  subsection Gmsh\n    set File name = %s\n  end\nend\n' \
      "$(cd "$(dirname "$1")" && pwd)/$mesh"
  fi
}
# copy_scene SRC DST: a copy of the scene file SRC at DST that reads the same
# mesh; the copy starts with SRC's text.
copy_scene() {
  cp "$1" "$2"
  mesh_override "$1" >> "$2"
}
