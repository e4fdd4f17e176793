#!/usr/bin/python3
"""Maps of a rocksweep spectra file, one panel per scenario.

    plot_spectra.py IN.h5 -o OUT [--field NAME ...|all] [--scenario NAME ...]
                    [--at AXIS=VALUE ...] [--across AXIS]
    plot_spectra.py IN.h5 -o OUT --diff A B [--at AXIS=VALUE ...]

x = omega_p / p (or T_p [s] for a sweep --period-range), y = a_p0 / (alpha g) (or a_p0 / g for
--pga-range); on the ratio axes, the pulse period T_p [s] on top and the peak ground
acceleration [g] on the right (from the file's p and alpha). Writes OUT.png and OUT.pdf (maps
raster inside the PDF); with several fields, OUT_<field>.png/.pdf for each.

Fields: outcome (safe, overturned with impact = mode 1, without = mode 2, not converged),
max_rotation, t_overturn, peak_force_ratio, mu_required (friction needed), pivot_uplift,
impacts, broken; `all` draws every one the file holds. --diff A B maps where scenario B keeps
the block up that A lets overturn (B saves it) and the reverse (B loses it).
Cells not yet computed in a partial file are grey and hatched; cells a --refine sweep
inferred carry only the outcome and are grey on the other maps.

A file swept over parameter axes (rocksweep sweep --axis, e.g. phase_rad) holds one spectrum per
point of them. --at AXIS=VALUE picks the point nearest VALUE (default: the configured value where
the axis holds it, else the first point); --across AXIS draws one panel per point of AXIS, which
is the default for a single scenario. T_p and the PGA on the secondary axes follow each panel's
block when R or alpha is an axis.
"""
import math
import os
import sys

import numpy as np
from matplotlib.collections import PatchCollection
from matplotlib.colors import BoundaryNorm, ListedColormap
from matplotlib.patches import Patch, Rectangle

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import read_spectra  # noqa: E402
import rsplot  # noqa: E402
from spectra_panels import Panel, choose_point, panels_of, point_words, scenario_titles  # noqa: E402,F401
from rsplot import plt  # noqa: E402

SAFE, MODE1, MODE2, NOT_CONVERGED = 0, 1, 2, 255
# (outcome code, colour, legend label)
OUTCOMES = [
    (SAFE, "#f7f7f7", "safe"),
    (MODE1, rsplot.OKABE_ITO["blue"], "overturned with impact (mode 1)"),
    (MODE2, rsplot.OKABE_ITO["orange"], "overturned without impact (mode 2)"),
    (NOT_CONVERGED, "#000000", "not converged"),
]
ALWAYS_LISTED = [label for code, _, label in OUTCOMES if code != NOT_CONVERGED]  # even where absent
PENDING_COLOUR, PENDING_HATCH = "#c8c8c8", "////"
NO_VALUE_COLOUR = "#bdbdbd"
OVERTURNED_COLOUR = "#5a5a5a"
SAFE_COLOUR = "#f2f2f2"
NO_ANCHORAGE = "no anchorage"

# field -> (kind, colour-bar label or None, title words)
FIELDS = {
    "outcome": ("categories", None, "outcome"),
    "max_rotation": ("values", r"max $|\theta| / \alpha$ of the blocks that stay up", "maximum rotation"),
    "t_overturn": ("values", "time of overturning [s]", "time of overturning"),
    "peak_force_ratio": ("values", r"peak anchorage force / $F_u$", "peak anchorage force"),
    "mu_required": ("values", r"friction coefficient needed to rock without sliding", "friction needed"),
    "pivot_uplift": ("categories", None, "pivot uplift (the block would jump)"),
    "impacts": ("values", "impacts of the blocks that stay up (above the settling threshold)", "impacts"),
    "broken": ("categories", None, "broken springs"),
}


# The spectrum's two axes: the paper's ratios, or the pulse's own period and peak.
AXIS_LABELS = {"omega_ratio": r"$\omega_p / p$ [–]", "period_s": r"pulse period $T_p$ [s]",
               "amplitude_ratio": r"$a_{p0} / (\alpha g)$ [–]", "pga_g": r"PGA $a_{p0}$ [g]"}


