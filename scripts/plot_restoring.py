#!/usr/bin/python3
"""The paper's Figs. 5-6: the restoring moment against theta/alpha, of gravity alone (the free
block) and of gravity plus each anchorage of a spectra file, up to the spring's fracture.

    plot_restoring.py SPECTRA.h5 -o OUT     writes OUT.png and OUT.pdf

Moments are scaled by m g R and counted positive when they pull the block back to theta = 0
(theta > 0; the other side is the mirror image):
    gravity      M_g / (m g R) = sin(alpha - theta)                  (Eq. 7)
    anchorage    M_a / (m g R) = 8 b^2 K sin(theta/2) / (m g R)      (Eq. 8), 0 once broken
with K = F_u / (4 b tan(theta_f/2)) computed here from each scenario's F_u and theta_f
(Section 3.4); the file's own K is checked against it. One panel: gravity alone (Fig. 5, black)
and gravity plus each anchorage (Fig. 6). An adaptive anchorage switches between K_max and
K_min: it is drawn dashed at K_min, and the legend says which constant line is its K_max; it
breaks at theta_f, or, with `adaptive-break = force`, where the K_min spring's force reaches F_u.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import read_spectra  # noqa: E402
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

THETA_MAX = 1.6  # theta/alpha drawn


def stiffness(strength_n, half_width_m, theta_f_rad):
    """K [N/m] of a spring that reaches F_u at theta_f: F_u = K 4b tan(theta_f/2)."""
    return strength_n / (4.0 * half_width_m * math.tan(theta_f_rad / 2.0))


def gravity_moment(theta, alpha):
    """Restoring moment of gravity / (m g R), theta >= 0 [rad]."""
    return np.sin(alpha - theta)


def anchorage_moment(theta, k, b, m, g, R, theta_break):
    """Restoring moment of an intact spring / (m g R), 0 once theta passes theta_break."""
    return np.where(theta <= theta_break, 8.0 * b * b * k * np.sin(theta / 2.0) / (m * g * R), 0.0)


def springs(S):
    """[(label, K [N/m], fracture angle [rad], dashed)] per anchored scenario, K from F_u, θ_f."""
    a = S["attrs"]
    b = a["half_width_m"]
    out = []
    for name, sc in S["scenarios"].items():
        at = sc["attrs"]
        if at.get("anchorage") == "free":
            continue
        k = stiffness(at["strength_N"], b, at["theta_f_rad"])
        stored = at.get("k_max_N_per_m")
        if stored is not None and not math.isclose(k, stored, rel_tol=1e-9):
            raise SystemExit("{}: K = {} N/m in the file, {} from F_u and theta_f".format(name, stored, k))
        words = rsplot.anchorage_words(at)
        if at.get("anchorage") == "adaptive":
            rho = at.get("kmin_ratio", 1.0)
            k_min_break = at["theta_f_rad"]
            if at.get("break_rule") == "force":
                k_min_break = 2 * math.atan(math.tan(at["theta_f_rad"] / 2) / rho)
            out.append((r"adaptive, drawn at $K_{{min}} = {:g}\,K_{{max}}$ = {:.4g} kN/m" "\n"
                        r"(at $K_{{max}}$ it is the constant $\theta_f = {}$ line)".format(
                            rho, rho * k / 1e3, rsplot.alpha_fraction(at.get("theta_f_ratio", 1))),
                        rho * k, k_min_break, True))
        else:
            out.append((words + ", K = {:.4g} kN/m".format(k / 1e3), k, at["theta_f_rad"], False))
    return out


def plot(S, out):
    a = S["attrs"]
    alpha, b, m, g, R = a["alpha_rad"], a["half_width_m"], a["mass_kg"], a["gravity_m_s2"], a["radius_m"]
    x = np.linspace(0, THETA_MAX, 2001)
    theta = x * alpha
    grav = gravity_moment(theta, alpha)
    fig, ax = plt.subplots(figsize=(10, 7.2), layout="constrained")

    ax.plot(x, grav, color="k", lw=1.6, zorder=3,
            label="gravity alone (Fig. 5): free-standing, or any anchorage once broken")
    for i, (label, k, theta_break, dashed) in enumerate(springs(S)):
        # Up to the fracture only: beyond it the block has gravity alone, the black curve.
        total = np.where(theta <= theta_break, grav + anchorage_moment(theta, k, b, m, g, R, theta_break), np.nan)
        colour = rsplot.run_colour(i)
        ax.plot(x, total, color=colour, lw=1.4, ls="--" if dashed else "-", label=label)
        x_break = theta_break / alpha
        if x_break <= THETA_MAX:
            top = float(np.sin(alpha - theta_break) + 8 * b * b * k * math.sin(theta_break / 2) / (m * g * R))
            ax.plot([x_break, x_break], [top, math.sin(alpha - theta_break)], color=colour, lw=0.8, ls=":")
    ax.plot([], [], color="0.3", lw=0.8, ls=":", label=r"fracture at $\theta_f$: the moment drops to gravity's")
    ax.axhline(0, color="0.5", lw=0.6)
    ax.axvline(1, color="0.4", lw=0.7, ls=":")
    ax.set_xlim(0, THETA_MAX)
    ax.set_xlabel(r"rotation $\theta / \alpha$ [–]")
    ax.set_ylabel(r"restoring moment $M / (m g R)$ [–]")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=2, fontsize=8.5, frameon=False)
    head = rsplot.block_words(b, a.get("half_height_m"), alpha, a.get("p_rad_s"))
    strengths = {sc["attrs"].get("strength_N") for sc in S["scenarios"].values()
                 if sc["attrs"].get("anchorage") != "free"}
    if len(strengths) == 1:
        f_u = strengths.pop()
        head += ", $F_u$ = {:.4g} kN = {:.3g} m g".format(f_u / 1e3, f_u / (m * g))
    fig.suptitle("Restoring moment against rotation (paper's Figs. 5-6): gravity + anchorage, brittle at "
                 r"$\theta_f$" "\nblock " + head, fontsize=11)
    return rsplot.save(fig, out)


def main(argv):
    p = rsplot.parser(__doc__, "spectra file (its block and scenarios)", n_inputs=1)
    args = p.parse_args(argv)
    plot(read_spectra.load(args.inputs[0]), args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
