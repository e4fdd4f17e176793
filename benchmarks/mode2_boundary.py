#!/usr/bin/python3
"""Does the overturning-without-impact (mode 2) boundary depend on the anchorage?
(the paper's Conclusions ii)

    mode2_boundary.py SPECTRA.h5

For each scenario and each omega_p/p column, the lowest a_p0/(alpha g) at which the block
overturns without impact; then, per scenario, how far that boundary lies from the one of the
stiffest and of the free block, in grid steps of a_p0/(alpha g).
"""
import sys

import h5py
import numpy as np


def boundary(outcome, amp):
    """Lowest amplitude with mode 2 in each omega column (NaN where there is none)."""
    b = np.full(outcome.shape[1], np.nan)
    for j in range(outcome.shape[1]):
        rows = np.nonzero(outcome[:, j] == 2)[0]
        if rows.size:
            b[j] = amp[rows[0]]
    return b


def main(path):
    with h5py.File(path, "r") as f:
        first = next(iter(f["spectra"].values()))  # every scenario group holds the same axes
        amp = first["amplitude_ratio"][:]
        w = first["omega_ratio"][:]
        step = amp[1] - amp[0]
        bounds = {name: boundary(f["spectra"][name]["outcome"][:], amp) for name in f["spectra"]}
    anchored = [n for n in bounds if n != "free"]
    ref = anchored[0]
    print(f"mode-2 boundary: lowest a_p0/(alpha g) overturning without impact, per omega_p/p column "
          f"(grid step {step:.4g})")
    print(f"{'scenario':22s} {'mean':>8s}  {'vs ' + ref:>24s}  {'vs free':>20s}")
    for name, b in bounds.items():
        d_ref = b - bounds[ref]
        d_free = b - bounds["free"] if "free" in bounds else np.full_like(b, np.nan)
        print(f"{name:22s} {np.nanmean(b):8.3f}  max |diff| {np.nanmax(np.abs(d_ref)):6.3f} "
              f"mean {np.nanmean(d_ref):+6.3f}   mean {np.nanmean(d_free):+6.3f}")
    for wv in (2.0, 4.0, 6.0, 8.0):
        j = int(np.argmin(np.abs(w - wv)))
        print(f"omega_p/p = {w[j]:.2f}: " + ", ".join(f"{n} {bounds[n][j]:.2f}" for n in bounds))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
