# Sourced by the other scripts: common settings.
# mpirun refuses to run as root unless told; only set this when we really are root.
if [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
# One OpenBLAS thread per MPI rank: the ranks already use the cores.
export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
# Open MPI in containers: avoid probing for fast interconnects that are not there.
export OMPI_MCA_btl_vader_single_copy_mechanism=none
project_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$project_root/build}
# The application; benchmark scripts call require_build before running it.
exe="$build_dir/ductile-contact"
require_build() {
  [[ -x "$exe" ]] || { echo "build first: scripts/build.sh" >&2; exit 1; }
}
