#!/usr/bin/python3
"""Writes a MOCK `rocksweep suite` file, laid out exactly as /work/spec/suite_layout.md (docs/suite.md)
says, so that the readers and plot_suite.py can be developed and tested before the C++ writer
exists. The numbers are made up but behave like the physics:

- 11 records (the shared suite's names and metadata), 20 levels of target PGA 0.05 ... 1.5 g,
  radii 0.5, 1, 2 m at one alpha (a slenderness axis of length 1), three anchorages free, constant_tf1, adaptive_rho0.1;
- record i overturns at and above its capacity c = c_i sqrt(R / 1 m) k_anchorage [g]
  (c_i lognormal about 0.35 g, k = 1, 1.5, 2.2: adaptive best); below it theta_max/alpha rises
  as 0.9 (x/c)^2; far above it (x > 1.6 c) the block falls without an impact (mode 2);
- the adaptive anchorage keeps every R = 2 m block standing (overturning fit: none_reached);
- two cells break the simple threshold: record RECORD_ISLAND (free, first radius) stays up on
  the two levels after its first overturning one (safe_above = 1), and record
  RECORD_UNCONVERGED (free, first radius) did not converge at the top level (outcome 255, left
  out of the fragility counts);
- overturning/ and fragility/ are computed from these outcome arrays (the fit: binomial MLE
  over the stripes, Baker 2015; degenerate data get the statuses of docs/fragility.md).

    make_suite_mock.py OUT.h5 [--radii N] [--partial] [--measure pga_g|pgv_m_s]

--radii N keeps the first N radii (1 gives the single-size file); --partial writes a checkpoint
(the last record pending everywhere, complete = 0, no overturning/ or fragility/ groups).
"""
import argparse
import math
import sys

import h5py
import numpy as np
from scipy import optimize, stats

G = 9.80665
LEVELS_G = np.linspace(0.05, 1.5, 20)
RADII_M = np.array([0.5, 1.0, 2.0])
ALPHA = math.atan(0.25 / 1.0)                     # b = 0.25 m, h = 1.0 m: the configured block
CAPACITY_G = [0.21, 0.42, 0.30, 0.55, 0.26, 0.37, 0.48, 0.19, 0.33, 0.62, 0.28]
PGA_G = [0.348, 0.843, 0.702, 1.497, 0.358, 0.472, 1.226, 0.820, 0.690, 0.770, 0.168]
# Sa(0.5 s, 5 %) of each record: 2.2 PGA (the mock's); floors: the ground (PFA = PGA) and a 2nd
# floor whose PFA is FLOOR_GAIN[i] PGA, spectra on SPECTRUM_PERIODS_S.
SA_PERIOD_S, SA_DAMPING = 0.5, 0.05
FLOOR_GAIN = [1.2, 1.5, 1.9, 1.4, 2.6, 1.7, 2.0, 1.1, 1.8, 2.3, 1.6]
SPECTRUM_PERIODS_S = np.array([0.1, 0.5, 2.0])
PGV_M_S = [0.36, 1.29, 1.19, 1.27, 0.47, 0.94, 1.16, 0.77, 0.80, 0.63, 0.61]
RECORDS = [  # name, file, format, units, event, station, component
    ("elcentro_1940_ns", "../tests/data/elcentro_1940_NS.dat", "time_accel", "g", "Imperial Valley 1940",
     "El Centro", "N-S"),
    ("sylmar_1994", "../tests/data/northridge_1994_sylmar.dat", "time_accel", "m/s^2", "Northridge 1994",
     "Sylmar County Hospital parking lot", ""),
    ("newhall_1994_rot", "../tests/data/RSN1044_northridge_1994_newhall_rot.AT2", "at2", "", "Northridge 1994",
     "Newhall Fire Station (PEER NGA RSN 1044)", "rotated 68.8 deg, clockwise from NWH090"),
    ("cape_mendocino_1992", "../tests/data/cape_mendocino_1992.dat", "time_accel", "m/s^2",
     "Cape Mendocino 1992", "(not stated by the source)", ""),
    ("kocaeli_1999", "../tests/data/kocaeli_1999.dat", "time_accel", "m/s^2", "Kocaeli 1999", "(not stated)", ""),
    ("loma_prieta_1989", "../tests/data/loma_prieta_1989.dat", "time_accel", "m/s^2", "Loma Prieta 1989",
     "(not stated)", ""),
    ("san_fernando_1971", "../tests/data/san_fernando_1971.dat", "time_accel", "m/s^2", "San Fernando 1971",
     "(not stated)", ""),
    ("spitak_1988", "../tests/data/spitak_1988.dat", "time_accel", "m/s^2", "Spitak (Armenia) 1988",
     "(not stated; the peak matches Gukasian)", ""),
    ("san_salvador_1986_gic090", "../tests/data/san_salvador_1986_gic090.txt", "time_accel", "m/s^2",
     "San Salvador 1986", "Geotech Investigation Center", "090"),
    ("cephalonia_2014_chv1_e", "../tests/data/cephalonia_2014_chv1_E.txt", "time_accel", "cm/s^2",
     "Cephalonia (Greece) 2014-02-03", "Chavriata CHV1", "E"),
    ("mexico_city_1985_sct_ns", "../tests/data/mexico_city_1985_sct.txt", "time_accel", "g", "Michoacan 1985",
     "Mexico City SCT", "N-S (column 2, unlabelled by the source); vertical column 4"),
]
RECORD_ISLAND = 3        # safe_above = 1 (free, first radius)
RECORD_UNCONVERGED = 9   # outcome 255 at the top level (free, first radius)
# name, anchorage, theta_f_ratio, kmin_ratio, capacity factor
SCENARIOS = [("free", "free", 0.0, 1.0, 1.0), ("constant_tf1", "constant", 1.0, 1.0, 1.5),
             ("adaptive_rho0.1", "adaptive", 1.0, 0.1, 2.2)]
