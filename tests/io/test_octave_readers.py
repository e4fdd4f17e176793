#!/usr/bin/python3
"""scripts/read_spectra.m and scripts/read_history.m run in GNU Octave (octave-cli with the
netcdf package) and return every dataset exactly as h5py reads it, in the file's index order.

    test_octave_readers.py SCRIPTS_DIR WORK_DIR SPECTRA... HISTORY

Octave saves what the readers return as a MAT file; scipy reads it back. Values are compared
bit for bit (NaN where NaN), types and shapes exactly.
"""
import os
import re
import subprocess
import sys
import unittest

import h5py
import numpy as np
import scipy.io

SCRIPTS, WORK = sys.argv[1:3] if len(sys.argv) >= 3 else (None, None)
SPECTRA, HISTORY = (sys.argv[3:-1], sys.argv[-1]) if len(sys.argv) >= 5 else ([], None)
DATASETS = ("outcome", "max_rotation", "impacts", "impacts_total", "t_overturn", "peak_force_ratio", "broken",
            "mu_required", "pivot_uplift", "done")


def octave(reader, path):
    """What `reader(path)` returns in Octave, as scipy reads it from a MAT file."""
    out = os.path.join(WORK, os.path.basename(path) + "." + reader + ".mat")
    code = "addpath('{}'); X = {}('{}'); save('-v7', '{}', 'X');".format(SCRIPTS, reader, path, out)
    run = subprocess.run(["octave-cli", "--no-gui", "--quiet", "--no-init-file", "--eval", code],
                         capture_output=True, text=True)
    if run.returncode != 0 or not os.path.exists(out):
        raise AssertionError("octave failed ({}): {}{}".format(run.returncode, run.stdout, run.stderr))
    return scipy.io.loadmat(out, squeeze_me=False)["X"][0, 0]


def field(struct, name):
    return struct[name][0, 0] if struct[name].dtype.names else struct[name]


def text(mat):
    return str(mat[0]) if mat.size else ""


def as_text(value):
    return value.decode() if isinstance(value, bytes) else value


def valid_name(name):
    """matlab.lang.makeValidName for the names rocksweep writes."""
    return re.sub(r"[^A-Za-z0-9_]", "_", name)


class Readers(unittest.TestCase):
    def expect_same(self, got, want, what):
        want = np.asarray(want)
        shape = want.shape if want.ndim >= 2 else (want.size, 1)  # 1-D comes back as a column
        self.assertEqual(got.dtype, want.dtype, what)
        self.assertEqual(got.shape, shape, what)
        self.assertEqual(np.ascontiguousarray(got).reshape(want.shape).tobytes(), want.tobytes(), what)

    def test_read_spectra_returns_every_dataset_as_h5py(self):
        for path in SPECTRA:
            S = octave("read_spectra", path)
            with h5py.File(path, "r") as f:
                groups = sorted(f["spectra"].items(), key=lambda kv: kv[1].attrs["index"])
                names = [str(n[0]) for n in S["scenario_names"][0]]
                self.assertEqual(names, [valid_name(n) for n, _ in groups], path)
                first = groups[0][1]
                # The file's axes, slowest first: parameter axes (sweep --axis), then the spectrum's two.
                axes = tuple(n.strip() for n in as_text(first["outcome"].attrs["dimensions"]).split(","))
                self.assertEqual(axes[-2:], ("amplitude_ratio", "omega_ratio"))
                self.assertEqual([str(a[0]) for a in S["axes"][0]], list(axes))
                for axis in axes:
                    self.expect_same(S[axis], first[axis][()], axis)
                compared = 0
                for name, g in groups:
                    sc = field(S, valid_name(name))
                    self.assertEqual(text(sc["name"]), name)
                    for ds in DATASETS + axes:
                        self.expect_same(sc[ds], g[ds][()], "{}: {}/{}".format(path, name, ds))
                        compared += 1
                    attrs = field(sc, "attrs")
                    self.assertEqual(text(attrs["anchorage"]), as_text(g.attrs["anchorage"]))
                    self.assertEqual(attrs["theta_f_ratio"][0, 0], g.attrs["theta_f_ratio"])
                    self.assertEqual(text(field(sc, "units")["t_overturn"]), "s")
                self.assertEqual(compared, (len(DATASETS) + len(axes)) * len(groups))
                root = field(S, "attrs")
                self.assertEqual(text(root["title"]), "rocksweep overturning spectra")
                self.assertEqual(root["format_version"][0, 0], 2)
                self.assertEqual(root["alpha_rad"][0, 0], f.attrs["alpha_rad"])
                self.assertIn("omega-ratio-points", text(field(S, "provenance")["config"]))

    def test_read_spectra_permutes_a_grid_of_three_axes(self):
        # The layout of a grid with one more axis (grid_layout.hpp), written here with h5py:
        # fixed-length text as rocksweep writes it, each axis a scale attached to its dimension.
        path = os.path.join(WORK, "three_axes.h5")
        axes = {"amplitude_ratio": [1.0, 2.0], "omega_ratio": [1.0, 4.0, 7.0], "duration_s": [0.1, 0.2, 0.3, 0.4]}
        with h5py.File(path, "w") as f:
            g = f.create_group("spectra/sine")
            g.attrs["index"] = np.int64(0)
            g.attrs["anchorage"] = np.bytes_("free")
            scales = []
            for name, values in axes.items():
                g[name] = np.array(values)
                g[name].make_scale(name)
                scales.append(g[name])
            g["outcome"] = np.arange(24, dtype=np.uint8).reshape(2, 3, 4)
            for d, scale in enumerate(scales):
                g["outcome"].dims[d].attach_scale(scale)
        S = octave("read_spectra", path)
        self.assertEqual([str(a[0]) for a in S["axes"][0]], list(axes))
        case = field(S, "sine")
        self.expect_same(case["outcome"], np.arange(24, dtype=np.uint8).reshape(2, 3, 4), "outcome[2, 3, 4]")
        for name, values in axes.items():
            self.expect_same(S[name], np.array(values), name)

    def test_read_history_returns_every_dataset_as_h5py(self):
        H = octave("read_history", HISTORY)
        with h5py.File(HISTORY, "r") as f:
            self.assertGreaterEqual(len(f), 9)
            for name, ds in f.items():
                self.expect_same(H[name], ds[()], name)
                self.assertEqual(text(field(H, "units")[name]), as_text(ds.attrs["units"]), name)
            attrs = field(H, "attrs")
            self.assertEqual(text(attrs["outcome"]), as_text(f.attrs["outcome"]))
            self.assertEqual(text(attrs["record"]), "")  # "" has no stray NUL
            self.assertEqual(attrs["omega_ratio"][0, 0], 4.0)


if __name__ == "__main__":
    sys.argv[1:] = []
    result = unittest.TextTestRunner(verbosity=2).run(unittest.defaultTestLoader.loadTestsFromTestCase(Readers))
    sys.exit(0 if result.wasSuccessful() and result.testsRun > 0 else 1)
