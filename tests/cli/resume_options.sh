#!/usr/bin/env bash
# resume_options.sh ROCKSWEEP CONFIG DATA DIR: suite --resume compares every option the file's
# /provenance/config records, not only the integrator's: the damage states (they change the
# stored fragility) and the friction coefficient are refused in one line naming the option, the
# value given and the file's, exit 2, the file byte for byte as it was; --lanes may differ.
# (sweep's side: resume_settings.sh.)
set -u
rs="$1"; cfg="$2"; data="$3"; dir="$4"
rm -rf "$dir"; mkdir -p "$dir"; s="$dir/suite.h5"
fail() { echo "FAIL: $*"; exit 1; }
printf 'name,file,format,units\nel,%s,time_accel,g\n' "$data/elcentro_1940_NS.dat" > "$dir/one.csv"
grid=(--config "$cfg" --anchorages free --suite "$dir/one.csv" --intensity-points 2 --quiet)
"$rs" suite "${grid[@]}" --damage-states 0.5 -o "$s" || fail "suite"
sum=$(md5sum < "$s")
tail="as $s was computed with \(--resume continues a file only with the settings that shaped its results\)"
n=0
for case in "--damage-states 0.3|--damage-states = 0.3 is invalid: 0.5" \
            "--damage-states 0.5 --friction-coefficient 0.4|--friction-coefficient = 0.4 is invalid: 0" \
            "--damage-states 0.5 0.7|--damage-states = 0.5 0.7 is invalid: 0.5"; do
  opts="${case%%|*}"; regex="^rocksweep: error: ${case#*|}, $tail"
  # shellcheck disable=SC2086
  err=$("$rs" suite "${grid[@]}" $opts --resume -o "$s" 2>&1 >/dev/null); status=$?
  echo "$opts -> $err"
  [ "$status" -eq 2 ] && [ "$(grep -c . <<<"$err")" -eq 1 ] || fail "$opts: exit status $status or not one line"
  grep -Eq -- "$regex" <<<"$err" || fail "$opts: message does not match /$regex/"
  [ "$(md5sum < "$s")" = "$sum" ] && [ ! -e "$s.tmp" ] && [ ! -e "$s.lock" ] || fail "$opts: the file changed or a tmp/lock was left"
  n=$((n + 1))
done
"$rs" suite "${grid[@]}" --damage-states 0.5 --lanes 4 --resume -o "$s" || fail "resume with other --lanes refused"
echo "ok: $n suite resumes refused"
