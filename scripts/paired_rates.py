#!/usr/bin/python3
"""The annual rates of a damage state that `rocksweep risk` gives each anchorage of a suite,
compared paired: anchorages swept over the same motions differ less than their separate ranges
say. A bootstrap over the motions (the same draw for every anchorage) refits each anchorage's
lognormal by the binomial likelihood (docs/fragility.md) and integrates the risk file's hazard
curve the way `risk` does (docs/risk.md), for the fit's rate and for the empirical fractions'.

    paired_rates.py SUITE.h5 RISK.h5 [--state overturning] [--bootstrap 200] [--radius R] [--alpha A]

Prints each anchorage's rates as the risk file holds them and as recomputed here (they must
agree to 1e-3: otherwise the two files do not belong together, and it exits with status 1), then for every pair the ratio of rates (later over earlier, in the file's order)
with its 2.5-50-97.5 % bootstrap percentiles: told apart when the interval misses 1.
"""
import argparse
import os
import sys

import numpy as np
from scipy import special

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_fragility_compare as pfc  # noqa: E402
import read_risk  # noqa: E402


class Site:
    """The hazard curve's |dH| on a fine ln x grid, beyond its points as `risk` extrapolates it."""

    def __init__(self, hazard_rate, x):
        self.lx = np.log(x)
        u = np.linspace(np.log(1e-3), np.log(20.0), 40001)
        H = hazard_rate(np.exp(u))
        self.dH, self.um, self.top = -np.diff(H), 0.5 * (u[1:] + u[:-1]), H[-1]

    def rate_fit(self, median, beta):
        return float(np.sum(special.ndtr((self.um - np.log(median)) / beta) * self.dH) + self.top)

    def rate_empirical(self, fraction):
        p = np.interp(self.um, self.lx, fraction, left=0.0, right=fraction[-1])
        return float(np.sum(p * self.dH) + fraction[-1] * self.top)


def rates(site, x, reach, seen, w):
    n, N = w @ reach, w @ seen
    return site.rate_fit(*pfc.probit_fit(x, n, N)), site.rate_empirical(np.where(N > 0, n / np.maximum(N, 1), 0.0))


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("suite")
    p.add_argument("risk")
    p.add_argument("--state", default="overturning")
    p.add_argument("--bootstrap", type=int, default=200, metavar="B")
    p.add_argument("--radius", type=float, metavar="R")
    p.add_argument("--alpha", type=float, metavar="A")
    args = p.parse_args(argv)
    S, j = pfc.load(args.suite, args.radius, args.alpha)
    R = read_risk.load(args.risk)
    names, x = list(S["scenarios"]), S["intensity"]
    site = Site(R["hazard_rate"], x)
    runs = pfc.runs_reaching(S, j, args.state)
    s = R["states"].index(args.state)
    a = int(np.argmin(np.abs(R["alpha_rad"] - S["alpha"]))) if "alpha_rad" in R else 0
    k = int(np.argmin(np.abs(R["radius_m"] - S["radius_m"][j]))) if "radius_m" in R else 0
    ones = np.ones(runs[0][0].shape[0])
    for nm, (reach, seen) in zip(names, runs):
        fit, emp = rates(site, x, reach, seen, ones)
        sc = R["scenarios"][nm]
        theirs = sc["rate_fit"][s, a, k], sc["rate_empirical"][s, a, k]
        print("{}: rate of {} {:.4g}/yr by the fit (risk file: {:.4g}), {:.4g}/yr by the fractions ({:.4g})".format(
            nm, args.state, fit, theirs[0], emp, theirs[1]))
        if not all(abs(ours / t - 1) < 1e-3 for ours, t in zip((fit, emp), theirs)):
            sys.stderr.write("paired_rates.py: {} and {} disagree on {}'s rates: not the risk of this suite?\n".format(
                args.suite, args.risk, nm))
            return 1
    rng = np.random.default_rng(1)
    G = len(ones)
    draws = np.zeros((args.bootstrap, len(names), 2))
    for b in range(args.bootstrap):
        w = np.bincount(rng.integers(0, G, G), minlength=G)
        for c, (reach, seen) in enumerate(runs):
            draws[b, c] = rates(site, x, reach, seen, w)
    for c0 in range(len(names)):
        for c in range(c0 + 1, len(names)):
            words = []
            for m, how in enumerate(("fit", "fractions")):
                r = draws[:, c, m] / draws[:, c0, m]
                lo, mid, hi = np.percentile(r[np.isfinite(r)], [2.5, 50, 97.5])
                words.append("{} {:.3f} ({:.3f}-{:.3f}){}".format(how, mid, lo, hi, "" if lo > 1 or hi < 1 else ", not told apart"))
            print("rate {} / {}: {}".format(names[c], names[c0], "; ".join(words)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