ROTATION_RATIOS = [0.1, 0.3, 0.5]
FIT_STATUS = "ok none_reached all_reached zero_dispersion not_identifiable decreasing".split()
OUTCOME_MEANINGS = "safe overturned_with_impact overturned_without_impact not_converged"
Z95 = stats.norm.ppf(0.975)


# --------------------------------------------------------------------------- writing helpers


def text(obj, name, value):
    """A fixed-length string attribute, as long as the text (one NUL byte for '')."""
    data = str(value).encode("utf-8")
    obj.attrs.create(name, np.bytes_(data or b"\0"), dtype=h5py.string_dtype("ascii", max(len(data), 1)))


def attrs(obj, values):
    for k, v in values.items():
        if isinstance(v, str):
            text(obj, k, v)
        elif isinstance(v, (int, np.integer)):
            obj.attrs.create(k, np.int64(v))
        elif isinstance(v, np.ndarray):
            obj.attrs.create(k, v)
        else:
            obj.attrs.create(k, np.asarray(v, dtype=np.float64))


def axis(group, name, values, units, long_name, extra=None):
    ds = group.create_dataset(name, data=np.asarray(values, dtype="<f8"))
    ds.make_scale(name)
    attrs(ds, dict(units=units, long_name=long_name, **(extra or {})))
    return ds


def result(group, name, data, dims, dtype, units=None, long_name=None, extra=None):
    ds = group.create_dataset(name, data=np.asarray(data).astype(dtype))
    for i, d in enumerate(dims):
        ds.dims[i].attach_scale(group[d])
    values = {"dimensions": ", ".join(dims)}
    if units is not None:
        values["units"] = units
    if long_name is not None:
        values["long_name"] = long_name
    values.update(extra or {})
    attrs(ds, values)
    return ds


