#!/usr/bin/python3
"""What a journal reviewer checks in each figure, on the figures the scripts draw from the test
inputs (captured before they are saved): nothing drawn outside the figure, colours from the
Okabe-Ito palette or greys, distinct legend labels, units on the axes, and per figure the faults
issue 21 listed (a clipped end marker, an overturn off the axes, coincident markers, ...).

    test_figure_review.py PLOT_INPUTS SUITE_INPUTS DESIGN_FILE
"""
import math
import os
import sys
import unittest

import h5py
import numpy as np
from matplotlib.colors import to_hex, to_rgb
from matplotlib.text import Text

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import plot_design  # noqa: E402
import plot_history  # noqa: E402
import plot_housner  # noqa: E402
import plot_phase  # noqa: E402
import plot_restoring  # noqa: E402
import plot_spectra  # noqa: E402
import plot_suite  # noqa: E402
import read_spectra  # noqa: E402
import read_suite  # noqa: E402
import rshistory  # noqa: E402
import rsplot  # noqa: E402
from rsplot import plt  # noqa: E402

INPUTS, SUITE_IN, DESIGN = sys.argv[1:4] if len(sys.argv) >= 4 else (None, None, None)
PALETTE = {c.lower() for k, c in rsplot.OKABE_ITO.items() if k != "yellow"}


def drawn(call, *args):
    """The figures `call(*args)` makes, in order, instead of saving them."""
    made, original = [], rsplot.save
    rsplot.save = lambda fig, out: made.append(fig)
    try:
        call(*args)
    finally:
        rsplot.save = original
    for fig in made:
        fig.canvas.draw()
    return made


def histories(*names):
    return rshistory.share_alpha([rshistory.History(os.path.join(INPUTS, n)) for n in names])


class Review(unittest.TestCase):
    def tearDown(self):
        plt.close("all")

    def assertInside(self, fig):
        """Everything drawn (titles, labels, ticks, legends, markers) lies within the figure."""
        inside, page = fig.get_tightbbox(fig.canvas.get_renderer()), fig.bbox_inches
        tol = 1.0 / rsplot.DPI  # a pixel
        self.assertTrue(inside.x0 >= page.x0 - tol and inside.x1 <= page.x1 + tol
                        and inside.y0 >= page.y0 - tol and inside.y1 <= page.y1 + tol,
                        "drawn beyond the figure: {} within {}".format(inside, page))

    def assertPalette(self, fig):
        """Every colour drawn on the axes (a line's, or its markers' where it has no line) is
        Okabe-Ito (yellow excepted), a grey or white."""
        for ax in fig.axes:
            for line in ax.get_lines():
                if not len(line.get_xdata()):
                    continue  # a legend entry's stand-in
                drawn_colours = []
                if line.get_linestyle() not in ("None", "", " "):
                    drawn_colours.append(line.get_color())
                if line.get_marker() not in ("None", "", " ", None):
                    drawn_colours += [line.get_markeredgecolor(), line.get_markerfacecolor()]
                for c in drawn_colours:
                    r, g, b = to_rgb(c)
                    if not (math.isclose(r, g, abs_tol=0.02) and math.isclose(g, b, abs_tol=0.02)):
                        self.assertIn(to_hex(c), PALETTE, ax.get_title())

    def assertLegendDistinct(self, fig):
        for legend in [ax.get_legend() for ax in fig.axes] + fig.legends:
            if legend:
                labels = [t.get_text() for t in legend.get_texts()]
                self.assertEqual(len(labels), len(set(labels)), labels)

    def assertUnits(self, fig):
        """Every axis label names its unit, [–] for a ratio; a list of names needs none."""
        for ax in fig.axes:
            for label in (ax.get_xlabel(), ax.get_ylabel()):
                if label and label != "record":
                    self.assertRegex(label, r"\[.+\]", ax.get_title())

    def review(self, fig):
        self.assertInside(fig)
        self.assertUnits(fig)
        self.assertPalette(fig)
        self.assertLegendDistinct(fig)