class Layers:
    """What one panel shows: flat-coloured categories [(mask, colour, label)] under an optional
    continuous `value` (NaN where a category is shown)."""

    def __init__(self, cats, value=None, always=()):
        self.cats = cats
        self.value = value
        self.always = set(always)  # labels listed in the legend even where no cell has them


def field_layers(field, sc):
    done = sc["done"]
    computed = done == 1
    pending = done == 0
    out = sc["outcome"]
    over = (out == MODE1) | (out == MODE2)
    no_value = (done == 2, NO_VALUE_COLOUR, "outcome only (inferred by --refine)")
    waiting = (pending, PENDING_COLOUR, "not yet computed")
    if field in ("broken", "peak_force_ratio") and sc["attrs"].get("anchorage") == "free":
        return Layers([(computed, SAFE_COLOUR, NO_ANCHORAGE), no_value, waiting],
                      np.full(out.shape, np.nan) if field == "peak_force_ratio" else None)
    if field == "outcome":
        cats = [((out == code) & ~pending, colour, label) for code, colour, label in OUTCOMES]
        return Layers(cats + [waiting])
    if field == "pivot_uplift":
        up = sc["pivot_uplift"] != 0
        return Layers([(computed & ~up, SAFE_COLOUR, "pivot stays down"),
                       (computed & up, rsplot.OKABE_ITO["vermillion"], "pivot would lift: the rocking model does not hold"),
                       no_value, waiting])
    if field == "broken":
        br = sc["broken"]
        return Layers([(computed & (br == 0), SAFE_COLOUR, "no spring broke"),
                       (computed & (br == 1), rsplot.OKABE_ITO["green"], r"left spring broke ($\theta > 0$)"),
                       (computed & (br == 2), rsplot.OKABE_ITO["purple"], r"right spring broke ($\theta < 0$)"),
                       (computed & (br == 3), rsplot.OKABE_ITO["vermillion"], "both broke"),
                       no_value, waiting])
    value = sc[field].astype(float)
    cats = [no_value, waiting]
    if field in ("max_rotation", "impacts"):
        # An overturned block's max |θ| is π/2 and its impacts are its mode (the outcome map):
        # these maps are about the blocks that stay up.
        cats.insert(0, (computed & over, OVERTURNED_COLOUR, "overturned"))
        value = np.where(computed & ~over, value, np.nan)
    elif field == "t_overturn":
        cats.insert(0, (computed & ~over, SAFE_COLOUR, "stays up"))
        value = np.where(computed & over, value, np.nan)
    else:
        value = np.where(computed, value, np.nan)
    return Layers(cats, value)


def diff_layers(sa, sb, name_a, name_b):
    """Where B saves the block A loses, and the reverse."""
    both_done = (sa["done"] != 0) & (sb["done"] != 0)
    valid = both_done & (sa["outcome"] != NOT_CONVERGED) & (sb["outcome"] != NOT_CONVERGED)
    up_a, up_b = sa["outcome"] == SAFE, sb["outcome"] == SAFE
    n = max(int(np.count_nonzero(valid)), 1)

    def share(mask):
        return "{} cells, {:.1f} %".format(int(np.count_nonzero(mask)), 100.0 * np.count_nonzero(mask) / n)

    saves, loses = valid & ~up_a & up_b, valid & up_a & ~up_b
    # Okabe-Ito blue / vermillion for the two differences (not red / green); the two greys for
    # what both do are dark enough to stand apart from the white page.
    saved_words = "{} saves the block ({})".format(name_b, share(saves))
    lost_words = "{} loses the block ({})".format(name_b, share(loses))
    return Layers([
        (valid & up_a & up_b, "#dedede", "safe in both"),
        (valid & ~up_a & ~up_b, "#8c8c8c", "overturns in both"),
        (saves, rsplot.OKABE_ITO["blue"], saved_words),
        (loses, rsplot.OKABE_ITO["vermillion"], lost_words),
        (both_done & ~valid, "#000000", "not converged in either"),
        (~both_done, PENDING_COLOUR, "not yet computed"),
    ], always=(saved_words, lost_words))  # "0 cells" is a finding too