def alpha_axis(group):
    axis(group, "alpha_rad", np.array([ALPHA]), "rad", "slenderness angle alpha = atan(b/h) of the block")


def on_alpha(group, name, values, dims, *args, **kwargs):
    """`result` with the one-point alpha_rad axis inserted after the first dimension."""
    return result(group, name, np.expand_dims(np.asarray(values), 1), dims[:1] + ["alpha_rad"] + dims[1:],
                  *args, **kwargs)


def record_axis(group, names):
    axis(group, "record", np.arange(len(names)), "1", "record",
         {"flag_values": np.arange(len(names), dtype=np.int64), "flag_meanings": " ".join(names)})


# --------------------------------------------------------------------------- the made-up runs


def runs(n_rec, radii, cap_factor, scenario_index):
    """outcome, max_rotation, t_overturn [record, radius, level] of one scenario."""
    shape = (n_rec, len(radii), len(LEVELS_G))
    cap = np.array(CAPACITY_G[:n_rec])[:, None, None] * np.sqrt(radii)[None, :, None] * cap_factor
    if scenario_index == 2 and len(radii) == 3:
        cap[:, 2] *= 3.0      # adaptive keeps every 2 m block up to 1.5 g: a fit with no data above
    x = LEVELS_G[None, None, :]
    over = np.broadcast_to(x >= cap, shape).copy()
    outcome = np.where(over, np.where(x > 1.6 * cap, 2, 1), 0).astype(np.uint8)
    if scenario_index == 0:
        first = int(np.argmax(over[RECORD_ISLAND, 0]))
        outcome[RECORD_ISLAND, 0, first + 1:first + 3] = 0     # a safe island above the first level
        outcome[RECORD_UNCONVERGED, 0, -1] = 255
    fell = (outcome == 1) | (outcome == 2)
    rot = np.minimum(0.9 * (x / cap) ** 2, 0.95)
    rot = np.where(fell, 0.5 * np.pi / ALPHA, np.broadcast_to(rot, shape))
    rot = np.where(outcome == 255, np.nan, rot)
    t_over = np.where(fell, 4.0 + 10.0 * np.broadcast_to(cap / x, shape), np.nan)
    return outcome, rot, t_over


def reached(outcome, rot, ratio):
    """Which runs reach a damage state (ratio None: overturning); not-converged runs never."""
    fell = (outcome == 1) | (outcome == 2)
    if ratio is None:
        return fell
    return fell | ((outcome == 0) & (np.nan_to_num(rot) >= ratio))


def first_overturning(outcome, levels):
    """first_intensity, below_intensity, safe_above [record, radius]."""
    fell = (outcome == 1) | (outcome == 2)
    any_fell = fell.any(axis=2)
    k = np.argmax(fell, axis=2)
    first = np.where(any_fell, levels[k], np.nan)
    below = np.where(any_fell & (k > 0), levels[np.maximum(k - 1, 0)], np.nan)
    above = np.arange(len(levels))[None, None, :] > k[:, :, None]
    safe_above = (any_fell & ((outcome == 0) & above).any(axis=2)).astype(np.uint8)
    return first, below, safe_above


def wilson(k, n, z=Z95):
    n_safe = np.maximum(n, 1)
    p = k / n_safe
    centre = (p + z * z / (2 * n_safe)) / (1 + z * z / n_safe)
    half = z * np.sqrt(p * (1 - p) / n_safe + z * z / (4 * n_safe * n_safe)) / (1 + z * z / n_safe)
    return np.where(n > 0, centre - half, np.nan), np.where(n > 0, centre + half, np.nan)


