#!/usr/bin/env bash
# suite_per_record.sh MODE ROCKSWEEP CONFIG DATA DIR: suite --synthetic-per-record over a site of
# two shared records (Loma Prieta, Spitak; an `event` metadata column).
#   equal: the made motions are synth's motions of each record's derived seed (the seed computed
#          here from the documented formula), swept as a CSV suite: bitwise the same /suite and
#          record measures, records first, with and without --synthetic-only; each motion carries
#          its record's metadata; the CSV's scale is fitted (I_a x scale^2); a resume with another
#          N, seed or --synthetic-only is refused and leaves the file as it was.
#   ranks: bitwise the same on 1, 2 and 3 ranks and any chunk (suite_ranks.sh).
#   kill:  killed at three moments on 2 ranks and resumed: the same file (suite_kill_resume.sh).
#   refused: a record whose PGA betrays a wrong unit (though only fitted) and one the model cannot
#          take are refused naming their suite line, exit 2, no output; a record only fitted is
#          still an input that no output may replace.
set -eu
mode="$1"; rs="$2"; cfg="$3"; data="$4"; dir="$5"
rm -rf "$dir"; mkdir -p "$dir"
site="$dir/site.csv"
site_csv() {  # site_csv SCALE: the two records, Loma Prieta's at SCALE
  printf 'name,file,format,units,dt,column,scale,vertical_file,vertical_column,event\n'
  printf 'loma,%s/loma_prieta_1989.dat,time_accel,m/s^2,,,%s,,,Loma Prieta 1989\n' "$data" "$1"
  printf 'spitak,%s/spitak_1988.dat,time_accel,m/s^2,,,1,,,Spitak 1988\n' "$data"
}
site_csv 1 > "$site"
fail() { echo "FAIL: $*"; exit 1; }

if [ "$mode" = ranks ]; then
  exec bash "$(dirname "$0")/suite_ranks.sh" "$rs" "$cfg" "$site" "$dir/ranks" --synthetic-per-record 5 --seed 11
fi
if [ "$mode" = kill ]; then
  LEVELS="${LEVELS:-48}" RADII="${RADII:-2}" exec bash "$(dirname "$0")/suite_kill_resume.sh" "$rs" "$cfg" "$site" "$dir/kill" 2 \
    --synthetic-per-record 4 --synthetic-only --seed 11
fi

if [ "$mode" = refused ]; then
  expect=(bash "$(dirname "$0")/expect_error.sh" 2)
  # El Centro (in g) read as cm/s^2: refused as the suite refuses it, though only fitted.
  printf 'name,file,format,units\nloma,%s/loma_prieta_1989.dat,time_accel,m/s^2\nel,%s/elcentro_1940_NS.dat,time_accel,cm/s^2\n' \
    "$data" "$data" > "$dir/cm.csv"
  "${expect[@]}" "^rocksweep: error: --suite = $dir/cm.csv line 3 is invalid: record el \(.*elcentro_1940_NS.dat\): its peak ground acceleration as read in cm/s\^2, .* pass --record-any-pga to accept every record of the suite$" \
    "$dir/bad.h5" -- "$rs" suite --config "$cfg" --suite "$dir/cm.csv" --synthetic-per-record 2 --synthetic-only -o "$dir/bad.h5"
  # A record only fitted (--synthetic-only) is still an input: no output may replace it.
  cp "$data/loma_prieta_1989.dat" "$dir/loma.dat"
  printf 'name,file,format,units\nloma,loma.dat,time_accel,m/s^2\n' > "$dir/own.csv"
  if err=$("$rs" suite --config "$cfg" --suite "$dir/own.csv" --synthetic-per-record 2 --synthetic-only --overwrite \
             -o "$dir/loma.dat" 2>&1); then fail "a fitted record overwritten"; fi
  echo "$err"
  grep -q "^rocksweep: error: --output = $dir/loma.dat is invalid: a file that is not one of the run's inputs (it is record loma of the --suite file" <<<"$err" \
    && cmp -s "$dir/loma.dat" "$data/loma_prieta_1989.dat" || fail "the fitted record as output: not refused, or changed"
  # 1.6 s of a 1 Hz sine: one up-crossing, the model's filter cannot be fitted.
  awk 'BEGIN { for (i = 0; i <= 160; ++i) printf "%.2f %.6f\n", i * 0.01, 0.3 * sin(6.283185307 * i * 0.01) }' > "$dir/sine.dat"
  printf 'name,file,format,units\nloma,%s/loma_prieta_1989.dat,time_accel,m/s^2\nsine,sine.dat,time_accel,g\n' "$data" > "$dir/bad.csv"
  exec "${expect[@]}" \
    "^rocksweep: error: --suite = $dir/bad.csv line 3 is invalid: record sine: the model cannot be fitted to it \(--synthetic-per-record\): 1 zero up-crossings between t5 and t95; at least 10 to fit the filter's frequency$" \
    "$dir/bad.h5" -- "$rs" suite --config "$cfg" --suite "$dir/bad.csv" --synthetic-per-record 2 -o "$dir/bad.h5"
fi

