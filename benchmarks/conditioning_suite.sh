#!/usr/bin/env bash
# Why the default is off the reference on a few runs of the whole shared suite
# (configs/suite_smatteo.toml, 8 640 runs): the default (--tolerance 1e-8, with
# --check-sensitivity) against a reference at 1e-11 with the same impact threshold, a check at
# 1e-12, and the reference rerun with every level (so the record scale) times 1 +- 1e-9 ... 1e-6.
# A run is counted ill-conditioned at eps where one of those moves its reference's outcome or
# theta_max / alpha by more than 1e-3. One rank, about 2 min on the loaded 2-core machine.
#   benchmarks/conditioning_suite.sh    -> benchmarks/results/conditioning_suite.txt
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
suite() { build/rocksweep suite --config configs/suite_smatteo.toml --quiet --overwrite "$@"; }
suite --check-sensitivity -o "$tmp/default.h5"
suite --tolerance 1e-11 -o "$tmp/ref.h5"
suite --tolerance 1e-12 -o "$tmp/ref12.h5"
perturbed=()
for e in 1e-9 -1e-9 1e-8 -1e-8 1e-7 -1e-7 1e-6 -1e-6; do
  # the config's levels, 0.05-1.5 g, each times (1 + e)
  range=$(/usr/bin/python3 -c "print(repr(0.05 * (1 + $e)), repr(1.5 * (1 + $e)))")
  # shellcheck disable=SC2086  # two numbers
  suite --tolerance 1e-11 --intensity-range $range -o "$tmp/p$e.h5"
  perturbed+=("$e=$tmp/p$e.h5")
done
{
  echo "benchmarks/conditioning_suite.sh, $(date -u '+%Y-%m-%d %H:%M UTC'), rocksweep $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  /usr/bin/python3 benchmarks/conditioning_suite.py "$tmp/default.h5" "$tmp/ref.h5" "$tmp/ref12.h5" "${perturbed[@]}"
} | tee "$out/conditioning_suite.txt"
