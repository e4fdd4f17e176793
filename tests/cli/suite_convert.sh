#!/usr/bin/env bash
# suite_convert.sh ROCKSWEEP CONFIG SUITE DIR: `suite --resume` of a partial file written whole
# (format 4 before streaming: compressed result datasets, NaN in the cells not done, no
# checkpoint cost in /provenance) rewrites it once in the streaming layout and ends bitwise
# like an uninterrupted run. The old file is made from a finished one by h5py: half its cells
# put back to pending, as a save of the old writer left them.
set -u
rs="$1"; cfg="$2"; suite="$3"; dir="$4"
rm -rf "$dir"; mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }
args=(suite --config "$cfg" --suite "$suite" --anchorages free constant --theta-f-ratios 1 --intensity-points 40
      --radius-range 0.6 3 --radius-points 3)
"$rs" "${args[@]}" --quiet -o "$dir/ref.h5" || fail "reference run"
cp "$dir/ref.h5" "$dir/old.h5"
/usr/bin/python3 - "$dir/old.h5" <<'PY' || fail "making the old file"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r+") as f:
    n_done = 0
    for name, g in f["suite"].items():
        assert g["outcome"].chunks is not None, "the finished file's results are not compressed"
        del g["overturning"], g["fragility"]
        done = g["done"][()]
        pending = np.zeros(done.shape, bool)
        pending[::2] = True  # every other record
        done[pending] = 0
        g["done"][()] = done
        for col in ("max_rotation", "t_overturn", "peak_force_ratio", "mu_required"):
            v = g[col][()]; v[pending] = np.nan; g[col][()] = v
        for col in ("outcome", "impacts", "impacts_total", "broken", "pivot_uplift"):
            v = g[col][()]; v[pending] = 0; g[col][()] = v
        n_done += int(np.count_nonzero(done))
    f.attrs["n_done"] = np.int64(n_done)
    f.attrs["complete"] = np.int64(0)
    del f["provenance"].attrs["checkpoint_s"], f["provenance"].attrs["checkpoints"]
PY
"$rs" "${args[@]}" -o "$dir/old.h5" --resume 2> "$dir/log.txt" || { cat "$dir/log.txt"; fail "resume of the old file"; }
grep -q "resuming" "$dir/log.txt" || { cat "$dir/log.txt"; fail "not resumed"; }
h5diff --exclude-path /provenance "$dir/ref.h5" "$dir/old.h5" || fail "the converted and resumed file differs"
[ ! -e "$dir/old.h5.tmp" ] || fail "old.h5.tmp left behind"
echo "a file written whole resumes into the same results"
