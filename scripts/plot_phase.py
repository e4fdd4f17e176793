#!/usr/bin/python3
"""Phase plane (theta/alpha, theta_dot) of one or more rocksweep time histories.

    plot_phase.py HISTORY.h5|HISTORY.csv [...] -o OUT     writes OUT.png and OUT.pdf

Each run is one curve in its own colour, from a circle (the start) to a cross (overturned) or
a dot (at rest or the end of the record). Impacts are the jumps on theta = 0 (theta_dot <- e
theta_dot). For a free-standing block the boundary of the overturning basin is drawn too:
moving outward at theta, the block overturns without a further impact iff
theta_dot^2 > 2 p^2 (1 - cos(alpha - |theta|)) (energy; the paper's Eq. 19 without springs).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rshistory  # noqa: E402
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

THETA_LIMIT = 1.6  # theta/alpha drawn; beyond it an overturning block is only falling


def free_basin_boundary(ax, alpha, p):
    """theta_dot on the boundary of the free block's overturning basin, both sides."""
    x = np.linspace(-1, 1, 401)
    speed = p * np.sqrt(2 * (1 - np.cos(alpha * (1 - np.abs(x)))))
    for sign in (1, -1):  # outward motion: theta_dot has the sign of theta
        part = np.sign(x) == sign
        ax.plot(x[part], sign * speed[part], color="0.35", lw=1.0, ls="--",
                label="free block: overturns without impact beyond" if sign == 1 else None)


def plot(runs, out, title=None):
    fig, ax = plt.subplots(figsize=(8.5, 6.2), layout="constrained")
    labels, common = rshistory.run_labels(runs)
    by_alpha = all(r.alpha for r in runs)
    peak = 1e-9
    for i, (run, label) in enumerate(zip(runs, labels)):
        if not run.has("theta_dot"):
            raise SystemExit("{}: no theta_dot: cannot draw a phase plane".format(run.path))
        c = rsplot.run_colour(i)
        x = run.data["theta"] / run.alpha if by_alpha else run.data["theta"]
        y = run.data["theta_dot"]
        shown = np.abs(x) <= (THETA_LIMIT if by_alpha else np.inf)
        peak = max(peak, float(np.max(np.abs(y[shown]))) if np.any(shown) else peak)
        overturned = math.isfinite(float(run.attrs.get("t_overturn", float("nan"))))
        # An overturning block is drawn up to the panel's edge, its cross just inside it.
        cut = np.flatnonzero(~shown)[0] if overturned and not np.all(shown) else len(x)
        ax.plot(x[:cut], y[:cut], color=c, lw=1.0, label=label)
        ax.plot(x[0], y[0], "o", color=c, ms=6, mfc="white")
        end = max(cut - 1, 0)
        ax.plot(x[end], y[end], "x" if overturned else "o", color=c, ms=8, mew=2, clip_on=False, zorder=4)
    if by_alpha:
        free = [r for r in runs if r.attrs.get("anchorage") == "free" and r.p]
        if free:
            free_basin_boundary(ax, free[0].alpha, free[0].p)
        for level in (-1, 1):
            ax.axvline(level, color="0.4", lw=0.7, ls=":")
        ax.set_xlim(-1.06 * THETA_LIMIT, 1.06 * THETA_LIMIT)
        ax.set_xlabel(r"$\theta / \alpha$ [–]")
    else:
        ax.set_xlabel(r"$\theta$ [rad]")
    ax.axhline(0, color="0.5", lw=0.6)
    ax.axvline(0, color="0.5", lw=0.6)
    ax.set_ylim(-1.15 * peak, 1.15 * peak)
    ax.set_ylabel(r"$\dot\theta$ [rad/s]")
    # What the markers mean, in grey beside the runs' colours.
    ax.plot([], [], "o", color="0.3", mfc="white", ls="none", label="start")
    ax.plot([], [], "o", color="0.3", ls="none", label="end of the record")
    if any(math.isfinite(float(r.attrs.get("t_overturn", float("nan")))) for r in runs):
        ax.plot([], [], "x", color="0.3", mew=2, ls="none",
                label="overturns (drawn to |θ| = {:g} α)".format(THETA_LIMIT) if by_alpha else "overturns")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.11), fontsize=9, frameon=False, ncol=2)
    fig.suptitle(title or "\n".join(["Phase plane"] + common), fontsize=11)
    return rsplot.save(fig, out)


def main(argv):
    p = rshistory.history_parser(__doc__)
    args = p.parse_args(argv)
    plot([rshistory.History(path, alpha=args.alpha) for path in args.inputs], args.output, args.title)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
