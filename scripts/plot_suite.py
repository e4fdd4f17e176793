#!/usr/bin/python3
"""The three products of a record-suite file (`rocksweep suite`, docs/suite.md), one panel per
anchorage scenario unless said otherwise:

    plot_suite.py IN.h5 -o OUT [--scenario NAME ...] [--radius R] [--alpha A]

Every figure is drawn at one slenderness alpha (--alpha [rad], default the configured block's, or
the nearest the file holds).

OUT_overturning.png/.pdf  first overturning PGA [g] of each record against the block size R
                          (thin lines, one colour per record) and the suite median (thick), or
                          against the slenderness alpha when the file holds several alphas and
                          one R;
                          open markers: records that stand again at some higher level
                          (safe_above = 1); a grey triangle at the top level with the number
                          of records that never overturn at that size.
                          With a single R: each record's first overturning PGA against its
                          name, the bar reaching down to the PGA of the level below it.
OUT_ida.png/.pdf          IDA curves at one R (--radius, default the configured block's): theta_max/alpha
                          against the intensity level, one line per record; runs that overturned
                          sit in the grey "overturned" strip on the right.
OUT_fragility.png/.pdf    fragility at one R, one panel per damage state (overturning first),
                          the anchorages compared: empirical fraction of records reaching the
                          state (points, Wilson 95 % bars) and the lognormal fit (lines; median
                          and beta in the legend; a zero-dispersion fit is a dashed step, other
                          degenerate fits are named and not drawn).

A partial file (checkpoint) has no overturning or fragility groups: only OUT_ida is drawn, from
the runs computed so far, and stderr says so.
"""
import math
import os
import sys

import numpy as np
from matplotlib.lines import Line2D

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import read_suite  # noqa: E402
import rsplot  # noqa: E402
from plot_spectra import scenario_titles  # noqa: E402

ROTATION_CAP = 1.05          # theta_max/alpha beyond this (a block that stands) is drawn at the cap
STRIP = (1.12, 1.3)          # the "overturned" strip of the IDA plot: each record a lane in it
SCENARIO_MARKERS = ("o", "s", "D", "^", "v", "P", "X", "*")
# Fits of several scenarios can coincide: each its own dash pattern and width, the first widest,
# so that one drawn over another still shows.
FIT_STYLES = (("-", 3.2), ((0, (6, 2)), 2.2), ((0, (1.5, 1.5)), 1.8), ("-.", 1.4))
DODGE = 0.012  # records' markers and lines side by side: this fraction of the x range apart


def record_style(i):
    """Colour and line style of record i, the same in every figure and panel: the seven
    Okabe-Ito colours (no yellow), then again dashed, dotted..."""
    return rsplot.run_style(i)


def scenario_colour(S, name):
    """A scenario's colour, by its place in the file: the same whatever --scenario picks."""
    return rsplot.run_colour(int(S["scenarios"][name]["attrs"].get("index", 0)))


def intensity_label(S):
    """The intensity axis in words with its unit."""
    measure, units = S["intensity_measure"], S["intensity_units"]
    words = {"pga_g": "PGA of the scaled record [g]",
             "pgv_m_s": "PGV of the scaled record [{}]".format(units),
             "pga_ratio": r"PGA / ($g \tan\alpha$) [–]",
             "scale": "scale factor of the record [–]"}
    if measure in words:
        return words[measure]
    return "{} [{}]".format(S["intensity_long_name"] or measure, "–" if units in ("1", "") else units)


def intensity_unit_words(S):
    """The intensity's unit after a number: ' g', ' m/s' or ''."""
    if S["intensity_measure"] == "pga_g":
        return " g"
    return "" if S["intensity_units"] in ("1", "") else " " + S["intensity_units"]


def block_at(S, radius):
    """The block of size R at the figure's alpha in words: b = R sin alpha, h = R cos alpha, and
    p ~ R^-1/2 (the mass distribution I0/(mR^2) is kept)."""
    a, alpha = S["attrs"], S["alpha"]
    if not a.get("radius_m"):
        return "R = {:g} m".format(radius)
    k = radius / a["radius_m"]
    return "R = {:.3g} m: {}".format(radius, rsplot.block_words(
        radius * math.sin(alpha), radius * math.cos(alpha), alpha, a["p_rad_s"] / math.sqrt(k)))


