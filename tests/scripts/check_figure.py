#!/usr/bin/python3
"""Runs a plotting command, then checks that each figure it should write is there and fit to
read: the PNG at least MIN_W x MIN_H pixels, not blank (grey-level spread and a share of
pixels away from the background colour), the PDF a PDF under a size bound, and (--raster)
holding its maps as images rather than thousands of vector cells.

    check_figure.py [--raster] [--max-pdf-kb N] --expect STEM [--expect STEM ...] -- COMMAND...
"""
import argparse
import os
import subprocess
import sys

import matplotlib.image as mpimg
import numpy as np

MIN_W, MIN_H = 1000, 600          # legible: 10-pt text at 150 dpi on a figure of at least 6.7 x 4 in
MIN_STD = 0.05                    # grey-level standard deviation (0..1) of a drawn figure
MIN_INK = 0.02                    # share of pixels that differ from the background
INK_CONTRAST = 0.03               # grey-level difference from the background that counts as drawn


def check_png(path):
    img = mpimg.imread(path)
    h, w = img.shape[:2]
    grey = img[..., :3].mean(axis=2) if img.ndim == 3 else img
    background = np.median(grey[[0, -1], :])  # the figure's border rows are background
    ink = float(np.mean(np.abs(grey - background) > INK_CONTRAST))
    problems = []
    if w < MIN_W or h < MIN_H:
        problems.append("{} x {} px, below {} x {}".format(w, h, MIN_W, MIN_H))
    if grey.std() < MIN_STD:
        problems.append("grey-level spread {:.3f} < {}: blank".format(grey.std(), MIN_STD))
    if ink < MIN_INK:
        problems.append("{:.1%} of pixels drawn, below {:.0%}: nearly blank".format(ink, MIN_INK))
    return problems, "{} x {} px, spread {:.2f}, {:.0%} drawn".format(w, h, grey.std(), ink)


def check_pdf(path, max_kb, raster):
    with open(path, "rb") as fh:
        data = fh.read()
    problems = []
    if not data.startswith(b"%PDF"):
        problems.append("not a PDF")
    if len(data) > max_kb * 1024:
        problems.append("{:.0f} kB, above {} kB".format(len(data) / 1024, max_kb))
    if raster and b"/Subtype /Image" not in data:
        problems.append("no raster image: the maps were written as vector cells")
    return problems, "{:.0f} kB".format(len(data) / 1024)


def main(argv):
    split = argv.index("--")
    p = argparse.ArgumentParser()
    p.add_argument("--expect", action="append", required=True, help="output stem: STEM.png and STEM.pdf")
    p.add_argument("--max-pdf-kb", type=float, default=500)
    p.add_argument("--raster", action="store_true", help="the PDF must hold raster maps")
    args = p.parse_args(argv[:split])
    for stem in args.expect:
        for ext in (".png", ".pdf"):
            if os.path.exists(stem + ext):
                os.remove(stem + ext)  # a figure left by an earlier run must not pass for this one
    run = subprocess.run(argv[split + 1:])
    if run.returncode != 0:
        print("command failed with status", run.returncode)
        return 1
    failed = False
    for stem in args.expect:
        for path, check in ((stem + ".png", check_png),
                            (stem + ".pdf", lambda q: check_pdf(q, args.max_pdf_kb, args.raster))):
            if not os.path.exists(path):
                print("MISSING", path)
                failed = True
                continue
            problems, summary = check(path)
            print("{} {}: {}".format("FAIL" if problems else "ok  ", path, "; ".join(problems) or summary))
            failed |= bool(problems)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
