#!/usr/bin/env bash
# 10^6 cells of the S. Matteo free spectrum (omega_p/p in [1,10] x a_p0/(alpha g) in [1,10],
# 1000 x 1000) on 2 ranks: wall time and agreement with a tight reference (steps per period
# 512, every cell). Run from the repository root on an idle machine:  benchmarks/million.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep
grid=(--config configs/smatteo.toml --anchorages free --omega-ratio-range 1 10 --amplitude-ratio-range 1 10
      --omega-ratio-points 1000 --amplitude-ratio-points 1000 --quiet --overwrite)
ref="$out/million_ref.h5"
if [ ! -f "$ref" ]; then
  echo "reference (steps per period 512, every cell): $(wall "${mpi[@]}" -np 2 build/rocksweep sweep "${grid[@]}" --steps-per-period 512 -o "$ref") s"
fi
for args in "--refine 32" "--refine 32 --steps-per-period 32" "--refine 64" ""; do
  f="$out/million_try.h5"
  t=$(wall "${mpi[@]}" -np 2 build/rocksweep sweep "${grid[@]}" $args -o "$f")
  echo "== default accuracy ${args:-(every cell)}: $t s wall on 2 ranks"
  /usr/bin/python3 benchmarks/compare_outcomes.py "$ref" "$f" | tail -2
done
