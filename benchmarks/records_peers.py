#!/usr/bin/python3
"""The scipy peer of the records benchmark (benchmarks/README.md, "Peers on recorded ground motions").

The S. Matteo block (b = 0.30 m, h = 1.36 m, m = 3361 kg) rocking under recorded ground motions,
as a careful researcher would script it with scipy: solve_ivp (RK45, rtol 1e-6, atol 1e-9) on the
equation of motion of docs/physics.md, a terminal event at theta = 0 (impact: theta_dot <- e
theta_dot, the pivot changes corner, integration restarts), one at |theta| = pi/2 (overturning)
and, anchored, one at the fracture angle (the spring of that corner breaks for good). A block at
rest lifts off when |a_g| > g tan(alpha) (Eq. 1); an impact slower than 1e-4 p alpha puts it at
rest (the settling rule of rocksweep's simulate). After the record, free rocking only loses
energy: the run is safe once the energy is below the lowest barrier, else integration goes on.

Runs: every record of the suite (default benchmarks/records_peers.csv) at each of its `scales`,
free and with the constant anchorage theta_f = alpha, F_u = 0.4 m g.

    /usr/bin/python3 benchmarks/records_peers.py [--suite S] [--out DIR]

Prints one line `scipy,RUNS,1,WALL_S,CPU_S` (one timed pass over all runs; reading files and
writing results are not timed) and writes DIR/records_peers_scipy.csv (run, t, theta at every
record sample up to the record's end or the overturning) and DIR/records_peers_scipy_outcomes.csv.
"""
import argparse
import csv
import math
import os
import re
import time

import numpy as np
from scipy.integrate import solve_ivp

G = 9.81             # the block's gravity [m/s^2]
G_STANDARD = 9.80665  # what a record "in g" means
UNIT_M_S2 = {"g": G_STANDARD, "m/s^2": 1.0, "cm/s^2": 0.01}


class Block:
    """Rectangular block (physics.md §1) and its anchorage coefficient kappa = 8 b^2 K / I0."""

    def __init__(self, b=0.30, h=1.36, m=3361.0, anchored=False, strength_ratio=0.4):
        self.R = math.hypot(b, h)
        self.alpha = math.atan2(b, h)
        self.p2 = 3.0 * G / (4.0 * self.R)
        self.e = 1.0 - 1.5 * math.sin(self.alpha) ** 2
        inertia = 4.0 / 3.0 * m * self.R ** 2
        self.theta_f = self.alpha if anchored else math.inf
        if anchored:
            k = strength_ratio * m * G / (4.0 * b * math.tan(self.theta_f / 2.0))
            self.kappa = 8.0 * b * b * k / inertia
        else:
            self.kappa = 0.0

    def potential(self, phi, intact):
        """Gravity and (intact) spring potential / I0 at |theta| = phi, zero at rest."""
        v = self.p2 * (math.cos(self.alpha - phi) - math.cos(self.alpha))
        return v + (2.0 * self.kappa * (1.0 - math.cos(phi / 2.0)) if intact else 0.0)


def read_record(path, fmt, units):
    """Samples at t = i dt from t = 0, as acceleration / the block's g, and dt."""
    if fmt == "at2":
        with open(path) as f:
            lines = f.read().splitlines()
        units = "g" if "UNITS OF G" in lines[2].upper() else None
        npts, dt = re.search(r"NPTS=\s*(\d+),\s*DT=\s*([0-9.Ee+-]+)", lines[3]).groups()
        acc = np.array(" ".join(lines[4:]).split(), dtype=float)
        assert units and len(acc) == int(npts), path
        dt = float(dt)
    elif fmt == "time_accel":
        data = np.loadtxt(path)
        t, acc = data[:, 0], data[:, 1]
        assert t[0] == 0.0, path + " must start at t = 0"
        dt = (t[-1] - t[0]) / (len(t) - 1)
    else:
        raise ValueError(fmt)
    return acc * UNIT_M_S2[units] / G, dt


def next_uplift(t, times, acc, thr):
    """First time >= t at which |a| > thr on the piecewise-linear record, or None."""
    i = min(int(t / (times[1] - times[0])), len(times) - 2)
    a_t = np.interp(t, times, acc)
    if abs(a_t) > thr:
        return t
    later = np.nonzero(np.abs(acc[i + 1:]) > thr)[0]
    if len(later) == 0:
        return None
    j = i + 1 + later[0]                      # first sample above the threshold
    t0, a0 = (t, a_t) if j == i + 1 else (times[j - 1], acc[j - 1])
    level = math.copysign(thr, acc[j])
    return t0 + (times[j] - t0) * (level - a0) / (acc[j] - a0)


