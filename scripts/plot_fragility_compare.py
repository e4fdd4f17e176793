#!/usr/bin/python3
"""The fragility of one damage state under several suites of motions (record-suite files of
`rocksweep suite`, docs/suite.md), side by side: can the anchorages be told apart?

    plot_fragility_compare.py A.h5 B.h5 ... -o OUT [--label "12 records" "1100 synthetic" ...]
                              [--state overturning] [--radius R] [--alpha A]

OUT.png/.pdf: one panel per file, its scenarios' lognormal fits (lines) over the fraction of its
motions reaching the state at each level (markers), the 95 % interval of each median as a bar at
P = 0.5; and a last panel with every median and its 95 % interval, file by file.

Two anchorages swept over the same motions are compared **paired**: the ratio of their medians,
with its 95 % interval from a bootstrap over the motions (--bootstrap replicates, each drawing
the file's motions with replacement, the same draw for every anchorage, and refitting each by the
binomial likelihood of docs/fragility.md). They are told apart when that interval excludes 1;
non-overlapping intervals of the medians themselves are a stricter test, which ignores that the
anchorages met the same motions. The ratios are printed and written under the medians panel.

The files must measure intensity alike (the same intensity measure and unit); each is drawn at
its own block nearest --radius and --alpha (default: its configured block's).
"""
import math
import os
import sys

import numpy as np
from scipy import optimize, special

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


def probit_fit(x, exceed, total):
    """(median, beta) of the lognormal P(x) = Phi(ln(x / median) / beta) maximising the binomial
    likelihood of the stripes (docs/fragility.md, section 2); NaNs without a finite maximum."""
    keep = total > 0
    u, n, N = np.log(x[keep]), exceed[keep], total[keep]
    if n.sum() == 0 or n.sum() == N.sum():
        return math.nan, math.nan
    ub = np.average(u, weights=N)

    def nll(p):
        z = p[0] + p[1] * (u - ub)
        return -np.sum(n * special.log_ndtr(z) + (N - n) * special.log_ndtr(-z))

    r = optimize.minimize(nll, [0.0, 1.0 / max(np.ptp(u), 0.1)], method="Nelder-Mead",
                          options={"xatol": 1e-9, "fatol": 1e-10, "maxiter": 4000})
    a, b = r.x
    return (math.exp(ub - a / b), 1.0 / b) if b > 0 else (math.nan, math.nan)


def runs_reaching(S, j, state):
    """Per scenario (in the file's order): (reached, converged) [motion, level] of the state."""
    fr0 = next(iter(S["scenarios"].values()))["fragility"]
    ratio = fr0["rotation_ratios"][state_index(fr0, state, "")]
    runs = []
    for sc in S["scenarios"].values():
        out, rot = sc["outcome"][:, j], sc["max_rotation"][:, j]   # [record, level]
        seen = out != 255
        runs.append((read_suite.reached(out, rot, None if np.isnan(ratio) else ratio) & seen, seen))
    return runs


def paired_ratios(S, j, state, replicates, seed=1):
    """[(name, reference, ratio of their medians, 2.5 %, 97.5 %, replicates with both fitted)]
    for every pair of scenarios (the later over the earlier, in the file's order), over a
    bootstrap of the motions: the same draw for every scenario."""
    names = list(S["scenarios"])
    s = state_index(S["scenarios"][names[0]]["fragility"], state, "")
    x = S["intensity"]
    runs = runs_reaching(S, j, state)
    rng = np.random.default_rng(seed)
    records = runs[0][0].shape[0]
    medians = np.full((replicates, len(names)), np.nan)
    for k in range(replicates):
        w = np.bincount(rng.integers(0, records, records), minlength=records)
        for c, (reach, seen) in enumerate(runs):
            medians[k, c] = probit_fit(x, w @ reach, w @ seen)[0]
    rows = []
    for c0 in range(len(names)):
        for c in range(c0 + 1, len(names)):
            med = [S["scenarios"][names[i]]["fragility"]["median_intensity"][s, j] for i in (c0, c)]
            r = medians[:, c] / medians[:, c0]
            r = r[np.isfinite(r)]
            lo, hi = np.percentile(r, [2.5, 97.5]) if len(r) else (math.nan, math.nan)
            rows.append((names[c], names[c0], med[1] / med[0], lo, hi, len(r)))
    return rows


