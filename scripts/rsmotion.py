"""Ground motions in Python, independently of rocksweep's C++: the shared records as read (their
units and columns), the two-column motions `rocksweep synth` writes, 5 %-damped response spectra
by scipy's exact discretisation of the oscillator (first-order hold, as rocksweep's own) and the
Arias landmarks (I_a, D5-95, t_mid). Used by plot_synthetic_fit.py and, as an independent
reference, by tests/synthetic/test_fitted_spectra.py.
"""
import math
import os
import subprocess

import numpy as np
from scipy import signal

G = 9.80665
UNITS = {"g": 1.0, "m/s^2": 1.0 / G, "cm/s^2": 0.01 / G}

# The shared records (tests/data, README there): file, units (None: the .AT2 header's), column
# of the acceleration counting the time column (0: the .AT2's own layout).
SHARED_RECORDS = [
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


def _read_text(path, column):
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


def _read_at2(path):
    with open(path) as f:
        lines = f.readlines()
    if "UNITS OF G" not in lines[2].upper():
        raise ValueError("{}: an .AT2 file not in g".format(path))
    head = lines[3].replace(",", " ").upper().split()
    dt = float(head[head.index("DT=") + 1]) if "DT=" in head else float(lines[3].split("DT=")[1].split()[0])
    return np.array([float(x) for line in lines[4:] for x in line.split()]), dt


def read_record(path, units, column):
    """(acceleration [g], dt [s]) of a shared record as rocksweep reads it (SHARED_RECORDS)."""
    if units is None:
        return _read_at2(path)
    a, dt = _read_text(path, column)
    return a * UNITS[units], dt


def synth_command(rocksweep, path, units, column):
    """The `rocksweep synth --record ...` options that read a shared record as read_record does."""
    cmd = [rocksweep, "synth", "--record", path]
    if units is not None:
        cmd += ["--record-units", units, "--record-column", str(column)]
    return cmd


def synthesise(rocksweep, path, units, column, count, seed, folder):
    """Fits the model to the record, writes `count` motions into `folder` and reads them back:
    (motions [g], one row each, the fitted line `synth` printed)."""
    out = subprocess.run(synth_command(rocksweep, path, units, column) +
                         ["--count", str(count), "--seed", str(seed), "--overwrite", "-o", folder],
                         check=True, capture_output=True, text=True).stdout
    motions = []
    for i in range(count):
        with open(os.path.join(folder, "synthetic_s%d_%06d.txt" % (seed, i))) as f:
            f.readline()
            motions.append(np.array(f.read().split(), dtype=float)[1::2])
    return np.array(motions), out.splitlines()[1]


def psa(acc_g, dt, periods, damping=0.05):
    """Pseudo-acceleration [g] of each row of acc_g at `periods` [s]: w^2 max|u| of
    u'' + 2 zeta w u' + w^2 u = -a, exact for a piecewise-linear a."""
    acc_g = np.atleast_2d(acc_g)
    out = np.empty((acc_g.shape[0], len(periods)))
    for j, period in enumerate(periods):
        w = 2.0 * math.pi / period
        num, den, _ = signal.cont2discrete(([-1.0], [1.0, 2.0 * damping * w, w * w]), dt, method="foh")
        u = signal.lfilter(np.ravel(num), den, acc_g, axis=1)
        out[:, j] = w * w * np.max(np.abs(u), axis=1)
    return out


def arias_landmarks(acc_g, dt):
    """I_a [m/s], D5-95 and t_mid [s] of each row, from the cumulative sum of squares."""
    cum = np.cumsum((np.atleast_2d(acc_g) * G) ** 2, axis=1) * dt
    total = cum[:, -1]
    times = [np.array([np.interp(f * c[-1], c, np.arange(len(c)) * dt) for c in cum]) for f in (0.05, 0.45, 0.95)]
    return math.pi / (2 * G) * total, times[2] - times[0], times[1]
