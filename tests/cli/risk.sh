#!/usr/bin/env bash
# risk.sh RS SUITE REPO DIR: the risk of a small suite at the illustrative site, from the plain
# curve and from the same curve in OpenQuake's layout: the same rates (to the 7 digits OpenQuake
# writes), P = 1 - exp(-rate t), the deaggregation integrating to the rate, the provenance.
set -eu
rs="$1"; suite="$2"; repo="$3"; dir="$4"
mkdir -p "$dir"
"$rs" risk --suite-file "$suite" --hazard "$repo/configs/hazard_illustrative_pga.csv" -o "$dir/plain.h5" --overwrite \
  --exposure-years 50 > "$dir/plain.txt"
cat "$dir/plain.txt"
grep -q "^overturning, 50 years:" "$dir/plain.txt"
"$rs" risk --suite-file "$suite" --hazard "$repo/configs/hazard_illustrative_pga_openquake.csv" -o "$dir/oq.h5" --overwrite --quiet \
  --exposure-years 50
/usr/bin/python3 - "$dir/plain.h5" "$dir/oq.h5" "$repo/scripts" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[3])
import read_risk
P, Q = read_risk.load(sys.argv[1]), read_risk.load(sys.argv[2])
assert P["attrs"]["hazard_format"] == "plain" and Q["attrs"]["hazard_format"] == "openquake"
assert Q["attrs"]["investigation_time_years"] == 1.0
with read_risk.h5py.File(sys.argv[1]) as f:
    assert "risk.hazard = " in f["provenance"].attrs["config"].decode()
checked = 0
for name, p in P["scenarios"].items():
    q = Q["scenarios"][name]
    for key in ("rate_fit", "rate_empirical"):
        a, b = p[key], q[key]
        ok = np.isfinite(a) & (a > 0)
        # OpenQuake's 7 significant digits of P near 1 (the lowest levels) limit the agreement.
        assert np.allclose(a[ok], b[ok], rtol=2e-4, atol=0), (name, key, a, b)
        checked += ok.sum()
    t = P["attrs"]["exposure_years"]
    assert np.allclose(p["probability_fit"], -np.expm1(-p["rate_fit"] * t), rtol=1e-12, equal_nan=True)
    pos = p["rate_fit"] > 0
    assert np.allclose(p["return_period_fit"][pos] * p["rate_fit"][pos], 1.0, rtol=1e-12)
    x = np.log(P["intensity"])
    for s in range(len(P["states"])):
        lam = p["rate_fit"][s, 0, 0]
        if np.isfinite(lam) and lam > 0 and p["beta"][s, 0, 0] > 0.05:
            area = np.trapz(p["deaggregation_fit"][s, 0, 0], x)
            assert abs(area / lam - 1) < 0.01, (name, s, area, lam)
assert checked >= 6, checked
print("plain and OpenQuake rates agree on", checked, "rates")
# As every rocksweep file (tests/io/test_xarray_names.py): CF Conventions, and no variable that
# xarray or numpy would hide behind a method (`median` is Dataset.median).
import xarray as xr
taken = set(dir(xr.Dataset)) | set(dir(xr.DataArray)) | set(dir(np.ndarray))
with read_risk.h5py.File(sys.argv[1]) as f:
    conventions = f.attrs["Conventions"]
    assert (conventions.decode() if isinstance(conventions, bytes) else conventions) == "CF-1.8", conventions
    names = set()
    f.visit(lambda n: names.add(n.rsplit("/", 1)[-1]))
assert not names & taken, sorted(names & taken)
PY

# A suite file of format 2 (before its median was renamed median_intensity) gives the same risk.
cp "$suite" "$dir/suite_v2.h5"
/usr/bin/python3 - "$dir/suite_v2.h5" <<'PY'
import sys
import h5py
with h5py.File(sys.argv[1], "r+") as f:
    f.attrs["format_version"] = 2
    for g in f["suite"].values():
        for new, old in (("median_intensity", "median"), ("median_intensity_lo", "median_lo"), ("median_intensity_hi", "median_hi")):
            g["fragility"].move(new, old)
PY
"$rs" risk --suite-file "$dir/suite_v2.h5" --hazard "$repo/configs/hazard_illustrative_pga.csv" -o "$dir/v2.h5" --overwrite --quiet \
  --exposure-years 50
h5diff -d 0 "$dir/plain.h5" "$dir/v2.h5" /risk
