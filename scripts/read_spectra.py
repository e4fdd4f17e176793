#!/usr/bin/python3
"""Reader for rocksweep spectra files (layout: docs/hdf5.md).

As a module:
    import read_spectra
    S = read_spectra.load("spectra.h5")
    S["axes"]                                  # the grid's axes in index order:
                                               #   ["amplitude_ratio", "omega_ratio"], after
                                               #   any parameter axes (sweep --axis)
    S["amplitude_ratio"], S["omega_ratio"]     # each axis, 1-D
    S["attrs"], S["provenance"]                # root and /provenance attributes (str, numbers)
    S["axis_attrs"]["pulse_family"]            # each axis's attributes: units, long_name, and
                                               #   flag_values / flag_meanings of a coded axis
    sc = S["scenarios"]["constant_tf0.5"]      # scenarios in config order
    sc["attrs"]["anchorage"]                   # "free" | "constant" | "adaptive", ...
    sc["outcome"][i_amp, i_omega]              # numpy arrays over the axes, C order
                                               #   ([i_phase, i_amp, i_omega] with --axis phase_rad=...)

Every scenario holds these arrays (docs/hdf5.md says what each means):
    outcome           uint8    0 safe, 1 overturned with impact, 2 without impact, 255 not converged
    max_rotation      float64  max |theta| / alpha
    impacts           int32    impacts above the settling threshold
    impacts_total     int32    impacts, the settling one included
    t_overturn        float64  [s] time of overturning; NaN if the block did not overturn
    peak_force_ratio  float64  peak anchorage force / F_u; NaN for a free block
    broken            uint8    bit 1: left spring broken, bit 2: right spring broken
    mu_required       float64  friction coefficient needed to rock without sliding
    pivot_uplift      uint8    1 if the pivot's vertical reaction went negative
    done              uint8    0 pending, 1 computed, 2 inferred by --refine

The file is netCDF-4 readable too: xarray.open_dataset(path, group="spectra/free") gives the
same arrays with the axes as coordinates. All scenarios in one xarray.Dataset:
    ds = read_spectra.to_xarray("spectra.h5")  # dims (scenario, <parameter axes>, amplitude_ratio,
                                               #   omega_ratio); each scenario's attributes
                                               #   (anchorage, theta_f_ratio, ...) as coordinates
    ds.outcome.sel(scenario="free")            #   along scenario (NaN / "" where one lacks it)

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


def _axis_names(group):
    """The grid's axes in index order, from a result dataset's `dimensions` attribute."""
    return [n.strip() for n in _value(group["outcome"].attrs["dimensions"]).split(",")]


def load(path):
    """Returns {"axes": axis names in index order, <axis>: 1-D array for each axis,
    "attrs": root attributes, "provenance": dict,
    "scenarios": {name: {"attrs": dict, <dataset>: array over the axes}}}.

    Arrays are indexed in the order of "axes": [i_amp, i_omega]. Scenarios keep the order
    of the config (their `index` attribute). Files of format_version 1 (axes in /axes) are
    read too."""
    with h5py.File(path, "r") as f:
        groups = sorted(f["spectra"].items(), key=lambda kv: kv[1].attrs.get("index", 0))
        if not groups:
            raise SystemExit("{}: no scenario under /spectra".format(path))
        names = _axis_names(groups[0][1])
        # Version 2 keeps the axes in every scenario group (all equal), version 1 in /axes.
        axes = f["axes"] if "axes" in f else groups[0][1]
        out = {"axes": names}
        out.update({n: axes[n][()] for n in names})
        # Units and, for a categorical axis (pulse_family), flag_values / flag_meanings.
        out["axis_attrs"] = {n: _attrs(axes[n]) for n in names}
        out["attrs"] = _attrs(f)
        out["provenance"] = _attrs(f["provenance"]) if "provenance" in f else {}
        scenarios = {}
        for name, g in groups:
            sc = {"attrs": _attrs(g)}
            for ds in DATASETS:
                if ds in g:
                    sc[ds] = g[ds][()]
            scenarios[name] = sc
        out["scenarios"] = scenarios
    return out


# What a variable's attributes keep in to_xarray: the netCDF ones (HDF5's dimension-scale
# bookkeeping, DIMENSION_LIST and the like, and `dimensions` stay behind).
VARIABLE_ATTRS = ("units", "long_name", "comment", "flag_values", "flag_masks", "flag_meanings")


def _scenario_coordinate(values):
    """One scenario attribute over all scenarios: float with NaN, or text with '' where a
    scenario lacks it."""
    present = [v for v in values if v is not None]
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in present):
        return np.array([np.nan if v is None else float(v) for v in values])
    return np.array(["" if v is None else str(v) for v in values], dtype=object)


def to_xarray(path):
    """Every scenario of a spectra file in one xarray.Dataset: each result array gets a leading
    dimension `scenario` (the names, in config order) before the file's axes, which are
    coordinates with their units; the scenarios' own attributes (anchorage, theta_f_ratio,
    kmin_ratio, ...) are coordinates along `scenario`; the root attributes are the Dataset's."""
    import xarray as xr

    S = load(path)
    names = list(S["scenarios"])
    with h5py.File(path, "r") as f:
        first = f["spectra"][names[0]]
        var_attrs = {ds: {k: _value(v) for k, v in first[ds].attrs.items() if k in VARIABLE_ATTRS}
                     for ds in DATASETS if ds in first}
    coords = {n: (n, S[n], {k: v for k, v in S["axis_attrs"][n].items() if k in VARIABLE_ATTRS}) for n in S["axes"]}
    coords["scenario"] = ("scenario", np.array(names, dtype=object), {"long_name": "scenario (anchorage)"})
    keys = []
    for sc in S["scenarios"].values():
        keys += [k for k in sc["attrs"] if k not in keys and k not in coords and np.ndim(sc["attrs"][k]) == 0]
    for k in keys:
        coords[k] = ("scenario", _scenario_coordinate([sc["attrs"].get(k) for sc in S["scenarios"].values()]))
    dims = ("scenario",) + tuple(S["axes"])
    data = {ds: (dims, np.stack([S["scenarios"][n][ds] for n in names]), var_attrs[ds])
            for ds in DATASETS if ds in var_attrs}
    attrs = {k: v for k, v in S["attrs"].items() if np.ndim(v) == 0}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def summary(S):
    """One line per scenario: outcome counts among the computed cells."""
    a = S["attrs"]
    lines = [
        "cells: {} done of {}{}".format(
            a.get("n_done"), a.get("n_cells"), "" if a.get("complete") == 1 else " (partial)"
        ),
        "grid: " + " x ".join("{} {}".format(len(S[n]), n) for n in S["axes"]),
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