def draw(ax, S, layers, norm=None, cmap=None):
    """Draws one panel; returns the continuous mappable (or None)."""
    xe = rsplot.cell_edges(S[S["axes"][-1]])
    ye = rsplot.cell_edges(S[S["axes"][-2]])
    ax.grid(False)  # the map is its own grid
    index = np.full(layers.cats[0][0].shape, -1)
    for k, (mask, _, _) in enumerate(layers.cats):
        index[mask] = k
    colours = ListedColormap([c for _, c, _ in layers.cats])
    ax.pcolormesh(xe, ye, np.ma.masked_less(index, 0), cmap=colours,
                  norm=BoundaryNorm(np.arange(-0.5, len(layers.cats)), len(layers.cats)),
                  shading="flat", rasterized=True)
    mappable = None
    if layers.value is not None and np.any(np.isfinite(layers.value)):
        mappable = ax.pcolormesh(xe, ye, np.ma.masked_invalid(layers.value), cmap=cmap, norm=norm,
                                 shading="flat", rasterized=True)
    pending = [mask for mask, colour, _ in layers.cats if colour == PENDING_COLOUR]
    cells = np.argwhere(pending[0]) if pending else []
    if len(cells):
        boxes = [Rectangle((xe[j], ye[i]), xe[j + 1] - xe[j], ye[i + 1] - ye[i]) for i, j in cells]
        ax.add_collection(PatchCollection(boxes, facecolor="none", edgecolor="#8a8a8a",
                                          hatch=PENDING_HATCH, linewidth=0, rasterized=True))
    return mappable


def value_scale(field, panels):
    """One colour scale for every panel of a field, so that panels compare."""
    values = np.concatenate([l.value[np.isfinite(l.value)].ravel() for l in panels if l.value is not None] + [[]])
    if field in ("max_rotation", "peak_force_ratio"):
        lo, hi = 0.0, max(1.0, float(np.max(values))) if values.size else 1.0
    elif field == "mu_required":
        # Real bases offer 0.3-0.8; demands beyond 1 (up to hundreds where the pivot's reaction
        # vanishes) would squash everything else into one colour: they show as "1 or more".
        lo, hi = 0.0, 1.0
    elif values.size:  # the bulk of the values; outliers show as the colour bar's ends
        lo, hi = float(np.percentile(values, 0.5)), float(np.percentile(values, 99.5))
    else:
        lo, hi = 0.0, 1.0
    if hi <= lo:
        hi = lo + 1.0
    cmap = plt.get_cmap({"t_overturn": "magma", "mu_required": "cividis"}.get(field, "viridis"))
    return plt.Normalize(lo, hi), cmap


def figure(S, n_panels, blocks=None):
    """A figure with n_panels map axes (2 columns beyond one) and a legend row below them;
    `blocks` gives each panel's (p, alpha) for its secondary axes (default: the file's).
    Returns (fig, panel axes in order, legend axis)."""
    ncols = 1 if n_panels == 1 else 2
    nrows = math.ceil(n_panels / ncols)
    spare = nrows * ncols > n_panels  # an empty slot holds the legend, else a row below does
    fig = plt.figure(figsize=(7.6 if ncols == 1 else 11.0, 3.5 * nrows + (1.6 if spare else 2.3)),
                     layout="constrained")
    grid = fig.add_gridspec(nrows + (0 if spare else 1), ncols,
                            height_ratios=[1.0] * nrows + ([] if spare else [0.12 + 0.05 * ncols]))
    axes = []
    for k in range(n_panels):
        r, c = divmod(k, ncols)
        share = axes[0] if axes else None
        axes.append(fig.add_subplot(grid[r, c], sharex=share, sharey=share))
    legend_ax = fig.add_subplot(grid[nrows - 1, ncols - 1] if spare else grid[nrows, :])
    legend_ax.axis("off")
    p, alpha = S["attrs"].get("p_rad_s"), S["attrs"].get("alpha_rad")
    x_name, y_name = S["axes"][-1], S["axes"][-2]
    xe, ye = rsplot.cell_edges(S[x_name]), rsplot.cell_edges(S[y_name])
    axes[0].set_xlim(xe[0], xe[-1])  # shared: every panel's limits, before the secondary axes' ticks
    axes[0].set_ylim(ye[0], ye[-1])
    for k, ax in enumerate(axes):
        r, c = divmod(k, ncols)
        last_in_column = k + ncols >= n_panels
        ax.set_xlabel(AXIS_LABELS[x_name] if last_in_column else "")
        ax.tick_params(labelbottom=last_in_column)
        ax.set_ylabel(AXIS_LABELS[y_name] if c == 0 else "")
        ax.tick_params(labelleft=c == 0)
        pk, ak = blocks[k] if blocks else (p, alpha)
        # The secondary axes turn ratios into the pulse's terms; a physical axis needs none.
        rsplot.user_axes(ax, pk if x_name == "omega_ratio" else None, ak if y_name == "amplitude_ratio" else None,
                         top=r == 0, right=c == ncols - 1 or k == n_panels - 1)
    return fig, axes, legend_ax