def short_title(S, name):
    """The scenario's words up to its first comma ('adaptive', 'constant K')."""
    return plot_suite.scenario_titles(S, [name])[0].split(",")[0]


def draw_ratios(ax, files, labels, ratios):
    """Each pair's ratio of medians with its paired-bootstrap 95 % interval, one row a pair."""
    ticks, y = [], 0.0
    for f, ((S, _), label, paired) in enumerate(zip(files, labels, ratios)):
        for k, (nm, ref, r, lo, hi, _) in enumerate(paired):
            apart = lo > 1 or hi < 1
            ax.errorbar([r], [y], xerr=[[r - lo], [hi - r]], fmt="o" if apart else "o", ms=6, lw=2, capsize=4,
                        color=rsplot.OKABE_ITO["black"] if apart else "0.6", mfc=None if apart else "white")
            ticks.append((y, "{}:\n{} / {}".format(label, short_title(S, nm), short_title(S, ref))))
            y -= 1.0
        y -= 0.8
    ax.axvline(1.0, color=rsplot.OKABE_ITO["vermillion"], lw=1.0, ls="--")
    ax.set_yticks([t for t, _ in ticks], [w for _, w in ticks], fontsize=8)
    ax.set_ylim(min(t for t, _ in ticks) - 0.7, 0.7)
    ax.grid(axis="y", visible=False)


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
    p.add_argument("--bootstrap", type=int, default=400, metavar="B",
                   help="bootstrap replicates of the paired ratios (default 400)")
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
    n = len(files) + 2
    ncols = 2 if n % 2 == 0 else n   # two files: a square of four panels
    fig, axes, _ = rsplot.panels(n, width=5.5 * ncols, height=5.2, ncols=ncols, sharey=False, legend_width=None)
    for ax, (S, j), label, path in zip(axes, files, labels, args.inputs):
        draw_file(ax, S, j, args.state, x)
        ax.set_title("{} ({} motions)".format(label, runs_of(S, j)))
        ax.set_xlim(0, top * 1.02)
        ax.set_ylim(-0.03, 1.03)
        ax.set_xlabel(plot_suite.intensity_label(S))
        ax.set_ylabel("P({}) [–]".format(args.state))
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), fontsize=8, frameon=False)
    ratios = [paired_ratios(S, j, args.state, args.bootstrap) for S, j in files]
    for label, paired in zip(labels, ratios):
        for nm, ref, r, lo, hi, n in paired:
            print("{}: median {} / {} = {:.4f}, paired bootstrap 95 % {:.4f}-{:.4f} ({} replicates): {}".format(
                label, nm, ref, r, lo, hi, n, "told apart" if lo > 1 or hi < 1 else "not told apart"))
    draw_medians(axes[-2], files, labels, args.state)
    axes[-2].set_xlabel("median " + plot_suite.intensity_label(S0) + ", 95 % interval")
    axes[-2].set_title("medians and their 95 % intervals")
    draw_ratios(axes[-1], files, labels, ratios)
    axes[-1].set_xlabel("ratio of the medians, paired bootstrap 95 % interval [–]")
    axes[-1].set_title("paired: told apart where the bar misses 1 (grey: not)")
    S, j = files[0]
    fig.suptitle("Fragility ({}) under each suite: lognormal MLE fits (lines), fraction of motions reaching it\n"
                 "(markers) and the medians' 95 % intervals (bars); block {}".format(
                     args.state, plot_suite.block_at(S, S["radius_m"][j])), fontsize=11)
    rsplot.save(fig, args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
