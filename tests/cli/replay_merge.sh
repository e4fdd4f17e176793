#!/usr/bin/env bash
# replay_merge.sh ROCKSWEEP CONFIG DIR: a merged file's stored config names its parts
# (merge.parts) and replays like any other output (replay.sh), as a merge.
set -u
rs="$1"; cfg="$2"; dir="$3"
grid=(--config "$cfg" --anchorages free --omega-ratio-points 20 --amplitude-ratio-points 20)
mkdir -p "$dir" && rm -f "$dir"/part*.h5
for k in 1 2; do "$rs" sweep "${grid[@]}" --part "$k/2" -o "$dir/part$k.h5" --quiet || exit 1; done
exec bash "$(dirname "$0")/replay.sh" "$rs" "$dir/replay" merge "$dir/part1.h5" "$dir/part2.h5" "${grid[@]}"
