#!/usr/bin/python3
"""Checks of a small design file against what it is made of, and of plot_design.py's reading:

- the free-standing safe fraction equals the trapezoid-weighted safe share of a plain
  `rocksweep sweep` of the free block on the same grid;
- each constant K's safe fraction equals the one computed here from its round file's outcome;
- K and theta_f / alpha in the file obey F_u = K 4b tan(theta_f / 2), as plot_design.py uses;
- the optimum holds the highest safe fraction.

    test_plot_design.py ROCKSWEEP CONFIG DESIGN.h5 WORKDIR
"""
import math
import os
import subprocess
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import plot_design  # noqa: E402
import read_spectra  # noqa: E402


def trapezoid(axis):
    axis = np.asarray(axis, dtype=float)
    if axis.size == 1:
        return np.ones(1)
    gaps = np.diff(axis)
    return 0.5 * (np.concatenate([[0.0], gaps]) + np.concatenate([gaps, [0.0]]))


def safe_share(S, outcome):
    w = np.outer(trapezoid(S["amplitude_ratio"]), trapezoid(S["omega_ratio"]))
    return float(np.sum(w * (outcome == 0)) / np.sum(w))


def main(rocksweep, config, design, workdir):
    failures = []
    D = plot_design.load(design)
    a = D["attrs"]
    grid = ["--omega-ratio-points", str(a["omega_ratio_points"]), "--amplitude-ratio-points", str(a["amplitude_ratio_points"])]
    free_file = os.path.join(workdir, "free_alone.h5")
    subprocess.run([rocksweep, "sweep", "--config", config, "--anchorages", "free", *grid, "--quiet", "--overwrite",
                    "-o", free_file], check=True)
    S = read_spectra.load(free_file)
    expected = safe_share(S, S["scenarios"]["free"]["outcome"])
    if not math.isclose(a["free_safe_fraction"], expected, rel_tol=1e-12):
        failures.append("free: {} in the design, {} from a sweep".format(a["free_safe_fraction"], expected))

    c = D["constant"]
    round0 = read_spectra.load(design[:-3] + ".round0.h5")
    checked = 0
    for name, sc in round0["scenarios"].items():
        if sc["attrs"]["anchorage"] != "constant":
            continue
        i = int(np.argmin(np.abs(c["stiffness"] - sc["attrs"]["k_max_N_per_m"])))
        mine = safe_share(round0, sc["outcome"])
        if not math.isclose(c["safe_fraction"][i], mine, rel_tol=1e-12):
            failures.append("{}: {} in the design, {} from its round file".format(name, c["safe_fraction"][i], mine))
        checked += 1
    if checked < 3:
        failures.append("only {} constant scenarios in round 0".format(checked))

    ratio = plot_design.theta_f_ratio(c["stiffness"], a)
    if not np.allclose(ratio, c["theta_f_ratio"], rtol=1e-9, atol=0):
        failures.append("theta_f / alpha: file {} vs F_u relation {}".format(c["theta_f_ratio"], ratio))
    for name in ("constant", "adaptive"):
        curve = D[name]
        best = curve["safe_fraction"][int(curve["attrs"]["optimum_index"])]
        if best != np.max(curve["safe_fraction"]):
            failures.append("{}: optimum {} below the highest value {}".format(name, best, np.max(curve["safe_fraction"])))
    with h5py.File(design, "r") as f:
        if f["constant/stiffness"].attrs["units"] != b"N/m":
            failures.append("stiffness units")
    for f in failures:
        print("FAIL:", f)
    print("{} checks failed".format(len(failures)) if failures else "design file consistent ({} constant K checked)".format(checked))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))
