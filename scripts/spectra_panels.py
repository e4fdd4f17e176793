#!/usr/bin/python3
"""The panels of a spectra file as plot_spectra.py draws them: which point of the parameter axes
(sweep --axis) each panel shows, its block (p and alpha follow R and alpha when they are axes),
and its title in words. Pure data: no drawing here.
"""
import math

import numpy as np

import rsplot


class Panel:
    """One map: a scenario's spectrum at one point of the parameter axes."""

    def __init__(self, S, name, at, title):
        self.name, self.title = name, title
        sc = S["scenarios"][name]
        self.sc = {k: (v[at] if isinstance(v, np.ndarray) and v.ndim == len(S["axes"]) else v) for k, v in sc.items()}
        # The block of this point: R and alpha may be axes (the file's attributes are the configured block's).
        a = S["attrs"]
        point = {n: S[n][i] for n, i in zip(S["axes"][:-2], at)}
        radius, alpha = point.get("radius_m", a.get("radius_m")), point.get("alpha_rad", a.get("alpha_rad"))
        self.alpha = alpha
        self.p = a.get("p_rad_s")
        if ("radius_m" in point or "alpha_rad" in point) and a.get("inertia_ratio") and a.get("gravity_m_s2"):
            self.p = math.sqrt(a["gravity_m_s2"] / (a["inertia_ratio"] * radius))


def value_words(S, name, i):
    """'R = 2.8 m', or for a coded axis (pulse_family) the name of its code: 'ricker pulses'."""
    attrs = S.get("axis_attrs", {}).get(name, {})
    if "flag_meanings" in attrs:
        meaning = dict(zip(np.atleast_1d(attrs["flag_values"]).tolist(), attrs["flag_meanings"].split()))
        return "{} pulses".format(meaning.get(float(S[name][i]), S[name][i]))
    if name in ANGLES:  # phases read as fractions of pi: psi = pi/4, not 0.7854 rad
        return "{} = ${}$".format(AXIS_SYMBOLS[name], rsplot.pi_fraction(float(S[name][i])))
    return "{} = {:.4g}{}".format(AXIS_SYMBOLS.get(name, name), S[name][i], AXIS_UNITS.get(name, ""))


def point_words(S, at):
    return ", ".join(value_words(S, n, i) for n, i in zip(S["axes"][:-2], at))


AXIS_SYMBOLS = {"phase_rad": "ψ", "vertical_g": "a_v0/g", "vertical_phase_rad": "ψ_v", "restitution": "e",
                "radius_m": "R", "alpha_rad": "α", "strength_ratio": "F_u/(mg)", "theta_f_ratio": "θ_f/α",
                "kmin_ratio": "K_min/K_max", "stiffness_n_m": "K"}
ANGLES = ("phase_rad", "vertical_phase_rad")
AXIS_UNITS = {"phase_rad": " rad", "vertical_phase_rad": " rad", "radius_m": " m", "alpha_rad": " rad", "stiffness_n_m": " N/m"}
CONFIGURED = {"phase_rad": "phase_rad", "vertical_g": "vertical_g", "vertical_phase_rad": "vertical_phase_rad",
              "restitution": "e", "radius_m": "radius_m", "alpha_rad": "alpha_rad"}


def choose_point(S, at_args, parser):
    """Index on every parameter axis: --at AXIS=VALUE (nearest), else the configured value if the
    axis holds it, else its first point."""
    params = S["axes"][:-2]
    at = []
    wanted = {}
    for text in at_args or []:
        name, _, value = text.partition("=")
        if name not in params:
            parser.error("--at {}: the file's parameter axes are {}".format(text, ", ".join(params) or "none"))
        try:
            wanted[name] = float(value)
        except ValueError:
            parser.error("--at {}: VALUE must be a number".format(text))
    for n in params:
        target = wanted.get(n, S["attrs"].get(CONFIGURED.get(n, ""), np.nan))
        hit = np.flatnonzero(S[n] == target) if n not in wanted else []
        at.append(int(hit[0]) if len(hit) else int(np.argmin(np.abs(S[n] - target))) if np.isfinite(target) else 0)
    return at


def panels_of(S, names, at, across):
    """Panels in order: each scenario, and within it each point of `across` (if any), titled by
    the scenario, its point on `across`, or both."""
    params = S["axes"][:-2]
    k = params.index(across) if across else None
    points = [at[:k] + [i] + at[k + 1:] for i in range(len(S[across]))] if across else [at]
    out = []
    for nm, title in zip(names, scenario_titles(S, names)):
        for pt in points:
            words = value_words(S, across, pt[k]) if across else ""
            text = words if len(names) == 1 and across else title + ("\n" + words if words else "")
            out.append(Panel(S, nm, tuple(pt), text))
    return out


# Scenario attributes that a parameter axis of the same quantity replaces (the group keeps the
# configured value): left out of its title.
SWEPT_ATTRS = {"theta_f_ratio": ["theta_f_ratio"], "stiffness_n_m": ["theta_f_ratio"], "kmin_ratio": ["kmin_ratio"]}


def scenario_titles(S, names):
    swept = {k for axis in S.get("axes", [])[:-2] for k in SWEPT_ATTRS.get(axis, [])}  # (suite files: none)
    laws = {S["scenarios"][nm]["attrs"].get("adaptive_law") for nm in names
            if S["scenarios"][nm]["attrs"].get("anchorage") == "adaptive"}
    titles = [rsplot.anchorage_words({k: v for k, v in S["scenarios"][nm]["attrs"].items() if k not in swept},
                                     with_law=len(laws) > 1)
              for nm in names]
    return [t + ("  [{}]".format(nm) if titles.count(t) > 1 else "") for t, nm in zip(titles, names)]
