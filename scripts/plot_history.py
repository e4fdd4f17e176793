#!/usr/bin/python3
"""Plot one or more rocksweep time histories (`rocksweep simulate -o X.h5` or `-o X.csv`).

    plot_history.py HISTORY.h5|HISTORY.csv [...] -o OUT     writes OUT.png and OUT.pdf

Panels, top to bottom: the ground acceleration; theta/alpha; theta_dot; the working stiffness
of the left and of the right spring as K/K_max (the paper's Fig. 16; 0 while a spring is idle
or broken); the cumulative works of the excitation and of the anchorage (Eq. 23-24). Each run
keeps one colour in every panel. The stiffness panels are left out when no run is anchored.

A CSV history carries no attributes: its label is its file name, and theta is drawn in radians
unless --alpha gives the block's alpha (all runs are then drawn as theta/alpha).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402


def load_all(paths, alpha):
    return [rsplot.History(p, alpha=alpha) for p in paths]


def panels_for(runs):
    """The panels worth drawing for these runs, in order."""
    panels = []
    if any(r.has("ground_acc") for r in runs):
        panels.append("ground")
    panels.append("theta")
    if any(r.has("theta_dot") for r in runs):
        panels.append("theta_dot")
    if any(r.anchored() for r in runs):
        panels += ["k_left", "k_right"]
    if any(r.has("w_excitation") or r.has("w_anchorage") for r in runs):
        panels.append("work")
    return panels


def end_of_motion(runs):
    """A little after the last run comes to rest (or overturns): the rest of a long record
    is flat lines."""
    ends = []
    for r in runs:
        theta = np.abs(r.data["theta"])
        moving = np.flatnonzero(theta > 1e-3 * (r.alpha or np.max(theta)))
        ends.append(r.t[moving[-1]] if moving.size else r.t[-1])
    t_end = max(r.t[-1] for r in runs)
    return min(t_end, 1.08 * max(ends) + 0.5)


def plot(runs, out, title=None):
    panels = panels_for(runs)
    heights = {"ground": 0.8, "theta": 1.3, "theta_dot": 1.0, "k_left": 0.6, "k_right": 0.6, "work": 1.0}
    fig, axes = plt.subplots(
        len(panels),
        1,
        figsize=(9, 1.55 * sum(heights[p] for p in panels) + 1.6),
        sharex=True,
        gridspec_kw={"height_ratios": [heights[p] for p in panels]},
        layout="constrained",
    )
    ax = dict(zip(panels, np.atleast_1d(axes)))
    by_alpha = all(r.alpha for r in runs)
    labels, common = rsplot.run_labels(runs)
    g = runs[0].g

    handles = []
    for i, (run, label) in enumerate(zip(runs, labels)):
        c = rsplot.run_colour(i)
        t = run.t
        theta = run.data["theta"] / run.alpha if by_alpha else run.data["theta"]
        (line,) = ax["theta"].plot(t, theta, color=c, lw=1.2, label=label)
        handles.append(line)
        if math.isfinite(float(run.attrs.get("t_overturn", float("nan")))):
            ax["theta"].plot(t[-1], theta[-1], "x", color=c, ms=8, mew=2)
        if "ground" in ax and run.has("ground_acc"):
            ax["ground"].plot(t, run.data["ground_acc"] / g, color=c, lw=1.2)
        if "theta_dot" in ax and run.has("theta_dot"):
            ax["theta_dot"].plot(t, run.data["theta_dot"], color=c, lw=1.2)
        k_max = run.k_max()
        for side in ("k_left", "k_right"):
            if side in ax and k_max and run.has(side):
                ax[side].plot(t, run.data[side] / k_max, color=c, lw=1.0, drawstyle="steps-post")
        if "work" in ax:
            if run.has("w_excitation"):
                ax["work"].plot(t, run.data["w_excitation"] / 1e3, color=c, lw=1.2)
            if run.has("w_anchorage") and run.anchored():
                ax["work"].plot(t, run.data["w_anchorage"] / 1e3, color=c, lw=1.2, ls="--")

    if "ground" in ax:
        ax["ground"].set_ylabel(r"$\ddot x_g / g$")
        ax["ground"].axhline(0, color="0.5", lw=0.6)
    if by_alpha:
        ax["theta"].set_ylabel(r"$\theta / \alpha$")
        for level in (-1, 1):
            ax["theta"].axhline(level, color="0.4", lw=0.7, ls=":")
        lo, hi = ax["theta"].get_ylim()
        ax["theta"].set_ylim(max(lo, -2.2), min(hi, 2.2))  # past 2α the block is lying down; keep the swings readable
    else:
        ax["theta"].set_ylabel(r"$\theta$ [rad]")
    if "theta_dot" in ax:
        ax["theta_dot"].set_ylabel(r"$\dot\theta$ [rad/s]")
        # Scale to the rocking, not to the fall of an overturning block (past 2 alpha).
        upright = [r.data["theta_dot"][np.abs(r.data["theta"]) <= 2 * (r.alpha or 0.5)] for r in runs
                   if r.has("theta_dot")]
        peak = max([np.max(np.abs(u)) for u in upright if u.size] + [1e-9])
        ax["theta_dot"].set_ylim(-1.15 * peak, 1.15 * peak)
    for side, words in (("k_left", "left"), ("k_right", "right")):
        if side in ax:
            ax[side].set_ylabel(r"$K_{{{}}} / K_{{max}}$".format(words))
            ax[side].set_ylim(-0.08, 1.12)
            ax[side].set_yticks([0, 0.5, 1])
    if "work" in ax:
        ax["work"].set_ylabel("work on the block [kJ]")
        ax["work"].plot([], [], color="0.3", label="excitation (Eq. 23)")
        if any(r.anchored() for r in runs):
            ax["work"].plot([], [], color="0.3", ls="--", label="anchorage (Eq. 24)")
        ax["work"].legend(loc="best", fontsize=8)
    list(ax.values())[-1].set_xlabel("t [s]")
    ax["theta"].set_xlim(0, end_of_motion(runs))

    if title is None:
        title = "\n".join(["Time history"] + common)
    fig.suptitle(title, fontsize=11)
    top = list(ax.values())[0]  # the runs' legend above the first panel; constrained layout makes room
    top.legend(handles=handles, loc="lower left", bbox_to_anchor=(0, 1.02),
               ncol=1, fontsize=9, frameon=False, borderaxespad=0)
    return rsplot.save(fig, out)


def main(argv):
    p = rsplot.history_parser(__doc__)
    args = p.parse_args(legacy_order(argv))
    plot(load_all(args.inputs, args.alpha), args.output, args.title)
    return 0


def legacy_order(argv):
    """Accepts the old form `plot_history.py OUT.png IN ...` (the output first) as well."""
    if argv and "-o" not in argv and "--output" not in argv and argv[0].lower().endswith((".png", ".pdf")):
        return argv[1:] + ["-o", argv[0]]
    return argv


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
