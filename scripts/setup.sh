#!/usr/bin/env bash
# Installs the Debian packages rocksweep needs (only those missing) and builds Release into
# build/. Sourced by run.sh and test.sh; a script that sources it may first list more packages
# in `extra_packages` (test.sh: the tools the tests read the files with) and the targets it
# needs in `build_targets` (run.sh: only `rocksweep`; unset: everything, tests and benchmarks).
# Both configure build/ with the same options, so run.sh then test.sh (or the reverse) reuses
# what the first one compiled instead of reconfiguring it. With ccache installed, compilers go
# through it: a rebuild after `rm -rf build` or in another checkout takes seconds.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
packages=(build-essential cmake libopenmpi-dev openmpi-bin libhdf5-dev hdf5-tools
          libcli11-dev libeigen3-dev libgtest-dev python3-h5py python3-numpy python3-matplotlib
          ${extra_packages[@]+"${extra_packages[@]}"})
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
jobs="$(nproc 2>/dev/null || echo 2)"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release ${launcher[@]+"${launcher[@]}"} >/dev/null
targets=()
for t in ${build_targets[@]+"${build_targets[@]}"}; do targets+=(--target "$t"); done
cmake --build "$here/build" -j "$jobs" ${targets[@]+"${targets[@]}"}
# What the run scripts start their 2-rank jobs with: mpirun "${mpi_run[@]}" ...
mpi_run=(-np 2 --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi_run+=(--allow-run-as-root)
res="$here/results" rs="$here/build/rocksweep" py=/usr/bin/python3
mkdir -p "$res"
