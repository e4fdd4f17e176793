"""mu_required of suite files against a tight one, per scenario, over the cells every file has
safe (benchmarks/friction_demand.sh). Run with Debian's /usr/bin/python3 (h5py, numpy)."""
import sys

import h5py
import numpy as np


def main(reference, others):
    ref = h5py.File(reference, "r")
    files = {path: h5py.File(path, "r") for path in others}
    for scenario in ref["suite"]:
        mu_ref = ref[f"suite/{scenario}/mu_required"][()]
        safe = (ref[f"suite/{scenario}/outcome"][()] == 0) & (mu_ref > 0)
        for f in files.values():
            safe &= f[f"suite/{scenario}/outcome"][()] == 0
        print(f"{scenario}: {safe.sum()} cells safe in every file")
        for path, f in files.items():
            r = f[f"suite/{scenario}/mu_required"][()][safe] / mu_ref[safe] - 1.0
            print(f"  {path.split('/')[-1]:<14} relative error: 1st pct {np.percentile(r, 1):+.2e}, median {np.median(r):+.2e}, "
                  f"99th pct {np.percentile(r, 99):+.2e}; cells low by > 1 %: {(r < -0.01).sum()}, > 10 %: {(r < -0.1).sum()}; "
                  f"high by > 1 %: {(r > 0.01).sum()}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
