#!/usr/bin/python3
"""The default's differences from the reference over a suite, apart for the runs whose reference
moves under small perturbations of the record scale (benchmarks/conditioning_suite.sh).

usage: /usr/bin/python3 benchmarks/conditioning_suite.py DEFAULT.h5 REF.h5 REF_TIGHTER.h5 EPS=PERTURBED.h5...
DEFAULT.h5 must have been run with --check-sensitivity (its flag is compared too).
"""
import sys
import h5py
import numpy as np

MOVE = 1e-3  # a change of theta_max / alpha that counts as moving a run (issue 22's bound)


def read(path):
    with h5py.File(path, "r") as f:
        a = f["records"]["record"].attrs
        meanings = a["flag_meanings"]
        names = dict(zip(a["flag_values"], (meanings.decode() if isinstance(meanings, bytes) else meanings).split()))
        cols = {}
        for s in sorted(f["suite"]):
            g = f["suite"][s]
            cols[s] = {k: g[k][()] for k in ("outcome", "max_rotation", "record", "radius_m", "intensity")}
            if "sensitive" in g:
                cols[s]["sensitive"] = g["sensitive"][()].astype(bool)
        return names, cols


def overturned(o):
    return np.isin(o, (1, 2))


def moved(x, ref):
    """Where run set x leaves the reference's outcome class or theta_max / alpha by > MOVE."""
    ox, orf = overturned(x["outcome"]), overturned(ref["outcome"])
    return (ox != orf) | (~ox & ~orf & (np.abs(x["max_rotation"] - ref["max_rotation"]) > MOVE))


def main(default, ref, tighter, *perturbed):
    names, d = read(default)
    r, t = read(ref)[1], read(tighter)[1]
    eps = sorted({abs(float(p.split("=", 1)[0])) for p in perturbed})
    pert = {e: [read(p.split("=", 1)[1])[1] for p in perturbed if abs(float(p.split("=", 1)[0])) == e] for e in eps}
    label = {e: f"reference moved by the tolerance 1e-12 or a scale change <= {e:g}" for e in eps}
    rows = {label[e]: [0, 0, 0.0, 0] for e in eps}  # apart, outcomes off, max |d|, |d| > MOVE (on the rest)
    rows["flagged by --check-sensitivity"] = [0, 0, 0.0, 0]
    runs = 0
    listed = []

    def count(row, apart, wrong, diff):
        row[0] += int(apart.sum())
        row[1] += int((wrong & ~apart).sum())
        row[2] = max(row[2], float(diff[~apart].max(initial=0.0)))
        row[3] += int(((diff > MOVE) & ~apart).sum())

    for s in r:
        x, y = d[s], r[s]
        runs += x["outcome"].size
        wrong = overturned(x["outcome"]) != overturned(y["outcome"])
        safe = ~overturned(x["outcome"]) & ~overturned(y["outcome"])
        diff = np.where(safe, np.abs(x["max_rotation"] - y["max_rotation"]), 0.0)
        apart = moved(t[s], y)
        first = np.full(diff.shape, np.inf)  # the smallest eps that moves the reference
        for e in eps:
            for p in pert[e]:
                apart = apart | moved(p[s], y)
            first = np.where(apart & np.isinf(first), e, first)
            count(rows[label[e]], apart, wrong, diff)
        flag = x["sensitive"]
        count(rows["flagged by --check-sensitivity"], flag, wrong, diff)
        for i in zip(*np.nonzero(diff > MOVE)):
            listed.append((s, names[x["record"][i[0]]], x["radius_m"][i[2]], x["intensity"][i[3]], diff[i],
                           x["max_rotation"][i], y["max_rotation"][i], first[i], bool(flag[i])))
    print(f"{runs} runs; default against the reference: "
          f"{int(sum((overturned(d[s]['outcome']) != overturned(r[s]['outcome'])).sum() for s in r))} outcomes differ")
    print(f"runs set apart                                                   | apart | outcomes off | max |d theta_max/alpha| | |d| > {MOVE:g}")
    for k, (n, w, m, b) in rows.items():
        print(f"  {k:64s} | {n:5d} | {w:12d} | {m:22.2e} | {b:d}")
    print(f"runs with |d theta_max/alpha| > {MOVE:g} (smallest relative scale change that moves the reference by > {MOVE:g}):")
    for s, rec, rad, lev, dd, a, b, e, fl in sorted(listed, key=lambda z: -z[4]):
        print(f"  {s:16s} {rec:24s} R = {rad:.4f} m, {lev:.2f} g: {a:.4f} against {b:.4f} (|d| {dd:.4f}); "
              f"moved at {e:g}; flagged: {'yes' if fl else 'no'}")


if __name__ == "__main__":
    main(*sys.argv[1:])
