#!/usr/bin/env bash
# suite_names.sh ROCKSWEEP CONFIG DATA DIR: a suite record name that cannot name its group
# /records/NAME of the output ('.', '..', a dataset of /records) is refused before any work:
# exit 2 at once (a grid that would take minutes), one line naming the suite file's line and
# the name, no output left.
set -u
rs="$1"; cfg="$2"; data="$3"; dir="$4"
rm -rf "$dir"; mkdir -p "$dir"; cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
n=0
for name in . .. pga_g record intensity alpha_rad scale_factor; do
  printf 'name,file,format,units\nok,%s,time_accel,g\n%s,%s,time_accel,g\n' "$data/elcentro_1940_NS.dat" "$name" "$data/elcentro_1940_NS.dat" > S.csv
  start=$(date +%s)
  err=$(timeout 60 "$rs" suite --config "$cfg" --suite S.csv --intensity-points 400 --radius-range 0.5 2 --radius-points 20 -o out.h5 2>&1 >/dev/null); status=$?
  took=$(( $(date +%s) - start ))
  echo "$name -> $err (${took} s)"
  [ "$status" -eq 2 ] || fail "name '$name': exit status $status, expected 2"
  [ "$(grep -c . <<<"$err")" -eq 1 ] || fail "name '$name': not one line"
  grep -Fq -- "rocksweep: error: --suite = S.csv line 3 is invalid: record name '$name' cannot name its group" <<<"$err" \
    || fail "name '$name': message"
  [ "$took" -le 5 ] || fail "name '$name': refused only after ${took} s of work"
  [ ! -e out.h5 ] && [ ! -e out.h5.tmp ] && [ ! -e out.h5.lock ] || fail "name '$name': an output was left"
  n=$((n + 1))
done
# Dots inside a name are fine.
printf 'name,file,format,units\nel.ns,%s,time_accel,g\n' "$data/elcentro_1940_NS.dat" > S.csv
"$rs" suite --config "$cfg" --anchorages free --suite S.csv --intensity-points 2 --quiet -o out.h5 || fail "name el.ns refused"
h5ls out.h5/records | grep -q '^el\.ns ' || fail "no group /records/el.ns"
echo "ok: $n names refused"
