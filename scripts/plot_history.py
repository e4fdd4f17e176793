#!/usr/bin/python3
"""Plot one or more rocksweep time histories (`rocksweep simulate -o X.h5` or `-o X.csv`).

    plot_history.py HISTORY.h5|HISTORY.csv [...] -o OUT     writes OUT.png and OUT.pdf

Panels, top to bottom: the ground acceleration; theta/alpha; theta_dot; the working stiffness
of the left and of the right spring as K/K_max (the paper's Fig. 16; 0 while a spring is idle
or broken); the cumulative works of the excitation and of the anchorage (Eq. 23-24). Each run
keeps one colour in every panel. The stiffness panels are left out when no run is anchored.

A CSV history carries no attributes: its label is its file name; its theta is drawn over the
alpha that --alpha gives, else over the alpha of the HDF5 runs when they share one (its label
says so), else every run is drawn in radians. An overturning run is drawn until it leaves the
theta panel (|theta| = 2.2 alpha, lying down), a cross marking that point in the theta and
theta_dot panels; the time axis spans the longest record.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rshistory  # noqa: E402
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402


THETA_SHOWN = 2.2  # |theta| / alpha drawn: past 2 alpha the block is lying down


def load_all(paths, alpha):
    return rshistory.share_alpha([rshistory.History(p, alpha=alpha) for p in paths])


def drawn_until(run, by_alpha):
    """Samples drawn of a run: all of them, or an overturning block's up to where it leaves
    the theta panel (beyond, it is falling over; its theta_dot would dwarf the rocking)."""
    if not by_alpha or not math.isfinite(float(run.attrs.get("t_overturn", float("nan")))):
        return len(run.t)
    out = np.flatnonzero(np.abs(run.data["theta"]) > THETA_SHOWN * run.alpha)
    return int(out[0]) + 1 if out.size else len(run.t)


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
    labels, common = rshistory.run_labels(runs)
    for j, run in enumerate(runs):  # a run drawn exactly over an earlier one would hide it: say so
        same = [i for i in range(j) if np.array_equal(runs[i].data["theta"], run.data["theta"])]
        if same:
            labels[j] += ", identical to the {} run (drawn over it)".format(rsplot.RUN_COLOUR_NAMES[same[0] % 7])
    g = runs[0].g

    handles = []
    peak_rate = 1e-9
    for i, (run, label) in enumerate(zip(runs, labels)):
        c, ls = rsplot.run_style(i)
        t = run.t
        n = drawn_until(run, by_alpha)
        theta = run.data["theta"] / run.alpha if by_alpha else run.data["theta"]
        (line,) = ax["theta"].plot(t[:n], theta[:n], color=c, ls=ls, lw=1.2, label=rsplot.wrap_label(label, 70 if len(runs) < 4 else 45))
        handles.append(line)
        falls = n < len(t) or math.isfinite(float(run.attrs.get("t_overturn", float("nan"))))
        if falls:
            ax["theta"].plot(t[n - 1], np.clip(theta[n - 1], -THETA_SHOWN, THETA_SHOWN) if by_alpha else theta[n - 1],
                             "x", color=c, ms=8, mew=2, clip_on=False, zorder=4)
        if "ground" in ax and run.has("ground_acc"):
            ax["ground"].plot(t, run.data["ground_acc"] / g, color=c, ls=ls, lw=1.2)
        if "theta_dot" in ax and run.has("theta_dot"):
            rate = run.data["theta_dot"][:n]
            ax["theta_dot"].plot(t[:n], rate, color=c, ls=ls, lw=1.2)
            if falls:
                ax["theta_dot"].plot(t[n - 1], rate[-1], "x", color=c, ms=8, mew=2, clip_on=False, zorder=4)
            peak_rate = max(peak_rate, float(np.max(np.abs(rate))))
        k_max = run.k_max()
        for side in ("k_left", "k_right"):
            if side in ax and k_max and run.has(side):
                ax[side].plot(t, run.data[side] / k_max, color=c, ls=ls, lw=1.0, drawstyle="steps-post")
        if "work" in ax:
            if run.has("w_excitation"):
                ax["work"].plot(t, run.data["w_excitation"] / 1e3, color=c, lw=1.2)
            if run.has("w_anchorage") and run.anchored():
                ax["work"].plot(t, run.data["w_anchorage"] / 1e3, color=c, lw=1.2, ls="--")
    if any(n < len(r.t) for r in runs for n in [drawn_until(r, by_alpha)]):
        handles.append(ax["theta"].plot([], [], "x", color="0.3", mew=2, ls="none",
                                        label=r"overturning: drawn until $|\theta|$ = {:g} $\alpha$".format(THETA_SHOWN))[0])

    if "ground" in ax:
        ax["ground"].set_ylabel(r"$\ddot x_g / g$ [–]")
        ax["ground"].axhline(0, color="0.5", lw=0.6)
    if by_alpha:
        ax["theta"].set_ylabel(r"$\theta / \alpha$ [–]")
        for level in (-1, 1):
            ax["theta"].axhline(level, color="0.4", lw=0.7, ls=":")
        lo, hi = ax["theta"].get_ylim()
        ax["theta"].set_ylim(max(lo, -THETA_SHOWN), min(hi, THETA_SHOWN))
    else:
        ax["theta"].set_ylabel(r"$\theta$ [rad]")
    if "theta_dot" in ax:
        ax["theta_dot"].set_ylabel(r"$\dot\theta$ [rad/s]")
        ax["theta_dot"].set_ylim(-1.1 * peak_rate, 1.1 * peak_rate)  # everything drawn stays inside
    for side, words in (("k_left", "left"), ("k_right", "right")):
        if side in ax:
            ax[side].set_ylabel(r"$K_{{{}}} / K_{{max}}$ [–]".format(words))
            ax[side].set_ylim(-0.08, 1.12)
            ax[side].set_yticks([0, 0.5, 1])
    if "work" in ax:
        ax["work"].set_ylabel("work on the block [kJ]")
        ax["work"].plot([], [], color="0.3", label="excitation (Eq. 23)")
        if any(r.anchored() for r in runs):
            ax["work"].plot([], [], color="0.3", ls="--", label="anchorage (Eq. 24)")
        ax["work"].legend(loc="best", fontsize=8)
    list(ax.values())[-1].set_xlabel("t [s]")
    ax["theta"].set_xlim(0, max(r.t[-1] for r in runs))  # the whole record, as computed

    if title is None:
        title = "\n".join(["Time history"] + common)
    fig.suptitle(title, fontsize=11)
    top = list(ax.values())[0]  # the runs' legend above the first panel; constrained layout makes room
    top.legend(handles=handles, loc="lower left", bbox_to_anchor=(0, 1.02), ncol=1 if len(handles) < 5 else 2,
               fontsize=9, frameon=False, borderaxespad=0)
    return rsplot.save(fig, out)


def main(argv):
    p = rshistory.history_parser(__doc__)
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
