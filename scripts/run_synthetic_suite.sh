#!/usr/bin/env bash
# run_synthetic_suite.sh [COUNT] [NP]: S. Matteo (configs/suite_smatteo.toml: free, constant
# theta_f = alpha, adaptive K_min = 0.1 K_max, 30 PGA levels) at its own size over COUNT motions
# of the model fitted to each of the eleven shared records, made on the NP ranks and never
# written (suite --synthetic-per-record COUNT --synthetic-only, seed 1; docs/synthetic.md): the
# README's synthetic fragility. The site is configs/records_suite.csv without the Mexico City E-W
# component (one component a record, the N-S as before). Writes results/synthetic_site.csv and
# results/suite_synthetic_pooled.h5.
set -eu
count="${1:-100}"; np="${2:-2}"
cd "$(dirname "$0")/.."
mkdir -p results
site=results/synthetic_site.csv  # beside configs/, so that its ../tests/data paths still hold
grep -v '^mexico_city_1985_sct_ew,' configs/records_suite.csv > "$site"
mpi=(); [ "$np" -gt 1 ] && mpi=(mpirun --oversubscribe -np "$np")
[ "$np" -gt 1 ] && [ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
"${mpi[@]}" build/rocksweep suite --config configs/suite_smatteo.toml --suite "$site" --synthetic-per-record "$count" \
  --synthetic-only --seed 1 --radius-points 1 --radius-range 1.392695228684288 1.392695228684288 --overwrite \
  -o results/suite_synthetic_pooled.h5