def fit_stripes(x, k, n):
    """(status, median, beta, se_ln_median, se_beta) of the binomial MLE over stripes."""
    use = n > 0
    x, k, n = x[use], k[use], n[use]
    if not k.any():
        return "none_reached", math.inf, math.nan, math.nan, math.nan
    if (k == n).all():
        return "all_reached", 0.0, math.nan, math.nan, math.nan
    mixed = (k > 0) & (k < n)
    below_all_zero = x[k == 0].max() if (k == 0).any() else None
    above_all_full = x[k == n].min() if (k == n).any() else None
    if not mixed.any() and below_all_zero is not None and above_all_full is not None \
            and below_all_zero < above_all_full:
        return "zero_dispersion", math.sqrt(below_all_zero * above_all_full), 0.0, math.nan, math.nan
    if mixed.sum() == 1 and np.all(k[x < x[mixed][0]] == 0) and np.all(k[x > x[mixed][0]] == n[x > x[mixed][0]]):
        return "zero_dispersion", float(x[mixed][0]), 0.0, math.nan, math.nan
    if len(np.unique(x)) == 1:
        return "not_identifiable", math.nan, math.nan, math.nan, math.nan

    def nll(params):
        ln_med, beta = params
        z = (np.log(x) - ln_med) / beta
        return -np.sum(k * stats.norm.logcdf(z) + (n - k) * stats.norm.logsf(z))

    res = optimize.minimize(nll, [np.log(np.median(x)), 0.5], method="Nelder-Mead",
                            options={"xatol": 1e-10, "fatol": 1e-12, "maxiter": 4000})
    ln_med, beta = res.x
    if beta <= 0:
        return "decreasing", math.nan, math.nan, math.nan, math.nan
    h = np.array([1e-4, 1e-4])
    hess = np.empty((2, 2))
    for i in range(2):
        for j in range(2):
            def f(di, dj):
                p = np.array([ln_med, beta])
                p[i] += di * h[i]
                p[j] += dj * h[j]
                return nll(p)
            hess[i, j] = (f(1, 1) - f(1, -1) - f(-1, 1) + f(-1, -1)) / (4 * h[i] * h[j])
    cov = np.linalg.inv(hess)
    return "ok", math.exp(ln_med), beta, math.sqrt(cov[0, 0]), math.sqrt(cov[1, 1])


# --------------------------------------------------------------------------- the file


