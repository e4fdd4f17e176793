#!/usr/bin/python3
"""The records panel of the work-precision benchmark (benchmarks/records_panel.sh).

    /usr/bin/python3 benchmarks/records_panel.py scipy-suite RECORDS_CSV OUT_CSV
    /usr/bin/python3 benchmarks/records_panel.py collect DIR OUT_CSV

scipy-suite writes the suite file (with a `scales` column) of the suite-slice cells the scipy
script runs: the records it can read (two columns), every fifth PGA level of suite_peers'
30 (0.05-1.5 g), scaled as the suite scales them (level / the record's PGA in standard g).

collect reads what records_panel.sh left in DIR and writes one CSV, one row per setting and
panel, and prints the comparison at equal theta error: for every rocksweep tolerance whose error
is at most 1e-4 rad, the speed of the paper's method and of the scipy script at that error,
interpolated log-log between the two settings of the peer that bracket it, or the peer's
smallest error when it never gets there.
"""
import collections
import csv
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import records_peers  # noqa: E402  (the scipy script: its record reader)
import records_peers_table as table  # noqa: E402

G_BLOCK, G_STANDARD = records_peers.G, records_peers.G_STANDARD
LEVELS = [0.05 + 0.05 * k for k in range(30)]  # suite_smatteo.hpp: Axis{0.05, 1.5, 30}
SCIPY_LEVELS = range(4, 30, 5)                  # 0.25, 0.5, ..., 1.5 g
SCENARIOS = ["free", "constant", "adaptive"]    # suite_smatteo.hpp's order
CLAIM_RAD = 1e-4

ENGINE_TOLS = ["1e-6", "1e-7", "1e-8", "1e-9", "1e-10"]
PAPER_DTS = ["0.0025", "0.00125", "0.000625", "0.0003125", "0.00015625"]
PAPER_LABELS = ["paper", "paper_dt1.3e-3", "paper_dt6.3e-4", "paper_dt3.1e-4", "paper_dt1.6e-4"]
RTOLS = ["1e-4", "1e-5", "1e-6", "1e-7", "1e-8", "1e-9", "1e-10"]
SUITE_RTOLS = ["1e-4", "1e-6", "1e-8"]


def read_suite(path):
    folder = os.path.dirname(os.path.abspath(path))
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def scipy_suite(records_csv, out_csv):
    folder = os.path.dirname(os.path.abspath(records_csv))
    with open(out_csv, "w") as f:
        f.write("name,file,format,units,scales\n")
        for i, row in enumerate(read_suite(records_csv)):
            if row["column"] or row["vertical_file"]:
                continue  # the scipy script reads two-column files only
            path = os.path.join(folder, row["file"])
            acc, _ = records_peers.read_record(path, row["format"], row["units"])
            pga_g = max(abs(acc)) * G_BLOCK / G_STANDARD
            for k in SCIPY_LEVELS:
                f.write(f"{row['name']}@{i}@{k},{path},{row['format']},{row['units']},{LEVELS[k] / pga_g!r}\n")


def suite_cells(path):
    """index -> (record, outcome code, max |theta| / alpha)."""
    cells = {}
    with open(path) as f:
        for line in f:
            i, rec, code, rot, _ = line.split()
            cells[int(i)] = (rec, int(code), float(rot))
    return cells


def suite_timing(path):
    t = {}
    with open(path) as f:
        for line in f:
            w = line.split()
            t[w[0]] = (int(w[6]), float(w[8]))  # cells, seconds
    return t


def overturned(code):
    return code != 0  # CellResult outcome: 0 safe, else overturned (with / without impact)


def interpolate(points, err):
    """Speed of a peer at theta error `err` from its (error, speed) settings, log-log between the
    fastest setting at least as accurate and the slowest one less accurate; (speed, how)."""
    better = [p for p in points if p[0] <= err]
    if not better:
        return None, "never reaches it"
    fastest_better = max(better, key=lambda p: p[1])
    worse = [p for p in points if p[0] > err and p[1] > fastest_better[1]]
    if not worse:
        return fastest_better[1], "its fastest setting is more accurate (a bound: at least this fast)" \
            if fastest_better[1] == max(p[1] for p in points) else "at a setting at least as accurate"
    w = min(worse, key=lambda p: p[1])
    f = (math.log(err) - math.log(fastest_better[0])) / (math.log(w[0]) - math.log(fastest_better[0]))
    return math.exp(math.log(fastest_better[1]) + f * (math.log(w[1]) - math.log(fastest_better[1]))), "interpolated"


