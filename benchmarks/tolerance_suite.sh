#!/usr/bin/env bash
# The issue-22 suite (configs/suite_smatteo.toml on 4 radii 0.3-0.6 m and 27 PGA levels 0.2-1.5 g:
# 3 888 runs) at several --tolerance values and at the old fixed default (--tolerance 0, 48 steps
# per period), each against a reference at a tolerance 1000x tighter (1e-11) with the same impact
# threshold. Runs where the reference rerun with the record scale perturbed by a relative 1e-9
# (every level x (1 + 1e-9)) differs in outcome or by more than 1e-3 in theta_max / alpha are
# sensitive (ill-conditioned) and counted apart. About 40 s. The cost: benchmarks/suite_peers.sh.
#   benchmarks/tolerance_suite.sh       -> benchmarks/results/tolerance_suite.txt
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
suite() {
  build/rocksweep suite --config configs/suite_smatteo.toml --radius-range 0.3 0.6 --radius-points 4 \
    --intensity-points 27 --quiet --overwrite "$@"
}
suite --intensity-range 0.2 1.5 --tolerance 1e-11 -o "$tmp/reference.h5"
suite --intensity-range 0.2000000002 1.5000000015 --tolerance 1e-11 -o "$tmp/perturbed.h5"
settings=("0" 1e-6 1e-7 1e-8 1e-9)
for t in "${settings[@]}"; do
  suite --intensity-range 0.2 1.5 --tolerance "$t" -o "$tmp/t$t.h5"
done
{
  echo "benchmarks/tolerance_suite.sh, $(date -u '+%Y-%m-%d %H:%M UTC'), rocksweep $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  for t in "${settings[@]}"; do
    echo "--tolerance $t$([ "$t" = 0 ] && echo ' (48 fixed steps per period, the default before issue 22)'):"
    /usr/bin/python3 benchmarks/tolerance_suite.py "$tmp/t$t.h5" "$tmp/reference.h5" "$tmp/perturbed.h5"
  done
} | tee "$out/tolerance_suite.txt"
