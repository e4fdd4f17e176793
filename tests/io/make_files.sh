#!/usr/bin/env bash
# Files the reader tests open (the `io_files` fixture), in DIR:
#   spectra.h5   the default sweep of configs/smatteo.toml (what scripts/run.sh computes)
#   line.h5      a 5 x 1 grid, free block only: a grid with a dimension of length 1
#   history.h5   the paper's sample case as `rocksweep simulate` writes it
# usage: make_files.sh ROCKSWEEP CONFIG DIR
set -euo pipefail
rs=$1 cfg=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
"$rs" sweep --config "$cfg" --quiet -o "$dir/spectra.h5"
"$rs" sweep --config "$cfg" --anchorages free --omega-ratio-points 1 --omega-ratio-range 4 4 --amplitude-ratio-points 5 --quiet \
  -o "$dir/line.h5"
"$rs" simulate --config "$cfg" --anchorage adaptive --kmin-ratio 0.5 -q -o "$dir/history.h5"