def collect(folder, out_csv):
    ref, chk = table.histories(folder, "reference"), table.histories(folder, "reference_check")
    ref_o, chk_o = table.outcomes(folder, "reference"), table.outcomes(folder, "reference_check")
    runs = list(ref_o)
    chaotic = {r for r in runs if table.max_diff(ref[r], chk[r]) > table.CHAOTIC_RAD or ref_o[r]["outcome"] != chk_o[r]["outcome"]}
    timing = collections.defaultdict(dict)
    with open(f"{folder}/records_peers_timing.csv") as f:
        for row in csv.DictReader(f):
            timing[int(row["round"])][row["label"]] = float(row["cpu_s"]) / (int(row["runs"]) * int(row["passes"]))
    settings = ([("rocksweep", "tolerance", t, f"tol{t}") for t in ENGINE_TOLS]
                + [("paper", "dt_s", d, l) for d, l in zip(PAPER_DTS, PAPER_LABELS)]
                + [("scipy", "rtol", r, f"scipy_rtol{r}") for r in RTOLS])
    rounds = [t for _, t in sorted(timing.items()) if all(s[3] in t for s in settings)]
    rows = []
    for family, knob, value, label in settings:
        h, o = table.histories(folder, label), table.outcomes(folder, label)
        errs = [table.max_diff(h[r], ref[r]) for r in runs if r not in chaotic]
        rows.append({"panel": "theta", "family": family, "knob": knob, "value": value, "label": label,
                     "cells": len(runs) - len(chaotic),
                     "per_s_per_core": statistics.median(1.0 / t[label] for t in rounds),
                     "per_s_min": min(1.0 / t[label] for t in rounds), "per_s_max": max(1.0 / t[label] for t in rounds),
                     "max_theta_err_rad": max(errs), "median_theta_err_rad": statistics.median(errs),
                     "wrong_outcomes": sum(o[r]["outcome"] != ref_o[r]["outcome"] for r in runs), "compared": len(runs)})

    # Outcomes over the suite slice: overturned or not, against the reference; cells where the
    # check disagrees with the reference are left out (sensitive).
    st = suite_timing(f"{folder}/suite_timing.txt")
    sref, schk = suite_cells(f"{folder}/suite_reference.cells"), suite_cells(f"{folder}/suite_check.cells")
    sensitive = {i for i in sref if overturned(sref[i][1]) != overturned(schk[i][1])}
    suite_settings = ([("rocksweep", "tolerance", t, f"tol{t}") for t in ENGINE_TOLS]
                      + [("paper", "dt_s", d, f"paper_dt{float(d):.6g}") for d in PAPER_DTS])
    for family, knob, value, label in suite_settings:
        c = suite_cells(f"{folder}/suite_{label}.cells")
        kept = [i for i in sref if i not in sensitive]
        n, sec = st[label]
        rows.append({"panel": "outcomes", "family": family, "knob": knob, "value": value, "label": label,
                     "cells": n, "per_s_per_core": n / sec, "per_s_min": n / sec, "per_s_max": n / sec,
                     "wrong_outcomes": sum(overturned(c[i][1]) != overturned(sref[i][1]) for i in kept),
                     "compared": len(kept)})
    # scipy's subset: run name <record>@<record index>@<level>_x<scale>_<free|constant>.
    index_of = {}
    for r in SUITE_RTOLS:
        o = table.outcomes(folder, f"suite_scipy_rtol{r}")
        wrong = compared = 0
        cpu = sum(float(x["cpu_s"]) for x in o.values())
        for name, x in o.items():
            rec, ri, rest = name.split("@")
            level, anch = int(rest.split("_x")[0]), rest.rsplit("_", 1)[1]
            i = (SCENARIOS.index(anch) * 12 + int(ri)) * 30 + level
            assert sref[i][0] == rec, (name, sref[i])
            index_of[name] = i
            if i in sensitive:
                continue
            compared += 1
            wrong += (x["outcome"] != "safe") != overturned(sref[i][1])
        rows.append({"panel": "outcomes_scipy_subset", "family": "scipy", "knob": "rtol", "value": r,
                     "label": f"suite_scipy_rtol{r}", "cells": len(o), "per_s_per_core": len(o) / cpu,
                     "per_s_min": len(o) / cpu, "per_s_max": len(o) / cpu, "wrong_outcomes": wrong, "compared": compared})
    # rocksweep and the paper on scipy's subset: their wrong outcomes there (speed is the slice's).
    subset = sorted(set(index_of.values()) - sensitive)
    for family, knob, value, label in suite_settings:
        c = suite_cells(f"{folder}/suite_{label}.cells")
        n, sec = st[label]
        rows.append({"panel": "outcomes_scipy_subset", "family": family, "knob": knob, "value": value, "label": label,
                     "cells": n, "per_s_per_core": n / sec, "per_s_min": n / sec, "per_s_max": n / sec,
                     "wrong_outcomes": sum(overturned(c[i][1]) != overturned(sref[i][1]) for i in subset),
                     "compared": len(subset)})

    fields = ["panel", "family", "knob", "value", "label", "cells", "per_s_per_core", "per_s_min", "per_s_max",
              "max_theta_err_rad", "median_theta_err_rad", "wrong_outcomes", "compared"]
    with open(out_csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, restval="")
        w.writeheader()
        w.writerows(rows)
    report(rows, len(rounds), chaotic, len(sensitive))


