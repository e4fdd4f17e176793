#!/usr/bin/python3
"""The table of benchmarks/records_peers.sh: speed and error of each peer against the reference.

    /usr/bin/python3 benchmarks/records_peers_table.py DIR

Reads DIR/records_peers_<label>.csv (theta at the record samples), ..._outcomes.csv and
DIR/records_peers_timing.csv. Error of a peer on a run = max |theta - theta_ref| over the record
samples up to the record's end or the first of the two overturnings; outcome = safe, or
overturned with or without impact. Speed: runs per CPU second of one process (every peer runs
on one thread, so this is per core), and in each round the ratio of the peers' CPU times per
run; the median round and the range are printed.
"""
import collections
import csv
import math
import statistics
import sys

# A run is called chaotic when the two tight reference settings (events 4096 / 1e-8 and
# 2048 / 1e-7, whose local errors are ~1e-13 rad) differ by more than this or in outcome: it
# then amplifies perturbations a thousandfold at least, and its theta error says more about
# the run than about the integrator. 1e-9 rad is a thousandth of the 1e-6 rad claim.
CHAOTIC_RAD = 1e-9
PEERS = ["events48", "events48_cross", "events96_cross", "events384", "tol1e-8", "tol1e-9", "tol1e-10", "paper", "paper_dt6.3e-4", "paper_dt1.6e-4", "scipy", "scipy_tight"]
TIMED = ["events48", "events48_cross", "events96_cross", "events384", "tol1e-8", "tol1e-9", "tol1e-10", "paper", "paper_dt6.3e-4", "paper_dt1.6e-4", "scipy"]
WHAT = {
    "events48": "rocksweep events, 48 steps/period, settle 1e-3 (sweep default): every sample ends a step",
    "events48_cross": "the same with steps that cross samples on moment nodes (steps_end_at_samples off)",
    "events96_cross": "96 steps/period crossing samples",
    "events384": "rocksweep events, 384 steps/period, settle 1e-4 (simulate's fixed step before issue 22)",
    "tol1e-8": "rocksweep events, steps from the error, tolerance 1e-8, settle 1e-3 (sweep default)",
    "tol1e-9": "rocksweep events, steps from the error, tolerance 1e-9, settle 1e-4",
    "tol1e-10": "rocksweep events, steps from the error, tolerance 1e-10, settle 1e-4",
    "paper": "paper's method: fixed-step RK4, dt 0.0025 s, impact at step end",
    "paper_dt6.3e-4": "paper's method at dt 0.000625 s",
    "paper_dt1.6e-4": "paper's method at dt 0.00015625 s",
    "scipy": "scipy solve_ivp RK45 rtol 1e-6 atol 1e-9, settle 1e-4",
    "scipy_tight": "scipy solve_ivp RK45 rtol 1e-11 atol 1e-13, settle 1e-8 (check only)",
}


def histories(folder, label):
    h = collections.defaultdict(list)
    with open(f"{folder}/records_peers_{label}.csv") as f:
        for row in csv.DictReader(f):
            h[row["run"]].append(float(row["theta"]))
    return h


def outcomes(folder, label):
    with open(f"{folder}/records_peers_{label}_outcomes.csv") as f:
        return {row["run"]: row for row in csv.DictReader(f)}


def max_diff(a, b):
    n = min(len(a), len(b))
    return max((abs(x - y) for x, y in zip(a[:n], b[:n])), default=0.0)


def fmt_t(x):
    return "-" if math.isnan(float(x)) else f"{float(x):.3f}"


