#!/usr/bin/python3
"""The records panel of the work-precision benchmark (benchmarks/records_panel.sh): speed per core
against theta error on the records peers' runs, and against wrong outcomes over the shared
suite's slice, for rocksweep at several --tolerance, the paper's fixed-step RK4 at several dt
and the scipy script at several rtol.

    /usr/bin/python3 benchmarks/plot_records_panel.py CSV OUT

CSV is benchmarks/results/records_panel.csv; writes OUT.png and OUT.pdf.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

C = rsplot.OKABE_ITO
STYLE = {"rocksweep": (C["blue"], "o", "rocksweep, --tolerance"),
         "paper": (C["vermillion"], "s", "paper's fixed-step RK4, dt"),
         "scipy": (C["green"], "^", "scipy solve_ivp RK45, rtol")}
DEFAULTS = {("rocksweep", "1e-8"), ("paper", "0.0025")}  # the sweep default, the paper's own dt


def tag(family, value):
    return f"{float(value) * 1e3:g} ms" if family == "paper" else value


def series(ax, rows, family, x, hollow=False, label_suffix=""):
    pts = [r for r in rows if r["family"] == family]
    if not pts:
        return
    colour, marker, words = STYLE[family]
    xs, ys = [x(r) for r in pts], [float(r["per_s_per_core"]) for r in pts]
    ax.plot(xs, ys, marker=marker, color=colour, mfc="white" if hollow else colour, ls="-", lw=1.2,
            label=words + label_suffix)
    for r, xv, yv in zip(pts, xs, ys):
        ax.annotate(tag(family, r["value"]), (xv, yv), textcoords="offset points", xytext=(5, 4), fontsize=7, color=colour)
        if (family, r["value"]) in DEFAULTS:
            ax.plot(xv, yv, marker="o", ms=13, mfc="none", mec="black", mew=1.0, ls="none")


def main(path, out):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 5.2), constrained_layout=True)

    theta = [r for r in rows if r["panel"] == "theta"]
    for fam in ("rocksweep", "paper", "scipy"):
        series(a, theta, fam, lambda r: float(r["max_theta_err_rad"]))
    a.axvspan(1e-12, 1e-4, color=C["sky"], alpha=0.12, lw=0)
    a.axvline(1e-4, color="black", lw=0.8, ls="--")
    a.set_xscale("log")
    a.set_yscale("log")
    a.set_xlim(1e-9, 3.0)
    a.set_xlabel("max |θ − θ_ref| over the runs [rad]")
    a.set_ylabel("runs per second per core [1/s]")
    n = theta[0]["cells"]
    a.set_title(f"(a) θ error: {n} runs (S. Matteo, free and θ_f = α, 3 records × 2 scales)")
    a.set_ylim(top=8.0 * max(float(r["per_s_per_core"]) for r in theta))  # room for the note
    a.text(0.02, 0.97, "shaded: θ error ≤ 10⁻⁴ rad, where issue 22 asks\n≥ 20× the paper's method and ≥ 1000× scipy",
           transform=a.transAxes, fontsize=8, va="top")
    a.plot([], [], marker="o", ms=10, mfc="none", mec="black", ls="none", label="sweep default / the paper's own dt")
    a.legend(loc="center", bbox_to_anchor=(0.52, 0.45), fontsize=8)

    # Wrong outcomes: a log axis, with "none wrong" drawn at half a cell below the smallest count.
    full = [r for r in rows if r["panel"] == "outcomes"]
    sub = [r for r in rows if r["panel"] == "outcomes_scipy_subset" and r["family"] == "scipy"]
    zero = 0.5 * 100.0 / max(int(r["compared"]) for r in full + sub)

    def pct(r):
        w = int(r["wrong_outcomes"])
        return 100.0 * w / int(r["compared"]) if w else zero

    series(b, full, "rocksweep", pct, label_suffix=f" ({full[0]['compared']} cells)")
    series(b, full, "paper", pct, label_suffix=f" ({full[0]['compared']} cells)")
    series(b, sub, "scipy", pct, hollow=True, label_suffix=f" ({sub[0]['compared']}-cell subset)")
    b.set_xscale("log")
    b.set_yscale("log")
    b.axvline(zero * 1.6, color="grey", lw=0.6, ls=":")
    b.set_xlim(zero / 2.5, 100.0)
    ticks = [t for t in (0.1, 1.0, 10.0, 100.0) if t > zero * 2]
    b.set_xticks([zero] + ticks)
    b.set_xticklabels(["none"] + [f"{t:g}" for t in ticks])
    b.set_xlabel("outcomes (overturned or not) ≠ reference [% of cells]")
    b.set_ylabel("cells per second per core [1/s]")
    b.set_title(f"(b) outcomes: the shared suite at the block's own size, {full[0]['cells']} cells")
    b.legend(loc="upper right", fontsize=8)
    for ax in (a, b):
        ax.grid(True, which="both", alpha=0.25)
    fig.suptitle("Work against precision under recorded ground motions: one thread, one lane, "
                 "medians of interleaved rounds", fontsize=10)
    print("\n".join(rsplot.save(fig, out)))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
