#!/usr/bin/env bash
# The default S. Matteo sweep (configs/smatteo.toml) as scripts/run.sh runs it, on 2 ranks:
# cells per second, and agreement with the same sweep at a tight setting (steps per period
# 512). Also the mode-2 boundary across anchorages (the paper's Conclusions ii).
# Run from the repository root on an idle machine:  benchmarks/smatteo_accuracy.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep
base=(build/rocksweep sweep --config configs/smatteo.toml --quiet --overwrite)
t=$(wall "${mpi[@]}" -np 2 "${base[@]}" -o "$out/smatteo_default.h5")
echo "default sweep, 267 337 cells on 2 ranks: $t s wall, $(echo "267337 / $t" | bc) cells/s (mpirun start-up and file included)"
t=$(wall "${mpi[@]}" -np 2 "${base[@]}" --steps-per-period 512 -o "$out/smatteo_tight.h5")
echo "tight sweep (steps per period 512): $t s"
/usr/bin/python3 benchmarks/compare_outcomes.py "$out/smatteo_tight.h5" "$out/smatteo_default.h5"
/usr/bin/python3 - "$out/smatteo_tight.h5" "$out/smatteo_default.h5" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
    worst = 0.0
    for n in a["spectra"]:
        x, y = a["spectra"][n]["max_rotation"][:], b["spectra"][n]["max_rotation"][:]
        safe = (a["spectra"][n]["outcome"][:] == 0) & (b["spectra"][n]["outcome"][:] == 0)
        worst = max(worst, float(np.nanmax(np.abs(x[safe] - y[safe]))))
    print(f"max |max_rotation difference| over cells safe in both: {worst:.2e} (in units of alpha)")
PY
/usr/bin/python3 benchmarks/mode2_boundary.py "$out/smatteo_tight.h5"
