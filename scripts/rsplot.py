"""Shared pieces of rocksweep's plotting scripts: reading histories (HDF5 or CSV), describing
blocks, pulses and scenarios in words, and writing each figure as PNG and PDF.

Spectra files are read by read_spectra.py (the one place that knows their layout); this
module reads history files (docs/hdf5.md, "History file"), defensively: a dataset or
attribute that is missing is simply absent, and datasets it does not know are kept too.
"""
import argparse
import csv
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

# One colour per run, the same in every panel (colour-blind safe, Okabe-Ito).
RUN_COLOURS = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"]


def run_colour(i):
    return RUN_COLOURS[i % len(RUN_COLOURS)]


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


def history_parser(description):
    """The command line of the scripts that draw histories: HISTORY... -o OUT [--alpha] [--title]."""
    p = parser(description, "history files (.h5 or .csv)")
    p.add_argument("--alpha", type=float, help="alpha [rad] for CSV histories (HDF5 files carry their own)")
    p.add_argument("--title", help="figure title (default: the block and the excitation the runs share)")
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


def anchorage_words(attrs):
    """A scenario's or history's anchorage in words (mathtext), from its attributes
    `anchorage`, `theta_f_ratio`, `kmin_ratio`, `break_rule`."""
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


# --------------------------------------------------------------------------- histories

HISTORY_COLUMNS = {  # CSV header name -> dataset name (docs/hdf5.md)
    "t_s": "t",
    "theta_rad": "theta",
    "theta_dot_rad_s": "theta_dot",
    "k_left_N_m": "k_left",
    "k_right_N_m": "k_right",
    "ground_acc_m_s2": "ground_acc",
    "w_excitation_J": "w_excitation",
    "w_anchorage_J": "w_anchorage",
}


def config_values(config_text):
    """The `key=value` lines of an effective config (the `config` attribute) as a dict of
    strings, quotes removed; '' for values that were not set."""
    values = {}
    for line in config_text.splitlines():
        if "=" in line:
            key, _, value = line.partition("=")
            values[key.strip()] = value.strip().strip('"')
    return values


def _float(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return None


class History:
    """One time history. `data[name]` holds every 1-D dataset found (t, theta, ...; unknown
    ones too); `attrs` the file's attributes (empty for CSV). Derived, None when unknown:
    alpha [rad], p [rad/s], g [m/s^2], b, h [m]."""

    def __init__(self, path, alpha=None):
        self.path = path
        self.name = os.path.splitext(os.path.basename(path))[0]
        self.attrs = {}
        self.data = {}
        if path.lower().endswith(".csv"):
            self._read_csv(path)
        else:
            self._read_h5(path)
        for required in ("t", "theta"):
            if required not in self.data:
                raise SystemExit("{}: no '{}' column/dataset: not a rocksweep history".format(path, required))
        cfg = config_values(self.attrs.get("config", ""))
        self.config = cfg
        self.alpha = _float(self.attrs.get("alpha_rad")) or alpha
        self.p = _float(self.attrs.get("p_rad_s"))
        self.g = _float(cfg.get("gravity")) or STANDARD_GRAVITY
        self.b = _float(cfg.get("half-width")) if not cfg.get("radius") else None
        self.h = _float(cfg.get("half-height")) if not cfg.get("radius") else None

    def _read_h5(self, path):
        import h5py

        with h5py.File(path, "r") as f:
            self.attrs = {k: text(v) for k, v in f.attrs.items()}
            for name, obj in f.items():
                if isinstance(obj, h5py.Dataset) and obj.ndim == 1:
                    self.data[name] = obj[()].astype(float)

    def _read_csv(self, path):
        with open(path, newline="") as fh:
            rows = list(csv.reader(fh))
        header = [HISTORY_COLUMNS.get(c.strip(), c.strip()) for c in rows[0]]
        values = np.array([[float(x) for x in r] for r in rows[1:] if r], dtype=float)
        values = values.reshape(-1, len(header))
        for j, name in enumerate(header):
            self.data[name] = values[:, j]

    def has(self, name):
        return name in self.data

    @property
    def t(self):
        return self.data["t"]

    def anchored(self):
        """True if any spring ever worked."""
        return any(self.has(k) and np.any(self.data[k] > 0) for k in ("k_left", "k_right"))

    def k_max(self):
        """The largest working stiffness recorded (K_max of an adaptive anchorage: a block
        lifts with K_max), or None for a free block."""
        ks = [np.max(self.data[k]) for k in ("k_left", "k_right") if self.has(k)]
        return max(ks) if ks and max(ks) > 0 else None

    def excitation_words(self):
        """The ground motion in words, '' if the file does not say."""
        a = self.attrs
        pulse = a.get("pulse")
        ratio = _float(a.get("amplitude_ratio"))
        if pulse == "sine":
            return r"one-sine pulse $\omega_p/p$ = {:g}, $a_{{p0}}/(\alpha g)$ = {:g}".format(
                a.get("omega_ratio"), ratio
            )
        if pulse == "constant":
            words = r"constant acceleration $a/(\alpha g)$ = {:g}".format(ratio)
            duration = _float(self.config.get("simulate.duration"))
            return words + (" for {:.4f} s".format(duration) if duration else "")
        if pulse == "record":
            words = "record " + os.path.basename(a.get("record", "?"))
            scale = _float(self.config.get("simulate.record-scale"))
            return words + (" × {:g}".format(scale) if scale not in (None, 1.0) else "")
        return ""

    def block_words(self):
        return block_words(self.b, self.h, self.alpha, self.p)

    def outcome_words(self):
        outcome = self.attrs.get("outcome")
        if outcome is None:
            return ""
        words = outcome.replace("_", " ")
        t_over = _float(self.attrs.get("t_overturn"))
        if t_over is not None and math.isfinite(t_over):
            words += " at {:.2f} s".format(t_over)
        return words


def run_labels(histories):
    """One label per run: its anchorage, plus whatever else differs between the runs (the
    excitation, the file), plus its outcome. Returns (labels, common) where `common` lists
    what all runs share (block, excitation), for the title."""
    anch = [anchorage_words(h.attrs) if h.attrs else "" for h in histories]
    exc = [h.excitation_words() for h in histories]
    blk = [h.block_words() for h in histories]
    names = [h.name for h in histories]
    labels = []
    for i, h in enumerate(histories):
        parts = [anch[i]] if anch[i] else []
        if len(set(exc)) > 1 and exc[i]:
            parts.append(exc[i])
        if len(set(blk)) > 1 and blk[i]:
            parts.append(blk[i])
        if h.outcome_words():
            parts.append(h.outcome_words())
        labels.append(", ".join(parts))
    repeated = {label for label in labels if labels.count(label) > 1}
    for i, label in enumerate(labels):
        if not label or label in repeated:  # nothing recorded, or twice the same: name the file
            labels[i] = names[i] + (": " + label if label else "")
    common = []
    if len(set(blk)) == 1 and blk[0]:
        common.append("block " + blk[0])
    if len(set(exc)) == 1 and exc[0]:
        common.append(exc[0])
    return labels, common


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
