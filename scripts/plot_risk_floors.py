#!/usr/bin/python3
"""Draws the annual rate of a risk file's damage state per anchorage and floor (rocksweep risk
of a suite on several floors, scenarios SCENARIO@FLOOR; docs/risk.md): one group of bars per
anchorage, one marker per floor, the lognormal fit's rate with its 95 % range (the risk file's
rate_fit_lo/hi: the delta method with the fit's covariance, docs/risk.md), the empirical
fractions' rate as a diamond beside it; the right axis gives P in the exposure time. The rate
axis is logarithmic: with a dozen records the ranges span about a decade.

usage: plot_risk_floors.py RISK.h5 -o OUT [--state overturning] [--alpha A] [--radius R]
"""
import os
import sys

import numpy as np
from matplotlib.ticker import FuncFormatter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_risk  # noqa: E402
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

FLOOR_COLOURS = ("blue", "orange", "vermillion", "green", "purple", "sky", "black")


def main(argv=None):
    opened = plot_risk.open_risk("Annual rate per anchorage and floor", argv, "plot_risk_floors.py")
    if isinstance(opened, int):
        return opened
    args, R, (s, a, j) = opened
    t = R["attrs"]["exposure_years"]
    anchorages, floors = [], []
    for name, sc in R["scenarios"].items():
        base = name.split("@")[0]
        anchorages += [base] if base not in anchorages else []
        floors += [sc["floor"]] if sc["floor"] not in floors else []
    rate = {(n.split("@")[0], sc["floor"]): sc for n, sc in R["scenarios"].items()}
    fig, ax = plt.subplots(figsize=(8.0, 4.8), layout="constrained")
    width = 0.8 / len(floors)
    top, bottom = 0.0, np.inf
    for k, floor in enumerate(floors):
        colour = rsplot.OKABE_ITO[FLOOR_COLOURS[k % len(FLOOR_COLOURS)]]
        xs = np.arange(len(anchorages)) + (k - (len(floors) - 1) / 2) * width
        fit = np.array([rate[(b, floor)]["rate_fit"][s, a, j] if (b, floor) in rate else np.nan for b in anchorages])
        lo = np.array([rate[(b, floor)]["rate_fit_lo"][s, a, j] if (b, floor) in rate else np.nan for b in anchorages])
        hi = np.array([rate[(b, floor)]["rate_fit_hi"][s, a, j] if (b, floor) in rate else np.nan for b in anchorages])
        emp = np.array([rate[(b, floor)]["rate_empirical"][s, a, j] if (b, floor) in rate else np.nan for b in anchorages])
        ax.errorbar(xs - 0.12 * width, fit, yerr=[fit - lo, hi - fit], fmt="o", color=colour, ms=8, capsize=4,
                    lw=1.6, label=f"{floor}: lognormal fit (95 % range)")
        ax.plot(xs + 0.22 * width, emp, "D", color=colour, mec="black", ms=6,
                label="empirical fractions (diamonds)" if k == 0 else None)
        top = max(top, np.nanmax(hi), np.nanmax(emp))
        bottom = min(bottom, np.nanmin(lo), np.nanmin(emp))
    ax.set_xticks(np.arange(len(anchorages)), anchorages)
    ax.set_xlabel("anchorage scenario")
    ax.set_ylabel(f"annual rate of {args.state} λ [1/yr]")
    ax.set_yscale("log")
    ax.set_ylim(bottom / 2, top * 4)
    ax.grid(True, which="major", axis="y", alpha=0.4)
    right = ax.secondary_yaxis("right", functions=(lambda lam: 100 * -np.expm1(-np.asarray(lam) * t),
                                                   lambda pct: -np.log1p(-np.clip(np.asarray(pct) / 100, 0, 0.999999)) / t))
    right.set_yscale("log")
    right.yaxis.set_major_formatter(FuncFormatter(lambda pct, _: f"{pct:g}"))
    right.set_ylabel(f"P in {t:g} years [%]")
    ax.set_title(f"{args.state} at the site of {os.path.basename(R['attrs']['hazard_file'])}, "
                 f"α = {R['alpha_rad'][a]:.3g} rad, R = {R['radius_m'][j]:.3g} m", fontsize=10)
    ax.legend(loc="upper right", fontsize=8, ncols=2)
    for path in rsplot.save(fig, args.output):
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
