#!/usr/bin/env bash
# interrupt.sh ROCKSWEEP CONFIG WORKDIR SIGNAL STATUS
# SIGINT/SIGTERM stop a sweep cleanly: exit status STATUS, a file that opens and says which
# cells are done (complete = 0), and --resume finishes it with the uninterrupted datasets.
set -eu
rs="$1"; cfg="$2"; dir="$3"; sig="$4"; want="$5"
mkdir -p "$dir"
grid=(--anchorages free constant --theta-f-ratios 1 0.25 --omega-ratio-points 60 --amplitude-ratio-points 60
      --steps-per-period 480 --quiet --chunk 64)
# At 480 steps per period the sweep takes seconds on one core (at the default, ~0.3 s: it could
# end before the signal). A stop is honoured within a second, so the test stays short.
ref="$dir/ref.h5"; out="$dir/stopped.h5"
rm -f "$ref" "$out"
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$ref"
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$out" 2>"$dir/stderr.txt" &
pid=$!
# The handlers are in place once the output is claimed (its .lock exists); then let it compute.
for _ in $(seq 100); do [ -e "$out.lock" ] && break; sleep 0.05; done
sleep 0.3
kill -"$sig" "$pid"
set +e; wait "$pid"; status=$?; set -e
cat "$dir/stderr.txt"
[ "$status" -eq "$want" ] || { echo "exit status $status, expected $want"; exit 1; }
grep -q "rerun with --resume" "$dir/stderr.txt" || { echo "no resume hint"; exit 1; }
h5dump -a /complete "$out" | grep -q "(0): 0" || { echo "file does not say it is incomplete"; exit 1; }
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$out" --resume
h5dump -a /complete "$out" | grep -q "(0): 1" || { echo "resumed file not complete"; exit 1; }
h5diff --exclude-path /provenance "$ref" "$out" || { echo "resumed file differs"; exit 1; }
echo "stopped by $sig with status $status, resumed: identical"
