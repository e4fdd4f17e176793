#!/usr/bin/env bash
# suite_ranks.sh ROCKSWEEP CONFIG SUITE WORKDIR [OPTION...]
# A suite sweep gives bitwise identical result datasets (products included) on 1, 2 and 3
# ranks and with any chunk size: h5diff of everything but /provenance. SUITE "-": no CSV (the
# options give synthetic motions); options after WORKDIR are added to every run (synthetic
# motions, floors, measures).
set -eu
rs="$1"; cfg="$2"; suite="$3"; dir="$4"; shift 4
mkdir -p "$dir"
source_args=(--suite "$suite")
[ "$suite" = - ] && source_args=()
args=(suite --config "$cfg" "${source_args[@]}" --anchorages free constant adaptive --theta-f-ratios 1 --kmin-ratios 0.1
      --intensity-points 4 --radius-range 0.8 2.4 --radius-points 2 --alpha-range 0.15 0.25 --alpha-points 2
      --quiet --overwrite "$@")
mpi=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
ref="$dir/ref.h5"
"$rs" "${args[@]}" -o "$ref"
h5ls -r "$ref/suite" | grep -q "/fragility/median_intensity " || { echo "no fragility in a complete suite file"; exit 1; }
for run in "2 1" "2 7" "3 64"; do
  set -- $run
  out="$dir/np$1-chunk$2.h5"
  "${mpi[@]}" -np "$1" "$rs" "${args[@]}" --chunk "$2" -o "$out"
  h5diff --exclude-path /provenance "$ref" "$out" || { echo "np=$1 chunk=$2 differs"; exit 1; }
done
echo "suite on 1, 2, 3 ranks: identical"
