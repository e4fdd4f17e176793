#!/usr/bin/python3
"""Draws a risk file (rocksweep risk; docs/risk.md): one column per anchorage scenario, three
rows: the site's hazard curve H(x) (its points, and the log-log extrapolation beyond them
dashed), the suite's fragility P(DS | x) (the lognormal fit and the empirical fractions), and
their product, the deaggregation d lambda / d ln x, whose area is the annual rate lambda.

usage: plot_risk.py RISK.h5 -o OUT [--state overturning] [--alpha A] [--radius R]
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import read_risk  # noqa: E402
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

# The lognormal fit and the empirical fractions, the same colours in every panel (Okabe-Ito).
FIT, EMPIRICAL = rsplot.OKABE_ITO["blue"], rsplot.OKABE_ITO["vermillion"]


def normal_cdf(z):
    """Phi(z), with the standard library's erfc (no scipy: setup.sh does not install it)."""
    return np.vectorize(lambda v: 0.5 * math.erfc(-v / math.sqrt(2.0)))(z)


def nearest(values, want):
    return 0 if want is None else int(np.argmin(np.abs(np.asarray(values) - want)))


def open_risk(description, argv, program):
    """The common command line of the risk figures: (args, R, (state, alpha, radius) indices),
    or an exit status after one line on stderr."""
    p = rsplot.parser(description, "a risk file (.h5)", n_inputs=1)
    p.add_argument("--state", default="overturning", help="damage state, by name (default overturning)")
    p.add_argument("--alpha", type=float, help="slenderness alpha [rad] (default the first in the file)")
    p.add_argument("--radius", type=float, help="block size R [m] (default the first in the file)")
    args = p.parse_args(argv)
    try:
        R = read_risk.load(args.inputs[0])
    except read_risk.RiskFileError as e:
        print(f"{program}: {e}", file=sys.stderr)
        return 1
    if args.state not in R["states"]:
        print(f"{program}: --state {args.state}: the file has {', '.join(R['states'])}", file=sys.stderr)
        return 2
    return args, R, (R["states"].index(args.state), nearest(R["alpha_rad"], args.alpha), nearest(R["radius_m"], args.radius))


def main(argv=None):
    opened = open_risk("Hazard, fragility and deaggregation per anchorage scenario", argv, "plot_risk.py")
    if isinstance(opened, int):
        return opened
    args, R, (s, a, j) = opened
    attrs, x, lv = R["attrs"], R["intensity"], R["level"]
    units = attrs["hazard_units"]
    hx, hr = R["hazard"]["intensity"], R["hazard"]["rate"]
    t = attrs["exposure_years"]
    names = list(R["scenarios"])
    fig, axes = plt.subplots(3, len(names), figsize=(max(7.0, 3.6 * len(names)), 8.5), sharex=True, squeeze=False,
                             layout="constrained")
    for c, name in enumerate(names):
        sc = R["scenarios"][name]
        inside = (x >= hx[0]) & (x <= hx[-1])
        ax = axes[0, c]
        ax.loglog(x, R["hazard_rate"](x), "k--", lw=1, label="extrapolated (end slopes)")
        ax.loglog(np.where(inside, x, np.nan), R["hazard_rate"](x), "k-", lw=1.5, label="hazard curve")
        ax.loglog(hx, hr, "ko", ms=3)
        ax.set_title(name)
        ax.set_ylabel("H(x): annual rate of exceedance [1/yr]" if c == 0 else "")
        if c == 0:
            ax.legend(loc="lower left", fontsize=8)
        ax = axes[1, c]
        med, beta = sc["median_intensity"][s, a, j], sc["beta"][s, a, j]
        status = sc["fit_status_names"][s, a, j]
        if np.isfinite(med) and np.isfinite(beta) and beta > 0:
            ax.semilogx(x, normal_cdf(np.log(x / med) / beta), "-", color=FIT, label=f"fit: median {med:.3g} {units}, β {beta:.2f}")
        elif np.isfinite(med) and beta == 0:
            ax.semilogx(x, (x >= med).astype(float), "--", color=FIT, label=f"fit: step at {med:.3g} {units}")
        else:
            ax.semilogx([], [], "-", color=FIT, label=f"no fit ({status})")
        ax.semilogx(lv, sc["fraction"][s, a, j], "o", color=EMPIRICAL, ms=4, label="empirical fractions")
        ax.set_ylim(-0.03, 1.03)
        ax.set_ylabel(f"P({args.state} | x)" if c == 0 else "")
        ax.legend(loc="upper left", fontsize=7)
        ax = axes[2, c]
        lam_f, lam_e = sc["rate_fit"][s, a, j], sc["rate_empirical"][s, a, j]
        ax.semilogx(x, sc["deaggregation_fit"][s, a, j], "-", color=FIT,
                    label=f"fit {lam_f:.2e}/yr, P{t:g} {sc['probability_fit'][s, a, j]:.3f}")
        ax.semilogx(x, sc["deaggregation_empirical"][s, a, j], "-", color=EMPIRICAL,
                    label=f"empirical {lam_e:.2e}/yr, P{t:g} {sc['probability_empirical'][s, a, j]:.3f}")
        for edge in (hx[0], hx[-1]):
            ax.axvline(edge, color="0.6", lw=0.8, ls=":")
        ax.set_xlabel(f"{attrs['hazard_measure']} x [{units}]")
        ax.set_ylabel("dλ / d ln x [1/yr]" if c == 0 else "")
        ax.legend(loc="upper left", fontsize=7)
    fig.suptitle(f"{args.state} at α = {R['alpha_rad'][a]:.4g} rad, R = {R['radius_m'][j]:.3g} m, "
                 f"hazard {os.path.basename(attrs['hazard_file'])}\n"
                 f"bottom: hazard x fragility, the deaggregation (area = annual rate); dotted: the curve's first and last points")
    rsplot.save(fig, args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