class Palette(unittest.TestCase):
    def test_every_colour_written_in_the_scripts_is_okabe_ito_or_grey(self):
        import re
        scripts = os.path.join(HERE, "..", "..", "scripts")
        for name in sorted(os.listdir(scripts)):
            if name.endswith(".py"):
                with open(os.path.join(scripts, name)) as fh:
                    for colour in re.findall(r"#[0-9a-fA-F]{6}\b", fh.read()):
                        r, g, b = (int(colour[k:k + 2], 16) for k in (1, 3, 5))
                        self.assertTrue(r == g == b or colour.lower() in PALETTE or name == "rsplot.py",
                                        "{}: {}".format(name, colour))


class Histories(Review):
    def test_laws_told_apart_and_csv_drawn_over_alpha(self):
        runs = histories("free.h5", "constant.csv", "adaptive.h5", "passive.h5")
        labels, _ = rshistory.run_labels(runs)
        self.assertIn("paper's law", labels[2])
        self.assertIn("passive law", labels[3])
        (fig,) = drawn(plot_history.plot, runs, "unused")
        self.review(fig)
        theta_ax = next(ax for ax in fig.axes if "theta" in ax.get_ylabel())
        self.assertIn(r"\alpha", theta_ax.get_ylabel())  # the CSV did not turn every run into radians
        csv = runs[1]
        self.assertTrue(any(line.get_xdata().size == csv.t.size
                            and np.allclose(line.get_ydata(), csv.data["theta"] / csv.alpha) for line in theta_ax.get_lines()))

    def test_whole_record_on_the_time_axis_and_everything_inside_its_panel(self):
        runs = histories("free.h5", "constant.h5", "adaptive.h5")
        (fig,) = drawn(plot_history.plot, runs, "unused")
        self.review(fig)
        for ax in fig.axes:
            self.assertGreaterEqual(ax.get_xlim()[1], max(r.t[-1] for r in runs) - 1e-9)
            if "dot" in ax.get_ylabel():  # theta_dot: no line runs off the panel
                lo, hi = ax.get_ylim()
                for line in ax.get_lines():
                    y = np.asarray(line.get_ydata(), dtype=float)
                    self.assertTrue(np.all((y >= lo) & (y <= hi)), line.get_label())

    def test_phase_end_markers_inside_the_axes(self):
        (fig,) = drawn(plot_phase.plot, histories("free.h5", "constant.h5", "adaptive.h5"), "unused")
        self.review(fig)
        ax = fig.axes[0]
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        for line in ax.get_lines():
            if line.get_marker() == "x" and len(line.get_xdata()):
                x, y = line.get_xydata()[0]
                self.assertTrue(x0 < x < x1 and y0 < y < y1, (x, y))

    def test_housner_overturn_on_the_axes_and_one_time_axis(self):
        runs = [rshistory.History(os.path.join(INPUTS, n)) for n in ("housner_0.6380.h5", "housner_0.6300.h5")]
        (fig,) = drawn(plot_housner.plot, runs, "unused")
        self.review(fig)
        left, right = fig.axes[:2]
        self.assertEqual(left.get_xlim(), right.get_xlim())
        t_over = float(runs[0].attrs["t_overturn"])
        self.assertTrue(math.isfinite(t_over) and t_over < left.get_xlim()[1])
        self.assertTrue(any("overturned at {:.2f} s".format(t_over) in t.get_text() for t in left.get_legend().get_texts()))


class Spectra(Review):
    def test_difference_map_in_okabe_ito_with_both_counts(self):
        S = read_spectra.load(os.path.join(INPUTS, "spectra.h5"))
        layers = plot_spectra.diff_layers(S["scenarios"]["constant_tf1"], S["scenarios"]["adaptive_rho0.5"], "A", "B")
        colours = {label.split(" (")[0]: c for _, c, label in layers.cats}
        self.assertEqual(colours["B saves the block"], rsplot.OKABE_ITO["blue"])
        self.assertEqual(colours["B loses the block"], rsplot.OKABE_ITO["vermillion"])
        self.assertLess(np.mean(to_rgb(colours["safe in both"])), 0.9)  # not near-white on white
        (fig,) = drawn(plot_spectra.plot_diff, S, "constant_tf1", "adaptive_rho0.5", [], "unused")
        self.review(fig)

    def test_phases_as_fractions_of_pi(self):
        self.assertEqual([rsplot.pi_fraction(x) for x in (0, math.pi / 4, math.pi / 2, 3 * math.pi / 4, 0.3)],
                         ["0", r"\pi/4", r"\pi/2", r"3\pi/4", "0.3"])
        S = read_spectra.load(os.path.join(INPUTS, "axes.h5"))
        from spectra_panels import value_words
        self.assertEqual(value_words(S, "phase_rad", 1), r"ψ = $\pi/2$")

    def test_restoring_says_what_an_adaptive_curve_is(self):
        (fig,) = drawn(plot_restoring.plot, read_spectra.load(os.path.join(INPUTS, "spectra.h5")), "unused")
        self.review(fig)
        self.assertEqual(len(fig.axes), 1)  # gravity alone no longer fills a panel of its own
        labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
        self.assertEqual(sum("drawn at $K_{min}" in lab for lab in labels), 2, labels)


