#!/usr/bin/env bash
# design_risk.sh RS REPO DIR: a small risk-based design (design --suite --hazard) and the same
# suite through rocksweep risk: the design's free-standing rate of overturning is the risk
# command's empirical rate of the round's free block, and the criterion is exp(-rate t).
# --keep-rounds: a finished design removes its round files otherwise.
set -eu
rs="$1"; repo="$2"; dir="$3"
mkdir -p "$dir"
cd "$repo"
"$rs" design --config configs/design.toml --suite configs/records_suite.csv --intensity-points 8 \
  --coarse-points 3 --rounds 1 --hazard configs/hazard_illustrative_pga.csv --exposure-years 50 --keep-rounds \
  --overwrite --quiet -o "$dir/design.h5"
"$rs" risk --suite-file "$dir/design.round0.h5" --hazard configs/hazard_illustrative_pga.csv --overwrite --quiet \
  -o "$dir/risk.h5"
/usr/bin/python3 - "$dir/design.h5" "$dir/risk.h5" scripts <<'PY'
import sys
import h5py
import numpy as np
sys.path.insert(0, sys.argv[3])
import read_risk
R = read_risk.load(sys.argv[2])
s = R["states"].index("overturning")
with h5py.File(sys.argv[1], "r") as f:
    t = f.attrs["exposure_years"]
    free = f.attrs["free_annual_rate_overturning"]
    emp = R["scenarios"]["free"]["rate_empirical"][s, 0, 0]
    assert abs(free / emp - 1) < 1e-12, (free, emp)
    assert abs(f.attrs["free_safe_fraction"] - np.exp(-f.attrs["free_annual_rate"] * t)) < 1e-15
    for g in ("constant", "adaptive"):
        rate, safe = f[g]["annual_rate"][()], f[g]["safe_fraction"][()]
        assert np.allclose(safe, np.exp(-rate * t), rtol=0, atol=1e-15), g
        best = f[g].attrs["optimum_index"]
        assert rate[best] == rate.min(), (g, rate)
    print("free", free, "best constant", f["constant/annual_rate"][f["constant"].attrs["optimum_index"]])
PY
