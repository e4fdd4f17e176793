#!/usr/bin/env bash
# suite_convert.sh ROCKSWEEP CONFIG SUITE DIR: `suite --resume` of a partial file written whole
# (format 4 before streaming: compressed result datasets, NaN in the cells not done, no
# checkpoint cost in /provenance) rewrites it once in the streaming layout and ends bitwise
# like an uninterrupted run. The old file is made from a finished one by h5py: half its cells
# put back to pending, as a save of the old writer left them. Then a running file with every
# run done but no products (a kill while the finished file was written) is finished by
# --resume on 1 and 2 ranks, without computing a run.
set -u
rs="$1"; cfg="$2"; suite="$3"; dir="$4"
rm -rf "$dir"; mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }
args=(suite --config "$cfg" --suite "$suite" --anchorages free constant --theta-f-ratios 1 --intensity-points 16
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

# A small suite keeps its finished datasets contiguous: stripped of its products and marked
# incomplete it is what a kill during the last step leaves (the running file, every run done).
small=(suite --config "$cfg" --suite "$suite" --anchorages free --intensity-points 4 --radius-range 0.8 2.4
       --radius-points 2)
"$rs" "${small[@]}" --quiet -o "$dir/small.h5" || fail "small reference run"
for np in 1 2; do
  cp "$dir/small.h5" "$dir/unfinished$np.h5"
  /usr/bin/python3 - "$dir/unfinished$np.h5" <<'PY' || fail "making the unfinished file"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r+") as f:
    g = f["suite/free"]
    assert g["outcome"].chunks is None, "a small suite's results are contiguous"
    del g["overturning"], g["fragility"]
    f.attrs["complete"] = np.int64(0)
PY
  run=("$rs")
  if [ "$np" -gt 1 ]; then
    run=(mpirun --oversubscribe -np "$np")
    [ "$(id -u)" -eq 0 ] && run+=(--allow-run-as-root)
    run+=("$rs")
  fi
  "${run[@]}" "${small[@]}" -o "$dir/unfinished$np.h5" --resume > "$dir/unfinished$np.log" 2>&1 ||
    { cat "$dir/unfinished$np.log"; fail "resume of an unfinished file on $np rank(s)"; }
  grep -q "resuming, 96 of 96 cells already done" "$dir/unfinished$np.log" || { cat "$dir/unfinished$np.log"; fail "not resumed"; }
  h5diff --exclude-path /provenance "$dir/small.h5" "$dir/unfinished$np.h5" || fail "the finished file differs ($np ranks)"
done
echo "a file written whole resumes into the same results; an unfinished one is finished"
