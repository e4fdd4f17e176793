#!/usr/bin/env bash
# Distributed-sweep figures: parallel efficiency at 1 and 2 ranks, the master's dispatch
# capacity, memory per rank for a 10^6-cell sweep. Run from the repository root on an
# otherwise idle machine:  benchmarks/scaling.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep bench_dispatch
rs=build/rocksweep

echo "== parallel efficiency: configs/smatteo.toml at 451 x 331 (7 scenarios, 1 044 967 cells)"
grid=(--config configs/smatteo.toml --omega-ratio-points 451 --amplitude-ratio-points 331 --quiet --overwrite)
t1=$(wall "$rs" sweep "${grid[@]}" -o "$out/eff1.h5")
t2=$(wall "${mpi[@]}" -np 2 "$rs" sweep "${grid[@]}" -o "$out/eff2.h5")
h5diff --exclude-path /provenance "$out/eff1.h5" "$out/eff2.h5" >/dev/null && same=identical || same=DIFFERENT
echo "1 rank: $t1 s   2 ranks: $t2 s   efficiency: $(echo "$t1 / (2 * $t2) * 100" | bc -l | cut -c1-5) %   results $same"
echo "cells/s: 1 rank $(echo "1044967 / $t1" | bc) , 2 ranks $(echo "1044967 / $t2" | bc)"

echo "== dispatch capacity (trivial work, oversubscribed ranks)"
for n in 2 4 8; do "${mpi[@]}" -np "$n" build/benchmarks/bench_dispatch --chunks 100000 | tail -1; done

echo "== memory per rank: 10^6-cell sweep (free, 1000 x 1000), 2 ranks"
"${mpi[@]}" -np 2 /usr/bin/time -f "rank max RSS %M KiB, %e s" "$rs" sweep --config configs/smatteo.toml \
  --anchorages free --omega-ratio-range 1 10 --amplitude-ratio-range 1 10 --omega-ratio-points 1000 \
  --amplitude-ratio-points 1000 --quiet --overwrite -o "$out/mem.h5" 2>&1 | grep "max RSS"
ls -l "$out/mem.h5" | awk '{print "output file: " $5 " bytes"}'
