#!/usr/bin/python3
"""Numbers the plotting scripts compute or print, checked against the program and the paper.

    test_plot_values.py ROCKSWEEP CONFIG INPUT_DIR
"""
import math
import os
import re
import subprocess
import sys
import tempfile
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
sys.path.insert(0, HERE)
import check_figure  # noqa: E402
import plot_history  # noqa: E402
import plot_housner  # noqa: E402
import plot_restoring  # noqa: E402
import plot_spectra  # noqa: E402
import rshistory  # noqa: E402
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

ROCKSWEEP, CONFIG, INPUTS = sys.argv[1:4] if len(sys.argv) >= 4 else (None, None, None)


def info():
    return subprocess.run([ROCKSWEEP, "info", "--config", CONFIG], check=True, capture_output=True,
                          text=True).stdout


class Restoring(unittest.TestCase):
    def test_stiffness_from_strength_and_fracture_angle_matches_rocksweep_info(self):
        text = info()
        b, h, m, g = 0.30, 1.36, 3361.0, 9.81  # configs/smatteo.toml
        alpha = math.atan(b / h)
        rows = re.findall(r"constant_tf\S+\s+constant\s+F_u = (\S+) N, theta_f = \S+ rad \((\S+) alpha\), K = (\S+) N/m",
                          text)
        self.assertEqual(len(rows), 4, text)
        for f_u, ratio, k_info in rows:
            self.assertAlmostEqual(float(f_u), 0.4 * m * g, delta=0.1)
            k = plot_restoring.stiffness(0.4 * m * g, b, float(ratio) * alpha)
            self.assertAlmostEqual(k / float(k_info), 1.0, delta=1e-5, msg="theta_f = {} alpha".format(ratio))

    def test_moments_are_the_paper_s_equations(self):
        alpha = 0.217111
        self.assertAlmostEqual(float(plot_restoring.gravity_moment(0.0, alpha)), math.sin(alpha))
        self.assertAlmostEqual(float(plot_restoring.gravity_moment(alpha, alpha)), 0.0)
        theta = np.array([0.05, 0.2])
        m_a = plot_restoring.anchorage_moment(theta, 1e5, 0.3, 3361.0, 9.81, 1.3927, theta_break=0.1)
        self.assertAlmostEqual(m_a[0], 8 * 0.09 * 1e5 * math.sin(0.025) / (3361.0 * 9.81 * 1.3927))
        self.assertEqual(m_a[1], 0.0)  # broken


class Housner(unittest.TestCase):
    p = 2.2984607482446227
    alpha = 0.21711131473490516

    def test_critical_durations_of_the_paper_s_case(self):
        self.assertAlmostEqual(plot_housner.critical_duration(1.3, self.p), 0.63796, delta=5e-6)
        self.assertAlmostEqual(plot_housner.critical_duration(0.2822 / self.alpha, self.p), 0.63819, delta=5e-6)

    def test_caption_says_which_durations_overturn_under_each_reading(self):
        words = plot_housner.caption(1.3, self.alpha, self.p, "linearised", [0.6380, 0.6300])
        self.assertIn("0.63796", words)
        self.assertIn("0.6380\u00a0s overturns; 0.6300\u00a0s does not", words)
        self.assertIn("a = 0.2822 g taken literally", words)
        self.assertIn("t* = 0.63819\u00a0s: 0.6380\u00a0s and 0.6300\u00a0s do not", words)


def proportional(y, d):
    """y = c d for some c != 0 (a dataset drawn in other units)."""
    if y.shape != d.shape or not np.any(d):
        return False
    j = int(np.argmax(np.abs(d)))
    return bool(y[j] != 0 and np.allclose(y, d * (y[j] / d[j]), rtol=1e-9, atol=0))


