#!/usr/bin/python3
"""plot_spectra.py on a file with parameter axes: each panel maps the spectrum at its point of
the axes, the point chosen by --at is the nearest, and the secondary axes (T_p, PGA) of a panel
follow its block's p = sqrt(g / (I0/(mR^2) R)) when R is an axis.

    test_plot_axes.py AXES.h5   (phase_rad = 0, pi/2; radius_m = 0.7, 2.8)
"""
import argparse
import math
import os
import sys
import unittest

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import plot_spectra  # noqa: E402
import read_spectra  # noqa: E402

PATH = sys.argv[1] if len(sys.argv) > 1 else None


class Panels(unittest.TestCase):
    def setUp(self):
        self.S = read_spectra.load(PATH)

    def test_at_picks_the_nearest_point_and_defaults_to_the_configured_one(self):
        parser = argparse.ArgumentParser()
        self.assertEqual(plot_spectra.choose_point(self.S, ["phase_rad=1.5", "radius_m=3"], parser), [1, 1])
        # No --at: psi = 0 and the block's own R (1.39 m) are configured; 1.39 is not on the axis,
        # so the nearest point, 0.7 m.
        self.assertEqual(plot_spectra.choose_point(self.S, None, parser), [0, 0])

    def test_each_panel_maps_its_plane_with_its_block(self):
        panels = plot_spectra.panels_of(self.S, ["constant_tf1"], [1, 0], "radius_m")
        self.assertEqual(len(panels), 2)
        a = self.S["attrs"]
        with h5py.File(PATH, "r") as f:
            for k, panel in enumerate(panels):
                want = f["spectra/constant_tf1/max_rotation"][1, k]
                self.assertEqual(panel.sc["max_rotation"].tobytes(), want.tobytes())
                radius = f["spectra/constant_tf1/radius_m"][k]
                p = math.sqrt(a["gravity_m_s2"] / (a["inertia_ratio"] * radius))
                self.assertAlmostEqual(panel.p, p, delta=1e-12 * p)
                self.assertEqual(panel.alpha, a["alpha_rad"])
                self.assertIn("R = {:.4g} m".format(radius), panel.title)
        self.assertGreater(panels[0].p, panels[1].p)  # the smaller block rocks faster


if __name__ == "__main__":
    sys.argv[1:] = []
    result = unittest.TextTestRunner(verbosity=2).run(unittest.defaultTestLoader.loadTestsFromTestCase(Panels))
    sys.exit(0 if result.wasSuccessful() and result.testsRun > 0 else 1)