def at_alpha(S, a):
    """S with every array taken at slenderness S["alpha_rad"][a]: results [record, radius, level],
    overturning [record, radius], fragility [state, radius(, level)], scale factors [record, level]."""
    S = dict(S, alpha=float(S["alpha_rad"][a]))
    rec = dict(S["records"])
    for k in ("scale_factor", "pga_scaled_g"):
        if k in rec:
            rec[k] = rec[k][:, a]
    S["records"] = rec
    scenarios = {}
    for name, sc in S["scenarios"].items():
        sc = dict(sc)
        for k in read_suite.RESULTS:
            if k in sc:
                sc[k] = sc[k][:, a]
        if sc["overturning"] is not None:
            sc["overturning"] = {k: (v[:, a] if k != "units" else v) for k, v in sc["overturning"].items()}
        if sc["fragility"] is not None:
            sc["fragility"] = {k: (v[:, a] if isinstance(v, np.ndarray) and v.ndim >= 3 else v)
                               for k, v in sc["fragility"].items()}
        scenarios[name] = sc
    S["scenarios"] = scenarios
    return S


def suite_words(S):
    a = S["attrs"]
    words = "suite {} ({} records)".format(os.path.basename(a.get("suite_file", "?")), len(S["records"]["names"]))
    if a.get("complete") != 1:
        words += "\npartial file: {} of {} runs computed".format(a.get("n_done"), a.get("n_cells"))
    return words


def record_legend(names):
    handles = [Line2D([], [], color=record_style(i)[0], ls=record_style(i)[1], lw=1.5, label=nm)
               for i, nm in enumerate(names)]
    return handles


# --------------------------------------------------------------------------- overturning


def level_pga(S, intensity):
    """The PGA [g] each record had at the given intensity levels [record, ...] (NaN where NaN)."""
    levels = S["intensity"]
    pga = S["records"]["pga_scaled_g"]
    out = np.full(np.shape(intensity), np.nan)
    for idx in np.ndindex(out.shape):
        x = intensity[idx]
        if np.isfinite(x):
            out[idx] = pga[idx[0], int(np.argmin(np.abs(levels - x)))]
    return out


def suite_median(first_pga):
    """Median over records [radius]; a record that never overturns counts as above every level
    (its capacity is censored there), so the median exists while fewer than half never do."""
    v = np.where(np.isnan(first_pga), np.inf, first_pga)
    med = np.median(v, axis=0)
    return np.where(np.isfinite(med), med, np.nan)


def across_alpha(S):
    """S for the overturning figure of a file with several alphas and one R: the overturning
    arrays [record, alpha] take the place of [record, radius], and the x axis is alpha."""
    S = dict(S, x_axis="alpha")
    scenarios = {}
    for name, sc in S["scenarios"].items():
        sc = dict(sc)
        if sc["overturning"] is not None:
            sc["overturning"] = {k: (v[:, :, 0] if k != "units" else v) for k, v in sc["overturning"].items()}
        scenarios[name] = sc
    S["scenarios"] = scenarios
    return S


