#!/usr/bin/python3
"""Overturning spectra of a rocksweep file, one panel per scenario.

usage: plot_spectra.py IN.h5 OUT.png

x = omega_p / p, y = a_p0 / (alpha g); each cell coloured by its outcome: safe (light),
overturned with impact (mode 1), overturned without impact (mode 2), not converged (black);
cells not yet computed in a partial file are grey and hatched.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PatchCollection  # noqa: E402
from matplotlib.colors import BoundaryNorm, ListedColormap  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import read_spectra  # noqa: E402

# (outcome code, colour, legend label); the position in this list is the colour index.
CLASSES = [
    (0, "#f7f7f7", "safe"),
    (1, "#4a7fb5", "overturned with impact (mode 1)"),
    (2, "#e08a3c", "overturned without impact (mode 2)"),
    (255, "#000000", "not converged"),
]
PENDING = len(CLASSES)
PENDING_COLOUR = "#c8c8c8"
PENDING_HATCH = "////"


def alpha_fraction(r):
    """theta_f / alpha as mathtext: 1 -> α, 0.5 -> α/2, 0.3 -> 0.3 α."""
    if r == 1:
        return r"\alpha"
    if r > 0:
        n = round(1.0 / r)
        if n >= 2 and math.isclose(r * n, 1.0, rel_tol=1e-9):
            return r"\alpha/{}".format(n)
    return r"{:g}\,\alpha".format(r)


def scenario_title(attrs):
    kind = attrs.get("anchorage", "")
    if kind == "free":
        return "free-standing"
    theta_f = r"$\theta_f = {}$".format(alpha_fraction(attrs.get("theta_f_ratio", float("nan"))))
    if kind == "constant":
        return "constant $K$, " + theta_f
    if kind == "adaptive":
        title = r"adaptive, $K_{{min}} = {:g}\,K_{{max}}$".format(attrs.get("kmin_ratio", float("nan")))
        if attrs.get("theta_f_ratio", 1) != 1:
            title += ", " + theta_f
        if attrs.get("break_rule") == "force":
            title += ", breaks at $F_u$"
        return title
    return kind


def cell_edges(centres):
    """Edges of cells centred on `centres` (midpoints; the end cells as wide as their
    neighbours); a single point gets a cell of width 10 % of its value (or 1)."""
    c = np.asarray(centres, dtype=float)
    if c.size == 1:
        half = 0.05 * abs(c[0]) if c[0] != 0 else 0.5
        return np.array([c[0] - half, c[0] + half])
    mid = 0.5 * (c[1:] + c[:-1])
    return np.concatenate([[c[0] - (mid[0] - c[0])], mid, [c[-1] + (c[-1] - mid[-1])]])


def class_index(outcome, done):
    """Colour index per cell: position in CLASSES, or PENDING."""
    idx = np.full(outcome.shape, PENDING, dtype=int)
    for i, (code, _, _) in enumerate(CLASSES):
        idx[(outcome == code) & done] = i
    return idx


def draw_panel(ax, S, sc, cmap, norm):
    xe, ye = cell_edges(S["omega_ratio"]), cell_edges(S["amplitude_ratio"])
    done = sc["done"] != 0
    ax.pcolormesh(xe, ye, class_index(sc["outcome"], done), cmap=cmap, norm=norm, shading="flat")
    pending = np.argwhere(~done)
    if len(pending):
        boxes = [
            Rectangle((xe[j], ye[i]), xe[j + 1] - xe[j], ye[i + 1] - ye[i]) for i, j in pending
        ]
        ax.add_collection(
            PatchCollection(boxes, facecolor="none", edgecolor="#8a8a8a", hatch=PENDING_HATCH, linewidth=0)
        )
    ax.set_xlim(xe[0], xe[-1])
    ax.set_ylim(ye[0], ye[-1])


def plot(S, out_png):
    names = list(S["scenarios"])
    n = max(len(names), 1)
    ncols = 1 if n == 1 else 2
    nrows = math.ceil(n / ncols)
    fig, axes = plt.subplots(
        nrows, ncols, figsize=(5.2 * ncols, 3.4 * nrows + 0.9), sharex=True, sharey=True, squeeze=False
    )
    cmap = ListedColormap([c for _, c, _ in CLASSES] + [PENDING_COLOUR])
    norm = BoundaryNorm(np.arange(-0.5, PENDING + 1), cmap.N)

    titles = [scenario_title(S["scenarios"][nm]["attrs"]) for nm in names]
    any_pending = False
    for k, name in enumerate(names):
        ax = axes[k // ncols][k % ncols]
        sc = S["scenarios"][name]
        draw_panel(ax, S, sc, cmap, norm)
        any_pending |= bool(np.any(sc["done"] == 0))
        title = titles[k]
        if titles.count(title) > 1:  # same description twice: the names tell them apart
            title += "  [{}]".format(name)
        ax.set_title(title, fontsize=10)
    spare = [axes[k // ncols][k % ncols] for k in range(len(names), nrows * ncols)]
    for ax in spare:
        ax.set_visible(False)
    for r in range(nrows):
        axes[r][0].set_ylabel(r"$a_{p0} / (\alpha g)$  [–]")
    for c in range(ncols):
        # The lowest visible panel of each column carries the x label and tick labels.
        last = max(r for r in range(nrows) if r * ncols + c < len(names)) if c < len(names) else 0
        axes[last][c].set_xlabel(r"$\omega_p / p$  [–]")
        axes[last][c].xaxis.set_tick_params(labelbottom=True)

    a = S["attrs"]
    head = "Overturning spectra: 2b = {:.3g} m, 2h = {:.3g} m, p = {:.4g} rad/s, α = {:.4g} rad".format(
        2 * a.get("half_width_m", float("nan")),
        2 * a.get("half_height_m", float("nan")),
        a.get("p_rad_s", float("nan")),
        a.get("alpha_rad", float("nan")),
    )
    if a.get("complete") != 1:
        head += "\npartial file: {} of {} cells computed".format(a.get("n_done"), a.get("n_cells"))
    fig.suptitle(head, fontsize=11)

    handles = [Patch(facecolor=c, edgecolor="#666666", label=lab) for _, c, lab in CLASSES]
    if any_pending:
        handles.append(
            Patch(facecolor=PENDING_COLOUR, edgecolor="#8a8a8a", hatch=PENDING_HATCH, label="not yet computed")
        )
    if spare:
        # An empty panel slot holds the legend.
        fig.tight_layout()
        spare[0].set_visible(True)
        spare[0].axis("off")
        spare[0].legend(handles=handles, loc="center", frameon=False, fontsize=10)
    else:
        ncol = len(handles) if len(handles) <= 4 else 3
        fig.legend(handles=handles, loc="lower center", ncol=ncol, frameon=False, fontsize=9)
        legend_in = 0.25 * math.ceil(len(handles) / ncol) + 0.15
        fig.tight_layout(rect=(0, legend_in / fig.get_figheight(), 1, 1))
    fig.savefig(out_png, dpi=130)
    plt.close(fig)


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: plot_spectra.py IN.h5 OUT.png\n")
        return 2
    plot(read_spectra.load(argv[1]), argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
