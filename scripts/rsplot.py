"""Shared pieces of rocksweep's plotting scripts, for every figure: the style (Okabe-Ito colours,
fonts, resolution), command lines, words for blocks, pulses, anchorages and angles (pi_fraction),
legend labels that wrap, panel grids, the spectra's secondary axes, and writing each figure as
PNG and PDF.

Spectra files are read by read_spectra.py, suite files by read_suite.py, histories by
rshistory.py.
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import read_spectra  # noqa: E402

# Every PNG is written at this resolution; figure sizes are chosen so that each PNG is at least
# MIN_PNG_PX wide and tall (the tests check it).
DPI = 150
MIN_PNG_PX = (1000, 600)
STANDARD_GRAVITY = 9.81  # only when a file does not say which g it used

plt.rcParams.update(
    {
        "font.size": 10,
        "axes.titlesize": 10,
        "axes.labelsize": 10,
        "legend.fontsize": 9,
        "axes.grid": True,
        "grid.alpha": 0.3,
        "savefig.dpi": DPI,
        "pdf.fonttype": 42,  # TrueType in the PDF: text stays text (searchable, editable)
    }
)

# The Okabe-Ito palette (Okabe & Ito 2008, "Color Universal Design"), safe for the common
# colour-vision deficiencies: every figure takes its colours from here. Yellow is left out of
# the run colours: on white it is barely visible as a line.
OKABE_ITO = {"blue": "#0072B2", "vermillion": "#D55E00", "green": "#009E73", "purple": "#CC79A7",
             "orange": "#E69F00", "sky": "#56B4E9", "black": "#000000", "yellow": "#F0E442"}
# One colour per run, the same in every panel.
RUN_COLOUR_NAMES = ("blue", "vermillion", "green", "purple", "orange", "sky blue", "black")
RUN_COLOURS = [OKABE_ITO[k.split()[0] if k != "sky blue" else "sky"] for k in RUN_COLOUR_NAMES]
# Beyond seven runs the colours come back with these line styles (run i: colour i % 7, style i // 7).
RUN_STYLES = ["-", "--", ":", "-."]


def run_colour(i):
    return RUN_COLOURS[i % len(RUN_COLOURS)]


def run_style(i):
    """(colour, line style) of run i: distinct for 28 runs."""
    return run_colour(i), RUN_STYLES[(i // len(RUN_COLOURS)) % len(RUN_STYLES)]


def pi_fraction(x, tol=1e-6):
    """An angle [rad] as mathtext in multiples of π where it is one (0, π/4, π/2, 3π/4, π,
    2π/3, ...; denominators up to 12), else as a decimal in rad."""
    if abs(x) < tol:
        return "0"
    r = x / math.pi
    for d in (1, 2, 3, 4, 6, 8, 12):
        n = round(r * d)
        if n and abs(r * d - n) < tol * d:
            sign = "-" if n < 0 else ""
            n = abs(n)
            num = r"\pi" if n == 1 else r"{}\pi".format(n)
            return sign + (num if d == 1 else num + "/{}".format(d))
    return "{:.4g}".format(x)


def wrap_label(label, width=60):
    """Breaks a legend label of comma-separated parts into lines of about `width` characters,
    only at ', ' outside mathtext ($...$), so that a legend never grows wider than its figure."""
    parts, current, dollars = [], "", 0
    pieces = label.split(", ")
    for k, piece in enumerate(pieces):
        current += piece
        dollars += piece.count("$")
        if k < len(pieces) - 1:
            if dollars % 2:  # inside mathtext: keep the comma
                current += ", "
                continue
            parts.append(current + ",")
            current = ""
    parts.append(current)
    lines, line = [], ""
    for part in parts:
        if line and len(line) + 1 + len(part) > width:
            lines.append(line)
            line = part
        else:
            line = (line + " " + part) if line else part
    lines.append(line)
    return "\n".join(lines)


# --------------------------------------------------------------------------- command lines


def parser(description, inputs_help, n_inputs="+"):
    """An argparse parser of the common shape: INPUT... -o OUT."""
    p = argparse.ArgumentParser(description=description, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("inputs", nargs=n_inputs, metavar="INPUT", help=inputs_help)
    p.add_argument(
        "-o",
        "--output",
        required=True,
        metavar="OUT",
        help="output name: OUT.png and OUT.pdf are written (a .png or .pdf suffix is dropped)",
    )
    return p


def output_stem(out):
    stem, ext = os.path.splitext(out)
    return stem if ext.lower() in (".png", ".pdf") else out


def save(fig, out):
    """Writes OUT.png and OUT.pdf; raster-marked artists (maps) stay raster in the PDF.
    Returns the two paths."""
    stem = output_stem(out)
    paths = (stem + ".png", stem + ".pdf")
    for path in paths:
        fig.savefig(path, dpi=DPI)
        # The layout is settled by the first file; laying out again for the second costs
        # as much as drawing it and changes nothing.
        if fig.get_layout_engine() is not None:
            fig.set_layout_engine("none")
    plt.close(fig)
    return paths


def panels(n, width=11.0, height=4.6, ncols=None, sharey=True, legend_width=0.55):
    """A figure of n panels (up to 3 a row, or ncols) and a legend column on the right (none if
    legend_width is None). Returns (fig, panel axes, legend axis or None)."""
    ncols = ncols or min(n, 3)
    nrows = int(math.ceil(n / ncols))
    fig = plt.figure(figsize=(width, height * nrows + 1.0), layout="constrained")
    if legend_width is None:
        grid = fig.add_gridspec(nrows, ncols)
    else:
        grid = fig.add_gridspec(nrows, ncols + 1, width_ratios=[1.0] * ncols + [legend_width])
    axes = []
    for k in range(n):
        share = axes[0] if sharey and axes else None
        axes.append(fig.add_subplot(grid[k // ncols, k % ncols], sharey=share))
    if legend_width is None:
        return fig, axes, None
    legend_ax = fig.add_subplot(grid[:, ncols])
    legend_ax.axis("off")
    return fig, axes, legend_ax


# --------------------------------------------------------------------------- words


# An attribute as plain Python (h5py returns fixed-length strings as bytes): the spectra
# reader's own conversion, so that both kinds of file decode alike.
text = read_spectra._value


def alpha_fraction(r):
    """theta_f / alpha as mathtext: 1 -> α, 0.5 -> α/2, 0.3 -> 0.3 α."""
    if r == 1:
        return r"\alpha"
    if r > 0:
        n = round(1.0 / r)
        if n >= 2 and math.isclose(r * n, 1.0, rel_tol=1e-6):
            return r"\alpha/{}".format(n)
    return r"{:g}\,\alpha".format(r)


def anchorage_words(attrs, with_law=False):
    """A scenario's or history's anchorage in words (mathtext), from its attributes
    `anchorage`, `theta_f_ratio`, `kmin_ratio`, `break_rule`, `adaptive_law` (named when it is
    not the paper's, or always with `with_law`)."""
    kind = attrs.get("anchorage", "")
    if kind == "free":
        return "free-standing"
    # A ratio left out of `attrs` (a spectra file sweeps it as an axis) is left out of the words.
    has_theta_f = "theta_f_ratio" in attrs
    theta_f = r"$\theta_f = {}$".format(alpha_fraction(attrs.get("theta_f_ratio", float("nan"))))
    if kind == "constant":
        return "constant $K$" + (", " + theta_f if has_theta_f else "")
    if kind == "adaptive":
        words = r"adaptive, $K_{{min}} = {:g}\,K_{{max}}$".format(attrs["kmin_ratio"]) if "kmin_ratio" in attrs else "adaptive"
        if has_theta_f and attrs["theta_f_ratio"] != 1:
            words += ", " + theta_f
        if attrs.get("break_rule") == "force":
            words += ", breaks at $F_u$"
        # --adaptive-law: the paper's law is the default and unnamed elsewhere; say it when asked
        # (with_law) so that runs differing by the law alone read differently.
        law = attrs.get("adaptive_law")
        if law == "passive" or (with_law and law):
            words += ", {} law".format("paper's" if law == "paper" else law)
        return words
    return kind or "anchorage not recorded"


def block_words(b=None, h=None, alpha=None, p=None):
    """'2b = 0.6 m, 2h = 2.72 m, α = 0.2171 rad, p = 2.298 rad/s', leaving out what is unknown."""
    parts = []
    if b is not None and h is not None:
        parts.append("2b = {:.3g} m, 2h = {:.3g} m".format(2 * b, 2 * h))
    if alpha is not None:
        parts.append(r"$\alpha$ = {:.4g} rad".format(alpha))
    if p is not None:
        parts.append("p = {:.4g} rad/s".format(p))
    return ", ".join(parts)


# --------------------------------------------------------------------------- spectra helpers


def cell_edges(centres):
    """Edges of cells centred on `centres` (midpoints; the end cells as wide as their
    neighbours); a single point gets a cell of width 10 % of its value (or 1)."""
    c = np.asarray(centres, dtype=float)
    if c.size == 1:
        half = 0.05 * abs(c[0]) if c[0] != 0 else 0.5
        return np.array([c[0] - half, c[0] + half])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]])