def plot_overturning(S, names, out):
    slender = S.get("x_axis") == "alpha"
    radii = S["alpha_rad"] if slender else S["radius_m"]
    recs = S["records"]["names"]
    top = S["records"]["pga_scaled_g"][..., -1]
    if top.ndim > 1:   # across alpha: the top level's PGA of each record, the largest over alpha
        top = top.max(axis=1)
    fig, axes, legend_ax = rsplot.panels(len(names), height=4.8 if len(radii) > 1 else 5.6)
    top_level = float(np.nanmax(top))
    span = (radii[-1] - radii[0]) if len(radii) > 1 else float(len(recs))
    dodge = (np.arange(len(recs)) - (len(recs) - 1) / 2) * DODGE * span   # records side by side
    highest, any_above = 0.0, False
    for ax, name, title in zip(axes, names, scenario_titles(S, names)):
        ov = S["scenarios"][name]["overturning"]
        first, safe_above = ov["first_pga_g"], ov["safe_above"] != 0
        never = np.isnan(first)
        highest = max(highest, float(np.nanmax(first, initial=0.0)))
        if len(radii) > 1:
            x = radii[None, :] + dodge[:, None]
            for i in range(len(recs)):
                colour, ls = record_style(i)
                ax.plot(x[i], first[i], color=colour, ls=ls, lw=1.0, alpha=0.85)
            draw_markers(ax, x, first, safe_above)
            draw_never(ax, radii, never, top_level)
            med = suite_median(first)
            ax.plot(radii, med, color="k", lw=3.0, marker="o", ms=6, zorder=5)
            # Where more than half never overturn the median is above the top level: say so
            # there rather than end the line.
            above = np.isnan(med)
            any_above |= bool(above.any())
            if above.any():
                ax.plot(radii[above], np.full(np.count_nonzero(above), top_level), "k^", ms=11, mfc="white", mew=2,
                        zorder=6)
            ax.set_xlabel(r"slenderness $\alpha$ = atan(b/h) [rad]" if slender else "block size R [m]")
        else:
            below = level_pga(S, ov["below_intensity"])[:, 0]
            x = np.arange(len(recs))
            for i in range(len(recs)):
                if not never[i, 0]:
                    lo = below[i] if np.isfinite(below[i]) else 0.0
                    ax.plot([i, i], [lo, first[i, 0]], color=record_style(i)[0], lw=4, alpha=0.45,
                            solid_capstyle="butt")
            draw_markers(ax, x[:, None], first, safe_above)
            ax.plot(x[never[:, 0]], np.full(np.count_nonzero(never[:, 0]), top_level), "^", color="0.3", ms=8, ls="")
            med = suite_median(first)[0]
            if np.isfinite(med):
                ax.axhline(med, color="k", lw=2.5)
            ax.set_xticks(x, recs, rotation=60, ha="right", fontsize=8)
            ax.set_xlim(-0.7, len(recs) - 0.3)
            ax.set_xlabel("record")
        ax.set_title(title)
    # The y axis to what is drawn: the top level only where a record never overturns there.
    any_never = any(np.isnan(S["scenarios"][nm]["overturning"]["first_pga_g"]).any() for nm in names)
    axes[0].set_ylim(0, 1.12 * (max(highest, top_level) if any_never else highest) or 1.0)  # markers whole
    axes[0].set_ylabel("first overturning PGA [g]")
    handles = [
        Line2D([], [], color="k", lw=3.0 if len(radii) > 1 else 2.5, label="suite median"),
        Line2D([], [], color="0.3", marker="o", ls="", label="first overturning level"),
        Line2D([], [], color="0.3", marker="o", mfc="white", ls="", label="stands again at a higher level (safe_above)"),
    ]
    if any_never:
        handles.append(Line2D([], [], color="0.3", marker="^", ls="", label="never overturns up to the top level"
                              + (" (number of records)" if len(radii) > 1 else "")))
    if any_above:
        handles.insert(1, Line2D([], [], color="k", marker="^", mfc="white", mew=2, ms=9, ls="",
                                 label="median above the top level"))
    if len(radii) > 1:
        handles += record_legend(recs)
    else:
        handles.insert(1, Line2D([], [], color="0.5", lw=4, alpha=0.45, label="PGA of the level below to the first"))
    legend_ax.legend(handles=handles, loc="center left", fontsize=8, frameon=False)
    if slender:
        where = "{} slendernesses α = {:.3g} to {:.3g} rad at R = {:.3g} m".format(
            len(radii), radii[0], radii[-1], S["radius_m"][0])
    elif len(radii) == 1:
        where = "block " + block_at(S, radii[0])
    else:
        where = "{} block sizes R = {:.3g} to {:.3g} m at α = {:.4g} rad".format(len(radii), radii[0], radii[-1], S["alpha"])
    fig.suptitle("Overturning acceleration of the record suite: first overturning PGA\n{}; {}".format(
        where, suite_words(S)), fontsize=11)
    return rsplot.save(fig, out)


def draw_markers(ax, x, first, safe_above):
    """Filled: a plain first level; open: safe_above (records that never overturn: draw_never)."""
    for i in range(first.shape[0]):
        colour = record_style(i)[0]
        plain = np.isfinite(first[i]) & ~safe_above[i]
        ax.plot(x[i][plain], first[i][plain], "o", color=colour, ms=5, ls="")
        ax.plot(x[i][safe_above[i]], first[i][safe_above[i]], "o", mfc="white", mec=colour, mew=1.6, ms=7, ls="")


def draw_never(ax, x, never, top_level):
    """One grey triangle per size at the top level with the number of records that never
    overturn there (one triangle per record would print them all on one spot)."""
    counts = never.sum(axis=0)
    some = counts > 0
    ax.plot(x[some], np.full(np.count_nonzero(some), top_level), "^", color="0.3", ms=8, ls="", zorder=7)
    for xi, n in zip(x[some], counts[some]):
        ax.annotate(str(int(n)), (xi, top_level), xytext=(0, 7), textcoords="offset points", ha="center",
                    fontsize=8, color="0.2")


# --------------------------------------------------------------------------- IDA


