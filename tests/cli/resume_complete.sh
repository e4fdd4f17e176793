#!/usr/bin/env bash
# resume_complete.sh ROCKSWEEP CONFIG DIR NP [K/N]: --resume on a sweep (or part K of N of one)
# that already ended (a requeued Slurm job) says so in one line, exits 0 and leaves the file byte
# for byte as it was — its recorded wall time included. One killed after its last cell but before
# its close-out (`complete` and the checksums still 0) is closed out by --resume: its results and
# root attributes end as the uninterrupted run's.
set -u
rs="$1"; cfg="$2"; dir="$3"; np="$4"; part="${5:-}"
rm -rf "$dir"; mkdir -p "$dir"; out="$dir/done.h5"
# 3 scenarios x 10 x 10 = 300 cells; part 2/2 gets 300 - 256 = 44 of them (blocks of 256).
args=(sweep --config "$cfg" --anchorages free adaptive --omega-ratio-points 10 --amplitude-ratio-points 10 -o "$out")
expected="$out: sweep already complete (300 cells); nothing to do"
if [ -n "$part" ]; then
  args+=(--part "$part")
  expected="$out: part ${part%/*} of ${part#*/} already complete (44 cells); nothing to do"
fi
"$rs" "${args[@]}" --quiet || exit 1
cp -p "$out" "$dir/before.h5"
run=("$rs"); [ "$np" -gt 1 ] && run=(mpirun --allow-run-as-root --oversubscribe -np "$np" "$rs")
msg=$("${run[@]}" "${args[@]}" --resume 2>&1); status=$?
echo "$msg"
[ "$status" -eq 0 ] || { echo "exit status $status, expected 0"; exit 1; }
[ "$msg" = "$expected" ] || { echo "not the one line expected"; exit 1; }
cmp "$out" "$dir/before.h5" || { echo "the file changed"; exit 1; }
quiet=$("${run[@]}" "${args[@]}" --resume --quiet 2>&1) && [ -z "$quiet" ] || { echo "--quiet: '$quiet'"; exit 1; }
if [ -z "$part" ]; then
  /usr/bin/python3 - "$out" <<'PY' || exit 1
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:  # as a kill between the last checkpoint and the close-out leaves it
    f.attrs.modify("complete", 0)
    for g in f["spectra"].values():
        g.attrs.modify("results_fnv1a64", 0)
PY
  "${run[@]}" "${args[@]}" --resume --quiet || { echo "resuming an unclosed file failed"; exit 1; }
  h5diff --exclude-path /provenance "$dir/before.h5" "$out" || { echo "an unclosed file was not closed out by --resume"; exit 1; }
  cp -p "$dir/before.h5" "$out"
fi
left=$(ls "$dir" | grep -v -x -e done.h5 -e before.h5)
[ -z "$left" ] || { echo "left behind: $left"; exit 1; }
echo ok
