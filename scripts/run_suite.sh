#!/usr/bin/env bash
# The S. Matteo block under the shared record suite (configs/suite_smatteo.toml: free /
# constant theta_f = alpha / adaptive K_min = 0.1 K_max, PGA 0.05-1.5 g, R = 0.39-3.89 m), on 2
# MPI ranks, and its three products (docs/suite.md):
#   results/suite.h5                                      the runs, spectra and fragility fits
#   results/suite_{overturning,ida,fragility}.png|pdf     the figures, the PNGs also in docs/figures/
# and the same block's size at five slendernesses (configs/suite_slenderness.toml):
#   results/suite_slenderness.h5, results/suite_slenderness_overturning.png|pdf (against alpha,
#   also docs/figures/suite_slenderness.png)
# and the same block on the floors of a building and on a plinth (configs/suite_floors.toml):
#   results/suite_floors.h5, results/suite_floors.png|pdf (plot_floors.py; also docs/figures/suite_floors.png)
# Extra arguments go to rocksweep suite.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_targets=(rocksweep)  # only what this script runs: the tests are test.sh's
source "$here/scripts/setup.sh"
mkdir -p "$here/docs/figures"
cd "$here"  # the config names its suite relative to the repository root
mpirun "${mpi_run[@]}" "$rs" suite --config configs/suite_smatteo.toml -o "$res/suite.h5" --overwrite "$@"
$py scripts/plot_suite.py "$res/suite.h5" -o "$res/suite"
for product in overturning ida fragility; do
  cp "$res/suite_$product.png" "docs/figures/suite_$product.png"
done
mpirun "${mpi_run[@]}" "$rs" suite --config configs/suite_slenderness.toml -o "$res/suite_slenderness.h5" --overwrite "$@"
$py scripts/plot_suite.py "$res/suite_slenderness.h5" -o "$res/suite_slenderness"
cp "$res/suite_slenderness_overturning.png" docs/figures/suite_slenderness.png
mpirun "${mpi_run[@]}" "$rs" suite --config configs/suite_floors.toml -o "$res/suite_floors.h5" --overwrite "$@"
$py scripts/plot_floors.py "$res/suite_floors.h5" -o "$res/suite_floors"
cp "$res/suite_floors.png" docs/figures/suite_floors.png
echo "suite: $res/suite.h5, $res/suite_{overturning,ida,fragility}.png; $res/suite_slenderness.h5, $res/suite_slenderness_overturning.png"