def write(path, n_radii, partial, measure):
    names = [r[0] for r in RECORDS]
    n_rec = len(names)
    radii = RADII_M[:n_radii]
    pga = np.array(PGA_G)
    pgv = np.array(PGV_M_S)
    if measure == "pga_g":
        levels, units, long_name = LEVELS_G, "1", "target peak ground acceleration / standard gravity"
        scale = levels[None, :] / pga[:, None]
    else:  # the same runs, labelled by the PGV each record had at them
        levels, units, long_name = LEVELS_G * 1.0, "m/s", "target peak ground velocity"
        scale = levels[None, :] / pgv[:, None]
    b, h = 0.25, 1.0
    r = math.hypot(b, h)
    with h5py.File(path, "w") as f:
        attrs(f, {
            "title": "rocksweep record-suite sweep", "Conventions": "CF-1.8", "format_version": 3, "kind": "suite",
            "half_width_m": b, "half_height_m": h, "radius_m": r, "alpha_rad": ALPHA,
            "p_rad_s": math.sqrt(3 * G / (4 * r)), "e": 1 - 1.5 * math.sin(ALPHA) ** 2, "inertia_ratio": 4.0 / 3.0,
            "mass_kg": 500.0, "gravity_m_s2": G, "intensity_measure": measure, "intensity_units": units,
            "intensity_long_name": long_name, "suite_file": "configs/records_suite.csv",
            "method": "rk45", "steps_per_period": 200.0, "max_steps": 2.0e6, "energy_stop": 1.0,
            "impact_threshold": 1e-4, "equations": "nonlinear",
        })
        rec = f.create_group("records")
        record_axis(rec, names)
        alpha_axis(rec)
        axis(rec, "intensity", levels, units, long_name)
        per_record = {
            "pga_g": (pga, "1", "peak ground acceleration / standard gravity"),
            "pga_time_s": (np.linspace(2.0, 9.0, n_rec), "s", "time of the PGA"),
            "pgv_m_s": (pgv, "m/s", "peak ground velocity"),
            "pgv_time_s": (np.linspace(2.5, 9.5, n_rec), "s", "time of the PGV"),
            "residual_velocity_m_s": (np.full(n_rec, 1e-3), "m/s", "ground velocity at the end of the record"),
            "arias_m_s": (0.5 + pga ** 2 * 3.0, "m/s", "Arias intensity"),
            "significant_duration_s": (np.linspace(6.0, 30.0, n_rec), "s", "significant duration (5-95 % Arias)"),
            "duration_s": (np.linspace(20.0, 60.0, n_rec), "s", "record duration"),
            "pga_vertical_g": (np.full(n_rec, np.nan), "1", "vertical peak ground acceleration / standard gravity"),
        }
        for name, (values, u, ln) in per_record.items():
            result(rec, name, values, ["record"], "<f8", u, ln)
        on_alpha(rec, "scale_factor", scale, ["record", "intensity"], "<f8", "1", "factor the record is multiplied by")
        on_alpha(rec, "pga_scaled_g", scale * pga[:, None], ["record", "intensity"], "<f8", "1",
               "peak ground acceleration of the scaled record / standard gravity")
        sa = result(rec, "sa_g", 2.2 * pga, ["record"], "<f8", "1", "spectral pseudo-acceleration / standard gravity")
        attrs(sa, {"period_s": SA_PERIOD_S, "damping": SA_DAMPING})
        write_floors(f, names, pga, scale)
        for name, file_, fmt, u, event, station, component in RECORDS:
            g = rec.create_group(name)
            attrs(g, {"file": file_, "format": fmt, "units": u, "dt_s": "", "column": "", "scale": "1",
                      "event": event, "station": station, "component": component})
        suite = f.create_group("suite")
        n_cells = 0
        n_done = 0
        for index, (sname, kind, tf, kmin, factor) in enumerate(SCENARIOS):
            g = suite.create_group(sname)
            k_max = 0.0 if kind == "free" else 2.0e5 / tf
            attrs(g, {"index": index, "anchorage": kind, "break_rule": "angle", "adaptive_law": "paper",
                      "theta_f_ratio": tf, "kmin_ratio": kmin, "k_max_N_per_m": k_max,
                      "k_min_N_per_m": k_max * kmin, "strength_N": 0.4 * 500.0 * G,
                      "theta_f_rad": tf * ALPHA})
            write_scenario(g, names, radii, levels, units, long_name, factor, index, partial)
            n_cells += g["done"].size
            n_done += int(np.count_nonzero(g["done"][()]))
        attrs(f, {"n_cells": n_cells, "n_done": n_done, "complete": int(n_done == n_cells)})
        prov = f.create_group("provenance")
        attrs(prov, {"version": "mock", "config": "# written by tests/scripts/make_suite_mock.py\n",
                     "created_utc": "2026-11-24T00:00:00Z", "ranks": 1, "wall_s": 0.0})


def write_floors(f, names, pga, scale):
    """/floors/ground and /floors/f2 (docs/suite.md, "Floors"): spectrum = PFA (T / 0.5 s)."""
    floors = f.create_group("floors")
    attrs(floors, {"spectrum_damping": 0.05})
    for name, gain, definition in (("ground", np.ones(len(names)), "ground"),
                                   ("f2", np.array(FLOOR_GAIN), "f2: 0.5 0.05 1.3")):
        g = floors.create_group(name)
        record_axis(g, names)
        alpha_axis(g)
        axis(g, "intensity", LEVELS_G, "1", "target peak ground acceleration / standard gravity")
        axis(g, "period_s", SPECTRUM_PERIODS_S, "s", "natural period of the 5 %-damped oscillator")
        pfa = gain * pga
        spectrum = pfa[:, None] * SPECTRUM_PERIODS_S[None, :] / 0.5
        result(g, "pfa_g", pfa, ["record"], "<f8", "1", "peak floor acceleration / standard gravity")
        result(g, "pfa_over_pga", gain, ["record"], "<f8", "1", "peak floor acceleration / PGA")
        result(g, "spectrum_g", spectrum, ["record", "period_s"], "<f8", "1", "floor spectrum / standard gravity")
        result(g, "median_spectrum_g", np.median(spectrum, axis=0), ["period_s"], "<f8", "1", "its median")
        on_alpha(g, "scale_factor", scale, ["record", "intensity"], "<f8", "1", "factor on this floor")
        attrs(g, {"floor": definition, "median_pfa_g": float(np.median(pfa)),
                  "median_pfa_over_pga": float(np.median(gain))})


