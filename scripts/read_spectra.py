#!/usr/bin/python3
"""Reader for rocksweep spectra files (layout: docs/hdf5.md).

As a module:
    import read_spectra
    S = read_spectra.load("spectra.h5")
    S["omega_ratio"], S["amplitude_ratio"]              # 1-D axes
    sc = S["scenarios"]["constant_2"]                   # scenarios in config order
    sc["outcome"][i_amp, i_omega]                        # 2-D numpy arrays, C order
    sc["attrs"]["anchorage"]                             # "free" | "constant" | "adaptive"

As a program:
    read_spectra.py FILE       prints, per scenario, how many cells ended in each outcome.
"""
import sys

import h5py
import numpy as np

OUTCOMES = {
    0: "safe",
    1: "overturned_with_impact",
    2: "overturned_without_impact",
    255: "not_converged",
}
DATASETS = ("outcome", "max_rotation", "impacts", "impacts_total", "t_overturn", "peak_force_ratio", "broken", "mu_required",
            "pivot_uplift", "done")


def _value(v):
    """Attribute value as plain Python: fixed-length strings arrive as bytes."""
    if isinstance(v, bytes):
        return v.decode("utf-8")
    if isinstance(v, np.ndarray) and v.shape == ():
        v = v[()]
    if isinstance(v, np.generic):
        return v.item()
    return v


def _attrs(obj):
    return {k: _value(v) for k, v in obj.attrs.items()}


def load(path):
    """Returns {"omega_ratio", "amplitude_ratio": 1-D arrays, "attrs": root attributes,
    "provenance": dict, "scenarios": {name: {"attrs": dict, <dataset>: 2-D array}}}.

    Each 2-D array has shape (n_amp, n_omega): [i_amp, i_omega]. Scenarios keep the order
    of the config (their `index` attribute)."""
    with h5py.File(path, "r") as f:
        out = {
            "omega_ratio": f["axes/omega_ratio"][()],
            "amplitude_ratio": f["axes/amplitude_ratio"][()],
            "attrs": _attrs(f),
            "provenance": _attrs(f["provenance"]) if "provenance" in f else {},
        }
        groups = sorted(f["spectra"].items(), key=lambda kv: kv[1].attrs.get("index", 0))
        scenarios = {}
        for name, g in groups:
            sc = {"attrs": _attrs(g)}
            for ds in DATASETS:
                if ds in g:
                    sc[ds] = g[ds][()]
            scenarios[name] = sc
        out["scenarios"] = scenarios
    return out


def summary(S):
    """One line per scenario: outcome counts among the computed cells."""
    a = S["attrs"]
    lines = [
        "cells: {} done of {}{}".format(
            a.get("n_done"), a.get("n_cells"), "" if a.get("complete") == 1 else " (partial)"
        ),
        "grid: {} amplitude_ratio x {} omega_ratio".format(
            len(S["amplitude_ratio"]), len(S["omega_ratio"])
        ),
    ]
    width = max([len(n) for n in S["scenarios"]] + [8])
    short = {0: "safe", 1: "mode1_impact", 2: "mode2_no_impact", 255: "not_converged"}
    header = "{:<{w}}  {:>8}".format("scenario", "pending", w=width) + "".join(
        "  {:>15}".format(short[c]) for c in OUTCOMES
    )
    lines.append(header)
    for name, sc in S["scenarios"].items():
        done = sc["done"] != 0
        row = "{:<{w}}  {:>8d}".format(name, int(np.count_nonzero(~done)), w=width)
        for code in OUTCOMES:
            row += "  {:>15d}".format(int(np.count_nonzero(done & (sc["outcome"] == code))))
        lines.append(row)
    return "\n".join(lines)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: read_spectra.py FILE\n")
        return 2
    print(summary(load(argv[1])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