def header(S, what):
    a = S["attrs"]
    # The pulse family (files before the pulse library have none: the one-sine).
    family = a.get("pulse") or "one-sine"
    cycles = a.get("pulse_cycles")
    if family in ("n-sine", "cycloidal-c") and cycles:
        family += " (n = {})".format(int(cycles))
    pulses = "{} pulses".format(family)
    if "phase_rad" not in S.get("axes", []) and a.get("phase_rad"):  # a phase not the paper's 0
        pulses += r", phase $\psi = {}$".format(rsplot.pi_fraction(a["phase_rad"]))
    if "pulse_family" in S.get("axes", []):  # each panel or point names its own
        pulses = "pulse families" + (" (n = {})".format(int(cycles)) if cycles and cycles > 1 else "")
    head = "{}: {}\n{}, {}".format(
        "Overturning spectra" if what == "outcome" else "Spectra",
        what,
        pulses,
        rsplot.block_words(a.get("half_width_m"), a.get("half_height_m"), a.get("alpha_rad"), a.get("p_rad_s")),
    )
    if a.get("complete") != 1:
        head += "\npartial file: {} of {} cells computed".format(a.get("n_done"), a.get("n_cells"))
    return head


def legend(legend_ax, layers_list, ncols):
    """One legend entry per category shown anywhere."""
    seen = {}
    for layers in layers_list:
        for mask, colour, label in layers.cats:
            if (np.any(mask) or label in ALWAYS_LISTED or label in layers.always) and label != NO_ANCHORAGE:  # that panel says so itself
                seen.setdefault(label, colour)
    handles = [Patch(facecolor=c, edgecolor="#666666", label=lab,
                     hatch=PENDING_HATCH if c == PENDING_COLOUR else None) for lab, c in seen.items()]
    if not handles:
        return
    legend_ax.legend(handles=handles, loc="center", ncol=min(len(handles), ncols),
                     frameon=False, fontsize=9)


def plot_field(S, maps, field, out, where=""):
    panels = [field_layers(field, m.sc) for m in maps]
    fig, axes, legend_ax = figure(S, len(maps), [(m.p, m.alpha) for m in maps])
    kind, bar_label, words = FIELDS[field]
    norm, cmap = value_scale(field, panels) if kind == "values" else (None, None)
    mappable = None
    for ax, layers, title in zip(axes, panels, [m.title for m in maps]):
        drawn = draw(ax, S, layers, norm, cmap)
        mappable = drawn or mappable
        ax.set_title(title)
        shown = [label for mask, _, label in layers.cats if np.any(mask)]
        if shown == [NO_ANCHORAGE]:  # a free block's panel of an anchorage field: say why it is flat
            ax.text(0.5, 0.5, shown[0], transform=ax.transAxes, ha="center", va="center", fontsize=11, color="0.3")
    if mappable is not None:
        extend = {"t_overturn": "both", "impacts": "both", "mu_required": "max"}.get(field, "neither")
        fig.colorbar(mappable, ax=axes, label=bar_label, shrink=0.9 if len(maps) <= 2 else 0.6, extend=extend)
    legend(legend_ax, panels, 1 if len(maps) % 2 else 2)
    fig.suptitle(header(S, words) + where, fontsize=11)
    return rsplot.save(fig, out)


