#!/usr/bin/env bash
# The S. Matteo block under every pulse family of `sweep --pulse` (configs/pulse_*.toml, reduced
# grids, free / constant theta_f = alpha / adaptive K_min = 0.1 K_max), on 2 MPI ranks, and the
# overturning spectrum of each (pulse_one_sine_phase sweeps the phase psi as a third axis of the
# grid, one panel per psi; pulse_one_sine_sizes three block sizes on T_p [s] x a_p0 [g] axes):
#   results/pulse_<family>.h5          the spectra (extra arguments go to every sweep)
#   results/pulse_<family>.png|pdf     their overturning spectra, the PNGs also in docs/figures/
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_targets=(rocksweep)  # only what this script runs: the tests are test.sh's
source "$here/scripts/setup.sh"
mkdir -p "$here/docs/figures"
for family in one_sine one_sine_phase one_sine_sizes n_sine cycloidal_b cycloidal_c ricker rectangle; do
  out="$res/pulse_$family"
  mpirun "${mpi_run[@]}" "$rs" sweep --config "$here/configs/pulse_$family.toml" -o "$out.h5" --overwrite --quiet "$@"
  $py "$here/scripts/plot_spectra.py" "$out.h5" -o "$out"
  cp "$out.png" "$here/docs/figures/pulse_$family.png"
  echo "pulse $family: $out.h5, $out.png"
done
