#!/usr/bin/python3
"""A spectra file and a history file read by the netCDF tools, checked against h5py.

    test_netcdf.py TOOL SPECTRA HISTORY     TOOL: ncdump | netcdf4 | h5netcdf (xarray engines)

SPECTRA is the default sweep of configs/smatteo.toml: axes omega_ratio = 181 points on
[1, 10], amplitude_ratio = 211 points on [1, 22], seven scenarios.
"""
import subprocess
import sys
import unittest

import h5py
import numpy as np

TOOL, SPECTRA, HISTORY = sys.argv[1:4] if len(sys.argv) >= 4 else (None, None, None)
AXES = {  # name: (points, lo, hi, long_name), from configs/smatteo.toml
    "amplitude_ratio": (211, 1.0, 22.0, "a_p0 / (alpha g)"),
    "omega_ratio": (181, 1.0, 10.0, "omega_p / p"),
}
DATASETS = ("outcome", "max_rotation", "impacts", "impacts_total", "t_overturn", "peak_force_ratio", "broken",
            "mu_required", "pivot_uplift", "done")
UNITS = {"max_rotation": "1", "impacts": "1", "impacts_total": "1", "t_overturn": "s", "peak_force_ratio": "1",
         "mu_required": "1"}


def scenarios():
    with h5py.File(SPECTRA, "r") as f:
        return list(f["spectra"])


def h5_array(path, name):
    with h5py.File(path, "r") as f:
        return f[name][()]


class Ncdump(unittest.TestCase):
    def header(self, path):
        run = subprocess.run(["ncdump", "-h", path], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        return run.stdout

    def test_every_scenario_has_its_dimensions_and_coordinates(self):
        text = self.header(SPECTRA)
        names = scenarios()
        self.assertEqual(len(names), 7)
        for name in names:
            start = text.index("group: {} {{".format(name))
            block = text[start:text.index("}} // group {}".format(name), start)]
            for axis, (n, _, _, long_name) in AXES.items():
                self.assertIn("\t{} = {} ;".format(axis, n), block, name)
                self.assertIn("double {0}({0}) ;".format(axis), block, name)
                self.assertIn('{}:units = "1" ;'.format(axis), block, name)
                self.assertIn('{}:long_name = "{}" ;'.format(axis, long_name), block, name)
            for ds in DATASETS:
                self.assertRegex(block, r"\b(ubyte|int|double) {}\(amplitude_ratio, omega_ratio\) ;".format(ds))
            for ds, units in UNITS.items():
                self.assertIn('{}:units = "{}" ;'.format(ds, units), block, name)
        # Text attributes are text, not variable-length strings that Octave cannot read.
        self.assertIn(':title = "rocksweep overturning spectra" ;', text)
        self.assertNotIn("string ", text)

    def test_history_has_t_as_its_dimension(self):
        text = self.header(HISTORY)
        self.assertIn("double theta(t) ;", text)
        self.assertIn('t:units = "s" ;', text)


class Xarray(unittest.TestCase):
    def open(self, path, group=None):
        import xarray as xr
        return xr.open_dataset(path, group=group, engine=TOOL)

    def test_every_scenario_has_named_coordinates_with_units_and_values(self):
        for name in scenarios():
            with self.subTest(scenario=name), self.open(SPECTRA, "spectra/" + name) as ds:
                self.assertEqual(sorted(ds.coords), sorted(AXES))
                for axis, (n, lo, hi, long_name) in AXES.items():
                    c = ds.coords[axis]
                    self.assertEqual(c.attrs["units"], "1")
                    self.assertEqual(c.attrs["long_name"], long_name)
                    self.assertEqual(c.values.tobytes(), h5_array(SPECTRA, "spectra/{}/{}".format(name, axis)).tobytes())
                    np.testing.assert_allclose(c.values, np.linspace(lo, hi, n), rtol=1e-12, atol=0)
                for d in DATASETS:
                    v = ds[d]
                    self.assertEqual(v.dims, ("amplitude_ratio", "omega_ratio"), d)
                    want = h5_array(SPECTRA, "spectra/{}/{}".format(name, d))
                    self.assertEqual(v.dtype, want.dtype, d)  # no fill value turned into NaN
                    self.assertEqual(v.values.tobytes(), want.tobytes(), d)
                    if d in UNITS:
                        self.assertEqual(v.attrs["units"], UNITS[d], d)
                self.assertEqual(ds.attrs["anchorage"], name.split("_")[0])

    def test_text_attributes_are_str_without_nul(self):
        with self.open(SPECTRA) as ds:
            self.assertEqual(ds.attrs["title"], "rocksweep overturning spectra")
            self.assertEqual(ds.attrs["equations"], "nonlinear")
            self.assertEqual(int(ds.attrs["format_version"]), 2)
        with self.open(HISTORY) as ds:
            texts = {k: v for k, v in ds.attrs.items() if isinstance(v, (str, bytes))}
            self.assertIn("outcome", texts)
            for k, v in texts.items():
                self.assertIsInstance(v, str, k)
                self.assertNotIn("\0", v, k)
            self.assertEqual(ds.attrs["record"], "")  # empty text stays empty

    def test_history_has_t_as_coordinate(self):
        with self.open(HISTORY) as ds:
            self.assertEqual(list(ds.coords), ["t"])
            self.assertEqual(ds["t"].attrs["units"], "s")
            self.assertEqual(ds["theta"].dims, ("t",))
            self.assertEqual(ds["theta"].values.tobytes(), h5_array(HISTORY, "theta").tobytes())


if __name__ == "__main__":
    case = {"ncdump": Ncdump, "netcdf4": Xarray, "h5netcdf": Xarray}[TOOL]
    suite = unittest.defaultTestLoader.loadTestsFromTestCase(case)
    result = unittest.TextTestRunner(verbosity=2).run(suite)
    sys.exit(0 if result.wasSuccessful() and result.testsRun > 0 else 1)
