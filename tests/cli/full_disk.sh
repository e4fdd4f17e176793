#!/usr/bin/env bash
# full_disk.sh ROCKSWEEP CONFIG DIR [NP]: a save that runs out of space (sweep, simulate, suite)
# ends with one line naming the file and "no space left on device", exit status 1 (no crash),
# no .tmp, and the last complete file intact.
#
# The disk is a 160 KiB tmpfs mounted in a private mount namespace (unshare --mount): it exists
# only for the commands inside it and vanishes with them, so nothing is left mounted even if
# the test fails or is killed. (`ulimit -f` is no substitute: MPI's start-up writes its own
# files and dies under it.) Skipped (77) where mount namespaces are not allowed.
set -u
rs="$1"; cfg="$2"; dir="$3"; np="${4:-1}"
if [ "${FULL_DISK_INSIDE:-}" != 1 ]; then
  rm -rf "$dir"; mkdir -p "$dir"
  unshare --mount true 2>/dev/null || { echo "SKIP: no mount namespaces here"; exit 77; }
  FULL_DISK_INSIDE=1 exec unshare --mount bash "$0" "$@"
fi
fail() { echo "FAIL: $*"; exit 1; }
mount -t tmpfs -o size=160k rocksweep-full "$dir" || { echo "SKIP: cannot mount a tmpfs"; exit 77; }
run=("$rs")
if [ "$np" -gt 1 ]; then
  run=(mpirun --oversubscribe -np "$np"); [ "$(id -u)" -eq 0 ] && run+=(--allow-run-as-root); run+=("$rs")
fi
grid=(--omega-ratio-points 5 --amplitude-ratio-points 5 --quiet)   # a file of about 100 KiB
out="$dir/out.h5"

# 1. The first save does not fit beside a filler: nothing is left at all.
head -c 100k /dev/zero > "$dir/filler"
err=$("${run[@]}" sweep --config "$cfg" "${grid[@]}" -o "$out" 2>&1 >/dev/null); status=$?
echo "$err"
[ "$status" -eq 1 ] || fail "exit status $status, expected 1"
grep -Eq "^rocksweep: error: cannot write $out: no space left on device$" <<<"$err" || fail "message"
[ "$(grep -ci "error" <<<"$err")" -eq 1 ] || fail "not exactly one error line"
[ ! -e "$out" ] && [ ! -e "$out.tmp" ] && [ ! -e "$out.lock" ] || fail "files left: $(ls "$dir")"
rm -f "$dir/filler"

# 2. A complete file fits once, not twice: replacing it fails and keeps it.
"${run[@]}" sweep --config "$cfg" "${grid[@]}" -o "$out" || fail "the first sweep should fit"
sum=$(md5sum < "$out")
err=$("${run[@]}" sweep --config "$cfg" "${grid[@]}" -o "$out" --overwrite 2>&1 >/dev/null); status=$?
echo "$err"
[ "$status" -eq 1 ] || fail "exit status $status, expected 1"
grep -Eq "^rocksweep: error: cannot write $out: no space left on device \($out still holds the previous save\)$" <<<"$err" \
  || fail "message"
[ "$(md5sum < "$out")" = "$sum" ] || fail "the last complete file changed"
[ ! -e "$out.tmp" ] && [ ! -e "$out.lock" ] || fail "tmp or lock left"

# 3. simulate, HDF5 and CSV: the same line, nothing left.
for ext in h5 csv; do
  head -c 150k /dev/zero > "$dir/filler" 2>/dev/null  # fills the disk
  err=$("$rs" simulate --config "$cfg" -q --t-end 200 -o "$dir/h.$ext" 2>&1 >/dev/null); status=$?
  echo "$err"
  [ "$status" -eq 1 ] || fail "simulate .$ext: exit status $status"
  grep -Eq "^rocksweep: error: cannot write $dir/h.$ext: no space left on device$" <<<"$err" || fail "simulate message"
  [ ! -e "$dir/h.$ext" ] && [ ! -e "$dir/h.$ext.tmp" ] || fail "simulate left files"
  rm -f "$dir/filler"
done
# 4. suite: the disk fills while the finished file is written beside the running one (every run
# done): one line, no .tmp, the running file intact with every run, and --resume finishes it.
rm -f "$out"  # the sweep of 2
record="$(cd "$(dirname "$0")/../data" && pwd)/loma_prieta_1989.dat"
printf 'name,file,format,units\nloma,%s,time_accel,m/s^2\n' "$record" > "$dir/one.csv"
suite=(suite --config "$cfg" --suite "$dir/one.csv" --anchorages free --intensity-points 4 --quiet)
"${run[@]}" "${suite[@]}" -o "$dir/s.h5" || fail "a small suite should fit"
size=$(stat -c %s "$dir/s.h5"); rm -f "$dir/s.h5"
head -c $((160 * 1024 - size * 3 / 2)) /dev/zero > "$dir/filler"  # room for one file, not two
err=$("${run[@]}" "${suite[@]}" -o "$dir/s.h5" 2>&1 >/dev/null); status=$?
echo "$err"
[ "$status" -eq 1 ] || fail "suite: exit status $status, expected 1"
grep -Eq "^rocksweep: error: cannot write $dir/s.h5: no space left on device \($dir/s.h5 still holds the previous save\)$" \
  <<<"$err" || fail "suite message"
[ ! -e "$dir/s.h5.tmp" ] || fail "suite: s.h5.tmp left"
h5dump -a /n_done "$dir/s.h5" | grep -q "(0): 4$" || fail "suite: the running file does not hold every run"
rm -f "$dir/filler"
"${run[@]}" "${suite[@]}" -o "$dir/s.h5" --resume || fail "suite: resume after the full disk"
h5dump -a /complete "$dir/s.h5" | grep -q "(0): 1$" || fail "suite: not finished by --resume"
echo ok
