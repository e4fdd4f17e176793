#!/usr/bin/python3
"""A peer of the floor filter and of Sa written with scipy, not with rocksweep's code:

    floor_peer.py ROCKSWEEP DATA_DIR WORKDIR

Runs `rocksweep suite` on three shared records (three units, two sampling intervals) with a
floor of two modes and that floor with a plinth on it, then recomputes from the record files:
the floor motion by scipy.signal.lsim (a continuous state space, its input linear between the
samples) on the ground sampled as finely as rocksweep samples the floor, whose peak must be
/floors/<floor>/pfa_g to 1e-9 of it; and Sa(T, zeta) of the ground by lsim on the ground
sampled 32 times finer, which may fall below rocksweep's exact peak by no more than its
sampling can miss, h^2 max|u''| / 8, and never lie above it.
"""
import math
import os
import subprocess
import sys

import h5py
import numpy as np
from scipy import signal

G = 9.80665
RECORDS = [("elcentro", "elcentro_1940_NS.dat", "g", 1.0),
           ("sylmar", "northridge_1994_sylmar.dat", "m/s^2", 1.0 / G),
           ("cephalonia", "cephalonia_2014_chv1_E.txt", "cm/s^2", 0.01 / G)]
FLOOR = [(0.5, 0.05, 1.3), (0.17, 0.05, -0.4)]
PLINTH = [(2.5, 0.15, 1.0)]
SA = (0.3, 0.05)


def stage(modes):
    """(A, B, C, D) of one structure: states (q, q') per mode, output a_g + sum gphi q''."""
    n = 2 * len(modes)
    a, b, c, d = np.zeros((n, n)), np.zeros((n, 1)), np.zeros((1, n)), 1.0
    for i, (t, z, gp) in enumerate(modes):
        w = 2 * math.pi / t
        a[2 * i, 2 * i + 1] = 1
        a[2 * i + 1, 2 * i], a[2 * i + 1, 2 * i + 1] = -w * w, -2 * z * w
        b[2 * i + 1, 0] = -1
        c[0, 2 * i], c[0, 2 * i + 1] = -gp * w * w, -gp * 2 * z * w
        d -= gp
    return a, b, c, d


def series(s1, s2):
    a1, b1, c1, d1 = s1
    a2, b2, c2, d2 = s2
    n1, n2 = a1.shape[0], a2.shape[0]
    a = np.block([[a1, np.zeros((n1, n2))], [b2 @ c1, a2]])
    return a, np.vstack([b1, b2 * d1]), np.hstack([d2 * c1, c2]), d2 * d1


def finer(a, m):
    """The same piecewise-linear motion at m samples per step."""
    t = np.arange(len(a))
    return np.interp(np.arange((len(a) - 1) * m + 1) / m, t, a)


def oversampling(shortest_t, dt):
    return max(1, math.ceil(dt / (shortest_t * math.sqrt(8e-3) / (2 * math.pi))))


def response(system, a, h):
    a_, b_, c_, d_ = system
    t = np.arange(len(a)) * h
    _, y, x = signal.lsim(signal.StateSpace(a_, b_, c_, np.array([[d_]])), a, t, interp=True)
    return y, x


def main():
    rs, data, work = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3]
    os.makedirs(work, exist_ok=True)
    suite = os.path.join(work, "peer_suite.csv")
    with open(suite, "w") as f:
        f.write("name,file,format,units\n")
        for name, path, units, _ in RECORDS:
            f.write(f"{name},{os.path.join(data, path)},time_accel,{units}\n")
    floor = "f2: " + "; ".join(f"{t} {z} {g}" for t, z, g in FLOOR)
    plinth = floor + " > " + "; ".join(f"{t} {z} {g}" for t, z, g in PLINTH)
    out = os.path.join(work, "peer.h5")
    subprocess.run([rs, "suite", "--suite", suite, "--anchorages", "free", "--intensity-points", "1",
                    "--intensity-range", "0.3", "0.3", "--intensity-measure", "sa", "--sa-period", str(SA[0]),
                    "--sa-damping", str(SA[1]), "--floor", floor, plinth.replace("f2:", "p2:", 1),
                    "--quiet", "--overwrite", "-o", out], check=True)
    worst_pfa, worst_sa = 0.0, 0.0
    with h5py.File(out, "r") as f:
        for k, (name, path, _, to_g) in enumerate(RECORDS):
            rec = np.loadtxt(os.path.join(data, path))
            dt = (rec[-1, 0] - rec[0, 0]) / (len(rec) - 1)
            ground = rec[:, 1] * to_g
            for fname, system, shortest in (("f2", stage(FLOOR), 0.17),
                                            ("p2", series(stage(FLOOR), stage(PLINTH)), 0.17)):
                m = oversampling(shortest, dt)
                y, _ = response(system, finer(ground, m), dt / m)
                pfa = np.max(np.abs(y))
                got = f["floors"][fname]["pfa_g"][k]
                worst_pfa = max(worst_pfa, abs(got - pfa) / pfa)
                assert abs(got - pfa) <= 1e-9 * pfa, (name, fname, got, pfa)
            # Sa: the relative displacement of the oscillator, 32 samples per step
            t_sa, z_sa = SA
            w = 2 * math.pi / t_sa
            osc = (np.array([[0, 1], [-w * w, -2 * z_sa * w]]), np.array([[0], [-1]]), np.array([[1.0, 0]]), 0.0)
            m, fine = 32, finer(ground, 32)
            h = dt / m
            u, x = response(osc, fine, h)
            peer = w * w * np.max(np.abs(u))
            # between samples h apart the peak of |u| exceeds the sampled one by <= h^2 max|u''| / 8
            curvature = np.max(np.abs(fine + 2 * z_sa * w * x[:, 1] + w * w * x[:, 0]))
            missed = w * w * h * h * curvature / 8
            got = f["records/sa_g"][k]
            worst_sa = max(worst_sa, got / peer - 1)
            assert missed < 1e-3 * peer, (name, missed, peer)
            assert peer * (1 - 1e-9) <= got <= peer * (1 + 1e-9) + missed, (name, got, peer, missed)
    print(f"scipy peer: PFA within {worst_pfa:.1e} of it on 3 records x 2 floors; "
          f"Sa above the 32x-sampled peer by at most {worst_sa:.1e}")


if __name__ == "__main__":
    main()
