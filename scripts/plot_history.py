#!/usr/bin/python3
"""Plot one or more rocksweep time histories (HDF5 from `rocksweep simulate`).

    plot_history.py OUT.png HISTORY.h5 [HISTORY.h5 ...]

Panels: theta/alpha, theta_dot, the working stiffness of each spring, and the cumulative works
of the excitation and of the anchorage (Eq. 23-24), like the paper's Figures 14-16.
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def text(v):
    return v.decode() if isinstance(v, bytes) else str(v)


def main(out, paths):
    fig, ax = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    for path in paths:
        with h5py.File(path, "r") as f:
            t = f["t"][:]
            alpha = float(f.attrs["alpha_rad"]) if "alpha_rad" in f.attrs else 1.0
            label = f"{path}: {text(f.attrs.get('anchorage', ''))}, {text(f.attrs['outcome'])}"
            ax[0].plot(t, f["theta"][:] / alpha, label=label)
            ax[1].plot(t, f["theta_dot"][:])
            ax[2].plot(t, f["k_left"][:] / 1e3, label=f"{path}: left (theta > 0)")
            ax[2].plot(t, -f["k_right"][:] / 1e3, "--", label=f"{path}: right (theta < 0), drawn negative")
            ax[3].plot(t, f["w_excitation"][:] / 1e3, label=f"{path}: excitation")
            ax[3].plot(t, f["w_anchorage"][:] / 1e3, "--", label=f"{path}: anchorage")
    ax[0].set_ylabel(r"$\theta/\alpha$")
    ax[1].set_ylabel(r"$\dot\theta$ [rad/s]")
    ax[2].set_ylabel("K [kN/m]")
    ax[3].set_ylabel("work on the block [kJ]")
    ax[3].set_xlabel("t [s]")
    for a in ax:
        a.grid(alpha=0.3)
    ax[0].legend(fontsize=8)
    ax[2].legend(fontsize=7)
    ax[3].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
