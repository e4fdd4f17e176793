#!/usr/bin/env bash
# resume_old_layout.sh ROCKSWEEP CONFIG DIR: `sweep --resume` of a format-version-1 file (axes
# in /axes, beside /spectra) fails with one line naming the file and both versions, exit
# status 2, and leaves the file as it was.
set -u
rs="$1"; cfg="$2"; dir="$3"; mkdir -p "$dir"; out="$dir/old.h5"; rm -f "$out"
grid=(--config "$cfg" --omega-ratio-points 4 --amplitude-ratio-points 3 --quiet -o "$out")
"$rs" sweep "${grid[@]}" || exit 1
# Back to version 1's layout: one /axes group, no axes inside the scenario groups.
/usr/bin/python3 - "$out" <<'PY' || exit 1
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    axes = f.create_group("axes")
    for name, g in f["spectra"].items():
        for axis in ("omega_ratio", "amplitude_ratio"):
            if axis not in axes:
                axes[axis] = g[axis][()]
            del g[axis]
    f.attrs["format_version"] = 1
PY
sum=$(md5sum < "$out")
err=$("$rs" sweep "${grid[@]}" --resume 2>&1 >/dev/null); status=$?
echo "$err"
[ "$status" -eq 2 ] || { echo "exit status $status, expected 2"; exit 1; }
[ "$(wc -l <<<"$err")" -eq 1 ] || { echo "not one line"; exit 1; }
grep -qF -- "--output = $out is invalid: a spectra file of format version 2 to resume; it is of version 1" <<<"$err" \
  || { echo "message does not say which versions"; exit 1; }
[ "$(md5sum < "$out")" = "$sum" ] || { echo "file changed"; exit 1; }
[ ! -e "$out.tmp" ] || { echo "tmp file left"; exit 1; }
echo ok