def user_axes(ax, p, alpha, top=True, right=True):
    """Secondary axes in the user's terms: pulse period T_p = 2π/ω_p [s] on top (from
    ω_p/p), peak ground acceleration a_p0/g [g] on the right (from a_p0/(αg))."""
    if top and p:
        def period(x):  # its own inverse; ω_p/p > 0 on every axis we draw
            return 2 * np.pi / (p * np.maximum(np.asarray(x, dtype=float), 1e-12))

        sec = ax.secondary_xaxis("top", functions=(period, period))
        sec.set_xticks(period_ticks(ax.get_xlim(), p))
        sec.set_xlabel(r"pulse period $T_p$ [s]", fontsize=9)
        sec.tick_params(labelsize=8)
    if right and alpha:
        sec = ax.secondary_yaxis("right", functions=(lambda y: y * alpha, lambda y: y / alpha))
        sec.set_ylabel(r"PGA $a_{p0}$ [g]", fontsize=9)
        sec.tick_params(labelsize=8)


def period_ticks(omega_ratio_limits, p, min_gap=0.07):
    """Round pulse periods T_p [s] for a top axis over ω_p/p, at least min_gap of the axis
    apart (T_p = 2π/(p x) crowds its ticks at small x)."""
    lo, hi = omega_ratio_limits
    nice = [0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.8, 1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 15, 20]
    chosen, last_x = [], None
    for period in nice:  # short periods (right end) first
        x = 2 * np.pi / (p * period)
        if lo <= x <= hi and (last_x is None or last_x - x >= min_gap * (hi - lo)):
            chosen.append(period)
            last_x = x
    return chosen
