#!/usr/bin/python3
"""The files and the Python readers' xarray views: no variable or coordinate is named like a
method or attribute of xarray.Dataset / DataArray or numpy.ndarray (`fr.median` would be the
method, not the data), every file declares its CF `Conventions`, read_spectra.to_xarray puts
every scenario in one Dataset, and read_suite prints a PGA in g.

    test_xarray_names.py SPECTRA HISTORY BASIN SUITE
"""
import os
import subprocess
import sys
import unittest

import h5py
import numpy as np
import xarray as xr

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import read_spectra  # noqa: E402
import read_suite  # noqa: E402

SPECTRA, HISTORY, BASIN, SUITE = sys.argv[1:5] if len(sys.argv) >= 5 else (None,) * 4
TAKEN = set(dir(xr.Dataset)) | set(dir(xr.DataArray)) | set(dir(np.ndarray))


def file_names(path):
    """Every group and dataset name in the file (the last path component)."""
    names = set()
    with h5py.File(path, "r") as f:
        f.visit(lambda n: names.add(n.rsplit("/", 1)[-1]))
    return names


class Names(unittest.TestCase):
    def test_no_variable_is_named_like_a_method(self):
        for path in (SPECTRA, HISTORY, BASIN, SUITE):
            names = file_names(path)
            self.assertTrue(names, path)
            self.assertEqual(sorted(names & TAKEN), [], path)

    def test_the_fragility_median_reads_as_data_in_xarray(self):
        with h5py.File(SUITE, "r") as f:
            scenario = next(iter(f["suite"]))
        fr = xr.open_dataset(SUITE, group="suite/{}/fragility".format(scenario), engine="h5netcdf")
        self.assertEqual(fr.median_intensity.attrs["units"], "1")
        self.assertEqual(fr.median_intensity.dims, ("damage_state", "alpha_rad", "radius_m"))

    def test_the_readers_xarray_views_too(self):
        for ds in list(read_suite.to_xarray(SUITE).values()) + [read_spectra.to_xarray(SPECTRA)]:
            names = set(ds.variables) | set(ds.coords)
            self.assertEqual(sorted(names & TAKEN), [])

    def test_every_file_declares_cf_conventions(self):
        for path in (SPECTRA, HISTORY, BASIN, SUITE):
            with h5py.File(path, "r") as f:
                self.assertEqual(read_spectra._value(f.attrs["Conventions"]), "CF-1.8", path)
            self.assertEqual(xr.open_dataset(path, engine="h5netcdf").attrs["Conventions"], "CF-1.8", path)


class SpectraDataset(unittest.TestCase):
    def test_one_dataset_with_scenario_as_a_dimension(self):
        S = read_spectra.load(SPECTRA)
        ds = read_spectra.to_xarray(SPECTRA)
        names = list(S["scenarios"])
        self.assertEqual(list(ds.scenario.values), names)
        self.assertEqual(ds.outcome.dims, ("scenario",) + tuple(S["axes"]))
        for n in names:
            for var in read_spectra.DATASETS:
                got = ds[var].sel(scenario=n).values
                self.assertEqual(got.tobytes(), S["scenarios"][n][var].tobytes(), (n, var))
            self.assertEqual(ds.anchorage.sel(scenario=n).item(), S["scenarios"][n]["attrs"]["anchorage"])
        for axis in S["axes"]:
            self.assertEqual(ds[axis].values.tobytes(), S[axis].tobytes())
        self.assertEqual(ds.omega_ratio.attrs["long_name"], "omega_p / p")
        self.assertEqual(ds.t_overturn.attrs["units"], "s")
        self.assertEqual(list(ds.outcome.attrs["flag_values"]), [0, 1, 2, 255])
        # a free block has no kmin_ratio of its own: NaN there, the value where it is one
        with h5py.File(SPECTRA, "r") as f:
            for n in names:
                want = f["spectra"][n].attrs.get("theta_f_ratio", np.nan)
                self.assertTrue(np.array_equal(ds.theta_f_ratio.sel(scenario=n).values, want, equal_nan=True), n)
        self.assertEqual(ds.attrs["Conventions"], "CF-1.8")
        # selection by an attribute works as on any coordinate
        constant = ds.where(ds.anchorage == "constant", drop=True)
        self.assertEqual(sorted(constant.scenario.values), sorted(n for n in names if n.startswith("constant")))


class SuiteText(unittest.TestCase):
    def test_median_pga_printed_in_g(self):
        out = subprocess.run([sys.executable, os.path.join(SCRIPTS, "read_suite.py"), SUITE],
                             capture_output=True, text=True, check=True).stdout
        self.assertIn("levels of pga_g [g]", out)
        self.assertRegex(out, r"overturning: median [0-9.e+-]+ \[g\], beta")
        self.assertNotIn("[1]", out)


if __name__ == "__main__":
    sys.argv[1:] = []
    result = unittest.TextTestRunner(verbosity=2).run(unittest.TestSuite(
        unittest.defaultTestLoader.loadTestsFromTestCase(c) for c in (Names, SpectraDataset, SuiteText)))
    sys.exit(0 if result.wasSuccessful() and result.testsRun > 0 else 1)
