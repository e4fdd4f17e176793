#!/usr/bin/python3
"""Reader for rocksweep record-suite files (`rocksweep suite`; layout: docs/suite.md). The one
place in Python that knows their layout.

As a module:
    import read_suite
    S = read_suite.load("results/suite.h5")
    S["attrs"]                        # root attributes (block, intensity_measure, complete, ...)
    S["intensity"], S["alpha_rad"], S["radius_m"]   # the levels [S["intensity_units"]], the
                                      # slenderness angles alpha [rad] and the block sizes R [m]
    S["records"]["names"]             # record names in suite order (index = the record axis)
    S["records"]["pga_g"][i]          # per-record measures; ["scale_factor"][i, a, k] per alpha, level
    S["records"]["metadata"][name]    # {"event": ..., "station": ..., "file": ..., ...}
    S["records"]["sa_g"][i]           # Sa(T, zeta) of record i as read [g]; S["records"]["sa"] =
                                      #   {"period_s": T, "damping": zeta} (None in files before it)
    fl = S["floors"]["f2"]            # floors by name ({} in files before them):
                                      #   "pfa_g", "pfa_over_pga" [record], "spectrum_g"
                                      #   [record, period], "median_spectrum_g", "period_s"
                                      #   [period], "scale_factor" [record, alpha, level],
                                      #   "median_pfa_g", "median_pfa_over_pga", "floor" (its
                                      #   definition); sc["attrs"]["floor"] names a scenario's
    sc = S["scenarios"]["free"]       # scenarios in config order
    sc["outcome"][i, a, j, k]         # record i, alpha_rad[a], radius_m[j], intensity[k]
    sc.get("sensitive")               # with --check-sensitivity (S["attrs"]["check_sensitivity"]
                                      #   == "on"): 1 where a perturbed rerun changed the outcome or
                                      #   damage state, else 0; None without (docs/suite.md)
    sc["overturning"]                 # None unless the sweep is complete, else
                                      #   {"first_intensity", "first_pga_g", "below_intensity",
                                      #    "safe_above": [record, alpha, radius]}
    sc["fragility"]                   # None unless complete, else {"states": names,
                                      #   "rotation_ratios", "fraction"[state, alpha, radius, level],
                                      #   ..., "median_intensity", "beta", ... [state, alpha, radius],
                                      #   "cov_ln_median_beta" (NaN in files before it),
                                      #   "fit_status" (codes), "fit_status_names" (str),
                                      #   "sensitive_runs" [state, alpha, radius] with the check}

    read_suite.to_xarray(path)        # {scenario: xarray.Dataset}, record names as a coordinate
    read_suite.fragility_curve(x, median, beta)   # Phi(ln(x / median) / beta)

Strings come decoded (str), arrays as numpy arrays in the file's (C) index order, attributes
as plain Python values. A file of format version 1 (written before the alpha_rad axis) reads
with an alpha_rad axis of length 1, the configured block's alpha. A file that is not a suite file raises SuiteFileError with one line
saying why.

As a program:
    read_suite.py FILE     prints the records, the grid, and per scenario the outcome counts and
                           the overturning fit.
"""
import math
import sys

import os

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import read_spectra  # noqa: E402

OUTCOMES = {0: "safe", 1: "overturned_with_impact", 2: "overturned_without_impact", 255: "not_converged"}
RESULTS = ("outcome", "max_rotation", "impacts", "impacts_total", "t_overturn", "peak_force_ratio", "broken",
           "mu_required", "pivot_uplift", "done", "sensitive")
PER_RECORD = ("pga_g", "pga_time_s", "pgv_m_s", "pgv_time_s", "residual_velocity_m_s", "arias_m_s",
              "significant_duration_s", "duration_s", "pga_vertical_g")
OVERTURNING = ("first_intensity", "first_pga_g", "below_intensity", "safe_above")
FRAGILITY = ("fraction", "fraction_lo", "fraction_hi", "exceed", "total", "median_intensity", "beta", "median_intensity_lo",
             "median_intensity_hi", "beta_lo", "beta_hi", "se_ln_median", "se_beta", "cov_ln_median_beta",
             "fit_status",
             "sensitive_runs")
FIT_STATUS = ("ok", "none_reached", "all_reached", "zero_dispersion", "not_identifiable", "decreasing")


class SuiteFileError(ValueError):
    """The file is not a (readable) rocksweep suite file; the message is one line."""