def main(folder):
    ref, chk = histories(folder, "reference"), histories(folder, "reference_check")
    ref_o, chk_o = outcomes(folder, "reference"), outcomes(folder, "reference_check")
    runs = list(ref_o)
    chaotic = {r: max_diff(ref[r], chk[r]) > CHAOTIC_RAD or ref_o[r]["outcome"] != chk_o[r]["outcome"] for r in runs}
    err, mism, dt_ot = {}, {}, {}
    for p in PEERS:
        h, o = histories(folder, p), outcomes(folder, p)
        err[p] = {r: max_diff(h[r], ref[r]) for r in runs}
        mism[p] = [r for r in runs if o[r]["outcome"] != ref_o[r]["outcome"]]
        dt_ot[p] = max((abs(float(o[r]["t_overturn_s"]) - float(ref_o[r]["t_overturn_s"])) for r in runs
                        if o[r]["outcome"] == ref_o[r]["outcome"] != "safe"), default=0.0)

    print("== Runs: S. Matteo (b 0.30 m, h 1.36 m, 3361 kg), free and constant anchorage theta_f = alpha, "
          "F_u = 0.4 m g ==")
    print(f"reference: rocksweep events 4096 steps/period, settle 1e-8 p alpha; check: 2048, 1e-7. "
          f"chaotic: they differ by > {CHAOTIC_RAD:g} rad or in outcome\n")
    print(f"{'run':32s} {'PGA/(g tan a)':>13s} {'outcome':>24s} {'t_ot [s]':>8s} {'|ref-check|':>11s} {'chaotic':>7s} | "
          + " ".join(f"{p:>11s}" for p in PEERS))
    for r in runs:
        o = ref_o[r]
        print(f"{r:32s} {float(o['pga_over_g_tan_alpha']):13.3f} {o['outcome']:>24s} {fmt_t(o['t_overturn_s']):>8s} "
              f"{max_diff(ref[r], chk[r]):11.2e} {'yes' if chaotic[r] else 'no':>7s} | "
              + " ".join(f"{err[p][r]:11.2e}" for p in PEERS))

    timing = collections.defaultdict(dict)
    with open(f"{folder}/records_peers_timing.csv") as f:
        for row in csv.DictReader(f):
            n = int(row["runs"]) * int(row["passes"])
            timing[int(row["round"])][row["label"]] = (float(row["cpu_s"]) / n, float(row["wall_s"]) / n)
    rounds = [t for _, t in sorted(timing.items()) if all(p in t for p in TIMED)]

    def med(values):
        return statistics.median(values), min(values), max(values)

    print(f"\n== Speed and error: {len(rounds)} interleaved rounds, one thread each; ratios of CPU time per run "
          f"within a round (median [min, max]) ==")
    print(f"{'peer':10s} {'runs/s/core':>11s} {'(wall)':>8s} {'vs scipy':>24s} {'vs paper':>20s} "
          f"{'max err, not chaotic':>20s} {'max err, all':>12s} {'outcomes != ref':>15s} {'max |dt_ot|':>11s}")
    for p in PEERS:
        quiet = [err[p][r] for r in runs if not chaotic[r]]
        line = f"{p:10s} "
        if p in TIMED:
            cpu = med([1.0 / t[p][0] for t in rounds])
            wall = med([1.0 / t[p][1] for t in rounds])
            vs_s = med([t["scipy"][0] / t[p][0] for t in rounds])
            vs_p = med([t["paper"][0] / t[p][0] for t in rounds])
            line += (f"{cpu[0]:11.1f} {wall[0]:8.1f} {vs_s[0]:9.0f} [{vs_s[1]:5.0f}, {vs_s[2]:5.0f}] "
                     f"{vs_p[0]:7.2f} [{vs_p[1]:4.2f}, {vs_p[2]:4.2f}] ")
        else:
            line += f"{'-':>11s} {'-':>8s} {'-':>24s} {'-':>20s} "
        line += f"{max(quiet):20.2e} {max(err[p].values()):12.2e} {len(mism[p]):15d} {dt_ot[p]:11.2e}"
        print(line)
    print("\n" + "\n".join(f"  {p:10s} {WHAT[p]}" for p in PEERS))
    print(f"  chaotic runs, left out of 'max err, not chaotic': {', '.join(r for r in runs if chaotic[r]) or 'none'}")
    for p in PEERS:
        if mism[p]:
            print(f"  {p}: outcome differs from the reference on {', '.join(mism[p])}")
    print("  error: max |theta - theta_ref| [rad] at the record samples up to its end or the first overturning; "
          "max |dt_ot|: overturning time, runs overturned in both [s]")

    # Why the events method's lead over the paper's is bounded: the ground's slope jumps at every
    # sample, so a one-step method of order 4 ends a step at every sample while the block rocks.
    rocking = sum(sum(1 for x in ref[r] if x != 0.0) for r in runs)
    steps = {}
    for p in ("events48", "events48_cross", "events96_cross", "events384", "tol1e-8", "tol1e-9", "tol1e-10", "paper",
              "paper_dt6.3e-4", "paper_dt1.6e-4"):
        o = outcomes(folder, p)  # read once per peer, not once per run
        steps[p] = sum(int(o[r]["steps"]) for r in runs)
    print(f"\n== Steps (RK4 steps over the {len(runs)} runs; each costs four evaluations of the equation of motion) ==")
    print(f"record samples at which the reference block is rocking: {rocking}")
    for p, n in steps.items():
        print(f"  {p:10s} {n:8d} steps, paper / this = {steps['paper'] / n:5.2f}")
    print(f"  a method with one step per rocking sample could be at most {steps['paper'] / rocking:.1f} x the "
          f"paper's method at equal cost per step")

    # The speed-up is the steps' ratio times the ratio of the costs of one step (each setting's
    # CPU time per pass over its steps, all it does counted: events, observers, rest scans), so
    # a target speed-up asks a setting's step for at most (its steps' ratio / target) of the
    # paper's step.
    print(f"\n== Cost of one step (CPU time per pass / RK4 steps per pass; median over the rounds) ==")
    print(f"{'peer':14s} {'ns/step':>8s} {'x paper step':>12s} {'for 20 x paper: at most':>24s}")
    for p in steps:
        ns = med([t[p][0] * len(runs) / steps[p] * 1e9 for t in rounds])
        rel = med([(t[p][0] / steps[p]) / (t["paper"][0] / steps["paper"]) for t in rounds])
        most = f"{steps['paper'] / steps[p] / 20:24.2f}" if p != "paper" else f"{'-':>24s}"
        print(f"{p:14s} {ns[0]:8.0f} {rel[0]:12.2f} {most}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "benchmarks/results")
