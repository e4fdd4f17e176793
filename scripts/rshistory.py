"""Time histories for the plotting scripts (plot_history.py, plot_phase.py, plot_housner.py):
reading `rocksweep simulate` files (docs/hdf5.md, "History file"; HDF5 or CSV) defensively (a
dataset or attribute that is missing is simply absent, and datasets it does not know are kept
too), and labelling runs by what tells them apart.
"""
import csv
import math
import os

import numpy as np

import rsplot
from rsplot import anchorage_words, block_words, text

STANDARD_GRAVITY = rsplot.STANDARD_GRAVITY


def history_parser(description):
    """The command line of the scripts that draw histories: HISTORY... -o OUT [--alpha] [--title]."""
    p = rsplot.parser(description, "history files (.h5 or .csv)")
    p.add_argument("--alpha", type=float, help="alpha [rad] for CSV histories (HDF5 files carry their own)")
    p.add_argument("--title", help="figure title (default: the block and the excitation the runs share)")
    return p


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


def share_alpha(histories):
    """A CSV history carries no alpha. When every history that knows its alpha knows the same
    one, the others are drawn with it (and say so in their label, run_labels) rather than
    turning every run's theta/alpha into theta [rad]. Returns the histories."""
    known = {h.alpha for h in histories if h.alpha}
    for h in histories:
        h.alpha_assumed = not h.alpha and len(known) == 1
        if h.alpha_assumed:
            h.alpha = known.pop()
            known.add(h.alpha)
    return histories


def run_labels(histories):
    """One label per run: its anchorage, plus whatever else differs between the runs (the
    excitation, the file), plus its outcome. Returns (labels, common) where `common` lists
    what all runs share (block, excitation), for the title."""
    laws = {h.attrs.get("adaptive_law") for h in histories if h.attrs.get("anchorage") == "adaptive"}
    anch = [anchorage_words(h.attrs, with_law=len(laws) > 1) if h.attrs else "" for h in histories]
    # A CSV history knows neither its block nor its excitation: what differs is judged among
    # the runs that do.
    exc = [h.excitation_words() if h.attrs else "" for h in histories]
    blk = [h.block_words() if h.attrs else "" for h in histories]
    exc_set, blk_set = set(exc) - {""}, set(blk) - {""}
    names = [h.name for h in histories]
    labels = []
    for i, h in enumerate(histories):
        parts = [anch[i]] if anch[i] else []
        if len(exc_set) > 1 and exc[i]:
            parts.append(exc[i])
        if len(blk_set) > 1 and blk[i]:
            parts.append(blk[i])
        if h.outcome_words():
            parts.append(h.outcome_words())
        if getattr(h, "alpha_assumed", False):
            parts.append(r"$\alpha$ taken from the other runs")
        if not h.attrs and parts:  # a CSV history: its file is all that tells it apart
            parts.insert(0, names[i])
        labels.append(", ".join(parts))
    repeated = {label for label in labels if labels.count(label) > 1}
    for i, label in enumerate(labels):
        if not label or label in repeated:  # nothing recorded, or twice the same: name the file
            labels[i] = names[i] + (": " + label if label else "")
    common = []
    if len(blk_set) == 1:
        common.append("block " + next(iter(blk_set)))
    if len(exc_set) == 1:
        common.append(next(iter(exc_set)))
    return labels, common
