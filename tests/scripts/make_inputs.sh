#!/usr/bin/env bash
# Inputs shared by the plotting tests (the `plot_inputs` fixture), small enough to take a
# second or two: a 20 x 20 sweep of all seven S. Matteo scenarios and of the free one alone,
# one over two parameter axes (phase, size), one on T_p x a_p0 axes over two sizes,
# the paper's sample case as HDF5 and CSV histories (and under the passive adaptive law), Housner's constant-pulse pair, and a
# 41 x 41 basin map of the seven scenarios.
# usage: make_inputs.sh ROCKSWEEP CONFIG DIR
set -euo pipefail
rs=$1 cfg=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
grid=(--omega-ratio-points 20 --amplitude-ratio-points 20 --quiet)
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$dir/spectra.h5"
"$rs" sweep --config "$cfg" "${grid[@]}" --scenario adaptive_rho0.5 -o "$dir/one.h5"
"$rs" sweep --config "$cfg" "${grid[@]}" --anchorages free constant --theta-f-ratios 1 \
  --axis phase_rad=0,1.5707963267948966 --axis radius_m=0.7,2.8 -o "$dir/axes.h5"
"$rs" sweep --config "$cfg" --quiet --anchorages constant --theta-f-ratios 1 --period-range 0.25 2.5 --period-points 20 \
  --pga-range 0.05 1.5 --pga-points 20 --axis radius_m=0.7,2.8 -o "$dir/physical.h5"
for a in free constant adaptive; do
  for ext in h5 csv; do
    "$rs" simulate --config "$cfg" --anchorage "$a" --kmin-ratio 0.5 --omega-ratio 4 --amplitude-ratio 2.7 \
      --t-end 8 -q -o "$dir/$a.$ext"
  done
done
# The adaptive case under the passive law: a run that differs from adaptive.h5 by --adaptive-law alone.
"$rs" simulate --config "$cfg" --anchorage adaptive --kmin-ratio 0.5 --adaptive-law passive --omega-ratio 4 \
  --amplitude-ratio 2.7 --t-end 8 -q -o "$dir/passive.h5"
for d in 0.6380 0.6300; do
  "$rs" simulate --config "$cfg" --pulse constant --amplitude-ratio 1.3 --duration "$d" \
    --equations linearised --t-end 6 -q -o "$dir/housner_$d.h5"
done
"$rs" basin --config "$cfg" --theta-ratio-points 41 --theta-dot-ratio-points 41 --quiet -o "$dir/basin.h5"