def write_scenario(g, names, radii, levels, units, long_name, factor, index, partial):
    dims = ["record", "radius_m", "intensity"]
    record_axis(g, names)
    alpha_axis(g)
    axis(g, "radius_m", radii, "m", "block size R (corner to centre of mass)")
    axis(g, "intensity", levels, units, long_name)
    outcome, rot, t_over = runs(len(names), radii, factor, index)
    fell = (outcome == 1) | (outcome == 2)
    done = np.ones(outcome.shape, np.uint8)
    if partial:
        done[-1] = 0
        outcome[-1] = 0
        rot[-1] = np.nan
        t_over[-1] = np.nan
    on_alpha(g, "outcome", outcome, dims, "u1", extra={
        "flag_values": np.array([0, 1, 2, 255], np.uint8), "flag_meanings": OUTCOME_MEANINGS})
    on_alpha(g, "max_rotation", rot, dims, "<f8", "1", "maximum |theta| / alpha")
    on_alpha(g, "impacts", np.where(outcome == 1, 3, 0), dims, "<i4", "1", "impacts above the settling threshold")
    on_alpha(g, "impacts_total", np.where(outcome == 1, 4, 1), dims, "<i4", "1", "impacts, the settling one included")
    on_alpha(g, "t_overturn", t_over, dims, "<f8", "s", "time of overturning")
    free = g.attrs["anchorage"] == b"free"
    force = np.full(outcome.shape, np.nan) if free else np.minimum(np.nan_to_num(rot, nan=0.0), 1.0)
    on_alpha(g, "peak_force_ratio", force, dims, "<f8", "1", "peak anchorage force / F_u")
    broken = np.zeros(outcome.shape) if free else np.where(fell, 3, 0)
    on_alpha(g, "broken", broken, dims, "u1", extra={"flag_masks": np.array([1, 2], np.uint8),
                                                   "flag_meanings": "left_spring_broken right_spring_broken"})
    on_alpha(g, "mu_required", np.full(outcome.shape, 0.25), dims, "<f8", "1",
           "friction coefficient needed to rock without sliding")
    on_alpha(g, "pivot_uplift", np.zeros(outcome.shape), dims, "u1")
    on_alpha(g, "done", done, dims, "u1", extra={"flag_values": np.array([0, 1], np.uint8),
                                               "flag_meanings": "pending computed"})
    if partial:
        return
    ov = g.create_group("overturning")
    record_axis(ov, names)
    alpha_axis(ov)
    axis(ov, "radius_m", radii, "m", "block size R (corner to centre of mass)")
    first, below, safe_above = first_overturning(outcome, levels)
    first_pga = np.full(first.shape, np.nan)
    for i in range(len(names)):
        for j in range(len(radii)):
            if np.isfinite(first[i, j]):
                first_pga[i, j] = g.file["records/pga_scaled_g"][i, 0, int(np.argmax(levels == first[i, j]))]
    two = ["record", "radius_m"]
    on_alpha(ov, "first_intensity", first, two, "<f8", units, "lowest level that overturns")
    on_alpha(ov, "first_pga_g", first_pga, two, "<f8", "1", "PGA of the record at its first overturning level")
    on_alpha(ov, "below_intensity", below, two, "<f8", units, "level before the first overturning one")
    on_alpha(ov, "safe_above", safe_above, two, "u1", "1", "1: a higher level leaves the block standing")
    write_fragility(g.create_group("fragility"), outcome, rot, radii, levels, units, long_name)