def plot_ida(S, names, j, out):
    recs = S["records"]["names"]
    levels = S["intensity"]
    fig, axes, legend_ax = rsplot.panels(len(names), height=4.8)
    for ax, name, title in zip(axes, names, scenario_titles(S, names)):
        sc = S["scenarios"][name]
        out_, rot, done = sc["outcome"][:, j], sc["max_rotation"][:, j], sc["done"][:, j] == 1
        fell = (out_ == 1) | (out_ == 2)
        lanes = STRIP[0] + (np.arange(len(recs)) + 0.5) / len(recs) * (STRIP[1] - STRIP[0])
        for i in range(len(recs)):   # each record its own lane in the strip, so the lines stay apart
            x = np.where(fell[i], lanes[i], np.minimum(rot[i], ROTATION_CAP))
            x = np.where(done[i] & (out_[i] != 255), x, np.nan)   # pending or not converged: a gap
            colour, ls = record_style(i)
            ax.plot(x, levels, color=colour, ls=ls, lw=1.3)
            ax.plot(np.where(fell[i], np.nan, x), levels, ".", color=colour, ms=5)   # the runs that stood
            if "sensitive" in sc:   # --check-sensitivity: a perturbed rerun changed outcome or state
                flagged = done[i] & (sc["sensitive"][i, j] == 1)
                ax.plot(np.where(flagged, x, np.nan), levels, "x", color="k", ms=8, mew=1.6, zorder=6)
        ax.axvspan(*STRIP, color="0.85", zorder=0)
        ax.text(sum(STRIP) / 2, 0.02, "overturned", rotation=90, transform=ax.get_xaxis_transform(),
                ha="center", va="bottom", fontsize=8, color="0.25")
        ax.set_xlim(0, STRIP[1])
        ax.set_xticks([0, 0.25, 0.5, 0.75, 1.0])
        ax.set_xlabel(r"max rotation $\theta_{max}/\alpha$ [–]")
        ax.set_title(title)
        n_bad = int(np.count_nonzero(done & (out_ == 255)))
        notes = ["{} run(s) not converged: left out".format(n_bad)] if n_bad else []
        if "sensitive" in sc:
            notes.append("x: {} sensitive run(s)".format(int(np.count_nonzero(done & (sc["sensitive"][:, j] == 1)))))
        if notes:
            ax.text(0.02, 0.98, "\n".join(notes), transform=ax.transAxes, va="top", fontsize=8)
    axes[0].set_ylabel(intensity_label(S))
    axes[0].set_ylim(0, levels[-1] * 1.03)
    legend_ax.legend(handles=record_legend(recs), loc="center left", fontsize=8, frameon=False)
    fig.suptitle(r"IDA curves of the record suite: $\theta_{{max}}/\alpha$ of each run, capped at {:g}; runs that "
                 "overturned in the grey strip, one lane per record\nblock {}; {}".format(
                     ROTATION_CAP, block_at(S, S["radius_m"][j]), suite_words(S)), fontsize=11)
    return rsplot.save(fig, out)


# --------------------------------------------------------------------------- fragility


def fit_label(words, fr, s, j, unit):
    """The fit in words: 'median' (not theta-hat: theta is the rotation here) and beta."""
    status = fr["fit_status_names"][s, j]
    med, beta = fr["median_intensity"][s, j], fr["beta"][s, j]
    if status == "ok":
        return r"{}: median {:.3g}{}, $\beta$ = {:.2f}".format(words, med, unit, beta)
    if status == "zero_dispersion" and np.isfinite(med):
        return r"{}: step at {:.3g}{} ($\beta$ = 0)".format(words, med, unit)
    return "{}: no fit ({})".format(words, status.replace("_", " "))


