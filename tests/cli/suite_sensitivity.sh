#!/usr/bin/env bash
# suite_sensitivity.sh ROCKSWEEP CONFIG SUITE DIR: `suite --check-sensitivity` stores a uint8
# `sensitive` flag per run with its CF flag attributes and a per-fit count of flagged runs,
# leaves every other result dataset as the run without it has them, prints the counts in its
# summary; --resume refuses a file computed with the other setting (exit 2, one line naming
# the option, the file unchanged).
set -u
rs="$1"; cfg="$2"; suite="$3"; dir="$4"
rm -rf "$dir"; mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }
args=(suite --config "$cfg" --suite "$suite" --anchorages free constant --theta-f-ratios 1 --intensity-points 6
      --intensity-range 0.2 1.2)
"$rs" "${args[@]}" --check-sensitivity -o "$dir/checked.h5" > "$dir/log.txt" 2>&1 || fail "checked suite"
"$rs" "${args[@]}" --quiet -o "$dir/plain.h5" || fail "plain suite"
grep -Eq "^  free +median .*; [0-9]+ of its runs flagged sensitive$" "$dir/log.txt" || { cat "$dir/log.txt"; fail "summary"; }
/usr/bin/python3 - "$dir/checked.h5" "$dir/plain.h5" <<'PY' || fail "datasets"
import sys, h5py, numpy as np
text = lambda x: x.decode() if isinstance(x, bytes) else x
with h5py.File(sys.argv[1]) as c, h5py.File(sys.argv[2]) as p:
    assert text(c.attrs["check_sensitivity"]) == "on"
    assert text(p.attrs["check_sensitivity"]) == "off"
    for s in ("free", "constant_tf1"):
        g, h = c["suite"][s], p["suite"][s]
        flag = g["sensitive"]
        assert flag.dtype == np.uint8 and flag.shape == g["outcome"].shape, (flag.dtype, flag.shape)
        assert list(flag.attrs["flag_values"]) == [0, 1] and text(flag.attrs["flag_meanings"]) == "robust sensitive"
        assert set(np.unique(flag[()])) <= {0, 1}
        assert "sensitive" not in h and "sensitive_runs" not in h["fragility"]
        for name in h:  # every dataset of the plain run, bitwise
            if isinstance(h[name], h5py.Dataset):
                assert np.array_equal(g[name][()], h[name][()], equal_nan=True), name
        # Each fit counts the flagged runs among its converged ones: the same for every state.
        counts = g["fragility/sensitive_runs"][()]
        converged = g["outcome"][()] != 255
        per_block = (flag[()].astype(bool) & converged).sum(axis=(0, 3))
        for d in range(counts.shape[0]):
            assert np.array_equal(counts[d], per_block), (counts[d], per_block)
        print(s, "flagged:", int(flag[()].sum()), "of", flag.size)
PY
refused() {  # refused FILE GIVEN IN_FILE [OPTION]: --resume of FILE with OPTION must be refused
  local file="$1" given="$2" in_file="$3" err status sum
  shift 3
  sum=$(md5sum < "$dir/$file")
  err=$("$rs" "${args[@]}" "$@" -o "$dir/$file" --resume 2>&1 >/dev/null); status=$?
  echo "$file $* -> $err"
  [ "$status" -eq 2 ] || fail "$file: exit status $status, expected 2"
  [ "$(grep -c . <<<"$err")" -eq 1 ] || fail "$file: not one line"
  grep -Eq -- "^rocksweep: error: --check-sensitivity = $given is invalid: $in_file, as $dir/$file was computed with" <<<"$err" ||
    fail "$file: message"
  [ "$(md5sum < "$dir/$file")" = "$sum" ] || fail "$file: the file changed"
}
refused checked.h5 off on
refused plain.h5 on off --check-sensitivity
"$rs" "${args[@]}" --check-sensitivity --quiet -o "$dir/checked.h5" --resume || fail "resume with the same setting"
# The readers expose the flag and the figure marks it: on a copy with two runs set flagged.
cp "$dir/checked.h5" "$dir/marked.h5"
/usr/bin/python3 - "$dir/marked.h5" "$(dirname "$0")/../../scripts" <<'PY' || fail "reader"
import sys, h5py
sys.path.insert(0, sys.argv[2])
import read_suite
with h5py.File(sys.argv[1], "r+") as f:
    f["suite/free/sensitive"][0, 0, 0, 2] = 1
    f["suite/free/sensitive"][3, 0, 0, 5] = 1
S = read_suite.load(sys.argv[1])
assert S["scenarios"]["free"]["sensitive"][0, 0, 0, 2] == 1 and S["scenarios"]["free"]["sensitive"].sum() == 2
assert "sensitive_runs" in S["scenarios"]["free"]["fragility"]
assert int(read_suite.to_xarray(sys.argv[1])["free"]["sensitive"].sum()) == 2
text = read_suite.summary(S)
assert "  2 run(s) flagged sensitive" in text, text
assert "flagged run(s)" in text, text
PY
/usr/bin/python3 "$(dirname "$0")/../../scripts/plot_suite.py" "$dir/marked.h5" -o "$dir/marked" > "$dir/plot.txt" 2>&1 ||
  { cat "$dir/plot.txt"; fail "plot_suite.py"; }
ls "$dir"/marked_ida* > /dev/null || fail "no IDA figure"
echo "sensitivity flags stored, other results unchanged, resume checked, read and drawn"
