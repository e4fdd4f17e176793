#!/usr/bin/python3
"""The suite-file readers against a mock suite file (make_suite_mock.py) whose numbers are known:

- read_suite.py returns the mock's values (names, metadata, a record's first overturning PGA,
  the safe island, the fit statuses) and fragility arrays consistent with the outcome arrays
  they summarise (exceed and total recounted from outcome and max_rotation, fraction =
  exceed / total inside its Wilson interval, the fitted curve 0.5 at its median);
- read_suite.py and read_suite.m read the records' Sa and each floor's products (PFA, PFA/PGA,
  spectra and medians) as the mock wrote them;
- read_suite.m (run by octave-cli) returns the same arrays as h5py, in the same index order
  and of the same types, for every scenario;
- xarray opens each scenario group with both engines (h5netcdf, netcdf4) with the same values,
  and read_suite.to_xarray selects by record name;
- plot_suite.py: one clear line and a non-zero status for files that are not suite files; on a
  partial file only the IDA figure, and a note on stderr.

usage: test_suite_readers.py MOCK_DIR     (holding suite.h5 and suite_partial.h5)
"""
import math
import os
import subprocess
import sys
import tempfile
import warnings

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
sys.path.insert(0, HERE)
import make_suite_mock as mock  # noqa: E402
import read_suite  # noqa: E402

FAILURES = []


def check(ok, what):
    print("{} {}".format("ok  " if ok else "FAIL", what))
    if not ok:
        FAILURES.append(what)


