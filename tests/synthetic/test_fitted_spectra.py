#!/usr/bin/env python3
"""Fitted to each shared record, the model's motions have the record's spectrum.

For every record of tests/data: `rocksweep synth --record` fits the model and writes COUNT
motions; the median of their 5 %-damped pseudo-acceleration spectra must lie within a stated
band of the record's own over 0.1-3 s, and their mean I_a, D5-95 and t_mid near the record's.
The spectra are computed here, independently of rocksweep: scipy's exact discretisation of the
oscillator for piecewise-linear ground motion (first-order hold), applied with lfilter.

usage: test_fitted_spectra.py ROCKSWEEP DATA_DIR WORK_DIR [COUNT]
"""
import math
import os
import shutil
import sys

import numpy as np

# The records, their reading and the spectra: scripts/rsmotion.py (scipy, not rocksweep's C++).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import rsmotion  # noqa: E402

PERIODS = np.geomspace(0.1, 3.0, 12)
DAMPING = 0.05
# Stated bands (docs/synthetic.md, "Fitted to the shared records"): the median spectrum within
# a factor BAND of the record's at every period, and its geometric mean ratio over the periods
# in MEAN_RANGE. The single-mode filter puts the motion's energy near f_mid: the median is low
# away from it (0.59-1.01 on average when written; 0.29 at 3 s under the pulse of Sylmar).
BAND = 3.5
MEAN_RANGE = (0.5, 1.2)
# Mean I_a of the motions: the record's within four standard errors of the mean and 1 % (the
# generator gives back the high-pass's share, 3 zeta_f f_c / f_mid of it, 42 % for Kocaeli);
# D5-95 and t_mid within LANDMARK of the record's (Kocaeli's t_mid, moved 25 % by the
# high-pass, which takes its long low-frequency tail, excepted to 30 %).
ARIAS_BIAS = 0.01
LANDMARK = {"kocaeli_1999.dat": 0.3}


def main():
    rocksweep, data_dir, work = sys.argv[1:4]
    count = int(sys.argv[4]) if len(sys.argv) > 4 else 200
    failures = []
    for name, units, column in rsmotion.SHARED_RECORDS:
        path = os.path.join(data_dir, name)
        a_rec, dt = rsmotion.read_record(path, units, column)
        out = os.path.join(work, name.split(".")[0])
        motions, fitted = rsmotion.synthesise(rocksweep, path, units, column, count, 2026, out)
        shutil.rmtree(out)
        median = np.median(rsmotion.psa(motions, dt, PERIODS, DAMPING), axis=0)
        own = rsmotion.psa(a_rec, dt, PERIODS, DAMPING)[0]
        ratio = median / own
        mean_ratio = math.exp(np.mean(np.log(ratio)))
        ia, d595, tmid = rsmotion.arias_landmarks(motions, dt)
        ia_r, d_r, t_r = (x[0] for x in rsmotion.arias_landmarks(a_rec, dt))
        line = (f"{name}: median/record PSA {ratio.min():.2f}-{ratio.max():.2f} (geometric mean {mean_ratio:.2f}); "
                f"mean I_a {ia.mean() / ia_r:.3f} (+- {ia.std(ddof=1) / math.sqrt(len(ia)) / ia_r:.3f}), D5-95 {d595.mean() / d_r:.3f}, t_mid {tmid.mean() / t_r:.3f} of the record's")
        print(line)
        print("   ", fitted)
        if not (ratio.max() < BAND and ratio.min() > 1 / BAND and MEAN_RANGE[0] < mean_ratio < MEAN_RANGE[1]):
            failures.append("spectrum: " + line)
        tol = LANDMARK.get(name, 0.1)
        ia_se = ia.std(ddof=1) / math.sqrt(len(ia))
        if not (abs(ia.mean() - ia_r) < 4.0 * ia_se + ARIAS_BIAS * ia_r and abs(d595.mean() / d_r - 1) < tol
                and abs(tmid.mean() / t_r - 1) < tol):
            failures.append("landmarks: " + line)
    if failures:
        print("FAILED:\n" + "\n".join(failures))
        return 1
    print(f"all {len(rsmotion.SHARED_RECORDS)} records: median spectrum of {count} motions within a factor {BAND} of the record's "
          f"(geometric mean ratio in {MEAN_RANGE}), landmarks in their bands")
    return 0


if __name__ == "__main__":
    sys.exit(main())
