#!/usr/bin/env bash
# A finished file stays as it is unless --overwrite is given.
set -eu
rs="$1"; cfg="$2"; dir="$3"
mkdir -p "$dir"; out="$dir/out.h5"; rm -f "$out"
small=(--omega-ratio-points 3 --amplitude-ratio-points 3 --quiet)
"$rs" sweep --config "$cfg" -o "$out" "${small[@]}"
sum1=$(md5sum < "$out")
set +e
msg=$("$rs" sweep --config "$cfg" -o "$out" "${small[@]}" 2>&1); status=$?
set -e
[ "$status" -eq 2 ] || { echo "status $status, expected 2"; exit 1; }
grep -q "pass --resume to continue it or --overwrite" <<<"$msg" || { echo "message: $msg"; exit 1; }
[ "$(md5sum < "$out")" = "$sum1" ] || { echo "file changed"; exit 1; }
"$rs" sweep --config "$cfg" -o "$out" "${small[@]}" --overwrite
echo ok
