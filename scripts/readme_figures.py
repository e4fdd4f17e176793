#!/usr/bin/python3
"""Copies one figure of each kind from results/ (made by scripts/run.sh) to docs/figures/ for
the README, as 256-colour PNGs so that each stays under 300 kB.

    readme_figures.py [RESULTS_DIR [FIGURES_DIR]]
"""
import os
import sys

from PIL import Image

HERE = os.path.dirname(os.path.abspath(__file__))
KINDS = ["smatteo", "smatteo_max_rotation", "adaptive_vs_constant", "history", "phase", "housner", "restoring"]
LIMIT = 300 * 1024


def main(argv):
    results = argv[1] if len(argv) > 1 else os.path.join(HERE, "..", "results")
    figures = argv[2] if len(argv) > 2 else os.path.join(HERE, "..", "docs", "figures")
    os.makedirs(figures, exist_ok=True)
    status = 0
    for kind in KINDS:
        src, dst = os.path.join(results, kind + ".png"), os.path.join(figures, kind + ".png")
        Image.open(src).convert("RGB").quantize(colors=256, dither=Image.Dither.NONE).save(dst, optimize=True)
        size = os.path.getsize(dst)
        print("{}: {:.0f} kB{}".format(dst, size / 1024, "  TOO LARGE" if size > LIMIT else ""))
        status |= size > LIMIT
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv))