def plot_diff(S, name_a, name_b, at, out):
    titles = dict(zip([name_a, name_b], scenario_titles(S, [name_a, name_b])))
    a, b = Panel(S, name_a, tuple(at), ""), Panel(S, name_b, tuple(at), "")
    layers = diff_layers(a.sc, b.sc, titles[name_a], titles[name_b])
    fig, axes, legend_ax = figure(S, 1, [(a.p, a.alpha)])
    draw(axes[0], S, layers)
    axes[0].set_title("B: {}\nagainst A: {}".format(titles[name_b], titles[name_a]))
    legend(legend_ax, [layers], 1)
    where = "\nat " + point_words(S, at) if at else ""
    fig.suptitle(header(S, "where anchorage B saves the block that A loses, and the reverse") + where, fontsize=11)
    return rsplot.save(fig, out)


def main(argv):
    p = rsplot.parser(__doc__, "spectra file (rocksweep sweep -o IN.h5)", n_inputs=1)
    p.add_argument("--field", nargs="+", default=["outcome"], choices=list(FIELDS) + ["all"], metavar="FIELD",
                   help="what to map: " + ", ".join(FIELDS) + " or all (default outcome); several write OUT_<field> each")
    p.add_argument("--scenario", nargs="+", help="only these scenarios (default: all, in config order)")
    p.add_argument("--diff", nargs=2, metavar=("A", "B"), help="map where B saves / loses the block against A")
    p.add_argument("--at", nargs="+", metavar="AXIS=VALUE", help="the point of the parameter axes to draw (nearest)")
    p.add_argument("--across", metavar="AXIS", help="one panel per point of this parameter axis")
    args = p.parse_args(legacy_order(argv))
    S = read_spectra.load(args.inputs[0])
    params = S["axes"][:-2]
    if args.across and args.across not in params:
        p.error("--across {}: the file's parameter axes are {}".format(args.across, ", ".join(params) or "none"))
    at = choose_point(S, args.at, p)
    names = args.scenario or list(S["scenarios"])
    unknown = [nm for nm in names + (args.diff or []) if nm not in S["scenarios"]]
    if unknown:
        p.error("no scenario {} in {}; it holds: {}".format(", ".join(unknown), args.inputs[0],
                                                            ", ".join(S["scenarios"])))
    if args.diff:
        plot_diff(S, args.diff[0], args.diff[1], at, args.output)
        return 0
    across = args.across or (params[0] if params and len(names) == 1 and not args.at else None)
    maps = panels_of(S, names, at, across)
    fixed = [i for i, n in enumerate(params) if n != across]
    where = "\nat " + point_words({**S, "axes": [params[i] for i in fixed] + ["", ""]}, [at[i] for i in fixed]) if fixed else ""
    if across and len(names) == 1:
        where = "\n" + scenario_titles(S, names)[0] + where.replace("\n", ", ")
    fields = list(FIELDS) if "all" in args.field else args.field
    stored = [f for f in fields if all(f in S["scenarios"][nm] for nm in names)]
    missing = sorted(set(fields) - set(stored))
    if missing:
        sys.stderr.write("plot_spectra.py: {} not stored in {}: skipped\n".format(", ".join(missing), args.inputs[0]))
    stem = rsplot.output_stem(args.output)
    for f in stored:
        plot_field(S, maps, f, stem if len(fields) == 1 else "{}_{}".format(stem, f), where)
    return 0 if stored else 1


def legacy_order(argv):
    """Accepts the old form `plot_spectra.py IN.h5 OUT.png` as well."""
    if len(argv) == 2 and argv[1].lower().endswith((".png", ".pdf")):
        return [argv[0], "-o", argv[1]]
    return argv


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
