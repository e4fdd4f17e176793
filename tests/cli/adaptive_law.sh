#!/usr/bin/env bash
# adaptive_law.sh ROCKSWEEP CONFIG DIR: a sweep with --adaptive-law passive names its scenarios
# after the law and stores it as a scenario attribute; --resume with the other law is refused
# (exit 2, the file named, the file untouched), with the same law it completes the file. A file
# written before the option existed (no adaptive_law attribute) resumes as the paper's law.
set -u
rs="$1"; cfg="$2"; dir="$3"; mkdir -p "$dir"; out="$dir/passive.h5"; rm -f "$out"
grid=(--anchorages adaptive --omega-ratio-points 4 --amplitude-ratio-points 3 --quiet)
"$rs" sweep --config "$cfg" "${grid[@]}" --adaptive-law passive -o "$out" || exit 1
law=$(h5dump -a /spectra/adaptive_rho0.5_passive/adaptive_law "$out" | grep '(0)')
grep -q '"passive"' <<<"$law" || { echo "attribute adaptive_law: $law"; exit 1; }
sum=$(md5sum < "$out")
err=$("$rs" sweep --config "$cfg" "${grid[@]}" --resume -o "$out" 2>&1); status=$?
echo "$err"
[ "$status" -eq 2 ] || { echo "exit status $status, expected 2"; exit 1; }
grep -q "$out" <<<"$err" || { echo "file not named"; exit 1; }
grep -q "adaptive_rho0.5_passive" <<<"$err" || { echo "the law's scenario names not shown"; exit 1; }
[ "$(md5sum < "$out")" = "$sum" ] || { echo "file changed"; exit 1; }
"$rs" sweep --config "$cfg" "${grid[@]}" --adaptive-law passive --resume -o "$out" || { echo "same-law resume failed"; exit 1; }
old="$dir/before_law.h5"; rm -f "$old"
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$old" || exit 1
/usr/bin/python3 -c "import h5py, sys
with h5py.File(sys.argv[1], 'r+') as f:
    for g in f['spectra'].values(): del g.attrs['adaptive_law']" "$old" || exit 1
"$rs" sweep --config "$cfg" "${grid[@]}" --resume -o "$old" || { echo "a file from before --adaptive-law did not resume"; exit 1; }
echo ok
