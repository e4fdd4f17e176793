#!/usr/bin/python3
"""The fragility of one damage state under several suites of motions (record-suite files of
`rocksweep suite`, docs/suite.md), side by side: can the anchorages be told apart?

    plot_fragility_compare.py A.h5 B.h5 ... -o OUT [--label "12 records" "1100 synthetic" ...]
                              [--state overturning] [--radius R] [--alpha A]

OUT.png/.pdf: one panel per file, its scenarios' lognormal fits (lines) over the fraction of its
motions reaching the state at each level (markers), the 95 % interval of each median as a bar at
P = 0.5; and a last panel with every median and its 95 % interval, file by file, where two
anchorages are told apart when their intervals do not overlap. The files must measure intensity
alike (the same intensity measure and unit); each is drawn at its own block nearest --radius and
--alpha (default: its configured block's).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_suite  # noqa: E402
import read_suite  # noqa: E402
import rsplot  # noqa: E402


def nearest(values, x):
    return int(np.argmin(np.abs(np.asarray(values) - x)))


def state_index(fr, state, path):
    if state not in fr["states"]:
        raise SystemExit("plot_fragility_compare.py: {}: no damage state {!r} (the file has {})".format(
            path, state, ", ".join(fr["states"])))
    return fr["states"].index(state)


def load(path, radius, alpha):
    try:
        S = read_suite.load(path)
    except read_suite.SuiteFileError as e:
        raise SystemExit("plot_fragility_compare.py: {}".format(e))
    missing = [nm for nm, sc in S["scenarios"].items() if sc["fragility"] is None]
    if missing:
        raise SystemExit("plot_fragility_compare.py: {}: no fragility for {} (the suite is not complete)".format(
            path, ", ".join(missing)))
    a = nearest(S["alpha_rad"], S["attrs"]["alpha_rad"] if alpha is None else alpha)
    j = nearest(S["radius_m"], S["attrs"]["radius_m"] if radius is None else radius)
    return plot_suite.at_alpha(S, a), j


def draw_file(ax, S, j, state, x):
    names = list(S["scenarios"])
    words = plot_suite.scenario_titles(S, names)
    unit = plot_suite.intensity_unit_words(S)
    levels = S["intensity"]
    for k, (nm, w) in enumerate(zip(names, words)):
        fr = S["scenarios"][nm]["fragility"]
        s = state_index(fr, state, "")
        colour = plot_suite.scenario_colour(S, nm)
        marker = plot_suite.SCENARIO_MARKERS[k % len(plot_suite.SCENARIO_MARKERS)]
        ax.plot(levels, fr["fraction"][s, j], marker, color=colour, ms=3.5, ls="", alpha=0.6)
        med, beta = fr["median_intensity"][s, j], fr["beta"][s, j]
        lo, hi = fr["median_intensity_lo"][s, j], fr["median_intensity_hi"][s, j]
        if fr["fit_status_names"][s, j] == "ok":
            ax.plot(x, read_suite.fragility_curve(x, med, beta), color=colour, lw=1.8,
                    label=r"{}: {:.3g} ({:.3g}–{:.3g}){}, $\beta$ = {:.2f}".format(w, med, lo, hi, unit, beta))
            ax.errorbar([med], [0.5], xerr=[[med - lo], [hi - med]], fmt="none", ecolor=colour, lw=2.2, capsize=4)
        else:
            ax.plot([], [], color=colour, label=plot_suite.fit_label(w, fr, s, j, unit))


def runs_of(S, j):
    """Motions per level of the first scenario (the fits' sample size)."""
    fr = next(iter(S["scenarios"].values()))["fragility"]
    return int(np.max(fr["total"][0, j])) if "total" in fr else len(S["records"]["names"])


def draw_medians(ax, files, labels, state):
    """Each scenario's median and 95 % interval, one row per (file, scenario)."""
    rows, ticks = 0, []
    for f, ((S, j), label) in enumerate(zip(files, labels)):
        names = list(S["scenarios"])
        for k, (nm, w) in enumerate(zip(names, plot_suite.scenario_titles(S, names))):
            fr = S["scenarios"][nm]["fragility"]
            s = state_index(fr, state, "")
            med, lo, hi = fr["median_intensity"][s, j], fr["median_intensity_lo"][s, j], fr["median_intensity_hi"][s, j]
            y = -(rows + f * 0.8)
            colour = plot_suite.scenario_colour(S, nm)
            marker = plot_suite.SCENARIO_MARKERS[k % len(plot_suite.SCENARIO_MARKERS)]
            if np.isfinite(med):
                ax.errorbar([med], [y], xerr=[[med - lo], [hi - med]], fmt=marker, color=colour, ms=6, lw=2, capsize=4)
            ticks.append((y, "{}:\n{}".format(label, w)))
            rows += 1
    ax.set_yticks([t for t, _ in ticks], [w for _, w in ticks], fontsize=8)
    ax.set_ylim(min(t for t, _ in ticks) - 0.7, 0.7)
    ax.grid(axis="y", visible=False)


def main(argv):
    p = rsplot.parser(__doc__, "record-suite files (rocksweep suite -o IN.h5)")
    p.add_argument("--label", nargs="+", help="a name per file (default: the file names)")
    p.add_argument("--state", default="overturning", help="the damage state (default: overturning; e.g. rotation>=0.5)")
    p.add_argument("--radius", type=float, metavar="R", help="block size R [m] (default: each file's configured block's)")
    p.add_argument("--alpha", type=float, metavar="A", help="slenderness alpha [rad] (default: the configured block's)")
    args = p.parse_args(argv)
    labels = args.label or [os.path.basename(f) for f in args.inputs]
    if len(labels) != len(args.inputs):
        p.error("--label gives {} names for {} files".format(len(labels), len(args.inputs)))
    files = [load(path, args.radius, args.alpha) for path in args.inputs]
    measures = {(S["intensity_measure"], S["intensity_units"]) for S, _ in files}
    if len(measures) > 1:
        p.error("the files measure intensity differently ({}): their medians cannot share an axis".format(
            ", ".join("{} [{}]".format(*m) for m in sorted(measures))))
    S0 = files[0][0]
    top = max(S["intensity"][-1] for S, _ in files)
    x = np.linspace(top * 1e-3, top * 1.02, 400)
    fig, axes, _ = rsplot.panels(len(files) + 1, width=5.0 * (len(files) + 1), height=4.8,
                                 ncols=len(files) + 1, sharey=False, legend_width=None)
    for ax, (S, j), label, path in zip(axes, files, labels, args.inputs):
        draw_file(ax, S, j, args.state, x)
        ax.set_title("{} ({} motions)".format(label, runs_of(S, j)))
        ax.set_xlim(0, top * 1.02)
        ax.set_ylim(-0.03, 1.03)
        ax.set_xlabel(plot_suite.intensity_label(S))
        ax.set_ylabel("P({}) [–]".format(args.state))
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), fontsize=8, frameon=False)
    draw_medians(axes[-1], files, labels, args.state)
    axes[-1].set_xlabel("median " + plot_suite.intensity_label(S0) + ", 95 % interval")
    axes[-1].set_title("medians: told apart where the bars do not overlap")
    S, j = files[0]
    fig.suptitle("Fragility ({}) under each suite: lognormal MLE fits (lines), fraction of motions reaching it\n"
                 "(markers) and the medians' 95 % intervals (bars); block {}".format(
                     args.state, plot_suite.block_at(S, S["radius_m"][j])), fontsize=11)
    rsplot.save(fig, args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
