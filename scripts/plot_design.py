#!/usr/bin/python3
"""The anchorage design of `rocksweep design`: the safe fraction of the hazard region against
the constant stiffness K (left) and against K_min/K_max of the adaptive anchorage (right).

    plot_design.py DESIGN.h5 -o OUT     writes OUT.png and OUT.pdf

Each value the search evaluated is a dot (hollow: the coarse round, filled: refinement
rounds); the recommended value is a star, the values within the file's near-optimal margin
of it are shaded, and the free-standing block is the dashed reference line. The K axis is
logarithmic, with theta_f / alpha on top (at a fixed F_u, theta_f = 2 atan(F_u / (4 b K)));
the paper's four constant springs (theta_f = alpha ... alpha/4) and its two adaptive ratios
(0.5, 0.1) are marked. Where the file sets a rotation or force limit, the share of the region
where the block merely stays up is drawn thin, for comparison.
"""
import os
import sys

import h5py
import numpy as np
from matplotlib.ticker import NullLocator

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

PAPER_THETA_F = (1.0, 0.5, 1.0 / 3.0, 0.25)  # Section 3.4: theta_f / alpha at F_u = 0.4 m g
PAPER_KMIN = (0.5, 0.1)                       # Section 3.5: K_min / K_max


def load(path):
    """The design file as {"attrs": root attributes, "constant": {...}, "adaptive": {...}},
    each curve's datasets as numpy arrays and its attributes beside them."""
    out = {}
    with h5py.File(path, "r") as f:
        if "constant" not in f or "adaptive" not in f:
            raise SystemExit("{}: not a rocksweep design file (no /constant, /adaptive)".format(path))
        out["attrs"] = {k: rsplot.text(v) for k, v in f.attrs.items()}
        for name in ("constant", "adaptive"):
            g = f[name]
            curve = {k: g[k][()] for k in g}
            curve["attrs"] = {k: rsplot.text(v) for k, v in g.attrs.items()}
            out[name] = curve
    return out


def theta_f_ratio(k, a):
    """theta_f / alpha of stiffness k [N/m] at the file's F_u: F_u = K 4b tan(theta_f / 2)."""
    return 2.0 * np.arctan(a["strength_N"] / (4.0 * a["half_width_m"] * np.asarray(k, dtype=float))) / a["alpha_rad"]


def stiffness(ratio, a):
    """K [N/m] whose fracture angle is ratio * alpha at the file's F_u (inverse of theta_f_ratio)."""
    ratio = np.maximum(np.asarray(ratio, dtype=float), 1e-9)
    return a["strength_N"] / (4.0 * a["half_width_m"] * np.tan(ratio * a["alpha_rad"] / 2.0))


def draw_curve(ax, x, curve, a, colour, unit):
    """Dots, line, near-optimal band, optimum star and free reference of one curve: the safe share,
    or, for a design at a site's hazard curve (design --hazard), the annual rate it minimised.
    Returns the values drawn, for a y range shared by both panels."""
    risk = "annual_rate" in curve
    y_key, standing_key, free_key = (("annual_rate", "annual_rate_overturning", "free_annual_rate") if risk
                                     else ("safe_fraction", "standing_fraction", "free_safe_fraction"))
    y = curve[y_key]
    shown = [y, [a[free_key]]]
    coarse = curve["search_round" if "search_round" in curve else "round"] == 0  # "round" before format 2
    ax.plot(x, y, color=colour, lw=1.2, zorder=2)
    ax.plot(x[coarse], y[coarse], "o", mfc="white", mec=colour, ms=6, zorder=3, label="coarse round")
    ax.plot(x[~coarse], y[~coarse], "o", color=colour, ms=4, zorder=3, label="refinement rounds")
    if a.get("max_rotation_ratio", 0) > 0 or a.get("max_force_ratio", 0) > 0:
        ax.plot(x, curve[standing_key], color=colour, lw=0.7, ls="-.",
                label="overturning alone" if risk else "stays up, limits ignored")
        shown.append(curve[standing_key])
    lo, hi = curve["attrs"]["near_optimal_range"]
    ax.axvspan(lo, hi, color=colour, alpha=0.12, lw=0,
               label="within {:g} of the best{}".format(a.get("near_optimal", 0), " exp(-rate t)" if risk else ""))
    i = int(curve["attrs"]["optimum_index"])
    ax.plot(x[i], y[i], "*", color=rsplot.OKABE_ITO["vermillion"], ms=16, mec="k", mew=0.6, zorder=4,
            label="best: {} → {}".format(unit(x[i]), "{:.2e}/yr".format(y[i]) if risk else "{:.3f}".format(y[i])))
    free = a[free_key]
    ax.axhline(free, color="k", ls="--", lw=1.0,
               label="free-standing: {}".format("{:.2e}/yr".format(free) if risk else "{:.3f}".format(free)))
    ax.set_xscale("log")
    if risk:
        ax.set_yscale("log")
        ax.set_ylabel("annual rate of the unacceptable state [1/yr]")
    else:
        ax.set_ylabel("safe fraction of the hazard [–]")
    return np.concatenate([np.ravel(v) for v in shown])


def mark_paper(ax, values, words):
    """The paper's values as dotted verticals, named just above the panel's lower edge (the top
    holds the secondary axis and the title)."""
    lo = ax.get_ylim()[0]
    for v, w in zip(values, words):
        ax.axvline(v, color="0.45", lw=0.8, ls=":")
        ax.annotate(w, (v, lo), xytext=(-3, 4), textcoords="offset points", rotation=90, va="bottom", ha="right",
                    fontsize=8, color="0.35")


