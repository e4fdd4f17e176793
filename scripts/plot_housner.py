#!/usr/bin/python3
"""The paper's Fig. 3: Housner's constant ground acceleration held a little longer and a
little shorter than the critical duration (linearised equations).

    plot_housner.py LONGER.h5 SHORTER.h5 -o OUT     writes OUT.png and OUT.pdf

Inputs: two histories of `rocksweep simulate --pulse constant --equations linearised
--amplitude-ratio A --duration T` (HDF5: the duration is read from the stored config). One
panel each: theta/alpha against t with the pulse shaded, and Housner's closed form during the
pulse, theta/alpha = -(A - 1)(cosh pt - 1), dotted over it. The caption gives the closed-form
critical duration t* = (1/p) ln(A/(A - 1)), A = a/(alpha g), and what it becomes when a is
rounded to 4 decimals in g (the paper quotes 0.2822 g: literally t* = 0.63819 s, so the pair
0.6380 s / 0.6300 s brackets t* only for a = 1.3 alpha g, t* = 0.63797 s).
"""
import math
import os
import sys
import textwrap

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rshistory  # noqa: E402
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402


def critical_duration(amplitude_ratio, p):
    """Housner's linearised t* [s]: a constant a = A alpha g held longer overturns the block."""
    A = amplitude_ratio
    return math.log(A / (A - 1.0)) / p


def pulse_of(run):
    """(A, duration [s]) of a constant-pulse history; exits with a message otherwise."""
    if run.attrs.get("pulse") != "constant":
        raise SystemExit("{}: not a constant-acceleration history (simulate --pulse constant)".format(run.path))
    A = float(run.attrs["amplitude_ratio"])
    duration = float(run.config.get("simulate.duration") or "nan")
    if not A > 1 or not math.isfinite(duration):
        raise SystemExit("{}: needs a/(alpha g) > 1 and a recorded duration".format(run.path))
    return A, duration


SECONDS = "{:.4f}\u00a0s"  # no line break between a duration and its unit


def caption(A, alpha, p, equations, durations):
    """The closed-form critical duration, which of the durations shown exceed it, and the same
    for a rounded to 4 decimals in g (the paper quotes a in g)."""
    t_star = critical_duration(A, p)

    def verdict(t_crit):
        over = [d for d in durations if d > t_crit]
        under = [d for d in durations if d <= t_crit]
        words = []
        if over:
            words.append(" and ".join(SECONDS.format(d) for d in over) + (" overturns" if len(over) == 1 else " overturn"))
        if under:
            words.append(" and ".join(SECONDS.format(d) for d in under) + (" does not" if len(under) == 1 else " do not"))
        return "; ".join(words)

    words = ("Housner's constant ground acceleration a = {A:g} αg = {a:.5f} g ({eq} equations). Closed form: "
             "t* = (1/p) ln(A/(A−1)) = {t:.5f}\u00a0s, A\u00a0=\u00a0a/(αg): of the durations shown, {v}.").format(
        A=A, a=A * alpha, eq=equations, t=t_star, v=verdict(t_star))
    rounded = round(A * alpha, 4)
    if not math.isclose(rounded, A * alpha, rel_tol=1e-12):
        t_rounded = critical_duration(rounded / alpha, p)
        words += (" With a = {r:.4f} g taken literally (A = {Ar:.5f}), t* = {tr:.5f}\u00a0s: {v}.").format(
            r=rounded, Ar=rounded / alpha, tr=t_rounded, v=verdict(t_rounded))
    return words


def plot(runs, out):
    pulses = [pulse_of(r) for r in runs]
    fig, axes = plt.subplots(1, len(runs), figsize=(11, 5.6), sharex=True, sharey=True, layout="constrained",
                             squeeze=False)
    t_end = max(r.t[-1] for r in runs)  # one time axis for both panels
    for i, (ax, run, (A, duration)) in enumerate(zip(axes[0], runs, pulses)):
        c = rsplot.run_colour(i)
        t, theta = run.t, run.data["theta"] / run.alpha
        ax.axvspan(0, duration, color="0.85", lw=0, label="ground acceleration on ({:.4f} s)".format(duration))
        ax.plot(t, theta, color=c, lw=1.4, label="rocksweep")
        tp = np.linspace(0, duration, 200)
        ax.plot(tp, -(A - 1) * (np.cosh(run.p * tp) - 1), ":", color="k", lw=2,
                label="closed form during the pulse")
        t_over = float(run.attrs.get("t_overturn", "nan"))
        if math.isfinite(t_over):
            # It leaves the panel at |theta| = 2.2 alpha and overturns (theta = pi/2) later:
            # both on the axes, the overturn as a marked time on the lower edge.
            ax.axvline(t_over, ymax=0.5, color=c, lw=1.0, ls="--")  # below the legend
            ax.plot(t_over, math.copysign(2.2, theta[-1]), "x", color=c, ms=9, mew=2, clip_on=False, zorder=4,
                    label="overturned at {:.2f} s".format(t_over))
        for level in (-1, 1):
            ax.axhline(level, color="0.4", lw=0.7, ls=":")
        ax.set_ylim(-2.2, 2.2)
        ax.set_xlim(0, 1.02 * max(t_end, t_over if math.isfinite(t_over) else 0))
        ax.set_xlabel("t [s]")
        ax.set_title("held {:.4f} s: {}".format(duration, run.outcome_words() or "?"))
        ax.legend(loc="upper right", fontsize=8)
    axes[0][0].set_ylabel(r"$\theta / \alpha$ [–]")
    head = runs[0].block_words()
    fig.suptitle("Housner's constant ground acceleration (paper's Fig. 3)\nblock " + head, fontsize=11)
    if len({A for A, _ in pulses}) > 1:
        raise SystemExit("the two histories have different accelerations: compare durations at one a")
    note = caption(pulses[0][0], runs[0].alpha, runs[0].p, runs[0].attrs.get("equations", "?"),
                   [d for _, d in pulses])
    fig.text(0.5, 0.01, "\n".join(textwrap.wrap(note, 140)), ha="center", va="bottom", fontsize=9)
    fig.get_layout_engine().set(rect=(0, 0.1, 1, 0.9))
    return rsplot.save(fig, out)


def main(argv):
    p = rsplot.parser(__doc__, "two constant-pulse histories (.h5)", n_inputs=2)
    args = p.parse_args(argv)
    plot([rshistory.History(path) for path in args.inputs], args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
