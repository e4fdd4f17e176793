#!/usr/bin/env bash
# resume_complete.sh ROCKSWEEP CONFIG DIR NP [K/N]: --resume on a sweep (or part K of N of one)
# that already ended (a requeued Slurm job) says so in one line, exits 0 and leaves the file byte
# for byte as it was — its recorded wall time included.
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
left=$(ls "$dir" | grep -v -x -e done.h5 -e before.h5)
[ -z "$left" ] || { echo "left behind: $left"; exit 1; }
echo ok
