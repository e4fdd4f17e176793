#!/usr/bin/python3
"""How the stochastic model fitted to a record compares with the record (`rocksweep synth
--record`, docs/synthetic.md): spectra for every record, and one record's motions.

    plot_synthetic_fit.py ROCKSWEEP DATA_DIR -o OUT [--count 200] [--seed 2026]
                          [--records FILE ...] [--example FILE]

DATA_DIR holds the shared records (tests/data); --records picks some of them (default: all
eleven). The spectra are scipy's (scripts/rsmotion.py), not rocksweep's.

OUT_spectra.png/.pdf   one panel per record: its 5 %-damped pseudo-acceleration spectrum, the
                       median of COUNT motions of the model fitted to it and their 16-84 %
                       band, on log axes, the issue's 0.1-3 s range shaded.
OUT_motions.png/.pdf   the record --example (default: the first one) and two of its motions:
                       acceleration against time, and the normalised cumulative Arias intensity
                       of the record against the 16-84 % band of all COUNT motions.
"""
import math
import os
import shutil
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rsmotion  # noqa: E402
import rsplot  # noqa: E402

PERIODS = np.geomspace(0.05, 5.0, 40)
BAND = (0.1, 3.0)  # the periods over which the issue compares the spectra [s]
C = rsplot.OKABE_ITO


def title_of(name):
    return os.path.splitext(name)[0].replace("_", " ")


def fitted_words(line):
    """synth's 'fitted: I_a = ... f_c = ...' line, as two short lines for a panel."""
    text = line.split("fitted:", 1)[-1].strip()
    parts = [p.strip() for p in text.split(",")]
    return ", ".join(parts[:3]) + "\n" + ", ".join(parts[3:6])


def draw_spectra(ax, rec, rec_dt, motions, dt, fitted):
    own = rsmotion.psa(rec, rec_dt, PERIODS)[0]
    sa = rsmotion.psa(motions, dt, PERIODS)
    lo, med, hi = np.percentile(sa, [16, 50, 84], axis=0)
    ax.axvspan(*BAND, color="0.93", zorder=0)
    ax.fill_between(PERIODS, lo, hi, color=C["sky"], alpha=0.35, lw=0, label="16–84 % of the motions")
    ax.plot(PERIODS, med, color=C["blue"], lw=1.8, label="median of the motions")
    ax.plot(PERIODS, own, color=C["vermillion"], lw=1.5, label="the record")
    inside = (PERIODS >= BAND[0]) & (PERIODS <= BAND[1])
    ratio = med[inside] / own[inside]
    ax.text(0.03, 0.03, "median / record, 0.1–3 s: {:.2f}–{:.2f}\n{}".format(ratio.min(), ratio.max(), fitted_words(fitted)),
            transform=ax.transAxes, fontsize=6.5, va="bottom")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(PERIODS[0], PERIODS[-1])


def draw_motions(fig_axes, name, rec, rec_dt, motions, dt, seed):
    acc_axes, arias_ax = fig_axes[:3], fig_axes[3]
    t_end = max(len(rec) * rec_dt, motions.shape[1] * dt)
    top = max(np.max(np.abs(rec)), np.max(np.abs(motions[:2])))
    rows = [(rec, rec_dt, "the record: " + title_of(name), C["vermillion"])]
    rows += [(motions[i], dt, "motion {} of seed {}".format(i, seed), C["blue"]) for i in range(2)]
    for ax, (a, step, label, colour) in zip(acc_axes, rows):
        ax.plot(np.arange(len(a)) * step, a, color=colour, lw=0.6)
        ax.set_ylim(-1.05 * top, 1.05 * top)
        ax.set_xlim(0, t_end)
        ax.set_ylabel("a [g]")
        ax.set_title(label, loc="left", fontsize=9)
    acc_axes[-1].set_xlabel("t [s]")

    def normalised(a, step):
        cum = np.cumsum(np.atleast_2d(a) ** 2, axis=1)
        return np.arange(cum.shape[1]) * step, cum / cum[:, -1:]

    t, cum = normalised(motions, dt)
    lo, med, hi = np.percentile(cum, [16, 50, 84], axis=0)
    arias_ax.fill_between(t, lo, hi, color=C["sky"], alpha=0.35, lw=0, label="16–84 % of the {} motions".format(len(motions)))
    arias_ax.plot(t, med, color=C["blue"], lw=1.6, label="median of the motions")
    tr, cr = normalised(rec, rec_dt)
    arias_ax.plot(tr, cr[0], color=C["vermillion"], lw=1.4, label="the record")
    for f in (0.05, 0.45, 0.95):
        arias_ax.axhline(f, color="0.5", lw=0.6, ls=":")
    arias_ax.set_xlim(0, t_end)
    arias_ax.set_ylim(0, 1.02)
    arias_ax.set_xlabel("t [s]")
    arias_ax.set_ylabel(r"$I_a(t) / I_a$ [–]")
    arias_ax.set_title("cumulative Arias intensity (dotted: 5, 45, 95 %: D5-95 and t_mid)", loc="left", fontsize=9)
    arias_ax.legend(loc="lower right", fontsize=8)