# An attribute as plain Python (fixed-length strings arrive from h5py as bytes): the spectra
# reader's own conversion, so that every rocksweep file decodes alike.
value = read_spectra._value


def attributes(obj):
    return {k: value(v) for k, v in obj.attrs.items()}


def flag_meanings(obj):
    """The space-separated `flag_meanings` of a dataset as a list of str."""
    return value(obj.attrs["flag_meanings"]).split()


def _open(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise SuiteFileError("{}: cannot read it as HDF5 ({})".format(path, str(e).split(",")[0]))
    kind = value(f.attrs.get("kind", ""))
    if kind != "suite" or "suite" not in f or "records" not in f:
        f.close()
        why = "kind = {!r}".format(kind) if kind else "no root attribute kind = 'suite'"
        raise SuiteFileError("{}: not a rocksweep suite file ({})".format(path, why))
    return f


def _group(g, names):
    """{name: array} of the datasets of `names` the group holds, plus their units."""
    out = {n: g[n][()] for n in names if n in g}
    out["units"] = {n: value(g[n].attrs["units"]) for n in names if n in g and "units" in g[n].attrs}
    return out


def _one_alpha(arrays, names):
    """A format-1 file (before the alpha_rad axis): its arrays get the axis, of length 1, after
    their first, so that every file reads alike."""
    for n in names:
        if n in arrays:
            arrays[n] = np.expand_dims(arrays[n], 1)
    return arrays


def _records(f):
    rec = f["records"]
    names = flag_meanings(rec["record"])
    out = _group(rec, PER_RECORD + ("scale_factor", "pga_scaled_g"))
    if "alpha_rad" not in rec:
        _one_alpha(out, ("scale_factor", "pga_scaled_g"))
    out["names"] = names
    out["intensity"] = rec["intensity"][()]
    out["metadata"] = {n: attributes(rec[n]) if n in rec else {} for n in names}
    out["sa"] = None
    if "sa_g" in rec:  # format 4 on: the Sa measure of every record, whatever the levels follow
        out["sa_g"] = rec["sa_g"][()]
        out["sa"] = {k: float(value(rec["sa_g"].attrs[k])) for k in ("period_s", "damping")}
    return out


FLOOR = ("pfa_g", "pfa_over_pga", "spectrum_g", "median_spectrum_g", "period_s", "scale_factor")


def _floors(f):
    """{floor name: its products} (docs/suite.md, "Floors"), in the file's order; {} before floors."""
    out = {}
    for name, g in f["floors"].items() if "floors" in f else ():
        fl = _group(g, FLOOR)
        for a in ("median_pfa_g", "median_pfa_over_pga"):
            fl[a] = float(value(g.attrs[a]))
        fl["floor"] = value(g.attrs["floor"])
        out[name] = fl
    return out


# Format 2 named the fitted median `median` (a name xarray's Dataset.median() hides): read
# under the name of format 3.
FRAGILITY_BEFORE_3 = {"median_intensity": "median", "median_intensity_lo": "median_lo",
                      "median_intensity_hi": "median_hi"}


def _fragility(g):
    out = _group(g, FRAGILITY)
    for new, old in FRAGILITY_BEFORE_3.items():
        if new not in g and old in g:
            out[new] = g[old][()]
            if "units" in g[old].attrs:
                out["units"][new] = value(g[old].attrs["units"])
    if "alpha_rad" not in g:
        _one_alpha(out, FRAGILITY)
    if "cov_ln_median_beta" not in out:  # files before it: unknown
        out["cov_ln_median_beta"] = np.full(out["beta"].shape, np.nan)
    out["states"] = flag_meanings(g["damage_state"])
    out["rotation_ratios"] = np.asarray(g["damage_state"].attrs["rotation_ratios"], dtype=float)
    meanings = flag_meanings(g["fit_status"]) if "flag_meanings" in g["fit_status"].attrs else FIT_STATUS
    out["fit_status_names"] = np.array([meanings[c] for c in out["fit_status"].ravel()],
                                       dtype=object).reshape(out["fit_status"].shape)
    return out


def _scenario(g):
    sc = _group(g, RESULTS)
    sc["attrs"] = attributes(g)
    for axis in ("radius_m", "intensity"):
        sc[axis] = g[axis][()]
    if "alpha_rad" in g:
        sc["alpha_rad"] = g["alpha_rad"][()]
    else:
        sc["alpha_rad"] = np.array([value(g.file.attrs["alpha_rad"])], dtype=float)
        _one_alpha(sc, RESULTS)
    sc["overturning"] = _group(g["overturning"], OVERTURNING) if "overturning" in g else None
    if sc["overturning"] is not None and "alpha_rad" not in g["overturning"]:
        _one_alpha(sc["overturning"], OVERTURNING)
    sc["fragility"] = _fragility(g["fragility"]) if "fragility" in g else None
    return sc


def load(path, scenarios=None):
    """The whole file as plain Python (see the module's description). `scenarios`: names to
    read (default all), in config order. Raises SuiteFileError."""
    with _open(path) as f:
        groups = sorted(f["suite"].items(), key=lambda kv: value(kv[1].attrs.get("index", 0)))
        if not groups:
            raise SuiteFileError("{}: no scenario under /suite".format(path))
        known = [n for n, _ in groups]
        for name in scenarios or ():
            if name not in known:
                raise SuiteFileError("{}: no scenario {!r} (the file has {})".format(path, name, ", ".join(known)))
        out = {"attrs": attributes(f)}
        out["provenance"] = attributes(f["provenance"]) if "provenance" in f else {}
        out["records"] = _records(f)
        out["floors"] = _floors(f)
        out["intensity"] = out["records"]["intensity"]
        out["radius_m"] = groups[0][1]["radius_m"][()]
        out["intensity_measure"] = out["attrs"].get("intensity_measure", "")
        out["intensity_units"] = out["attrs"].get("intensity_units", "")
        out["intensity_long_name"] = out["attrs"].get("intensity_long_name", "")
        out["scenarios"] = {n: _scenario(g) for n, g in groups if not scenarios or n in scenarios}
        out["alpha_rad"] = next(iter(out["scenarios"].values()))["alpha_rad"]
    return out


def record_names(path):
    """The record names in suite order (the record axis's flag_meanings)."""
    with _open(path) as f:
        return flag_meanings(f["records"]["record"])


def fragility_curve(x, median, beta):
    """The lognormal fragility Phi(ln(x / median) / beta); beta = 0 gives the step at the
    median. NaN where the median is not a positive finite number."""
    from scipy.special import ndtr

    x = np.asarray(x, dtype=float)
    if not (math.isfinite(median) and median > 0 and math.isfinite(beta)):
        return np.full(x.shape, np.nan)
    if beta == 0:
        return (x >= median).astype(float)
    return ndtr(np.log(x / median) / beta)


def reached(outcome, max_rotation, rotation_ratio):
    """Which runs reach a damage state: overturning (rotation_ratio NaN or None) or
    theta_max/alpha >= rotation_ratio; an overturned block has reached every state and a run
    that did not converge none."""
    fell = (outcome == 1) | (outcome == 2)
    if rotation_ratio is None or not math.isfinite(rotation_ratio):
        return fell
    return fell | ((outcome == 0) & (np.nan_to_num(max_rotation) >= rotation_ratio))


# --------------------------------------------------------------------------- xarray


def to_xarray(path):
    """{scenario: xarray.Dataset}: the scenario's result arrays and, when present, its
    overturning and fragility arrays and the per-record measures, over the coordinates record
    (the names; record_index beside it), alpha_rad, radius_m, intensity and damage_state (the state
    names), each with its units; attributes = root attributes then the scenario's."""
    import xarray as xr

    S = load(path)
    rec = S["records"]
    units = dict(intensity=S["intensity_units"])
    coords = {
        "record": ("record", np.array(rec["names"], dtype=object), {"long_name": "record"}),
        "record_index": ("record", np.arange(len(rec["names"])), {"long_name": "position in the suite"}),
        "alpha_rad": ("alpha_rad", S["alpha_rad"], {"units": "rad", "long_name": "slenderness angle alpha"}),
        "radius_m": ("radius_m", S["radius_m"], {"units": "m", "long_name": "block size R"}),
        "intensity": ("intensity", S["intensity"], {"units": units["intensity"],
                                                    "long_name": S["intensity_long_name"]}),
    }
    dims_of = {4: ("record", "alpha_rad", "radius_m", "intensity"), 3: ("record", "alpha_rad", "radius_m")}
    out = {}
    for name, sc in S["scenarios"].items():
        ds = xr.Dataset(coords=dict(coords))
        for k in RESULTS:
            if k in sc:
                ds[k] = (dims_of[4], sc[k], _unit(sc["units"], k))
        for k in PER_RECORD:
            if k in rec:
                ds[k] = (("record",), rec[k], _unit(rec["units"], k))
        for k in ("scale_factor", "pga_scaled_g"):
            if k in rec:
                ds[k] = (("record", "alpha_rad", "intensity"), rec[k], _unit(rec["units"], k))
        ov = sc["overturning"]
        for k in OVERTURNING if ov else ():
            ds[k] = (dims_of[3], ov[k], _unit(ov["units"], k))
        fr = sc["fragility"]
        if fr:
            ds = ds.assign_coords(damage_state=("damage_state", np.array(fr["states"], dtype=object)),
                                  rotation_ratio=("damage_state", fr["rotation_ratios"]))
            for k in (k for k in FRAGILITY if k in fr):
                dims = ("damage_state", "alpha_rad", "radius_m", "intensity")[:fr[k].ndim]
                ds[k] = (dims, fr[k], _unit(fr["units"], k))
        ds.attrs.update({k: v for k, v in S["attrs"].items() if np.ndim(v) == 0})
        ds.attrs.update({k: v for k, v in sc["attrs"].items() if np.ndim(v) == 0})
        ds.attrs["scenario"] = name
        out[name] = ds
    return out


def _unit(units, name):
    return {"units": units[name]} if name in units else {}


# --------------------------------------------------------------------------- summary


# The intensity's unit as a reader writes it: the file keeps CF units, "1" for PGA / g.
UNIT_WORDS = {"pga_g": "g", "pga_ratio": "g tan(alpha)", "scale": "x record"}


def intensity_unit_words(S):
    """The intensity's unit for text and axis labels: 'g' for PGA (stored as PGA / g, CF units
    '1'), 'g tan(alpha)' for pga_ratio, 'x record' for a plain scale, else the file's units."""
    return UNIT_WORDS.get(S["intensity_measure"], S["intensity_units"])


def summary(S):
    a = S["attrs"]
    rec = S["records"]
    iu = intensity_unit_words(S)
    lines = [
        "runs: {} done of {}{}".format(a.get("n_done"), a.get("n_cells"), "" if a.get("complete") == 1 else " (partial)"),
        "grid: {} records x {} alphas x {} radii x {} levels of {} [{}] {:g} ... {:g}".format(
            len(rec["names"]), len(S["alpha_rad"]), len(S["radius_m"]), len(S["intensity"]), S["intensity_measure"],
            iu, S["intensity"][0], S["intensity"][-1]),
        "alphas [rad]: " + " ".join("{:g}".format(a) for a in S["alpha_rad"]),
        "radii [m]: " + " ".join("{:g}".format(r) for r in S["radius_m"]),
        "records: " + " ".join(rec["names"]),
    ]
    for name, sc in S["scenarios"].items():
        done = sc["done"] != 0
        counts = ", ".join("{} {}".format(int(np.count_nonzero(done & (sc["outcome"] == c))), w)
                           for c, w in OUTCOMES.items())
        lines.append("{}: {} pending, {}".format(name, int(np.count_nonzero(~done)), counts))
        if "sensitive" in sc:
            lines.append("  {} run(s) flagged sensitive".format(int(np.count_nonzero(done & (sc["sensitive"] == 1)))))
        fr = sc["fragility"]
        if fr is None:
            lines.append("  no overturning/fragility groups (the sweep is not complete)")
            continue
        s = len(fr["states"]) - 1
        for a, alpha in enumerate(S["alpha_rad"]):
            for j, r in enumerate(S["radius_m"]):
                flagged = ", {} flagged run(s)".format(fr["sensitive_runs"][s, a, j]) if "sensitive_runs" in fr else ""
                lines.append("  alpha = {:g} rad, R = {:g} m, {}: median {:.4g} [{}], beta {:.3g} ({}{})".format(
                    alpha, r, fr["states"][s], fr["median_intensity"][s, a, j], iu, fr["beta"][s, a, j],
                    fr["fit_status_names"][s, a, j], flagged))
    return "\n".join(lines)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: read_suite.py FILE\n")
        return 2
    try:
        print(summary(load(argv[1])))
    except SuiteFileError as e:
        sys.stderr.write("{}\n".format(e))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
