#!/usr/bin/env bash
# Installs the Debian packages ductile-contact needs, skipping those already present.
# Works as root, or as a normal user through sudo. Usage: scripts/install-deps.sh [--plots]
#   --plots  also installs python3-matplotlib, time, python3-vtk9, python3-h5py
#            and xvfb (the main job's plots and 3-D pictures of vtu or HDF5
#            output, the benchmarks)
set -euo pipefail

# libmumps-ptscotch-dev: MUMPS with PT-Scotch, its parallel analysis
# (Linear solver/Ordering = pt-scotch); libmumps-dev's headers.
packages=(cmake make g++ libdeal.ii-dev libmumps-dev libmumps-ptscotch-dev
          libmetis-dev openmpi-bin numdiff libopenblas0-pthread python3)
if [[ "${1:-}" == "--plots" ]]; then
  packages+=(python3-matplotlib time python3-vtk9 python3-h5py xvfb xauth)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "-- all required Debian packages are installed"
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "error: not root and sudo is missing; install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

echo "-- installing: ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -q
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
