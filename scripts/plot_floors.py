#!/usr/bin/python3
"""The floors of a record-suite file (`rocksweep suite --floor ...`, docs/suite.md, "Floors"):

    plot_floors.py IN.h5 -o OUT

OUT.png/.pdf  left: each floor's 5 %-damped floor response spectrum, every record thin and the
              suite's median thick, one colour per floor (the ground included), log-log;
              right: each record's peak floor acceleration over its PGA (PFA/PGA) on each
              floor, points per record and a bar at the suite's median.
"""
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402


def floors_of(f):
    """(name, group) of each floor, in the order the scenarios list them (the ground first if given)."""
    if "floors" not in f:
        sys.exit(f"{f.filename}: no /floors group (a suite file of format 4 or later has one)")
    order = []
    for s in sorted(f["suite"].values(), key=lambda g: int(g.attrs["index"])):
        name = rsplot.text(s.attrs.get("floor", "ground"))
        if name not in order:
            order.append(name)
    return [(n, f["floors"][n]) for n in order]


def main():
    args = rsplot.parser(__doc__, "a suite file (HDF5)", n_inputs=1).parse_args()
    with h5py.File(args.inputs[0], "r") as f:
        floors = floors_of(f)
        fig, (ax_s, ax_r) = plt.subplots(1, 2, figsize=(12, 5.2), gridspec_kw={"width_ratios": [1.6, 1]},
                                         layout="constrained")
        for k, (name, g) in enumerate(floors):
            colour = rsplot.run_colour(k)
            t = g["period_s"][:]
            for row in g["spectrum_g"][:]:
                ax_s.plot(t, row, color=colour, lw=0.5, alpha=0.35)
            ax_s.plot(t, g["median_spectrum_g"][:], color=colour, lw=2.2, label=f"{name}: median of the records")
            ratio = g["pfa_over_pga"][:]
            ax_r.plot(np.full(ratio.size, k) + np.linspace(-0.15, 0.15, ratio.size), ratio, "o", color=colour, ms=4)
            ax_r.hlines(np.median(ratio), k - 0.3, k + 0.3, color=colour, lw=2.5)
            ax_r.annotate(f"{np.median(ratio):.2f}", (k + 0.32, np.median(ratio)), va="center", fontsize=9)
        ax_s.set(xscale="log", yscale="log", xlabel="oscillator period T [s]",
                 ylabel="Sa(T, 5 %) of the floor motion [g]", title="floor response spectra")
        ax_s.legend(loc="lower left")
        ax_r.set_xticks(range(len(floors)), [n for n, _ in floors])
        ax_r.set(ylabel="PFA / PGA [–]", title="peak floor acceleration over the ground's (bar: median)",
                 xlim=(-0.6, len(floors) - 0.4))
        ax_r.axhline(1.0, color="0.5", lw=0.8, ls=":")
    for p in rsplot.save(fig, args.output):
        print("wrote", p)


if __name__ == "__main__":
    main()
