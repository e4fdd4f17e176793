#!/usr/bin/env bash
# What each skip saves on the default S. Matteo sweep (configs/smatteo.toml, 7 scenarios,
# 267 337 cells), one process, and whether the results stay the same.
# Run from the repository root on an idle machine:  benchmarks/skips.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep
rs=build/rocksweep
base=(sweep --config configs/smatteo.toml --quiet --overwrite)
echo "default (all skips):              $(wall "$rs" "${base[@]}" -o "$out/skip_default.h5") s"
echo "without the energy decision:      $(wall "$rs" "${base[@]}" --no-energy-stop -o "$out/skip_noenergy.h5") s"
/usr/bin/python3 benchmarks/compare_outcomes.py "$out/skip_noenergy.h5" "$out/skip_default.h5" | tail -1
echo "with boundary refinement from 16: $(wall "$rs" "${base[@]}" --refine 16 -o "$out/skip_refine.h5") s"
/usr/bin/python3 benchmarks/compare_outcomes.py "$out/skip_default.h5" "$out/skip_refine.h5"
echo "scalar lanes (--lanes 1, no vector loop): $(wall "$rs" "${base[@]}" --lanes 1 -o "$out/skip_lanes1.h5") s"
echo "8 lanes without AVX2 (SSE2 loop):  $(ROCKSWEEP_NO_AVX2=1 wall "$rs" "${base[@]}" -o "$out/skip_sse2.h5") s"
h5diff --exclude-path /provenance "$out/skip_default.h5" "$out/skip_lanes1.h5" >/dev/null &&
  h5diff --exclude-path /provenance "$out/skip_default.h5" "$out/skip_sse2.h5" >/dev/null &&
  echo "lanes 1, SSE2 and AVX2 files: identical"
/usr/bin/python3 - "$out/skip_default.h5" <<'PY'
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    a = f["spectra/free/amplitude_ratio"][:]
    alpha = f.attrs["alpha_rad"]
    below = (a * alpha <= np.tan(alpha)).sum()
    print(f"cells below the uplift threshold, decided without integrating: {below} of {a.size} amplitude rows "
          f"({100 * below / a.size:.2f} % of the cells)")
PY