class Histories(unittest.TestCase):
    def test_csv_and_hdf5_histories_read_alike(self):
        h5 = rshistory.History(os.path.join(INPUTS, "adaptive.h5"))
        csv = rshistory.History(os.path.join(INPUTS, "adaptive.csv"))
        for name in ("t", "theta", "theta_dot", "k_left", "k_right", "ground_acc", "w_excitation", "w_anchorage"):
            np.testing.assert_array_equal(h5.data[name], csv.data[name], err_msg=name)
        self.assertAlmostEqual(h5.k_max(), csv.k_max())

    def test_no_stiffness_panels_for_free_blocks_alone(self):
        free = rshistory.History(os.path.join(INPUTS, "free.h5"))
        anchored = rshistory.History(os.path.join(INPUTS, "constant.csv"))
        self.assertNotIn("k_left", plot_history.panels_for([free]))
        self.assertIn("ground", plot_history.panels_for([free]))
        self.assertIn("k_left", plot_history.panels_for([free, anchored]))

    def test_a_run_keeps_its_colour_in_every_panel(self):
        runs = [rshistory.History(os.path.join(INPUTS, n)) for n in ("free.h5", "constant.h5", "adaptive.csv")]
        made = []
        original = rsplot.save
        rsplot.save = lambda fig, out: made.append(fig)
        try:
            plot_history.plot(runs, "unused")
        finally:
            rsplot.save = original
        fig = made[0]
        # A line belongs to the runs whose times it is drawn over and one of whose datasets it
        # draws (up to a scale: theta/alpha, K/K_max, kJ); its colour must be one of theirs
        # (the ground motion is the same for all three runs).
        checked = 0
        for ax in fig.axes:
            for line in ax.get_lines():
                x = np.asarray(line.get_xdata(), dtype=float)
                y = np.asarray(line.get_ydata(), dtype=float)
                owners = {rsplot.run_colour(i) for i, run in enumerate(runs)
                          if x.size == run.t.size and np.array_equal(x, run.t)
                          and any(proportional(y, d) for d in run.data.values())}
                if owners:
                    checked += 1
                    self.assertIn(line.get_color(), owners, ax.get_ylabel())
        self.assertGreaterEqual(checked, 3 * 5)  # every run in theta, theta_dot, ground, K and work panels
        plt.close(fig)

    def test_old_argument_order_is_still_understood(self):
        self.assertEqual(plot_history.legacy_order(["o.png", "a.h5", "b.csv"]), ["a.h5", "b.csv", "-o", "o.png"])
        self.assertEqual(plot_history.legacy_order(["a.h5", "-o", "o"]), ["a.h5", "-o", "o"])
        self.assertEqual(plot_spectra.legacy_order(["s.h5", "s.png"]), ["s.h5", "-o", "s.png"])


class Spectra(unittest.TestCase):
    def test_difference_counts_saved_and_lost_cells(self):
        done = np.ones((2, 2), dtype=np.uint8)
        a = {"outcome": np.array([[0, 1], [2, 0]], dtype=np.uint8), "done": done}
        b = {"outcome": np.array([[0, 0], [2, 1]], dtype=np.uint8), "done": done}
        layers = plot_spectra.diff_layers(a, b, "A", "B")
        by_label = {label.split(" (")[0]: mask for mask, _, label in layers.cats}
        np.testing.assert_array_equal(by_label["B saves the block"], [[False, True], [False, False]])
        np.testing.assert_array_equal(by_label["B loses the block"], [[False, False], [False, True]])
        self.assertIn("1 cells, 25.0 %", [label for _, _, label in layers.cats][2])

    def test_period_ticks_are_round_and_apart(self):
        ticks = rsplot.period_ticks((1, 10), 2.2985)
        xs = [2 * math.pi / (2.2985 * t) for t in ticks]
        self.assertGreaterEqual(len(ticks), 4)
        self.assertTrue(all(1 <= x <= 10 for x in xs))
        self.assertTrue(all(x0 - x1 >= 0.07 * 9 - 1e-12 for x0, x1 in zip(xs, xs[1:])))


class FigureCheck(unittest.TestCase):
    """The figure checks themselves fail on what they are meant to catch."""

    def test_blank_and_small_pngs_fail(self):
        with tempfile.TemporaryDirectory() as d:
            blank = os.path.join(d, "blank.png")
            fig = plt.figure(figsize=(8, 5))
            fig.savefig(blank, dpi=150)
            plt.close(fig)
            problems, _ = check_figure.check_png(blank)
            self.assertTrue(any("blank" in p for p in problems), problems)
            small = os.path.join(d, "small.png")
            fig, ax = plt.subplots(figsize=(4, 3))
            ax.plot([0, 1], [0, 1])
            fig.savefig(small, dpi=100)
            plt.close(fig)
            problems, _ = check_figure.check_png(small)
            self.assertTrue(any("below 1000 x 600" in p for p in problems), problems)

    def test_vector_maps_fail_the_raster_check(self):
        with tempfile.TemporaryDirectory() as d:
            pdf = os.path.join(d, "vector.pdf")
            fig, ax = plt.subplots()
            ax.grid(False)
            ax.pcolormesh(np.random.default_rng(1).random((30, 30)))  # not rasterized
            fig.savefig(pdf)
            plt.close(fig)
            problems, _ = check_figure.check_pdf(pdf, 500, raster=True)
            self.assertTrue(any("no raster image" in p for p in problems), problems)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
