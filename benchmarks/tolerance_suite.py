#!/usr/bin/python3
"""A suite file against a reference and the reference's rerun with the record scale perturbed
(benchmarks/tolerance_suite.sh): outcome differences and max |d theta_max / alpha| over the runs
safe in both, apart for the runs the perturbation shows to be sensitive.

usage: /usr/bin/python3 benchmarks/tolerance_suite.py UNDER_TEST.h5 REFERENCE.h5 PERTURBED.h5
"""
import sys
import h5py
import numpy as np


def columns(path):
    with h5py.File(path, "r") as f:
        return {s: (f["suite"][s]["outcome"][()], f["suite"][s]["max_rotation"][()]) for s in sorted(f["suite"])}


def overturned(o):
    return np.isin(o, (1, 2))


def main(test, ref, pert):
    t, r, p = columns(test), columns(ref), columns(pert)
    runs = wrong = wrong_sens = sens = 0
    worst = worst_sens = 0.0
    for s in r:
        (ot, rt), (orf, rr), (op, rp) = t[s], r[s], p[s]
        sensitive = (overturned(orf) != overturned(op)) | (~overturned(orf) & ~overturned(op) & (np.abs(rr - rp) > 1e-3))
        differs = overturned(ot) != overturned(orf)
        safe = ~overturned(ot) & ~overturned(orf)
        d = np.where(safe, np.abs(rt - rr), 0.0)
        runs += ot.size
        sens += int(sensitive.sum())
        wrong += int((differs & ~sensitive).sum())
        wrong_sens += int((differs & sensitive).sum())
        worst = max(worst, float(d[~sensitive].max(initial=0.0)))
        worst_sens = max(worst_sens, float(d[sensitive].max(initial=0.0)))
    print(f"  {runs} runs, {sens} sensitive; outcome differences: {wrong} (+ {wrong_sens} sensitive); "
          f"max |d theta_max/alpha| on safe runs: {worst:.2e} (sensitive: {worst_sens:.2e})")


if __name__ == "__main__":
    main(*sys.argv[1:4])
