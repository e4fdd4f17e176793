#!/usr/bin/python3
"""Checks of a small `rocksweep design --suite` file against the suite files of its rounds:

- the free-standing safe fraction, and each constant K's and each K_min/K_max's, equals the
  share of that scenario's runs (every record at every level) that stay up in its round's file;
- the root attributes name the suite hazard (not a pulse region);
- the optimum holds the highest safe fraction.

    test_design_suite.py DESIGN.h5
"""
import glob
import sys

import h5py
import numpy as np


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def main(path):
    stem = path[:-3]
    rounds = sorted(glob.glob(stem + ".round*.h5"))
    assert rounds, "no round files beside " + path
    standing = {}  # (anchorage, k_max, kmin_ratio) -> share of runs that stay up
    for r in rounds:
        with h5py.File(r, "r") as f:
            assert text(f.attrs["kind"]) == "suite", r
            for name, g in f["suite"].items():
                key = (text(g.attrs["anchorage"]), round(float(g.attrs["k_max_N_per_m"]), 6), round(float(g.attrs["kmin_ratio"]), 12))
                standing[key] = float(np.mean(g["outcome"][()] == 0))
    with h5py.File(path, "r") as f:
        a = f.attrs
        assert "suite_file" in a and "omega_ratio_range" not in a, "the hazard is not recorded as a suite"
        assert text(a["intensity_measure"]) == "pga_g"
        free = [v for k, v in standing.items() if k[0] == "free"]
        assert len(free) == 1 and abs(free[0] - a["free_safe_fraction"]) < 1e-15, (free, a["free_safe_fraction"])
        c = f["constant"]
        for k, sf in zip(c["stiffness"][()], c["safe_fraction"][()]):
            key = ("constant", round(float(k), 6), 1.0)
            assert abs(standing[key] - sf) < 1e-15, (k, standing[key], sf)
        ad = f["adaptive"]
        kmax = round(float(ad.attrs["k_max_N_per_m"]), 6)
        for rho, sf in zip(ad["kmin_ratio"][()], ad["safe_fraction"][()]):
            assert abs(standing[("adaptive", kmax, round(float(rho), 12))] - sf) < 1e-15, (rho, sf)
        for g in (c, ad):
            assert g["safe_fraction"][int(g.attrs["optimum_index"])] == g["safe_fraction"][()].max()
    print("design --suite: {} values checked against {} round files".format(len(standing), len(rounds)))


if __name__ == "__main__":
    main(sys.argv[1])
