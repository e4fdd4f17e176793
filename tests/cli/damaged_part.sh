#!/usr/bin/env bash
# damaged_part.sh ROCKSWEEP CONFIG DIR
# merge of a part file that is damaged (bytes overwritten, cut short) or no HDF5 file at all
# names that file and says what is wrong with it; exit status 2, no output left.
set -u
rs="$1"; cfg="$2"; dir="$3"
rm -rf "$dir"; mkdir -p "$dir"; cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
grid=(--config "$cfg" --omega-ratio-points 23 --amplitude-ratio-points 17 --anchorages free --quiet)
"$rs" sweep "${grid[@]}" --part 1/2 -o p1.h5 || fail "part 1"
"$rs" sweep "${grid[@]}" --part 2/2 -o p2.h5 || fail "part 2"
size=$(stat -c %s p2.h5)
cp p2.h5 zeroed.h5; dd if=/dev/zero of=zeroed.h5 bs=1 seek=$((size / 2)) count=$((size / 4)) conv=notrunc status=none
head -c $((size / 2)) p2.h5 >cut.h5
head -c 64 /dev/urandom >noise.h5
cp "$cfg" config.h5
for bad in zeroed.h5 cut.h5 noise.h5 config.h5; do
  err=$("$rs" merge "${grid[@]}" -o all.h5 p1.h5 "$bad" 2>&1); status=$?
  echo "$bad: $err"
  [ "$status" -eq 2 ] || fail "$bad: status $status, expected 2"
  grep -Eq -- "part file = $bad is invalid: a rocksweep part file; it is (damaged|not)" <<<"$err" || fail "$bad: message"
  [ "$(wc -l <<<"$err")" -eq 1 ] || fail "$bad: more than one line"
  [ ! -e all.h5 ] && [ ! -e all.h5.tmp ] || fail "$bad: an output was left"
done
echo "damaged parts named"
