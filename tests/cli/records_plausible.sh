#!/usr/bin/env bash
# records_plausible.sh ROCKSWEEP DATA DIR: every one of the 11 shared records, read in its own
# unit (tests/data/README.md), passes the plausible-PGA check and prints what it is as read.
set -u
rs="$1"; data="$2"; dir="$3"
rm -rf "$dir"; mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }
n=0
while read -r file units column; do
  args=(--record "$data/$file")
  [ "$units" = "-" ] || args+=(--record-units "$units")
  [ "$column" = "-" ] || args+=(--record-column "$column")
  out=$("$rs" simulate "${args[@]}" --t-end 0.05 -o "$dir/$n.csv" 2>&1) || fail "$file ($units) refused: $out"
  line=$(grep "^record " <<<"$out")
  echo "$line"
  grep -Eq "^record .*$file: PGA [0-9.]+ g \([0-9.]+ m/s\^2\) as read in (g|m/s\^2|cm/s\^2), dt 0.0(2|05) s, [0-9.]+ s, [0-9]+ samples$" <<<"$line" \
    || fail "$file: no record line"
  n=$((n + 1))
done <<'LIST'
elcentro_1940_NS.dat g -
northridge_1994_sylmar.dat m/s^2 -
cape_mendocino_1992.dat m/s^2 -
kocaeli_1999.dat m/s^2 -
loma_prieta_1989.dat m/s^2 -
san_fernando_1971.dat m/s^2 -
spitak_1988.dat m/s^2 -
san_salvador_1986_gic090.txt m/s^2 -
cephalonia_2014_chv1_E.txt cm/s^2 -
mexico_city_1985_sct.txt g 2
mexico_city_1985_sct.txt g 3
RSN1044_northridge_1994_newhall_rot.AT2 - -
LIST
[ "$n" -eq 12 ] || fail "$n records read"
echo "ok: the 11 shared records ($n components) are plausible"
