#!/usr/bin/python3
"""Basins of attraction (the paper's Fig. 7) from a `rocksweep basin` file.

    plot_basin.py BASIN.h5 -o OUT [--scenario NAME ...]     writes OUT.png and OUT.pdf

One panel per scenario: the outcome of free rocking from each initial state (theta/alpha,
theta_dot/p), integrated by rocksweep, as a raster, and over it the two boundaries the energy
argument gives (docs/physics.md, "Basins"): beyond the solid line the block overturns without
an impact, beyond the dashed one after one impact. Dotted verticals: theta = +-alpha and the
spring's fracture angle.
"""
import math
import os
import sys

import numpy as np
from matplotlib.colors import BoundaryNorm, ListedColormap
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

# (outcome code, colour, legend label): the spectra's colours, rest for safe.
OUTCOMES = [
    (0, "#f7f7f7", "comes back to rest"),
    (1, rsplot.OKABE_ITO["blue"], "overturns after an impact"),
    (2, rsplot.OKABE_ITO["orange"], "overturns without an impact"),
    (255, "#000000", "not converged"),
]


def load(path, only=None):
    """Axes, root attributes and per scenario (in the file's order) its maps, curves and attributes."""
    import h5py

    with h5py.File(path, "r") as f:
        if rsplot.text(f.attrs.get("format", "")) != "rocksweep basin":
            raise SystemExit("{}: not a rocksweep basin file".format(path))
        data = {
            "attrs": {k: rsplot.text(v) for k, v in f.attrs.items()},
            "theta": f["axes/theta_ratio"][()],
            "theta_dot": f["axes/theta_dot_ratio"][()],
            "curve_theta": f["axes/curve_theta_ratio"][()],
            "scenarios": [],
        }
        groups = sorted(f["basins"].values(), key=lambda g: int(g.attrs["index"]))
        for g in groups:
            name = g.name.rsplit("/", 1)[-1]
            if only and name not in only:
                continue
            data["scenarios"].append({
                "name": name,
                "attrs": {k: rsplot.text(v) for k, v in g.attrs.items()},
                "outcome": g["outcome"][()],
                "no_impact": g["no_impact_boundary"][()],
                "impact": g["impact_boundary"][()],
            })
    if only:
        missing = sorted(set(only) - {s["name"] for s in data["scenarios"]})
        if missing:
            raise SystemExit("{}: no scenario {}".format(path, ", ".join(missing)))
    return data


def draw_curve(ax, x, y, **style):
    """One boundary, broken at theta = 0 where the two sides' curves meet."""
    for side in (x < 0, x > 0):
        ax.plot(x[side], y[side], **style)


def panel(ax, data, s):
    x, y = data["theta"], data["theta_dot"]
    codes = [c for c, _, _ in OUTCOMES]
    index = np.searchsorted(codes, s["outcome"])
    ax.grid(False)  # the map is its own grid
    ax.pcolormesh(rsplot.cell_edges(x), rsplot.cell_edges(y), index,
                  cmap=ListedColormap([c for _, c, _ in OUTCOMES]),
                  norm=BoundaryNorm(np.arange(-0.5, len(OUTCOMES)), len(OUTCOMES)), shading="flat", rasterized=True)
    cx = data["curve_theta"]
    draw_curve(ax, cx, s["no_impact"], color="k", lw=1.3)
    draw_curve(ax, cx, s["impact"], color="k", lw=1.3, ls="--")
    verticals = [1.0]
    tf = float(s["attrs"].get("theta_f_ratio", 0))
    if s["attrs"].get("anchorage") != "free" and tf > 0 and not math.isclose(tf, 1.0):
        verticals.append(tf)
    for v in verticals:
        for sign in (-1, 1):
            ax.axvline(sign * v, color="0.35", lw=0.7, ls=":")
    ax.set_xlim(x[0], x[-1])
    ax.set_ylim(y[0], y[-1])
    rest = float(s["attrs"].get("rest_fraction", float("nan")))
    ax.set_title("{}\nrest basin {:.1%} of the map".format(rsplot.anchorage_words(s["attrs"]), rest))


def plot(data, out):
    n = len(data["scenarios"])
    cols = min(n + 1, 4)  # one slot more, for the legend
    rows = math.ceil((n + 1) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(max(7.0, 3.4 * cols), max(4.4, 0.8 + 3.1 * rows)), layout="constrained",
                             squeeze=False)
    for ax, s in zip(axes.flat, data["scenarios"]):
        panel(ax, data, s)
        ax.set_xlabel(r"initial $\theta / \alpha$ [–]")
        ax.set_ylabel(r"initial $\dot\theta / p$ [–]")
    for ax in axes.flat[n:]:
        ax.axis("off")
    present = set(np.unique(np.concatenate([s["outcome"].ravel() for s in data["scenarios"]])))
    handles = [Patch(facecolor=c, edgecolor="0.5", label=l) for code, c, l in OUTCOMES if code != 255 or code in present]
    handles += [Line2D([], [], color="k", lw=1.3, label="energy: no-impact boundary"),
                Line2D([], [], color="k", lw=1.3, ls="--", label="energy: one-impact boundary"),
                Line2D([], [], color="0.35", lw=0.7, ls=":", label=r"$\theta = \pm\alpha$, $\pm\theta_f$")]
    axes.flat[n].legend(handles=handles, loc="center", frameon=False)
    a = data["attrs"]
    words = rsplot.block_words(alpha=float(a["alpha_rad"]), p=float(a["p_rad_s"]))
    fig.suptitle("Basins of attraction in free rocking: {}, e = {:.4g}".format(words, float(a["e"])), fontsize=11)
    return rsplot.save(fig, out)


def main(argv):
    p = rsplot.parser(__doc__, "a basin file written by `rocksweep basin`", n_inputs=1)
    p.add_argument("--scenario", action="append", help="draw only this scenario (repeatable)")
    args = p.parse_args(argv)
    plot(load(args.inputs[0], args.scenario), args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