def write_fragility(fr, outcome, rot, radii, levels, units, long_name):
    ratios = ROTATION_RATIOS + [None]
    n_state = len(ratios)
    axis(fr, "damage_state", np.arange(n_state), "1", "damage state", {
        "flag_values": np.arange(n_state, dtype=np.int64),
        "flag_meanings": " ".join(["rotation>={:g}".format(r) for r in ROTATION_RATIOS] + ["overturning"]),
        "rotation_ratios": np.array([np.nan if r is None else r for r in ratios])})
    alpha_axis(fr)
    axis(fr, "radius_m", radii, "m", "block size R (corner to centre of mass)")
    axis(fr, "intensity", levels, units, long_name)
    total = np.count_nonzero(outcome != 255, axis=0)                       # [radius, level]
    exceed = np.stack([np.count_nonzero(reached(outcome, rot, r), axis=0) for r in ratios])
    total = np.broadcast_to(total, exceed.shape)
    fraction = np.where(total > 0, exceed / np.maximum(total, 1), np.nan)
    lo, hi = wilson(exceed, total)
    three = ["damage_state", "radius_m", "intensity"]
    on_alpha(fr, "fraction", fraction, three, "<f8", "1", "fraction of the records reaching the state")
    on_alpha(fr, "fraction_lo", lo, three, "<f8", "1", "Wilson 95 % interval, lower end")
    on_alpha(fr, "fraction_hi", hi, three, "<f8", "1", "Wilson 95 % interval, upper end")
    on_alpha(fr, "exceed", exceed, three, "<i4", "1", "records reaching the state")
    on_alpha(fr, "total", total, three, "<i4", "1", "records run (not-converged runs left out)")
    fits = {k: np.full((n_state, len(radii)), np.nan) for k in
            ("median_intensity", "beta", "median_intensity_lo", "median_intensity_hi", "beta_lo", "beta_hi", "se_ln_median", "se_beta")}
    status = np.zeros((n_state, len(radii)), np.uint8)
    for s in range(n_state):
        for j in range(len(radii)):
            st, med, beta, se_ln, se_b = fit_stripes(levels, exceed[s, j], total[s, j])
            status[s, j] = FIT_STATUS.index(st)
            fits["median_intensity"][s, j], fits["beta"][s, j] = med, beta
            fits["se_ln_median"][s, j], fits["se_beta"][s, j] = se_ln, se_b
            if st == "ok":
                fits["median_intensity_lo"][s, j] = med * math.exp(-Z95 * se_ln)
                fits["median_intensity_hi"][s, j] = med * math.exp(Z95 * se_ln)
                fits["beta_lo"][s, j] = beta * math.exp(-Z95 * se_b / beta)
                fits["beta_hi"][s, j] = beta * math.exp(Z95 * se_b / beta)
    two = ["damage_state", "radius_m"]
    for k, v in fits.items():
        u = units if k.startswith("median_intensity") else "1"
        on_alpha(fr, k, v, two, "<f8", u, k.replace("_", " "))
    on_alpha(fr, "fit_status", status, two, "u1", extra={
        "flag_values": np.arange(len(FIT_STATUS), dtype=np.uint8), "flag_meanings": " ".join(FIT_STATUS)})


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("output")
    p.add_argument("--radii", type=int, default=len(RADII_M), choices=range(1, len(RADII_M) + 1))
    p.add_argument("--partial", action="store_true")
    p.add_argument("--measure", choices=("pga_g", "pgv_m_s"), default="pga_g")
    args = p.parse_args(argv)
    write(args.output, args.radii, args.partial, args.measure)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