def report(rows, n_rounds, chaotic, n_sensitive):
    print(f"== theta error: {rows[0]['cells']} runs of records_peers.csv (chaotic left out: {', '.join(sorted(chaotic)) or 'none'}), "
          f"runs/s per core: median of {n_rounds} interleaved rounds [min, max] ==")
    for r in rows:
        if r["panel"] == "theta":
            print(f"  {r['family']:9s} {r['knob']:9s} {r['value']:>10s} {r['per_s_per_core']:10.1f} "
                  f"[{r['per_s_min']:9.1f}, {r['per_s_max']:9.1f}]  max err {r['max_theta_err_rad']:.2e} rad  "
                  f"median {r['median_theta_err_rad']:.2e}  outcomes off {r['wrong_outcomes']}/{r['compared']}")
    for key, words in (("max_theta_err_rad", "max"), ("median_theta_err_rad", "median")):
        curve = {f: [(r[key], r["per_s_per_core"]) for r in rows if r["panel"] == "theta" and r["family"] == f]
                 for f in ("paper", "scipy")}
        print(f"\n== rocksweep against its peers at equal {words} theta error over the runs (<= {CLAIM_RAD:g} rad); "
              f"goals: 20x the paper, 1000x scipy ==")
        for r in rows:
            if r["panel"] != "theta" or r["family"] != "rocksweep" or r[key] > CLAIM_RAD:
                continue
            line = f"  tolerance {r['value']:>6s}: {r[key]:.2e} rad, {r['per_s_per_core']:8.1f} runs/s;"
            for f in ("paper", "scipy"):
                speed, how = interpolate(curve[f], r[key])
                if speed is None:
                    best = min(curve[f])
                    line += (f" {f}: never reaches it (smallest error {best[0]:.2e} rad, at {best[1]:.1f} runs/s: "
                             f"this is {r['per_s_per_core'] / best[1]:.0f}x faster);")
                else:
                    line += f" {f}: {speed:.2f} runs/s ({how}), ratio {r['per_s_per_core'] / speed:.0f}x;"
            print(line)
    for panel, what in (("outcomes", "the suite slice (S. Matteo size, 12 records, 30 levels, 3 anchorages)"),
                        ("outcomes_scipy_subset", "scipy's subset of it (free and constant, 10 records, 6 levels)")):
        print(f"\n== wrong outcomes (overturned or not) over {what}, against --tolerance 1e-12; "
              f"{n_sensitive} cells where 1e-11 disagrees left out; one pass each ==")
        for r in rows:
            if r["panel"] == panel:
                print(f"  {r['family']:9s} {r['knob']:9s} {r['value']:>10s} {r['per_s_per_core']:10.1f} cells/s  "
                      f"wrong {r['wrong_outcomes']:4d} of {r['compared']}")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "scipy-suite":
        scipy_suite(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "collect":
        collect(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