def simulate(block, acc, dt, rtol, atol, settle):
    """One run: (theta at the samples up to the end or the overturning, outcome, t_overturn,
    max |theta| / alpha, impacts)."""
    times = dt * np.arange(len(acc))
    T = times[-1]
    thr = math.tan(block.alpha)
    v_settle = settle * math.sqrt(block.p2) * block.alpha
    theta_s = np.zeros(len(acc))
    broken = {1: False, -1: False}
    t, side, y = 0.0, 0, [0.0, 0.0]
    impacts, phi_max = 0, 0.0

    def rhs(t, y, s, kappa, moving):
        a = np.interp(t, times, acc) if moving else 0.0
        return [y[1], -block.p2 * (math.sin(s * block.alpha - y[0]) + a * math.cos(s * block.alpha - y[0]))
                - s * kappa * math.sin(s * y[0] / 2.0)]

    def fate_after_record(phi, thd, s):
        """True once free rocking can no longer overturn: energy below every barrier."""
        energy = 0.5 * thd * thd + block.potential(phi, not broken[s])
        barrier = min(block.potential(block.alpha, not broken[k] and block.theta_f >= block.alpha) for k in (1, -1))
        return energy < barrier

    while True:
        moving = t < T
        if side == 0:
            tu = next_uplift(t, times, acc, thr) if moving else None
            if tu is None:
                return theta_s, "safe", math.nan, phi_max / block.alpha, impacts
            t, y = tu, [0.0, 0.0]
            side = -1 if np.interp(tu, times, acc) > 0 else 1
            moving = True
        elif not moving and fate_after_record(abs(y[0]), y[1], side):
            return theta_s, "safe", math.nan, phi_max / block.alpha, impacts
        s = side
        intact = block.kappa > 0 and not broken[s]
        kappa = block.kappa if intact else 0.0
        impact = lambda t, y, *_: y[0]
        impact.terminal, impact.direction = True, -s
        overturn = lambda t, y, *_: math.pi / 2 - s * y[0]
        overturn.terminal = True
        fracture = lambda t, y, *_: block.theta_f - s * y[0]
        fracture.terminal = True
        events = [impact, overturn] + ([fracture] if intact else [])
        t_stop = T if moving else t + 100.0
        t_eval = times[(times > t) & (times <= t_stop)] if moving else None
        sol = solve_ivp(rhs, (t, t_stop), y, method="RK45", rtol=rtol, atol=atol, events=events,
                        t_eval=t_eval, args=(s, kappa, moving))
        if moving and len(sol.t):
            theta_s[np.searchsorted(times, sol.t[0]):np.searchsorted(times, sol.t[-1]) + 1] = sol.y[0]
        phi_max = max(phi_max, float(np.max(np.abs(sol.y[0]))) if len(sol.t) else 0.0)
        if sol.status != 1:            # reached t_stop, the record's end (its last sample)
            if not moving:
                raise RuntimeError("free rocking undecided after 100 s")
            t, y = t_stop, list(sol.y[:, -1])
            continue
        fired = [k for k, te in enumerate(sol.t_events) if len(te)]
        k = fired[0]
        t, y = float(sol.t_events[k][0]), list(sol.y_events[k][0])
        phi_max = max(phi_max, abs(y[0]))
        if k == 1:                     # overturned
            n = int(np.searchsorted(times, t, side="right"))
            outcome = "overturned_with_impact" if impacts else "overturned_without_impact"
            return theta_s[:n], outcome, t, math.pi / 2 / block.alpha, impacts
        if k == 2:                     # the spring of this corner breaks for good
            broken[s] = True
            continue
        impacts += 1                   # impact: Eq. 14, the pivot changes corner
        if abs(y[1]) < v_settle:
            side, y = 0, [0.0, 0.0]
        else:
            side, y = -s, [0.0, block.e * y[1]]


def read_runs(suite):
    """(name, acc, dt, anchored, record, scale) for every row and scale of the suite file."""
    folder = os.path.dirname(os.path.abspath(suite))
    with open(suite) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    runs = []
    for row in rows:
        for scale_text in row["scales"].split():
            acc, dt = read_record(os.path.join(folder, row["file"]), row["format"], row["units"])
            scale = float(scale_text)
            for anch in ("free", "constant"):
                name = f"{row['name']}_x{scale:g}_{anch}"
                runs.append((name, scale * acc, dt, anch == "constant", row["name"], scale))
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--suite", default="benchmarks/records_peers.csv")
    ap.add_argument("--out", default="benchmarks/results")
    ap.add_argument("--rtol", type=float, default=1e-6)
    ap.add_argument("--atol", type=float, default=1e-9)
    ap.add_argument("--settle", type=float, default=1e-4, help="settling speed / (p alpha)")
    ap.add_argument("--label", default="scipy")
    args = ap.parse_args()
    runs = read_runs(args.suite)
    results, seconds = [], []
    wall0, cpu0 = time.perf_counter(), time.process_time()
    for name, acc, dt, anchored, _, _ in runs:
        c = time.process_time()
        results.append(simulate(Block(anchored=anchored), acc, dt, args.rtol, args.atol, args.settle))
        seconds.append(time.process_time() - c)
    wall, cpu = time.perf_counter() - wall0, time.process_time() - cpu0
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, f"records_peers_{args.label}.csv"), "w") as h, \
         open(os.path.join(args.out, f"records_peers_{args.label}_outcomes.csv"), "w") as o:
        h.write("run,t,theta\n")
        o.write("run,record,scale,anchorage,outcome,t_overturn_s,max_rotation,impacts,cpu_s\n")
        for (name, acc, dt, anchored, rec, scale), (th, outcome, t_ot, rot, imp), sec in zip(runs, results, seconds):
            h.writelines(f"{name},{k * dt!r},{x!r}\n" for k, x in enumerate(th))
            o.write(f"{name},{rec},{scale:g},{'constant' if anchored else 'free'},{outcome},{t_ot!r},{rot!r},{imp},{sec:.4f}\n")
    print(f"{args.label},{len(runs)},1,{wall:.6f},{cpu:.6f}", flush=True)


if __name__ == "__main__":
    main()
