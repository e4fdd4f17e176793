#!/usr/bin/python3
"""Compare the overturning outcomes of a suite sweep (configs/suite_smatteo.toml) at some numerics
("default" below: the setting under test) against a tight reference, excluding cells where two
tight runs disagree; and its max rotation over the cells that stay up. Called by
benchmarks/records_outcomes.sh.

usage: /usr/bin/python3 benchmarks/records_outcomes.py UNDER_TEST.h5 TIGHT.h5 TIGHTCHECK.h5
"""
import sys
import h5py
import numpy as np

OVER = (1, 2)      # overturned_with_impact, overturned_without_impact
SAFE, NC = 0, 255  # safe, not_converged


def cls(o):
    """Outcome class: 0 safe, 1 overturned (either code), 2 not_converged, 3 other."""
    c = np.full(o.shape, 3, dtype=np.int8)
    c[o == SAFE] = 0
    c[np.isin(o, OVER)] = 1
    c[o == NC] = 2
    return c


NAMES = {0: "safe", 1: "overturned", 2: "not_converged", 3: "other"}


def dec(x):
    return x.decode() if isinstance(x, bytes) else str(x)


def main(fd, ft, fc):
    files = {k: h5py.File(p, "r") for k, p in (("default", fd), ("tight", ft), ("check", fc))}
    for k, f in files.items():
        p = f["provenance"].attrs
        print(f"{k:8s} {f.filename}: steps_per_period={p['steps_per_period']}, "
              f"wall_s={float(p['wall_s']):.2f}, ranks={p['ranks']}")
    scen = sorted(files["default"]["suite"].keys())
    for f in files.values():
        assert sorted(f["suite"].keys()) == scen, "scenario groups differ"
    print("scenarios:", scen)

    tot = excl = ncmp = 0
    dis = []
    drot = []
    nident = ncompared_rot = zero = 0
    best = (-1.0,)
    for s in scen:
        g = {k: f["suite"][s] for k, f in files.items()}
        # the grids must be the same
        for name in ("record", "radius_m", "intensity", "alpha_rad"):
            a = g["default"][name][()]
            for k in ("tight", "check"):
                b = g[k][name][()]
                assert a.shape == b.shape and (a == b).all(), f"{s}/{name} differs in {k}"
        for k in g:
            d = g[k]["done"][()]
            assert d.all(), f"{s}: {k} has {(~d.astype(bool)).sum()} unfinished cells"
        flags = dict(zip(g["default"]["outcome"].attrs["flag_values"],
                         dec(g["default"]["outcome"].attrs["flag_meanings"]).split()))
        ra = files["default"]["records"]["record"].attrs
        names = dict(zip(ra["flag_values"], dec(ra["flag_meanings"]).split()))
        rec = [names[v] for v in g["default"]["record"][()]]
        rad = g["default"]["radius_m"][()]
        inten = g["default"]["intensity"][()]
        alph = g["default"]["alpha_rad"][()]
        o = {k: g[k]["outcome"][()] for k in g}
        r = {k: g[k]["max_rotation"][()] for k in g}
        c = {k: cls(o[k]) for k in g}
        for k in g:
            u, n = np.unique(o[k], return_counts=True)
            print(f"  {s:16s} {k:8s} outcome counts: " +
                  ", ".join(f"{flags.get(v, v)}={m}" for v, m in zip(u, n)))
        ex = c["tight"] != c["check"]
        keep = ~ex
        bad = keep & (c["default"] != c["tight"])
        tot += o["default"].size
        excl += int(ex.sum())
        ncmp += int(keep.sum())
        for idx in zip(*np.nonzero(bad)):
            i, a, j, l = idx
            dis.append((s, rec[i], float(alph[a]), float(rad[j]), float(inten[l]),
                        NAMES[c["default"][idx]], NAMES[c["tight"][idx]],
                        float(r["default"][idx]), float(r["tight"][idx]), float(r["check"][idx])))
        # rotation differences over non-overturned (in default and tight), non-excluded cells
        m = keep & (c["default"] != 1) & (c["tight"] != 1)
        dd = np.abs(r["default"][m] - r["tight"][m])
        drot.append(dd)
        if dd.size and dd.max() > best[0]:
            i, a, j, l = [x[np.argmax(dd)] for x in np.nonzero(m)]
            best = (float(dd.max()), s, rec[i], float(rad[j]), float(inten[l]),
                    float(r["default"][i, a, j, l]), float(r["tight"][i, a, j, l]),
                    float(r["check"][i, a, j, l]))
        zero += int(((r["default"][m] == 0) & (r["tight"][m] == 0)).sum())
        ncompared_rot += int(m.sum())
        nident += int((r["default"][m] == r["tight"][m]).sum())
        print(f"  {s:16s} cells={o['default'].size} excluded={int(ex.sum())} "
              f"default!=tight (kept)={int(bad.sum())}  "
              f"[default!=tight incl. excluded: {int((c['default'] != c['tight']).sum())}]")

    print()
    print(f"cells: {tot}")
    print(f"excluded (tight vs tight-check outcome class differs): {excl}")
    print(f"compared: {ncmp}")
    print(f"default disagrees with tight among compared: {len(dis)}")
    for d in dis[:20]:
        print(f"  {d[0]:16s} record={d[1]:26s} alpha={d[2]:.4f} R={d[3]:.4f} m I={d[4]:.4f} g: "
              f"default={d[5]} tight={d[6]}  max_rot/alpha default={d[7]:.4f} "
              f"tight={d[8]:.4f} check={d[9]:.4f}")
    if len(dis) > 20:
        print(f"  ... {len(dis) - 20} more")
    dd = np.concatenate(drot)
    print()
    print(f"max_rotation (max |theta|/alpha) over {ncompared_rot} non-overturned, non-excluded cells:")
    if dd.size:
        print(f"  max |default - tight| = {dd.max():.6g}, median = {np.median(dd):.6g}, "
              f"mean = {dd.mean():.6g}")
        print(f"  95th pct = {np.percentile(dd, 95):.6g}, 99th pct = {np.percentile(dd, 99):.6g}, "
              f"cells > 0.01: {(dd > 0.01).sum()}, > 0.05: {(dd > 0.05).sum()}, > 0.1: {(dd > 0.1).sum()}")
        print(f"  bit-identical cells = {nident} (of which max_rotation = 0 in both, i.e. no rocking: {zero})")
        print(f"  largest at {best[1]} record={best[2]} R={best[3]:.4f} m I={best[4]:.4f} g: "
              f"default={best[5]:.4f} tight={best[6]:.4f} check={best[7]:.4f}")


if __name__ == "__main__":
    main(*sys.argv[1:4])
