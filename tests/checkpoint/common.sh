# Shared by the checkpoint scripts (source it after setting mpiexec and exe):
# MPI as root and on 3 ranks over 2 cores (ranks that wait yield the core
# instead of polling), fail MESSAGE, and run NP PRM [--resume] with its
# screen output in PRM.log.
if [[ $(id -u) -eq 0 ]]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
export OMPI_MCA_btl_vader_single_copy_mechanism=none OPENBLAS_NUM_THREADS=1
export OMPI_MCA_mpi_yield_when_idle=1
fail() { echo "FAIL: $*"; exit 1; }
run() { # NP PRM [--resume]; screen output in PRM.log
  local np=$1 prm=$2 start=$SECONDS code
  shift 2
  "$mpiexec" --oversubscribe -np "$np" "$exe" "$@" "$prm" > "${prm%.prm}.log" 2>&1
  code=$?
  echo "$prm $* on $np rank(s): exit code $code, $((SECONDS - start)) s"
  return $code
}
