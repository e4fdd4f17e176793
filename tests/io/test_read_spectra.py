#!/usr/bin/python3
"""scripts/read_spectra.py returns every dataset as h5py reads it, the axes in index order and
text attributes as str.

    test_read_spectra.py SPECTRA...
"""
import os
import sys
import unittest

import h5py

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import read_spectra  # noqa: E402

FILES = sys.argv[1:]


class Load(unittest.TestCase):
    def test_every_dataset_axis_and_attribute(self):
        for path in FILES:
            S = read_spectra.load(path)
            with h5py.File(path, "r") as f:
                names = f.attrs.get("parameter_axes", b"")
                names = names.decode() if isinstance(names, bytes) else names
                params = [n.strip() for n in names.split(",") if n.strip()]
                self.assertEqual(S["axes"], params + ["amplitude_ratio", "omega_ratio"])
                order = sorted(f["spectra"], key=lambda n: f["spectra"][n].attrs["index"])
                self.assertEqual(list(S["scenarios"]), order)
                for name in order:
                    g, sc = f["spectra"][name], S["scenarios"][name]
                    for axis in S["axes"]:
                        self.assertEqual(S[axis].tobytes(), g[axis][()].tobytes(), axis)
                    self.assertEqual(sorted(read_spectra.DATASETS), sorted(k for k in g if k not in S["axes"]))
                    for ds in read_spectra.DATASETS:
                        want = g[ds][()]
                        self.assertEqual((sc[ds].dtype, sc[ds].shape), (want.dtype, want.shape), ds)
                        self.assertEqual(sc[ds].tobytes(), want.tobytes(), ds)
                    self.assertEqual(sc["attrs"]["anchorage"], name.split("_")[0])
                self.assertEqual(S["attrs"]["title"], "rocksweep overturning spectra")
                self.assertIsInstance(S["provenance"]["config"], str)

    def test_summary_names_the_grid(self):
        S = read_spectra.load(FILES[0])
        self.assertIn("grid: {} amplitude_ratio x {} omega_ratio".format(len(S["amplitude_ratio"]), len(S["omega_ratio"])),
                      read_spectra.summary(S))

    def test_parameter_axes_come_first(self):
        with_axes = [p for p in FILES if "phase_rad" in read_spectra.load(p)["axes"]]
        self.assertTrue(with_axes, "no file with parameter axes among " + ", ".join(FILES))
        S = read_spectra.load(with_axes[0])
        self.assertEqual(S["axes"], ["phase_rad", "radius_m", "amplitude_ratio", "omega_ratio"])
        self.assertEqual(S["scenarios"]["free"]["outcome"].shape, (2, 3, 6, 5))
        self.assertIn("grid: 2 phase_rad x 3 radius_m x 6 amplitude_ratio x 5 omega_ratio", read_spectra.summary(S))


if __name__ == "__main__":
    sys.argv[1:] = []
    result = unittest.TextTestRunner(verbosity=2).run(unittest.defaultTestLoader.loadTestsFromTestCase(Load))
    sys.exit(0 if result.wasSuccessful() and result.testsRun > 0 else 1)
