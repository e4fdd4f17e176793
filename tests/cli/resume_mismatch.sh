#!/usr/bin/env bash
# resume_mismatch.sh ROCKSWEEP CONFIG DIR: --resume on a file of another sweep is refused
# (exit 2, the file named, the file untouched).
set -u
rs="$1"; cfg="$2"; dir="$3"; mkdir -p "$dir"; out="$dir/a.h5"; rm -f "$out"
"$rs" sweep --config "$cfg" --omega-ratio-points 4 --amplitude-ratio-points 3 --quiet -o "$out" || exit 1
sum=$(md5sum < "$out")
err=$("$rs" sweep --config "$cfg" --omega-ratio-points 5 --amplitude-ratio-points 3 --quiet --resume -o "$out" 2>&1); status=$?
echo "$err"
[ "$status" -eq 2 ] || { echo "exit status $status, expected 2"; exit 1; }
grep -q "$out" <<<"$err" || { echo "file not named"; exit 1; }
[ "$(md5sum < "$out")" = "$sum" ] || { echo "file changed"; exit 1; }
echo ok
