#!/usr/bin/python3
"""Agreement of the outcomes of two spectra files, per scenario and in all.

    compare_outcomes.py REFERENCE.h5 OTHER.h5

Prints, per scenario, the cells whose outcome differs and, from OTHER's `done`, the fraction of
cells it computed (the rest were inferred by boundary refinement).
"""
import sys

import h5py


def main(ref_path, other_path):
    total = differ = 0
    with h5py.File(ref_path, "r") as ref, h5py.File(other_path, "r") as other:
        for name in ref["spectra"]:
            a = ref["spectra"][name]["outcome"][:]
            b = other["spectra"][name]["outcome"][:]
            done = other["spectra"][name]["done"][:]
            d = int((a != b).sum())
            total += a.size
            differ += d
            print(f"{name:22s} {d:7d} of {a.size:8d} differ ({100.0 * d / a.size:7.4f} %), "
                  f"computed {100.0 * (done == 1).mean():6.2f} %")
    print(f"all scenarios: {differ} of {total} differ, agreement {100.0 * (1 - differ / total):.4f} %")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
