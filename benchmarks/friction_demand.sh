#!/usr/bin/env bash
# The friction demand (mu_required) over the shared suite (configs/suite_smatteo.toml, 8 640
# cells) at the sweep default and with --record-steps cross, against 2 048 steps per period:
# how far the demand taken between steps is from the one taken densely (docs/physics_kernel.md,
# "a record is not smooth at its samples"). About 20 s on 2 ranks.
#   benchmarks/friction_demand.sh [BUILD]   (BUILD: a build folder, default build/)
#                                            -> benchmarks/results/friction_demand.txt
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep
rs="${1:-build}/rocksweep"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
suite() { "${mpi[@]}" -np 2 "$rs" suite --config configs/suite_smatteo.toml --overwrite --quiet -o "$@"; }
suite "$tmp/reference.h5" --steps-per-period 2048
suite "$tmp/default.h5"
suite "$tmp/cross.h5" --record-steps cross
{
  echo "benchmarks/friction_demand.sh $rs, $(date -u '+%Y-%m-%d %H:%M UTC'), rocksweep $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  /usr/bin/python3 benchmarks/friction_demand.py "$tmp/reference.h5" "$tmp/default.h5" "$tmp/cross.h5"
} | tee "$out/friction_demand.txt"
