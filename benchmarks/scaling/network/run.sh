#!/usr/bin/env bash
# The latency and bandwidth of one MPI message and the time of a small
# all-reduce between 2 ranks of this machine (pingpong.c, built here with
# mpicc): the constants a, b and a_ar of ../projection.py. Run on the quiet
# machine (about 15 s). Writes results.md: the raw lines of pingpong, the
# fitted a and 1/b, the date and the MPI library.
# Usage: benchmarks/scaling/network/run.sh
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
source "$here/../../../scripts/env.sh"
mkdir -p "$here/runs"
mpicc -O2 -o "$here/runs/pingpong" "$here/pingpong.c"
raw=$(mpirun -np 2 "$here/runs/pingpong")
{
  echo "# MPI latency and bandwidth between 2 ranks of this machine"
  echo
  echo "From \`run.sh\` on $(date -u +%Y-%m-%d), $(mpirun --version | head -1), $(nproc --all) cores"
  echo "(shared memory: both ranks on one node). Half round trips of a ping-pong (fastest of 5"
  echo "batches of ~0.2 s) and the mean time of an all-reduce of 8 B and 8 kB:"
  echo
  echo '```'
  echo "$raw"
  echo '```'
  echo
  echo "$raw" | awk '
    $1 == "p2p" && $2 <= 512 { if (a == "" || $3 < a) a = $3 }
    $1 == "p2p" && $2 >= 1048576 { n += $2; t[$2] = $3 }
    END {
      s = 0; for (k in t) s += t[k] - a;
      printf "Fitted: a = %.3g us (the smallest time of 8 ... 512 B), 1/b = %.3g GB/s (the sizes of 1 MiB and more).\n", a * 1e6, n / s / 1e9
    }'
} > "$here/results.md"
cat "$here/results.md"