def main(argv):
    p = rsplot.parser(__doc__, "ROCKSWEEP (the binary) and DATA_DIR (the shared records)", n_inputs=2)
    p.add_argument("--count", type=int, default=200, help="motions per record (default 200)")
    p.add_argument("--seed", type=int, default=2026, help="seed of the motions (default 2026)")
    p.add_argument("--records", nargs="+", metavar="FILE", help="only these record files of DATA_DIR")
    p.add_argument("--example", metavar="FILE", help="the record of OUT_motions (default: the first drawn)")
    args = p.parse_args(argv)
    rocksweep, data_dir = args.inputs
    known = {r[0]: r for r in rsmotion.SHARED_RECORDS}
    names = args.records or [r[0] for r in rsmotion.SHARED_RECORDS]
    for n in names + ([args.example] if args.example else []):
        if n not in known:
            p.error("--records/--example: {} is not a shared record ({})".format(n, ", ".join(known)))
    example = args.example or names[0]
    import matplotlib.pyplot as plt

    ncols = min(4, len(names))
    nrows = int(math.ceil(len(names) / ncols))
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.4 * ncols + 0.6, 2.9 * nrows + 1.2), layout="constrained",
                             squeeze=False, sharex=True)
    work = tempfile.mkdtemp(prefix="plot_synthetic_fit.")
    try:
        for k, name in enumerate(names):
            _, units, column = known[name]
            path = os.path.join(data_dir, name)
            rec, rec_dt = rsmotion.read_record(path, units, column)
            motions, fitted = rsmotion.synthesise(rocksweep, path, units, column, args.count, args.seed,
                                                  os.path.join(work, str(k)))
            ax = axes[k // ncols][k % ncols]
            draw_spectra(ax, rec, rec_dt, motions, rec_dt, fitted)
            ax.set_title(title_of(name), fontsize=9)
            if k % ncols == 0:
                ax.set_ylabel("PSA [g]")
            if k // ncols == nrows - 1 or k + ncols >= len(names):
                ax.set_xlabel("T [s]")
            if name == example:
                mfig, maxes = plt.subplots(4, 1, figsize=(10, 9), layout="constrained")
                draw_motions(maxes, name, rec, rec_dt, motions, rec_dt, args.seed)
                mfig.suptitle("A record and the stochastic model fitted to it (Rezaeian & Der Kiureghian): two of its "
                              "motions and the Arias build-up of all {}".format(args.count), fontsize=11)
                rsplot.save(mfig, rsplot.output_stem(args.output) + "_motions")
            shutil.rmtree(os.path.join(work, str(k)))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    for k in range(len(names), nrows * ncols):
        axes[k // ncols][k % ncols].axis("off")
    axes[0][0].legend(loc="upper right", fontsize=7)
    fig.suptitle("5 %-damped spectra of each record and of {} motions of the model fitted to it (seed {}); "
                 "grey: 0.1–3 s".format(args.count, args.seed), fontsize=11)
    rsplot.save(fig, rsplot.output_stem(args.output) + "_spectra")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
