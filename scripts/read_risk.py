#!/usr/bin/python3
"""Reader for rocksweep risk files (`rocksweep risk`; layout: docs/risk.md). The one place in
Python that knows their layout.

As a module:
    import read_risk
    R = read_risk.load("results/risk.h5")
    R["attrs"]                        # root attributes (hazard_measure, exposure_years, suite_file, ...)
    R["hazard"]["intensity"], R["hazard"]["rate"]   # the hazard curve's points as used [1/yr]
    R["hazard_rate"](x)               # H(x): log-log between points, end slopes beyond (as rocksweep)
    R["states"], R["alpha_rad"], R["radius_m"], R["intensity"], R["level"]   # axes; intensity: the
                                      # deaggregation's, level: the suite's intensity levels
    sc = R["scenarios"]["free"]       # in the suite's order; a suite on several floors names
                                      #   them SCENARIO@FLOOR, sc["floor"] the floor ("ground", ...)
    sc["rate_fit"][s, a, j]           # state s, alpha_rad[a], radius_m[j]: lambda [1/yr], and
                                      # rate_fit_lo/hi, probability_fit, return_period_fit,
                                      # share_below_fit, share_above_fit; the same *_empirical
    sc["deaggregation_fit"][s, a, j, k]   # d lambda / d ln x at intensity[k]
    sc["median_intensity"], sc["beta"], sc["fit_status_names"]   # [s, a, j]: the suite's lognormal fit
    sc["fraction"][s, a, j, l]        # the suite's empirical fraction at level[l]

A file that is not a risk file raises RiskFileError with one line saying why.

As a program:
    read_risk.py FILE     prints, per scenario and block, lambda and P in the exposure time of
                          the last damage state (overturning).
"""
import sys

import h5py
import numpy as np

FIT_STATUS = ("ok", "none_reached", "all_reached", "zero_dispersion", "not_identifiable", "decreasing")


class RiskFileError(ValueError):
    """The file is not a (readable) rocksweep risk file; the message is one line."""


def _text(v):
    return v.decode() if isinstance(v, bytes) else v


def _attrs(obj):
    out = {}
    for k, v in obj.attrs.items():
        v = _text(v)
        if isinstance(v, np.generic):
            v = v.item()
        out[k] = v
    return out


def _per_block_names():
    out = []
    for src in ("fit", "empirical"):
        out += [f"rate_{src}", f"rate_{src}_lo", f"rate_{src}_hi", f"probability_{src}", f"return_period_{src}",
                f"share_below_{src}", f"share_above_{src}"]
    return out


def hazard_rate(x, intensity, rate):
    """H(x) as rocksweep evaluates it: ln H linear in ln x, the end segments' slopes beyond."""
    lx, lh = np.log(np.asarray(intensity, float)), np.log(np.asarray(rate, float))
    u = np.log(np.asarray(x, float))
    i = np.clip(np.searchsorted(lx, u, side="right") - 1, 0, len(lx) - 2)
    slope = (lh[i + 1] - lh[i]) / (lx[i + 1] - lx[i])
    return np.exp(lh[i] + slope * (u - lx[i]))


def load(path):
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise RiskFileError(f"{path}: not an HDF5 file ({e})") from None
    with f:
        attrs = _attrs(f)
        if attrs.get("kind") != "risk" or "risk" not in f:
            raise RiskFileError(f"{path}: not a rocksweep risk file (kind = {attrs.get('kind')!r})")
        hz = {"intensity": f["hazard/intensity"][()], "rate": f["hazard/rate"][()]}
        R = {"attrs": attrs, "hazard": hz, "scenarios": {}}
        R["hazard_rate"] = lambda x: hazard_rate(x, hz["intensity"], hz["rate"])
        # The suite's order (free, constant, adaptive; ground, then upstairs), not HDF5's by name.
        groups = sorted(f["risk"].items(), key=lambda kv: int(kv[1].attrs.get("index", 0)))
        for name, g in groups:
            if "states" not in R:
                R["states"] = _text(g["damage_state"].attrs["flag_meanings"]).split(" ")
                for axis in ("alpha_rad", "radius_m", "intensity"):
                    R[axis] = g[axis][()]
            if "level" not in R:
                R["level"] = g["level"][()]
            sc = {k: g[k][()] for k in _per_block_names() + ["deaggregation_fit", "deaggregation_empirical",
                                                               "median_intensity", "beta", "fraction"]}
            sc["floor"] = _text(g.attrs["floor"]) if "floor" in g.attrs else "ground"
            sc["fit_status"] = g["fit_status"][()]
            sc["fit_status_names"] = np.vectorize(lambda c: FIT_STATUS[c])(sc["fit_status"]) if sc["fit_status"].size else sc["fit_status"]
            R["scenarios"][name] = sc
    return R


def main(argv):
    if len(argv) != 2:
        print("usage: read_risk.py FILE", file=sys.stderr)
        return 2
    try:
        R = load(argv[1])
    except RiskFileError as e:
        print(f"read_risk.py: {e}", file=sys.stderr)
        return 1
    a = R["attrs"]
    t = a["exposure_years"]
    print(f"hazard {a['hazard_measure']} [{a['hazard_units']}] from {a['hazard_file']} ({a['hazard_format']}); "
          f"suite {a['suite_file']}")
    s = len(R["states"]) - 1
    print(f"{R['states'][s]}: annual rate and probability in {t:g} years")
    for name, sc in R["scenarios"].items():
        for i, alpha in enumerate(R["alpha_rad"]):
            for j, radius in enumerate(R["radius_m"]):
                lam, p = sc["rate_fit"][s, i, j], sc["probability_fit"][s, i, j]
                lo, hi = sc["rate_fit_lo"][s, i, j], sc["rate_fit_hi"][s, i, j]
                period = "" if not lam > 0 else f", 1 in {1 / lam:.0f} yr"
                print(f"  {name:22s} alpha {alpha:.4f} R {radius:.3f} m: fit {lam:.3g}/yr ({lo:.3g} .. {hi:.3g}), "
                      f"P = {p:.3g}{period}; empirical {sc['rate_empirical'][s, i, j]:.3g}/yr, "
                      f"P = {sc['probability_empirical'][s, i, j]:.3g}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
