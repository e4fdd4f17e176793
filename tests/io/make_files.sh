#!/usr/bin/env bash
# Files the reader tests open (the `io_files` fixture), in DIR:
#   spectra.h5   the default sweep of configs/smatteo.toml (what scripts/run.sh computes)
#   line.h5      a 5 x 1 grid, free block only: a grid with a dimension of length 1
#   axes.h5      a grid over two parameter axes (sweep --axis): [2, 3, 6, 5] per scenario
#   history.h5   the paper's sample case as `rocksweep simulate` writes it
#   basin.h5     a 5 x 5 basin map of every scenario
#   suite.h5     the shared records on 3 PGA levels x 2 sizes, free and adaptive
# usage: make_files.sh ROCKSWEEP CONFIG DIR
set -euo pipefail
rs=$1 cfg=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
"$rs" sweep --config "$cfg" --quiet -o "$dir/spectra.h5"
"$rs" sweep --config "$cfg" --anchorages free --omega-ratio-points 1 --omega-ratio-range 4 4 --amplitude-ratio-points 5 --quiet \
  -o "$dir/line.h5"
"$rs" sweep --config "$cfg" --anchorages free constant --theta-f-ratios 1 --omega-ratio-points 5 --amplitude-ratio-points 6 \
  --axis phase_rad=0,1.5707963267948966 --axis radius_m=0.7:2.8:3 --quiet -o "$dir/axes.h5"
"$rs" simulate --config "$cfg" --anchorage adaptive --kmin-ratio 0.5 -q -o "$dir/history.h5"
"$rs" basin --config "$cfg" --theta-ratio-points 5 --theta-dot-ratio-points 5 --quiet -o "$dir/basin.h5"
"$rs" suite --config "$(dirname "$cfg")/suite_smatteo.toml" --suite "$(dirname "$cfg")/records_suite.csv" \
  --anchorages free adaptive --intensity-points 3 --radius-points 2 --quiet -o "$dir/suite.h5"
