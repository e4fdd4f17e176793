#!/usr/bin/env bash
# The default S. Matteo sweep, all seven scenarios, on 2 MPI ranks:
# writes results/smatteo.h5 and results/smatteo.png.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$here/scripts/setup.sh"
mkdir -p "$here/results"
mpi_flags=(-np 2)
[ "$(id -u)" -eq 0 ] && mpi_flags+=(--allow-run-as-root)
mpi_flags+=(--oversubscribe)
mpirun "${mpi_flags[@]}" "$here/build/rocksweep" sweep --config "$here/configs/smatteo.toml" \
  -o "$here/results/smatteo.h5" --overwrite "$@"
/usr/bin/python3 "$here/scripts/plot_spectra.py" "$here/results/smatteo.h5" "$here/results/smatteo.png"
echo "spectra: $here/results/smatteo.h5"
echo "plot:    $here/results/smatteo.png"