class Suite(Review):
    def figures(self, name, **kw):
        S = read_suite.load(os.path.join(SUITE_IN, name))
        names = list(S["scenarios"])
        S = plot_suite.at_alpha(S, 0)
        out = {}
        for kind, call in (("overturning", lambda: plot_suite.plot_overturning(S, names, "unused")),
                           ("ida", lambda: plot_suite.plot_ida(S, names, 0, "unused")),
                           ("fragility", lambda: plot_suite.plot_fragility(S, names, 0, "unused"))):
            (out[kind],) = drawn(call)
        return S, out

    def test_every_suite_figure(self):
        S, figs = self.figures("suite.h5")
        for fig in figs.values():
            self.review(fig)
        # never-overturning records (the mock's adaptive scenario, largest R: 11 of 12): one marker
        # per size with their number, not one per record on one spot
        seen = 0
        for ax in figs["overturning"].axes[:-1]:
            points = [tuple(p) for line in ax.get_lines() if line.get_marker() == "^" and line.get_color() == "0.3"
                      for p in line.get_xydata()]
            self.assertEqual(len(points), len(set(points)))
            seen += len(points)
            counts = [t.get_text() for t in ax.texts]
            self.assertEqual(len(counts), len(points))
        self.assertGreater(seen, 0)
        # IDA: every record its own colour and line style
        styles = [(line.get_color(), line.get_linestyle()) for line in figs["ida"].axes[-1].get_legend().get_lines()]
        self.assertEqual(len(set(styles)), len(S["records"]["names"]))
        text = " ".join(t.get_text() for t in figs["fragility"].findobj(Text))
        self.assertNotIn(r"\hat", text)  # the median is not a theta
        self.assertNotRegex(text, r"R = \d\.\d{4,} m")

    def test_one_size_axis_fits_its_data(self):
        S, figs = self.figures("suite_one.h5")
        ax = figs["overturning"].axes[0]
        first = np.concatenate([S["scenarios"][n]["overturning"]["first_pga_g"].ravel() for n in S["scenarios"]])
        if not np.isnan(first).any():
            self.assertLessEqual(ax.get_ylim()[1], 1.15 * np.nanmax(first))
        self.review(figs["overturning"])


class Design(Review):
    def test_no_variable_named_like_a_numpy_or_xarray_method(self):
        import xarray as xr
        taken = set(dir(xr.Dataset)) | set(dir(xr.DataArray)) | set(dir(np.ndarray))
        names = set()
        with h5py.File(DESIGN, "r") as f:
            f.visit(lambda n: names.add(n.rsplit("/", 1)[-1]))
        self.assertIn("search_round", names)
        self.assertEqual(sorted(names & taken), [])

    def test_panels_share_one_y_range_and_the_top_is_clear(self):
        (fig,) = drawn(plot_design.plot, plot_design.load(DESIGN), "unused")
        self.review(fig)
        ax_k, ax_r = [ax for ax in fig.axes if ax.get_xscale() == "log"][:2]
        self.assertEqual(ax_k.get_ylim(), ax_r.get_ylim())
        lo, hi = ax_k.get_ylim()
        for t in ax_k.texts:  # the paper's values are named at the bottom, not in the crowded top
            self.assertLess(t.xy[1], lo + 0.5 * (hi - lo))


if __name__ == "__main__":
    with h5py.File(DESIGN, "r"):
        pass  # a missing input fails here, not as a skip
    sys.argv[1:] = []
    result = unittest.TextTestRunner(verbosity=2).run(unittest.TestSuite(
        unittest.defaultTestLoader.loadTestsFromTestCase(c) for c in (Palette, Histories, Spectra, Suite, Design)))
    sys.exit(0 if result.wasSuccessful() and result.testsRun > 0 else 1)
