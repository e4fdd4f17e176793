#!/usr/bin/python3
"""plot_fragility_compare.py's statistics on a real suite file (rocksweep suite): its probit fit of
the stripes gives the file's own medians (rocksweep's Newton fit, docs/fragility.md) to 1e-4, and
each paired bootstrap interval holds the ratio of the file's medians.

usage: test_fragility_compare.py SUITE.h5
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import plot_fragility_compare as pfc  # noqa: E402


def main(path):
    S, j = pfc.load(path, None, None)
    failures, checked = [], 0
    for name, sc in S["scenarios"].items():
        fr = sc["fragility"]
        for s, state in enumerate(fr["states"]):
            if fr["fit_status_names"][s, j] != "ok":
                continue
            ours = pfc.probit_fit(S["intensity"], fr["exceed"][s, j].astype(float), fr["total"][s, j].astype(float))[0]
            theirs = fr["median_intensity"][s, j]
            checked += 1
            if not abs(ours / theirs - 1) < 1e-4:
                failures.append("{} {}: probit median {:.6g}, the file's {:.6g}".format(name, state, ours, theirs))
    for nm, ref, r, lo, hi, n in pfc.paired_ratios(S, j, "overturning", 200):
        if n and not (lo <= r <= hi):
            failures.append("{} / {}: ratio {:.4f} outside its bootstrap interval {:.4f}-{:.4f}".format(nm, ref, r, lo, hi))
    print("{} fits compared; {}".format(checked, "; ".join(failures) or "all agree"))
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