def same(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and bool(np.all((a == b) | (np.isnan(a.astype(float)) & np.isnan(b.astype(float)))))


def test_values(path):
    S = read_suite.load(path)
    names = S["records"]["names"]
    check(names == [r[0] for r in mock.RECORDS], "record names decoded from flag_meanings, in suite order")
    check(list(S["scenarios"]) == [s[0] for s in mock.SCENARIOS], "scenarios in config order")
    meta = S["records"]["metadata"]["newhall_1994_rot"]
    check(meta["station"] == "Newhall Fire Station (PEER NGA RSN 1044)" and meta["dt_s"] == "",
          "per-record metadata as str ('' for an empty attribute)")
    check(S["intensity_units"] == "1" and S["intensity_measure"] == "pga_g", "intensity measure and units")
    free = S["scenarios"]["free"]
    ov = free["overturning"]
    i = names.index("cape_mendocino_1992")
    # capacity 0.55 g sqrt(0.5): the first of the 20 levels 0.05 + k 1.45/19 g at or above 0.389 g is k = 5
    check(math.isclose(ov["first_pga_g"][i, 0, 0], 0.05 + 5 * 1.45 / 19, rel_tol=1e-12),
          "first_pga_g of cape_mendocino_1992, free, R = 0.5 m is 0.4316 g ({:.6g})".format(ov["first_pga_g"][i, 0, 0]))
    check(math.isclose(ov["below_intensity"][i, 0, 0], 0.05 + 4 * 1.45 / 19, rel_tol=1e-12), "its below_intensity")
    check(ov["safe_above"][i, 0, 0] == 1 and int(ov["safe_above"].sum()) == 1, "safe_above = 1 for it alone")
    check(free["outcome"][names.index("cephalonia_2014_chv1_e"), 0, 0, -1] == 255, "the not-converged run kept as 255")
    adaptive = S["scenarios"]["adaptive_rho0.1"]
    check(np.all(np.isnan(adaptive["overturning"]["first_pga_g"][:, 0, 2])), "no 2 m block overturns when adaptive")
    check(adaptive["fragility"]["fit_status_names"][-1, 0, 2] == "none_reached", "so its overturning fit is none_reached")
    check(np.isnan(read_suite.fragility_curve([0.5], adaptive["fragility"]["median_intensity"][-1, 0, 2],
                                              adaptive["fragility"]["beta"][-1, 0, 2])).all(),
          "and it has no curve")

    for name, sc in S["scenarios"].items():
        fr = sc["fragility"]
        ok_done = (sc["done"] == 1) & (sc["outcome"] != 255)
        total = ok_done.sum(axis=0)
        check(np.all(fr["total"] == total[None]), "{}: total = computed, converged runs".format(name))
        for s, state in enumerate(fr["states"]):
            hit = read_suite.reached(sc["outcome"], sc["max_rotation"], fr["rotation_ratios"][s]) & ok_done
            check(np.array_equal(fr["exceed"][s], hit.sum(axis=0)),
                  "{}, {}: exceed recounted from outcome and max_rotation".format(name, state))
        check(np.allclose(fr["fraction"], fr["exceed"] / fr["total"]), "{}: fraction = exceed / total".format(name))
        check(np.all((fr["fraction_lo"] <= fr["fraction"] + 1e-12) & (fr["fraction"] <= fr["fraction_hi"] + 1e-12)),
              "{}: fraction inside its Wilson interval".format(name))
        ok = fr["fit_status_names"] == "ok"
        at_median = [read_suite.fragility_curve([m], m, b)[0] for m, b in zip(fr["median_intensity"][ok], fr["beta"][ok])]
        check(ok.any() and np.allclose(at_median, 0.5), "{}: each ok fit is 0.5 at its median".format(name))
        check(np.all((fr["median_intensity_lo"][ok] < fr["median_intensity"][ok]) & (fr["median_intensity"][ok] < fr["median_intensity_hi"][ok])),
              "{}: median inside its interval".format(name))
        # The mock, like a file written before the fits' covariance, lacks it: NaN of beta's shape.
        check(fr["cov_ln_median_beta"].shape == fr["beta"].shape and np.isnan(fr["cov_ln_median_beta"]).all(),
              "{}: a file without cov_ln_median_beta reads it as NaN".format(name))
    check(list(read_suite.fragility_curve([0.1, 0.2, 0.3], 0.2, 0.0)) == [0.0, 1.0, 1.0]
          and np.isnan(read_suite.fragility_curve([0.1], math.inf, math.nan)).all(),
          "fragility_curve: a zero-dispersion fit is a step at its median, an infinite median no curve")
    # overturning is most likely for small blocks and free ones: medians in that order
    med = np.array([S["scenarios"][n]["fragility"]["median_intensity"][-1, 0, :2] for n in S["scenarios"]])
    check(np.all(np.diff(med, axis=0) > 0) and np.all(np.diff(med, axis=1) > 0),
          "overturning medians rise with anchorage (free < constant < adaptive) and with R")


def test_floors_and_sa(path):
    S = read_suite.load(path)
    rec = S["records"]
    check(np.allclose(rec["sa_g"], 2.2 * np.array(mock.PGA_G), rtol=1e-15, atol=0)
          and rec["sa"] == {"period_s": mock.SA_PERIOD_S, "damping": mock.SA_DAMPING},
          "records' Sa(T, zeta) with its T and zeta")
    check(sorted(S["floors"]) == ["f2", "ground"], "one entry per /floors group")
    ground, f2 = S["floors"]["ground"], S["floors"]["f2"]
    gain = np.array(mock.FLOOR_GAIN)
    check(np.array_equal(ground["pfa_g"], rec["pga_g"]) and np.all(ground["pfa_over_pga"] == 1.0),
          "ground floor: PFA = PGA")
    check(np.allclose(f2["pfa_g"], gain * rec["pga_g"], rtol=1e-15, atol=0) and np.array_equal(f2["pfa_over_pga"], gain)
          and f2["floor"] == "f2: 0.5 0.05 1.3", "f2: PFA, PFA/PGA and its definition")
    check(math.isclose(f2["median_pfa_over_pga"], float(np.median(gain)), rel_tol=1e-15)
          and math.isclose(f2["median_pfa_g"], float(np.median(gain * rec["pga_g"])), rel_tol=1e-15),
          "f2: the medians over the records")
    check(f2["spectrum_g"].shape == (len(mock.RECORDS), 3) and np.array_equal(f2["period_s"], mock.SPECTRUM_PERIODS_S)
          and np.allclose(f2["median_spectrum_g"], np.median(f2["spectrum_g"], axis=0), rtol=1e-15, atol=0)
          and f2["units"]["spectrum_g"] == "1", "f2: floor spectra [record, period], their median and units")
    check(f2["scale_factor"].shape == (len(mock.RECORDS), 1, len(mock.LEVELS_G)), "f2: scale factors [record, alpha, level]")


def test_partial(path):
    S = read_suite.load(path)
    check(all(sc["overturning"] is None and sc["fragility"] is None for sc in S["scenarios"].values()),
          "partial file: absent groups read as None")
    check(S["attrs"]["complete"] == 0 and np.any(S["scenarios"]["free"]["done"] == 0), "partial file: pending runs")


OCTAVE = r"""
addpath('{scripts}');
X = struct();
names = {{{names}}};
for k = 1:numel(names)
    S = read_suite('{path}', names{{k}});
    p = sprintf('s%d_', k);
    for f = {{'record', 'alpha_rad', 'radius_m', 'intensity', 'outcome', 'max_rotation', 'impacts', 't_overturn', 'broken', 'done'}}
        X.([p f{{1}}]) = S.(f{{1}});
    end
    for f = fieldnames(S.overturning)'
        if ~strcmp(f{{1}}, 'units'), X.([p 'ov_' f{{1}}]) = S.overturning.(f{{1}}); end
    end
    for f = {{'fraction', 'exceed', 'total', 'median_intensity', 'beta', 'fit_status', 'rotation_ratios'}}
        X.([p 'fr_' f{{1}}]) = S.fragility.(f{{1}});
    end
    X.([p 'fr_states']) = strjoin(S.fragility.states', ' ');
    X.([p 'anchorage']) = S.scenario_attrs.anchorage;
end
X.sa_g = S.records.sa_g;
X.sa_period_s = S.records.sa_period_s;
X.sa_damping = S.records.sa_damping;
X.floor_names = strjoin({{S.floors.name}}, ' ');
for k = 1:numel(S.floors)
    for f = {{'pfa_g', 'pfa_over_pga', 'spectrum_g', 'median_spectrum_g', 'period_s', 'scale_factor', 'median_pfa_g', 'median_pfa_over_pga'}}
        X.(['fl_' S.floors(k).name '_' f{{1}}]) = S.floors(k).(f{{1}});
    end
    X.(['fl_' S.floors(k).name '_floor']) = S.floors(k).floor;
end
X.record_names = strjoin(S.record_names', ' ');
X.scale_factor = S.records.scale_factor;
X.pga_g = S.records.pga_g;
X.kind = S.attrs.kind;
X.alpha_rad = S.attrs.alpha_rad;
save('-v7', '{out}', '-struct', 'X');
"""


def test_octave(path):
    from scipy.io import loadmat

    names = [s[0] for s in mock.SCENARIOS]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "octave.mat")
        script = os.path.join(tmp, "read.m")
        with open(script, "w") as fh:
            fh.write(OCTAVE.format(scripts=os.path.abspath(SCRIPTS), path=os.path.abspath(path), out=out,
                                   names=", ".join("'{}'".format(n) for n in names)))
        run = subprocess.run(["octave-cli", "--no-gui", "--quiet", "--norc", script], capture_output=True, text=True)
        check(run.returncode == 0 and os.path.exists(out), "octave-cli ran read_suite.m on every scenario")
        if run.returncode != 0 or not os.path.exists(out):
            print(run.stdout + run.stderr)
            return
        M = loadmat(out, squeeze_me=False)
    with h5py.File(path, "r") as f:
        def text(key):
            return str(np.asarray(M[key]).ravel()[0])
        check(text("record_names") == " ".join(read_suite.record_names(path)), "Octave: record names")
        check(text("kind") == "suite" and math.isclose(float(M["alpha_rad"][0, 0]), f.attrs["alpha_rad"]),
              "Octave: root attributes (read by name where Octave's ncinfo cannot list the file)")
        check(same(M["scale_factor"], f["records/scale_factor"][()]) and same(M["pga_g"].ravel(), f["records/pga_g"][()]),
              "Octave: per-record arrays")
        check(same(M["sa_g"].ravel(), f["records/sa_g"][()]) and float(M["sa_period_s"][0, 0]) == mock.SA_PERIOD_S
              and float(M["sa_damping"][0, 0]) == mock.SA_DAMPING, "Octave: Sa of each record, its T and zeta")
        floors = sorted(f["floors"])
        check(sorted(text("floor_names").split()) == floors, "Octave: one element per floor")
        bad = []
        for fl in floors:
            g = f["floors"][fl]
            for ds in ("pfa_g", "pfa_over_pga", "spectrum_g", "median_spectrum_g", "period_s", "scale_factor"):
                m = M["fl_{}_{}".format(fl, ds)]
                if not same(m.ravel() if g[ds].ndim == 1 else m, g[ds][()]):
                    bad.append(fl + "/" + ds)
            for a in ("median_pfa_g", "median_pfa_over_pga"):
                if float(M["fl_{}_{}".format(fl, a)][0, 0]) != float(g.attrs[a]):
                    bad.append(fl + "." + a)
            if text("fl_{}_floor".format(fl)) != read_suite.value(g.attrs["floor"]):
                bad.append(fl + ".floor")
        check(not bad, "Octave = h5py for the floors' products{}".format(": differs in " + ", ".join(bad) if bad else ""))
        for k, name in enumerate(names, start=1):
            g = f["suite"][name]
            p = "s{}_".format(k)
            bad = []
            for ds in ("record", "alpha_rad", "radius_m", "intensity", "outcome", "max_rotation", "impacts", "t_overturn",
                       "broken", "done"):
                h5 = g[ds][()]
                m = M[p + ds]
                if h5.ndim == 1:
                    m = m.ravel()
                if not (same(m, h5) and m.dtype == h5.dtype):
                    bad.append(ds)
            for ds in read_suite.OVERTURNING:
                if not same(M[p + "ov_" + ds], g["overturning"][ds][()]):
                    bad.append("overturning/" + ds)
            for ds in ("fraction", "exceed", "total", "median_intensity", "beta", "fit_status"):
                if not same(M[p + "fr_" + ds], g["fragility"][ds][()]):
                    bad.append("fragility/" + ds)
            if not same(M[p + "fr_rotation_ratios"].ravel(), g["fragility/damage_state"].attrs["rotation_ratios"]):
                bad.append("rotation_ratios")
            if text(p + "fr_states") != read_suite.value(g["fragility/damage_state"].attrs["flag_meanings"]):
                bad.append("states")
            if text(p + "anchorage") != read_suite.value(g.attrs["anchorage"]):
                bad.append("anchorage")
            check(not bad, "Octave = h5py (values, index order, types) for {}{}".format(
                name, ": differs in " + ", ".join(bad) if bad else ""))


