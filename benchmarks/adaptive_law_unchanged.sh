#!/usr/bin/env bash
# adaptive_law_unchanged.sh OLD_ROCKSWEEP NEW_ROCKSWEEP DIR: the paper's law gives the same bits
# after --adaptive-law was added. Sweeps configs/smatteo.toml (all seven scenarios, 46 x 53
# cells) with both binaries and compares every result dataset with h5diff (exact: no -d/-p).
# The group attributes are not compared: the new file adds adaptive_law = "paper".
set -eu
old="$1"; new="$2"; dir="$3"; mkdir -p "$dir"
cfg="$(dirname "$0")/../configs/smatteo.toml"
grid=(--omega-ratio-points 46 --amplitude-ratio-points 53 --quiet --overwrite)
"$old" sweep --config "$cfg" "${grid[@]}" -o "$dir/old.h5"
"$new" sweep --config "$cfg" "${grid[@]}" -o "$dir/new.h5"
n=0
for ds in $(h5ls -r "$dir/old.h5" | awk '$1 ~ "^/spectra/.*/" && $2 == "Dataset" {print $1}'); do
    h5diff "$dir/old.h5" "$dir/new.h5" "$ds" "$ds" >/dev/null || { echo "differs: $ds"; h5diff -r "$dir/old.h5" "$dir/new.h5" "$ds" "$ds" | head; exit 1; }
    n=$((n + 1))
done
echo "$n result datasets identical"
