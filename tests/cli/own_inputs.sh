#!/usr/bin/env bash
# own_inputs.sh ROCKSWEEP CONFIG DESIGN_CONFIG DATA DIR: no command writes its output onto one of
# its inputs (config, --record and --record-vertical, the suite CSV and every record it lists, a
# part given to merge, a design's round files), whatever name reaches the same file (a hard link,
# a symbolic link, another spelling): exit 2, one line naming the option and the file, the input
# byte for byte as it was, nothing else left behind.
set -u
rs="$1"; cfg="$2"; dcfg="$3"; data="$4"; dir="$5"
rm -rf "$dir"; mkdir -p "$dir"; cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
small=(--anchorages free --omega-ratio-points 3 --amplitude-ratio-points 3 --quiet)
n=0
refused() {  # refused KEPT REGEX COMMAND...: COMMAND refused with REGEX, KEPT untouched
  local kept="$1" regex="$2"; shift 2
  local sum err status
  sum=$(md5sum < "$kept")
  err=$("$@" 2>&1 >/dev/null); status=$?
  echo "${*:2} -> $err"
  [ "$status" -eq 2 ] || fail "${*:2}: exit status $status, expected 2"
  [ "$(grep -c . <<<"$err")" -eq 1 ] || fail "${*:2}: not one line"
  grep -Eq -- "^rocksweep: error: $regex" <<<"$err" || fail "${*:2}: message does not match /$regex/"
  [ "$(md5sum < "$kept")" = "$sum" ] || fail "${*:2}: $kept changed"
  [ -z "$(find . -name '*.tmp' -o -name '*.lock')" ] || fail "${*:2}: a .tmp or .lock was left"
  n=$((n + 1))
}
tail="is invalid: a file that is not one of the run's inputs \(it is"

# The config, under its own name, another spelling, a hard link and a symbolic link.
cp "$cfg" my.toml
ln my.toml hard.h5; ln -s my.toml soft.h5
refused my.toml "--output = my.toml $tail the --config file, which" "$rs" sweep --config my.toml "${small[@]}" --overwrite -o my.toml
refused my.toml "--output = \./my.toml $tail the --config file my.toml," "$rs" sweep --config my.toml "${small[@]}" --overwrite -o ./my.toml
refused my.toml "--output = hard.h5 $tail the --config file my.toml," "$rs" sweep --config my.toml "${small[@]}" --overwrite -o hard.h5
refused my.toml "--output = soft.h5 $tail the --config file my.toml," "$rs" sweep --config my.toml "${small[@]}" --overwrite -o soft.h5
refused my.toml "--output = hard.h5 $tail the --config file my.toml," "$rs" basin --config my.toml --overwrite -o hard.h5
refused my.toml "--output = hard.h5 $tail the --config file my.toml," "$rs" simulate --config my.toml --overwrite -o hard.h5

# simulate's records: the horizontal and the vertical file.
cp "$data/elcentro_1940_NS.dat" rec.csv; cp "$data/elcentro_1940_NS.dat" vert.csv
refused rec.csv "--output = rec.csv $tail the --record file," "$rs" simulate --record rec.csv --record-units g --overwrite -o rec.csv
refused vert.csv "--output = vert.csv $tail the --record-vertical file," \
  "$rs" simulate --record rec.csv --record-vertical vert.csv --record-units g --overwrite -o vert.csv

# suite: its CSV, a record it lists (through a hard link), a vertical file it lists.
cp "$data/northridge_1994_sylmar.dat" sylmar.dat
printf 'name,file,format,units,vertical_file\nel,rec.csv,time_accel,g,vert.csv\nsy,sylmar.dat,time_accel,m/s^2,\n' > S.csv
ln sylmar.dat sylmar_link.h5
suite=(suite --config "$cfg" --anchorages free --suite S.csv --intensity-points 2 --quiet --overwrite)
refused S.csv "--output = S.csv $tail the --suite file," "$rs" "${suite[@]}" -o S.csv
refused sylmar.dat "--output = sylmar_link.h5 $tail record sy of the --suite file \(S.csv line 3\) .*sylmar.dat," \
  "$rs" "${suite[@]}" -o sylmar_link.h5
refused vert.csv "--output = vert.csv $tail record el's vertical file \(S.csv line 2\)" "$rs" "${suite[@]}" -o vert.csv

# merge: a part, named as given or through a hard link.
"$rs" sweep --config "$cfg" "${small[@]}" --part 1/2 -o p1.h5 || fail "part 1"
"$rs" sweep --config "$cfg" "${small[@]}" --part 2/2 -o p2.h5 || fail "part 2"
ln p2.h5 p2_link.h5
refused p1.h5 "--output = \./p1.h5 $tail one of the parts given p1.h5," "$rs" merge --config "$cfg" "${small[@]}" p1.h5 p2.h5 --overwrite -o ./p1.h5
refused p2.h5 "--output = p2_link.h5 $tail one of the parts given p2.h5," "$rs" merge --config "$cfg" "${small[@]}" p1.h5 p2.h5 --overwrite -o p2_link.h5

# design: its output may not be one of its round files, which a resumed design reads back.
cp p1.h5 D.round0.h5; ln D.round0.h5 D.h5
refused D.round0.h5 "--output = D.h5 $tail the design's round file D.round0.h5," \
  "$rs" design --config "$dcfg" --omega-ratio-points 3 --amplitude-ratio-points 3 --quiet --resume -o D.h5

# design --suite: its records are inputs of the design's own file too, not only of its rounds'.
refused sylmar.dat "--output = sylmar_link.h5 $tail record sy of the --suite file \(S.csv line 3\) .*sylmar.dat," \
  "$rs" design --config "$dcfg" --suite S.csv --intensity-points 2 --quiet --overwrite -o sylmar_link.h5

# A file that is no input is still replaced when asked, and merge still merges.
"$rs" merge --config "$cfg" "${small[@]}" p1.h5 p2.h5 -o merged.h5 || fail "merge to a new file"
"$rs" sweep --config my.toml "${small[@]}" --overwrite -o merged.h5 || fail "--overwrite of a file that is no input"
echo "ok: $n outputs that were inputs refused"
