#!/usr/bin/env bash
# merge_parts.sh ROCKSWEEP CONFIG DIR: a sweep split into parts (one of them on 2 ranks) and
# merged is bitwise the unsplit sweep; merge refuses a part of
# another sweep (or of another refinement), two parts that disagree and an output that is one of its inputs, leaving no
# output; a missing part gives a file that `sweep --resume` completes.
set -u
rs="$1"; cfg="$2"; dir="$3"
rm -rf "$dir"; mkdir -p "$dir"; cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
mpi=(mpirun --oversubscribe -np 2); [ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
grid=(--config "$cfg" --omega-ratio-points 23 --amplitude-ratio-points 17 --anchorages free constant --theta-f-ratios 1)
q=--quiet
"$rs" sweep "${grid[@]}" $q -o ref.h5 || fail "reference"
# 2 scenarios x 391 cells = 782 cells: parts of 256-cell blocks, part 3 gets one block.
"$rs" sweep "${grid[@]}" $q --part 1/3 -o p1.h5 || fail "part 1"
"${mpi[@]}" "$rs" sweep "${grid[@]}" $q --part 2/3 -o p2.h5 || fail "part 2 on 2 ranks"
msg=$("$rs" sweep "${grid[@]}" --part 3/3 -o p3.h5 2>&1) || fail "part 3: $msg"
grep -q "wrote part 3 of 3 (256 of 782 cells) to p3.h5; join the parts with rocksweep merge" <<<"$msg" || fail "part message: $msg"
h5dump -a /complete p1.h5 | grep -q "(0): 0" || fail "a part file must not say it is complete"

"$rs" merge "${grid[@]}" $q -o all.h5 p1.h5 p2.h5 p3.h5 || fail "merge"
h5diff --exclude-path /provenance ref.h5 all.h5 || fail "merged file differs from the unsplit sweep"
h5dump -a /complete all.h5 | grep -q "(0): 1" || fail "merged file not complete"
# A part given twice agrees with itself.
"$rs" merge "${grid[@]}" $q -o twice.h5 p1.h5 p1.h5 p2.h5 p3.h5 || fail "repeated part"

refused() {  # refused OUT PATTERN ARGS...: exit 2, one line matching PATTERN, no OUT.tmp/.lock, OUT
             # not created (OUT "-": it existed before)
  local out="$1" pattern="$2"; shift 2
  local err; err=$("$rs" merge "$@" 2>&1); local status=$?
  [ "$status" -eq 2 ] || fail "exit $status for: merge $* ($err)"
  [ "$(wc -l <<<"$err")" -eq 1 ] || fail "not one line: $err"
  grep -q -- "$pattern" <<<"$err" || fail "message '$err' lacks '$pattern'"
  if [ "$out" != - ]; then [ ! -e "$out" ] || fail "output created: $out"; fi
  [ ! -e "$out.tmp" ] && [ ! -e "$out.lock" ] || fail "temporary file left behind: $out"
  echo "refused as expected: $err"
}
# A part of another sweep (another grid), named.
"$rs" sweep --config "$cfg" --omega-ratio-points 22 --amplitude-ratio-points 17 --anchorages free constant \
  --theta-f-ratios 1 --quiet --part 1/3 -o other.h5 || fail "other sweep"
refused bad1.h5 "other.h5" "${grid[@]}" -o bad1.h5 p1.h5 other.h5
# Two parts whose common cell differs: not one sweep's.
cp p1.h5 forged.h5
/usr/bin/python3 -c "
import h5py
with h5py.File('forged.h5', 'r+') as f:
    d = f['spectra/free/max_rotation']; v = d[...]; v[0, 0] += 1e-9; d[...] = v
    for g in f['spectra'].values(): del g.attrs['results_fnv1a64']  # as a part from before checksums
" || fail "forging"
refused bad2.h5 "part file = forged.h5 is invalid: a part of one sweep with p1.h5; the two differ at scenario free, a_p0/(alpha g) = 1, omega_p/p = 1" \
  "${grid[@]}" -o bad2.h5 p1.h5 forged.h5
# The output may not be one of the parts; an existing output needs --overwrite.
sum=$(md5sum < p1.h5)
refused - "not one of the run's inputs (it is one of the parts given" "${grid[@]}" -o p1.h5 p1.h5 p2.h5
[ "$(md5sum < p1.h5)" = "$sum" ] || fail "a part was changed"
refused - "--overwrite" "${grid[@]}" -o all.h5 p1.h5
h5diff --exclude-path /provenance ref.h5 all.h5 || fail "existing output touched"
# --part with --refine, and malformed parts.
for bad in 0/3 4/3 3 x/y; do
  err=$("$rs" sweep "${grid[@]}" --part "$bad" -o bad3.h5 2>&1); [ $? -eq 2 ] || fail "--part $bad accepted"
  grep -q -- "--part = $bad is invalid" <<<"$err" || fail "message: $err"
done
err=$("$rs" sweep "${grid[@]}" --part 1/2 --refine 4 -o bad4.h5 2>&1); [ $? -eq 2 ] || fail "--part with --refine accepted"
grep -q "not with --refine" <<<"$err" || fail "message: $err"
[ ! -e bad3.h5 ] && [ ! -e bad4.h5 ] || fail "output left by a refused sweep"

# A refined sweep's file merges to itself, its refinement recorded; with a file of the unrefined
# sweep (computed cells beside inferred ones) it is refused.
"$rs" sweep "${grid[@]}" $q --refine 4 -o refined.h5 || fail "refined sweep"
"$rs" merge "${grid[@]}" $q -o refined_merged.h5 refined.h5 || fail "merge of a refined file"
h5diff --exclude-path /provenance refined.h5 refined_merged.h5 || fail "merged refined file differs"
refused mixed.h5 "refine = 4 is invalid: not given, as ref.h5" "${grid[@]}" -o mixed.h5 refined.h5 ref.h5

# A missing part: the merged file is partial, and --resume completes it to the unsplit sweep.
msg=$("$rs" merge "${grid[@]}" -o partial.h5 p1.h5 p3.h5 2>&1) || fail "merge of two parts"
grep -q "cells are in none of them" <<<"$msg" || fail "missing cells not reported: $msg"
"$rs" sweep "${grid[@]}" $q --resume -o partial.h5 || fail "resume of the partial merge"
h5diff --exclude-path /provenance ref.h5 partial.h5 || fail "resumed merge differs"
echo ok