def plot(D, out):
    a, c, r = D["attrs"], D["constant"], D["adaptive"]
    # One y range for both panels: the two anchorages compare at a glance.
    fig, (ax_k, ax_r) = plt.subplots(1, 2, figsize=(13, 6.4), layout="constrained", sharey=True)

    k = c["stiffness"]
    shown = draw_curve(ax_k, k, c, a, rsplot.run_colour(0),
                       lambda v: "K = {:.3g} kN/m ($\\theta_f$ = {:.3g} α)".format(v / 1e3, float(theta_f_ratio(v, a))))
    rho = r["kmin_ratio"]
    shown = np.concatenate([shown, draw_curve(ax_r, rho, r, a, rsplot.run_colour(2),
                                              lambda v: "$K_{{min}}/K_{{max}}$ = {:.3g}".format(v))])
    if "annual_rate" in c:
        ax_k.set_ylim(float(shown.min()) / 1.5, float(shown.max()) * 2.5)
    else:
        ax_k.set_ylim(float(shown.min()) - 0.05, float(shown.max()) + 0.04)
    ax_r.tick_params(labelleft=True)
    paper_k = [r for r in PAPER_THETA_F if k.min() <= float(stiffness(r, a)) <= k.max()]
    mark_paper(ax_k, [float(stiffness(r, a)) for r in paper_k],
               [r"$\theta_f = {}$".format(rsplot.alpha_fraction(r)) for r in paper_k])
    ax_k.set_xlabel("constant anchorage stiffness K [N/m]  (dotted: the paper's $\\theta_f$)")
    ax_k.set_title("constant K, $F_u$ = {:.3g} kN".format(a["strength_N"] / 1e3))
    sec = ax_k.secondary_xaxis("top", functions=(lambda v: theta_f_ratio(v, a), lambda t: stiffness(t, a)))
    ticks = [t for t in (8, 4, 2, 1, 0.5, 0.25, 0.125, 0.0625, 0.03125) if k.min() <= float(stiffness(t, a)) <= k.max()]
    sec.set_xticks(ticks, labels=["{:g}".format(t) for t in ticks])
    sec.set_xlabel(r"fracture angle $\theta_f / \alpha$ at $F_u$", fontsize=9)
    sec.tick_params(labelsize=8)
    sec.xaxis.set_minor_locator(NullLocator())  # minor ticks of a log axis crowd the top of the panel

    paper_r = [v for v in PAPER_KMIN if rho.min() <= v <= rho.max()]
    mark_paper(ax_r, paper_r, ["paper: {:g}".format(v) for v in paper_r])
    ax_r.set_xlabel("$K_{min} / K_{max}$ [–]  (dotted: the paper's 0.5 and 0.1)")
    ax_r.set_title("adaptive, $K_{{max}}$ = {:.3g} kN/m ($\\theta_f$ = ${}$)".format(
        r["attrs"]["k_max_N_per_m"] / 1e3, rsplot.alpha_fraction(r["attrs"].get("k_max_theta_f_ratio", 1))))
    for ax in (ax_k, ax_r):
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), fontsize=8, ncol=2 if "annual_rate" in c else 3)

    limits = []
    if a.get("max_rotation_ratio", 0) > 0:
        limits.append(r"max $|\theta|/\alpha$ ≤ {:g}".format(a["max_rotation_ratio"]))
    if a.get("object_force_N", 0) > 0:
        limits.append("force on the object ≤ {:.3g} kN".format(a["object_force_N"] / 1e3))
    head = rsplot.block_words(a["half_width_m"], None, a["alpha_rad"], a["p_rad_s"])
    what = ("annual rate of the unacceptable state (overturned{}) at the site of {} (minimised)".format(
        ", " + ", ".join(limits) if limits else "", os.path.basename(a["hazard_curve_file"])) if "hazard_curve_file" in a
            else "safe (not overturned{}) share of the {}".format(", " + ", ".join(limits) if limits else "",
                                                                 "runs" if "suite_file" in a else "region"))
    fig.suptitle("Anchorage design: {}\n{}; block {}".format(what, hazard_words(a), head), fontsize=11)
    return rsplot.save(fig, out)


def hazard_words(a):
    """The hazard the design file was searched over, in words: a pulse region or a record suite."""
    if "suite_file" in a:
        lo, hi = a["intensity_range"]
        unit = {"pga_g": " g", "pgv_m_s": " m/s"}.get(a["intensity_measure"], "")
        return "{} records of {} at {} levels of {} from {:g} to {:g}{}".format(
            a["records"], os.path.basename(a["suite_file"]), a["intensity_points"], a["intensity_measure"], lo, hi, unit)
    w, amp = a["omega_ratio_range"], a["amplitude_ratio_range"]
    return (r"one-sine pulses, $\omega_p/p$ ∈ [{:g}, {:g}] × $a_{{p0}}/(\alpha g)$ ∈ [{:g}, {:g}]"
            " ({} × {} nodes)").format(w[0], w[1], amp[0], amp[1], a["omega_ratio_points"], a["amplitude_ratio_points"])


def main(argv):
    p = rsplot.parser(__doc__, "design file written by rocksweep design", n_inputs=1)
    args = p.parse_args(argv)
    plot(load(args.inputs[0]), args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
