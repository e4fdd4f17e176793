#!/usr/bin/python3
"""Plot of the work-precision benchmark (benchmarks/work_precision.cpp).

    /usr/bin/python3 benchmarks/plot_work_precision.py [DIR]

Reads DIR/work_precision_single.csv and DIR/work_precision_spectra.csv (DIR defaults to
benchmarks/results) and writes DIR/work_precision.png: left, the single-run error in theta
against the wall time per run; right, the fraction of spectrum cells whose outcome differs
from the reference against the wall time per cell, one line per scenario. The events method
and the paper's fixed-step method are separate series; rocksweep's default
(steps_per_period = 48) and the paper's dt = 0.0025 s are ringed.
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

DEFAULT_STEPS = "48"
PAPER_DT = "0.0025"
COLOURS = {"events": "tab:blue", "paper": "tab:orange"}
MARKERS = {"events": "o", "paper": "s"}
SCENARIO_STYLES = ["-", "--", ":", "-."]


def read_rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def label(method, setting):
    return setting if method == "events" else f"{float(setting) * 1e3:g} ms"


def ring_defaults(ax, method, setting, x, y):
    if (method, setting) in (("events", DEFAULT_STEPS), ("paper", PAPER_DT)):
        ax.plot([x], [y], marker="o", markersize=15, markerfacecolor="none",
                markeredgecolor="black", markeredgewidth=1.6, zorder=5)


def single_panel(ax, rows):
    for method in ("events", "paper"):
        pts = [(float(r["wall_s_per_cell_or_run"]) * 1e6, float(r["error"]), r["setting"])
               for r in rows if r["method"] == method]
        if not pts:
            continue
        xs, ys, ss = zip(*pts)
        name = ("events: RK4 with located events, steps per period" if method == "events"
                else "paper: fixed dt, impact at step end")
        ax.plot(xs, ys, marker=MARKERS[method], color=COLOURS[method], label=name)
        for x, y, s in pts:
            ax.annotate(label(method, s), (x, y), textcoords="offset points", xytext=(5, 4),
                        fontsize=7.5, color=COLOURS[method])
            ring_defaults(ax, method, s, x, y)
    for r in rows:
        if r["method"] == "reference":
            y = float(r["error"])
            ax.axhline(y, color="grey", linestyle=":", linewidth=1)
            ax.annotate(f"reference's own error (4096 vs 8192): {y:.1e} rad",
                        (0.98, y), xycoords=("axes fraction", "data"), textcoords="offset points",
                        xytext=(0, 4), fontsize=7.5, color="grey", ha="right")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time per run [µs]  (one run: rest to t = 2 ... 5 s, one thread)")
    ax.set_ylabel(r"max $|\theta(t) - \theta_{ref}(t)|$ [rad]")
    ax.set_title("Single runs through 1-5 impacts (4 cases, 12 times)", fontsize=10)
    ax.grid(True, which="major", alpha=0.3)
    handles, _ = ax.get_legend_handles_labels()
    handles.append(Line2D([], [], color="black", marker="o", markersize=11, markerfacecolor="none",
                          linestyle="none", label="rocksweep default 48 / paper's 2.5 ms"))
    ax.legend(handles=handles, fontsize=8, loc="center right")


def spectra_panel(ax, rows):
    scenarios = list(dict.fromkeys(r["scenario"] for r in rows))
    cells = max(int(r["cells"]) for r in rows)
    floor = 0.5 / cells  # where a setting with no mismatched cell is drawn
    for k, scenario in enumerate(scenarios):
        style = SCENARIO_STYLES[k % len(SCENARIO_STYLES)]
        for method in ("events", "paper"):
            pts = [(float(r["wall_s_per_cell_or_run"]) * 1e6, float(r["error"]), r["setting"])
                   for r in rows if r["method"] == method and r["scenario"] == scenario]
            if not pts:
                continue
            xs = [p[0] for p in pts]
            ys = [max(p[1], floor) for p in pts]
            ax.plot(xs, ys, linestyle=style, color=COLOURS[method], linewidth=1.3)
            for (x, y0, s), y in zip(pts, ys):
                ax.plot([x], [y], marker=MARKERS[method] if y0 > 0 else "v", color=COLOURS[method],
                        markerfacecolor=COLOURS[method] if y0 > 0 else "white", linestyle="none")
                if y0 > 0:
                    ax.annotate(label(method, s), (x, y), textcoords="offset points",
                                xytext=(4, 4 if k == 0 else -10), fontsize=7, color=COLOURS[method])
                else:  # the zero row is crowded: vertical labels, above for one scenario, below for the next
                    gap = 10 if (method, s) in (("events", DEFAULT_STEPS), ("paper", PAPER_DT)) else 7
                    ax.annotate(label(method, s), (x, y), textcoords="offset points",
                                xytext=(0, gap if k % 2 == 0 else -gap), fontsize=6.5, color=COLOURS[method],
                                rotation=90, ha="center", va="bottom" if k % 2 == 0 else "top")
                ring_defaults(ax, method, s, x, y)
        for r in rows:
            if r["method"] == "reference" and r["scenario"] == scenario and r["setting"].startswith("512"):
                x, y = float(r["wall_s_per_cell_or_run"]) * 1e6, max(float(r["error"]), floor)
                ax.plot([x], [y], marker="X", color="black", markersize=8, linestyle="none")
                ax.annotate(f"512 vs 1024:\n{r['mismatched_cells']} cells", (x, y), textcoords="offset points",
                            xytext=(6, 10 if k % 2 == 0 else -22), fontsize=6.5)
    ax.axhline(1.0 / cells, color="grey", linestyle=":", linewidth=1)
    top = max([float(r["error"]) for r in rows] + [floor])
    ax.set_ylim(floor / 3, top * 3)
    ax.annotate(f"1 cell of {cells}", (0.98, 1.0 / cells), xycoords=("axes fraction", "data"),
                textcoords="offset points", xytext=(0, 4), fontsize=7.5, color="grey", ha="right")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time per cell [µs]  (one thread, 8 lanes, energy stop)")
    ax.set_ylabel("fraction of cells whose outcome differs from the reference")
    side = round(cells ** 0.5)
    ax.set_title(f"Spectra, {side} x {side} cells per scenario; reference = events at 1024", fontsize=10)
    ax.grid(True, which="major", alpha=0.3)
    handles = [Line2D([], [], color=COLOURS["events"], marker="o", label="events (steps per period)"),
               Line2D([], [], color=COLOURS["paper"], marker="s", label="paper (dt)")]
    handles += [Line2D([], [], color="black", linestyle=SCENARIO_STYLES[k % len(SCENARIO_STYLES)], label=s)
                for k, s in enumerate(scenarios)]
    handles += [Line2D([], [], color="grey", marker="v", markerfacecolor="white", linestyle="none",
                       label="no mismatch (drawn at 1/2 cell)"),
                Line2D([], [], color="black", marker="X", linestyle="none",
                       label="events 512 vs 1024 (reference's own)"),
                Line2D([], [], color="black", marker="o", markersize=11, markerfacecolor="none",
                       linestyle="none", label="rocksweep default 48 / paper's 2.5 ms")]
    ax.legend(handles=handles, fontsize=7.5, loc="center left")


def main():
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("benchmarks/results")
    single = read_rows(out / "work_precision_single.csv")
    spectra = read_rows(out / "work_precision_spectra.csv")
    fig, (left, right) = plt.subplots(1, 2, figsize=(15, 6.2))
    single_panel(left, single)
    spectra_panel(right, spectra)
    fig.suptitle("rocksweep work-precision: S. Matteo block, one-sine pulses", fontsize=12)
    fig.tight_layout()
    png = out / "work_precision.png"
    fig.savefig(png, dpi=130)
    print(f"plot: {png}")


if __name__ == "__main__":
    main()
