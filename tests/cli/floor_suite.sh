#!/usr/bin/env bash
# floor_suite.sh ROCKSWEEP CONFIG SUITE WORKDIR
# A suite on the ground, a building's floor and a plinth on it stores each floor's products as
# docs/suite.md says (PFA, PFA/PGA, the 5 %-damped floor spectra, their medians, Sa of the
# ground), each scenario knows its floor, plot_floors.py draws them, and a resume with another
# floor or another Sa oscillator is refused with exit status 2, the file left as it was, and one
# with the same floors spelt otherwise is accepted.
# `simulate --floor` and `design --suite --floor` run on the floor and store it.
set -eu
rs="$1"; cfg="$2"; suite="$3"; dir="$4"
mkdir -p "$dir"
out="$dir/floors.h5"
floors=(--floor ground "f2: 0.5 0.05 1.3; 0.17 0.05 -0.4" "plinth2: 0.5 0.05 1.3; 0.17 0.05 -0.4 > 2.5 0.15 1")
args=(suite --config "$cfg" --suite "$suite" --anchorages free --intensity-points 2 --intensity-range 0.2 0.4
      --intensity-measure sa --quiet)
"$rs" "${args[@]}" "${floors[@]}" --sa-period 0.5 -o "$out" --overwrite
/usr/bin/python3 - "$out" <<'PY'
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], "r")
assert sorted(f["suite"]) == ["free@f2", "free@ground", "free@plinth2"], list(f["suite"])
assert f["suite/free@f2"].attrs["floor"] in (b"f2", "f2")
pga = f["records/pga_g"][:]
sa = f["records/sa_g"]
assert sa.attrs["period_s"] == 0.5 and sa.attrs["damping"] == 0.05
g = f["floors/ground"]
assert np.array_equal(g["pfa_g"][:], pga), "the ground's PFA is the PGA"
for name in ("ground", "f2", "plinth2"):
    fl = f["floors"][name]
    pfa, spectrum = fl["pfa_g"][:], fl["spectrum_g"][:]
    assert spectrum.shape == (len(pga), 60)
    assert np.array_equal(fl["pfa_over_pga"][:], pfa / pga)
    assert np.array_equal(fl["median_spectrum_g"][:], np.median(spectrum, axis=0))
    assert fl.attrs["median_pfa_g"] == np.median(pfa)
    assert np.all(np.isfinite(spectrum)) and np.all(spectrum > 0), name
    # levels follow Sa of the ground on every floor: the same factors
    assert np.array_equal(fl["scale_factor"][:], f["records/scale_factor"][:])
# The isolated plinth (2.5 s) cuts the floor's acceleration 3-14 times, except under Mexico
# City's SCT records, whose soft-soil motion near 2 s it amplifies: isolation is no cure-all.
names = f["records/record"].attrs["flag_meanings"]
names = (names.decode() if isinstance(names, bytes) else names).split()
ratio = f["floors/plinth2/pfa_g"][:] / f["floors/f2/pfa_g"][:]
mexico = np.array([n.startswith("mexico") for n in names])
assert np.all(ratio[~mexico] < 0.35), ratio
assert np.all(ratio[mexico] > 1.0), ratio
print("floor products as documented")
PY
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
/usr/bin/python3 "$here/tests/scripts/check_figure.py" --expect "$dir/floors" -- \
  /usr/bin/python3 "$here/scripts/plot_floors.py" "$out" -o "$dir/floors"
# Levels of Sa(0.5 s) meet a site's SA(0.5) hazard curve in rocksweep risk; SA(1.0) is refused.
printf 'SA(0.5) [g],annual_rate [1/yr]\n0.1,1e-2\n0.5,1e-4\n' > "$dir/sa05.csv"
printf 'SA(1.0) [g],annual_rate [1/yr]\n0.1,1e-2\n0.5,1e-4\n' > "$dir/sa10.csv"
"$rs" risk --suite-file "$out" --hazard "$dir/sa05.csv" --overwrite --quiet -o "$dir/risk.h5"
h5ls "$dir/risk.h5/risk/free@f2" >/dev/null || { echo "no risk of the block on f2"; exit 1; }
set +e
err=$("$rs" risk --suite-file "$out" --hazard "$dir/sa10.csv" --overwrite --quiet -o "$dir/risk10.h5" 2>&1)
status=$?
set -e
[ "$status" -eq 2 ] && grep -qF "sa_g at T = 0.5 s" <<<"$err" || { echo "SA(1.0) against Sa(0.5 s) levels: exit $status: $err"; exit 1; }
cp "$out" "$dir/before.h5"
expect_refusal() {
  local what="$1"; shift
  set +e
  err=$("$rs" "${args[@]}" "$@" -o "$out" --resume 2>&1)
  status=$?
  set -e
  [ "$status" -eq 2 ] || { echo "resume with $what: exit $status, not 2"; exit 1; }
  grep -q "$what" <<<"$err" || { echo "resume with another $what: message does not name it: $err"; exit 1; }
  cmp -s "$out" "$dir/before.h5" || { echo "a refused resume changed the file"; exit 1; }
}
expect_refusal floors --sa-period 0.5 --floor ground "f2: 0.5 0.05 1.2; 0.17 0.05 -0.4" "plinth2: 0.5 0.05 1.3; 0.17 0.05 -0.4 > 2.5 0.15 1"
expect_refusal sa_oscillator "${floors[@]}" --sa-period 0.6
# The same floors spelt otherwise are the same floors (compared parsed, not as typed): resumed.
"$rs" "${args[@]}" --floor ground "f2: 0.50 0.05 1.30; 0.17 0.050 -0.4" "plinth2: 0.5 0.05 1.3; 0.17 0.05 -0.4 > 2.5 0.15 1.0" \
  --sa-period 0.50 -o "$out" --resume || { echo "resume with the same floors spelt otherwise refused"; exit 1; }
cmp -s "$out" "$dir/before.h5" || { echo "resuming a complete file changed it"; exit 1; }

here_cfg="$here/configs"
"$rs" simulate --config "$cfg" --record "$here/tests/data/elcentro_1940_NS.dat" --record-units g \
  --floor "f2: 0.5 0.05 1.3" --quiet --overwrite -o "$dir/history.h5"
h5dump -a /floor "$dir/history.h5" | grep -qF '"f2: 0.5 0.05 1.3"' || { echo "simulate does not store its floor"; exit 1; }
"$rs" design --config "$here_cfg/design.toml" --suite "$suite" --intensity-points 2 --coarse-points 4 --rounds 1 \
  --floor "f2: 0.5 0.05 1.3" --keep-rounds --quiet --overwrite -o "$dir/design.h5"
h5ls "$dir/design.round0.h5/suite" | grep -q "^free@f2 " || { echo "design's rounds do not stand on the floor"; exit 1; }
h5dump -a /provenance/config "$dir/design.h5" | grep -qF 'floor = ["f2: 0.5 0.05 1.3"]' \
  || { echo "design's provenance does not hold the floor"; exit 1; }
echo "floor suite: products stored, resume checks floors and Sa; simulate and design on a floor"
