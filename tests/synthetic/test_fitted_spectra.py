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
import subprocess
import sys

import numpy as np
from scipy import signal

G = 9.80665
UNITS = {"g": 1.0, "m/s^2": 1.0 / G, "cm/s^2": 0.01 / G}
# file, units (None: the .AT2 header's), column of the acceleration counting the time column
RECORDS = [
    ("elcentro_1940_NS.dat", "g", 2),
    ("northridge_1994_sylmar.dat", "m/s^2", 2),
    ("cape_mendocino_1992.dat", "m/s^2", 2),
    ("kocaeli_1999.dat", "m/s^2", 2),
    ("loma_prieta_1989.dat", "m/s^2", 2),
    ("san_fernando_1971.dat", "m/s^2", 2),
    ("spitak_1988.dat", "m/s^2", 2),
    ("san_salvador_1986_gic090.txt", "m/s^2", 2),
    ("cephalonia_2014_chv1_E.txt", "cm/s^2", 2),
    ("mexico_city_1985_sct.txt", "g", 2),
    ("RSN1044_northridge_1994_newhall_rot.AT2", None, 0),
]
PERIODS = np.geomspace(0.1, 3.0, 12)
DAMPING = 0.05
# Stated bands (docs/synthetic.md, "Fitted to the shared records"): the median spectrum within
# a factor BAND of the record's at every period, and its geometric mean ratio over the periods
# in MEAN_RANGE. The single-mode filter puts the motion's energy near f_mid: the median is low
# away from it (0.57-0.97 on average when written; 0.29 at 3 s under the pulse of Sylmar).
BAND = 3.5
MEAN_RANGE = (0.5, 1.2)
# Mean I_a of the motions over the record's: the high-pass takes about 3 zeta_f f_c / f_mid of
# it, 42 % for Kocaeli (f_mid = 1 Hz, zeta_f = 0.9); D5-95 and t_mid within LANDMARK of the
# record's (Kocaeli's t_mid, moved 25 % by that loss, excepted to 30 %).
ARIAS_RANGE = (0.5, 1.02)
LANDMARK = {"kocaeli_1999.dat": 0.3}


def read_text(path, column):
    rows = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line[0] in "#%":
                continue
            rows.append([float(x) for x in line.replace(",", " ").split()])
    data = np.array(rows)
    t, a = data[:, 0], data[:, column - 1]
    dt = (t[-1] - t[0]) / (len(t) - 1)
    if t[0] > 0.5 * dt:  # a file that starts at t = dt: rocksweep puts a zero at t = 0
        a = np.concatenate([[0.0], a])
    return a, dt


def read_at2(path):
    with open(path) as f:
        lines = f.readlines()
    unit = "g" if "UNITS OF G" in lines[2].upper() else None
    head = lines[3].replace(",", " ").upper().split()
    dt = float(head[head.index("DT=") + 1]) if "DT=" in head else float(lines[3].split("DT=")[1].split()[0])
    a = np.array([float(x) for line in lines[4:] for x in line.split()])
    assert unit == "g", "the shared .AT2 is in g"
    return a, dt


def psa(acc_g, dt):
    """5 %-damped pseudo-acceleration [g] of each row of acc_g at PERIODS."""
    out = np.empty((acc_g.shape[0], len(PERIODS)))
    for j, period in enumerate(PERIODS):
        w = 2.0 * math.pi / period
        # u'' + 2 zeta w u' + w^2 u = -a: relative displacement, exact for linear segments.
        num, den, _ = signal.cont2discrete(([-1.0], [1.0, 2.0 * DAMPING * w, w * w]), dt, method="foh")
        u = signal.lfilter(np.ravel(num), den, acc_g, axis=1)
        out[:, j] = w * w * np.max(np.abs(u), axis=1)
    return out


def arias_landmarks(acc_g, dt):
    """I_a [m/s], D5-95 and t_mid [s] of each row, from the cumulative sum of squares."""
    cum = np.cumsum((acc_g * G) ** 2, axis=1) * dt
    total = cum[:, -1]
    times = [np.array([np.interp(f * c[-1], c, np.arange(len(c)) * dt) for c in cum]) for f in (0.05, 0.45, 0.95)]
    return math.pi / (2 * G) * total, times[2] - times[0], times[1]


def main():
    rocksweep, data_dir, work = sys.argv[1:4]
    count = int(sys.argv[4]) if len(sys.argv) > 4 else 200
    failures = []
    for name, units, column in RECORDS:
        path = os.path.join(data_dir, name)
        if units is None:
            a_rec, dt = read_at2(path)
        else:
            a_rec, dt = read_text(path, column)
            a_rec = a_rec * UNITS[units]
        out = os.path.join(work, name.split(".")[0])
        shutil.rmtree(out, ignore_errors=True)
        cmd = [rocksweep, "synth", "--record", path, "--count", str(count), "--seed", "2026", "-o", out]
        if units is not None:
            cmd += ["--record-units", units, "--record-column", str(column)]
        fitted = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
        motions = []
        for i in range(count):
            with open(os.path.join(out, "synthetic_s2026_%06d.txt" % i)) as f:
                f.readline()
                motions.append(np.array(f.read().split(), dtype=float)[1::2])
        motions = np.array(motions)
        shutil.rmtree(out)
        median = np.median(psa(motions, dt), axis=0)
        own = psa(a_rec[None, :], dt)[0]
        ratio = median / own
        mean_ratio = math.exp(np.mean(np.log(ratio)))
        ia, d595, tmid = arias_landmarks(motions, dt)
        ia_r, d_r, t_r = (x[0] for x in arias_landmarks(a_rec[None, :], dt))
        line = (f"{name}: median/record PSA {ratio.min():.2f}-{ratio.max():.2f} (geometric mean {mean_ratio:.2f}); "
                f"mean I_a {ia.mean() / ia_r:.3f}, D5-95 {d595.mean() / d_r:.3f}, t_mid {tmid.mean() / t_r:.3f} of the record's")
        print(line)
        print("   ", fitted.splitlines()[1])
        if not (ratio.max() < BAND and ratio.min() > 1 / BAND and MEAN_RANGE[0] < mean_ratio < MEAN_RANGE[1]):
            failures.append("spectrum: " + line)
        tol = LANDMARK.get(name, 0.1)
        if not (ARIAS_RANGE[0] < ia.mean() / ia_r < ARIAS_RANGE[1] and abs(d595.mean() / d_r - 1) < tol
                and abs(tmid.mean() / t_r - 1) < tol):
            failures.append("landmarks: " + line)
    if failures:
        print("FAILED:\n" + "\n".join(failures))
        return 1
    print(f"all {len(RECORDS)} records: median spectrum of {count} motions within a factor {BAND} of the record's "
          f"(geometric mean ratio in {MEAN_RANGE}), landmarks in their bands")
    return 0


if __name__ == "__main__":
    sys.exit(main())
