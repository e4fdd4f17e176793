#!/usr/bin/env bash
# sweep_ranks.sh ROCKSWEEP CONFIG WORKDIR NP
# The result datasets must be bitwise identical at NP ranks, with any chunk size, and with
# boundary refinement, to those of one process: h5diff of everything but /provenance.
set -eu
rs="$1"; cfg="$2"; dir="$3"; np="$4"
mkdir -p "$dir"
grid=(--omega-ratio-points 37 --amplitude-ratio-points 29 --quiet --overwrite)
mpi=(mpirun --oversubscribe -np "$np")
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
ref="$dir/ref.h5"
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$ref"
for chunk in 1 7 256; do
  out="$dir/np$np-chunk$chunk.h5"
  "${mpi[@]}" "$rs" sweep --config "$cfg" "${grid[@]}" --chunk "$chunk" -o "$out"
  h5diff --exclude-path /provenance "$ref" "$out" || { echo "np=$np chunk=$chunk differs"; exit 1; }
  [ "$(h5dump -a /provenance/ranks "$out" | grep -c "(0): $np")" -eq 1 ] || { echo "provenance ranks"; exit 1; }
done
refr="$dir/ref-refine.h5"
"$rs" sweep --config "$cfg" "${grid[@]}" --refine 8 -o "$refr"
"${mpi[@]}" "$rs" sweep --config "$cfg" "${grid[@]}" --refine 8 --chunk 5 -o "$dir/np$np-refine.h5"
h5diff --exclude-path /provenance "$refr" "$dir/np$np-refine.h5" || { echo "np=$np refine differs"; exit 1; }
echo "np=$np: identical"