def test_xarray(path):
    import xarray as xr

    S = read_suite.load(path)
    for engine in ("h5netcdf", "netcdf4"):
        for name, sc in S["scenarios"].items():
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)   # netCDF4's import warns about numpy's ABI
                with xr.open_dataset(path, group="suite/" + name, engine=engine) as ds, \
                        xr.open_dataset(path, group="suite/{}/fragility".format(name), engine=engine) as fr:
                    ok = (ds.outcome.dims == ("record", "alpha_rad", "radius_m", "intensity")
                          and same(ds.outcome.values, sc["outcome"]) and same(ds.t_overturn.values, sc["t_overturn"])
                          and ds.radius_m.attrs["units"] == "m" and ds.attrs["anchorage"] == sc["attrs"]["anchorage"]
                          and same(fr["median_intensity"].values, sc["fragility"]["median_intensity"])
                          and fr.damage_state.attrs["flag_meanings"].split() == sc["fragility"]["states"])
            check(ok, "xarray.open_dataset(group='suite/{}', engine='{}'): same arrays and axes".format(name, engine))
    D = read_suite.to_xarray(path)
    free = D["free"]
    check(math.isclose(float(free.first_pga_g.isel(alpha_rad=0).sel(record="cape_mendocino_1992", radius_m=0.5)), 0.05 + 5 * 1.45 / 19),
          "to_xarray: select by record name")
    check(float(free.fraction.sel(damage_state="overturning", radius_m=1.0).isel(alpha_rad=0, intensity=-1)) == 1.0
          and free.intensity.attrs["units"] == "1", "to_xarray: damage_state names as a coordinate, units kept")