def plot_fragility(S, names, j, out):
    levels = S["intensity"]
    frs = [S["scenarios"][nm]["fragility"] for nm in names]
    states = frs[0]["states"]
    order = sorted(range(len(states)), key=lambda s: (not np.isnan(frs[0]["rotation_ratios"][s]), s))
    fig, axes, _ = rsplot.panels(len(states), width=11.0, height=4.6, ncols=2, legend_width=None)
    x = np.linspace(levels[0] * 0.5, levels[-1] * 1.02, 400)
    unit = intensity_unit_words(S)
    words = scenario_titles(S, names)
    spread = 0.006 * (levels[-1] - levels[0])
    # Wilson bars at every n-th level only, each scenario on its own levels (staggered): with
    # every bar of every scenario the panel is a forest.
    every = max(2 * len(names), int(math.ceil(len(levels) / 6)))
    for ax, s in zip(axes, order):
        for k, (fr, w, nm) in enumerate(zip(frs, words, names)):
            colour = scenario_colour(S, nm)
            off = (k - (len(names) - 1) / 2) * spread   # side by side, so the points do not hide each other
            f, lo, hi = fr["fraction"][s, j], fr["fraction_lo"][s, j], fr["fraction_hi"][s, j]
            marker = SCENARIO_MARKERS[k % len(SCENARIO_MARKERS)]
            ax.plot(levels + off, f, marker, color=colour, ms=4.5, ls="", alpha=0.9, clip_on=False)
            bars = np.arange(len(levels)) % every == (k * every // len(names)) % every
            ax.errorbar((levels + off)[bars], f[bars], yerr=[np.maximum(f - lo, 0)[bars], np.maximum(hi - f, 0)[bars]],
                        fmt="none", ecolor=colour, lw=1.0, capsize=3, alpha=0.9)
            status = fr["fit_status_names"][s, j]
            y = read_suite.fragility_curve(x, fr["median_intensity"][s, j], fr["beta"][s, j])
            drawn = status in ("ok", "zero_dispersion") and np.isfinite(y).any()
            ls, lw = FIT_STYLES[k % len(FIT_STYLES)]
            ax.plot(x if drawn else [], y if drawn else [], color=colour, ls=ls, lw=lw, label=fit_label(w, fr, s, j, unit),
                    marker=marker, markevery=[], zorder=3 + 0.1 * k)  # the thinner on top
        state = states[s]
        ax.set_title("overturning" if state == "overturning" else
                     r"$\theta_{{max}}/\alpha \geq$ {:g}".format(frs[0]["rotation_ratios"][s]))
        ax.set_ylim(-0.03, 1.03)
        ax.set_xlim(0, levels[-1] * 1.03)
        ax.set_xlabel(intensity_label(S))
        ax.set_ylabel("P(state reached) [–]")
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.15), fontsize=8, frameon=False)
    fig.suptitle("Fragility under the record suite\nmarkers: fraction of records reaching the state (Wilson 95 % "
                 "bars at every {}th level); lines: lognormal MLE fit\nblock {}; {}".format(every,
                     block_at(S, S["radius_m"][j]), suite_words(S)), fontsize=11)
    return rsplot.save(fig, out)


# --------------------------------------------------------------------------- command line


def axis_index(S, axis, value, p, words, unit):
    """Index of `value` on S[axis]; None: the configured block's own value, or the nearest."""
    values = S[axis]
    if value is None:
        own = S["attrs"].get(axis)
        return int(np.argmin(np.abs(values - own))) if own else 0
    j = int(np.argmin(np.abs(values - value)))
    if not math.isclose(values[j], value, rel_tol=1e-6):
        p.error("no {} {:g} {} in the file; it holds {} {}".format(
            words, value, unit, ", ".join("{:g}".format(r) for r in values), unit))
    return j


def main(argv):
    p = rsplot.parser(__doc__, "suite file (rocksweep suite -o IN.h5)", n_inputs=1)
    p.add_argument("--scenario", nargs="+", help="only these scenarios (default: all, in config order)")
    p.add_argument("--radius", type=float, metavar="R", help="block size R [m] of the IDA and fragility figures "
                                                              "(default: the one nearest the configured block's)")
    p.add_argument("--alpha", type=float, metavar="A", help="slenderness alpha [rad] of every figure "
                                                             "(default: the one nearest the configured block's)")
    args = p.parse_args(argv)
    path = args.inputs[0]
    try:
        S = read_suite.load(path, args.scenario)
    except read_suite.SuiteFileError as e:
        raise SystemExit("plot_suite.py: {}".format(e))
    names = list(S["scenarios"])
    j = axis_index(S, "radius_m", args.radius, p, "block size R =", "m")
    full = S
    S = at_alpha(S, axis_index(S, "alpha_rad", args.alpha, p, "slenderness alpha =", "rad"))
    stem = rsplot.output_stem(args.output)
    plot_ida(S, names, j, stem + "_ida")
    missing = [nm for nm in names if S["scenarios"][nm]["overturning"] is None
               or S["scenarios"][nm]["fragility"] is None]
    if missing:
        sys.stderr.write("plot_suite.py: {}: no overturning/fragility groups for {} (the sweep is not complete: "
                         "{} of {} runs): drew {}_ida only\n".format(path, ", ".join(missing), S["attrs"].get("n_done"),
                                                                     S["attrs"].get("n_cells"), stem))
        return 0
    plot_overturning(across_alpha(full) if len(full["alpha_rad"]) > 1 and len(full["radius_m"]) == 1 else S,
                     names, stem + "_overturning")
    plot_fragility(S, names, j, stem + "_fragility")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