[ "$mode" = equal ] || fail "unknown mode $mode"
seed=5; n=3
common=(--config "$cfg" --quiet)
levels=(--intensity-points 5)
"$rs" suite "${common[@]}" "${levels[@]}" --suite "$site" --synthetic-per-record $n --seed $seed --synthetic-only -o "$dir/made_only.h5"
"$rs" suite "${common[@]}" "${levels[@]}" --suite "$site" --synthetic-per-record $n --seed $seed -o "$dir/made.h5"
# Each record's seed from the formula of docs/synthetic.md, independently of the program; the
# file's `file` attributes must name it, and the motions carry their record's metadata.
seeds=$(/usr/bin/python3 - "$dir/made_only.h5" $seed $n "$site" <<'PY'
import sys, h5py
M = (1 << 64) - 1
def mix64(x):
    x = (x + 0x9e3779b97f4a7c15) & M
    x = ((x ^ (x >> 30)) * 0xbf58476d1ce4e5b9) & M
    x = ((x ^ (x >> 27)) * 0x94d049bb133111eb) & M
    return x ^ (x >> 31)
path, seed, n = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
seeds = []
with h5py.File(path, "r") as f:
    for k, (name, event) in enumerate([("loma", "Loma Prieta 1989"), ("spitak", "Spitak 1988")]):
        s = mix64(mix64(mix64(seed) ^ k)) >> 2
        seeds.append(s)
        for i in range(n):
            g = f["records"]["%s_s%06d" % (name, i)]
            want = "synthetic:%d:%d:%s" % (s, i, name)
            got = g.attrs["file"].decode() if isinstance(g.attrs["file"], bytes) else g.attrs["file"]
            ev = g.attrs["event"].decode() if isinstance(g.attrs["event"], bytes) else g.attrs["event"]
            assert got == want, (got, want)
            assert ev == event, (ev, event)
    # --synthetic-only read no record, yet the file names the suite the model was fitted to
    suite_file = f.attrs["suite_file"]
    assert (suite_file.decode() if isinstance(suite_file, bytes) else suite_file) == sys.argv[4], suite_file
print(" ".join(map(str, seeds)))
PY
) || fail "seeds or metadata"
set -- $seeds
# synth's motions of those seeds, renamed as the suite names them, after the site's records.
"$rs" synth --record "$data/loma_prieta_1989.dat" --record-units m/s^2 --seed "$1" --count $n -q -o "$dir/w/loma"
"$rs" synth --record "$data/spitak_1988.dat" --record-units m/s^2 --seed "$2" --count $n -q -o "$dir/w/spitak"
for r in loma spitak; do
  tail -n +3 "$dir/w/$r/suite.csv" | sed "s|^synthetic_s[0-9]*_\([0-9]*\),|${r}_s\1,$r/|"
done > "$dir/w/motions.rows"
{ sed -n 2p "$dir/w/loma/suite.csv"; cat "$dir/w/motions.rows"; } > "$dir/w/only.csv"
{ sed -n 2p "$dir/w/loma/suite.csv"
  tail -n +2 "$site" | sed 's|,[^,]*$|,,|'
  cat "$dir/w/motions.rows"; } > "$dir/w/all.csv"
"$rs" suite "${common[@]}" "${levels[@]}" --suite "$dir/w/only.csv" -o "$dir/files_only.h5"
"$rs" suite "${common[@]}" "${levels[@]}" --suite "$dir/w/all.csv" -o "$dir/files.h5"
for pair in "files_only made_only" "files made"; do
  set -- $pair
  h5diff "$dir/$1.h5" "$dir/$2.h5" /suite /suite || fail "$2: /suite differs from synth's motions swept from files"
  for ds in record pga_g pgv_m_s arias_m_s sa_g scale_factor; do
    h5diff "$dir/$1.h5" "$dir/$2.h5" /records/$ds /records/$ds || fail "$2: /records/$ds differs"
  done
done
# The CSV's scale is the record's as swept, and is fitted: Loma Prieta at 2 has 4 times its I_a.
site_csv 2 > "$dir/site2.csv"
ia() { h5dump -a /synthetic_motions "$1" | grep -o 'loma: I_a = [0-9.e+-]*' | sed 's/.* //'; }
"$rs" suite "${common[@]}" --suite "$dir/site2.csv" --synthetic-per-record 1 --synthetic-only --intensity-points 1 --intensity-range 0.5 0.5 -o "$dir/scaled.h5"
"$rs" suite "${common[@]}" --suite "$site" --synthetic-per-record 1 --synthetic-only --intensity-points 1 --intensity-range 0.5 0.5 -o "$dir/unscaled.h5"
awk -v a="$(ia "$dir/scaled.h5")" -v b="$(ia "$dir/unscaled.h5")" 'BEGIN { r = a / b; exit !(r > 3.998 && r < 4.002) }' \
  || fail "I_a at scale 2: $(ia "$dir/scaled.h5") against $(ia "$dir/unscaled.h5") at 1"
# Resume: another N, seed or --synthetic-only is refused, the file untouched.
sum=$(md5sum < "$dir/made_only.h5")
for other in "--synthetic-per-record 4 --seed $seed --synthetic-only" "--synthetic-per-record $n --seed 6 --synthetic-only" \
             "--synthetic-per-record $n --seed $seed"; do
  # shellcheck disable=SC2086
  if err=$("$rs" suite "${common[@]}" "${levels[@]}" --suite "$site" $other --resume -o "$dir/made_only.h5" 2>&1); then fail "$other: resumed"; fi
  echo "$other -> $err"
  [ "$(grep -c . <<<"$err")" -eq 1 ] && grep -q "made_only.h5" <<<"$err" || fail "$other: not one line naming the file"
  [ "$(md5sum < "$dir/made_only.h5")" = "$sum" ] || fail "$other: the file changed"
  # Another seed makes other motions: said as such, not as a record file that changed.
  case "$other" in *"--seed 6"*) grep -q "synthetic motion .* the synthetic options" <<<"$err" || fail "$other: $err";; esac
done
"$rs" suite "${common[@]}" "${levels[@]}" --suite "$site" --synthetic-per-record $n --seed $seed --synthetic-only --resume -o "$dir/made_only.h5" \
  || fail "the same options: not resumed"
echo "ok: fitted motions made on the ranks = synth's of the derived seeds, swept from files"