def test_plot_errors(mock_dir):
    plot = os.path.join(SCRIPTS, "plot_suite.py")
    with tempfile.TemporaryDirectory() as tmp:
        other = os.path.join(tmp, "other.h5")
        with h5py.File(other, "w") as f:
            f.attrs["kind"] = np.bytes_("spectra")
            f.create_group("spectra")
        text_file = os.path.join(tmp, "notes.txt")
        with open(text_file, "w") as fh:
            fh.write("not HDF5\n")
        for bad, words in ((other, "not a rocksweep suite file"), (text_file, "cannot read it as HDF5")):
            run = subprocess.run([sys.executable, plot, bad, "-o", os.path.join(tmp, "x")], capture_output=True,
                                 text=True)
            lines = run.stderr.strip().split("\n")
            check(run.returncode != 0 and len(lines) == 1 and words in lines[0] and not os.listdir(tmp).count("x_ida.png"),
                  "plot_suite.py on {}: status {}, one line: {}".format(os.path.basename(bad), run.returncode, lines[-1]))
        run = subprocess.run([sys.executable, plot, os.path.join(mock_dir, "suite_partial.h5"), "-o",
                              os.path.join(tmp, "part")], capture_output=True, text=True)
        written = sorted(os.listdir(tmp))
        check(run.returncode == 0 and "not complete" in run.stderr and "part_ida.png" in written
              and "part_fragility.png" not in written and "part_overturning.png" not in written,
              "plot_suite.py on a partial file: IDA only, and says why on stderr")


def main(argv):
    mock_dir = argv[1]
    path = os.path.join(mock_dir, "suite.h5")
    test_values(path)
    test_floors_and_sa(path)
    test_partial(os.path.join(mock_dir, "suite_partial.h5"))
    test_octave(path)
    test_xarray(path)
    test_plot_errors(mock_dir)
    print("{} failure(s)".format(len(FAILURES)))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
