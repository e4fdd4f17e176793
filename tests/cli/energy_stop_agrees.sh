#!/usr/bin/env bash
# energy_stop_agrees.sh ROCKSWEEP CONFIG DIR: deciding a block's fate by energy after the pulse
# gives the outcomes of integrating it to rest, for an adaptive restrainer whose K_max spring
# breaks beyond the peak of the K_min potential (theta_f = 2 alpha): the case the shortcut once
# called safe in 33 of these 3721 cells that overturn.
set -u
rs="$1"; cfg="$2"; dir="$3"; rm -rf "$dir"; mkdir -p "$dir"
grid=(--config "$cfg" --anchorages adaptive --kmin-ratios 0.1 0.5 --adaptive-theta-f-ratio 2
      --omega-ratio-points 61 --amplitude-ratio-points 61 --quiet)
"$rs" sweep "${grid[@]}" -o "$dir/energy.h5" || exit 1
"$rs" sweep "${grid[@]}" --no-energy-stop -o "$dir/integrated.h5" || exit 1
/usr/bin/python3 - "$dir/energy.h5" "$dir/integrated.h5" <<'PY'
import sys, h5py, numpy as np
a, b = (h5py.File(p, "r")["spectra"] for p in sys.argv[1:3])
bad = 0
for name in a:
    n = int((a[name]["outcome"][()] != b[name]["outcome"][()]).sum())
    print(name, n, "cells differ")
    bad += n
sys.exit(1 if bad else 0)
PY
