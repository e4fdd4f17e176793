#!/usr/bin/env bash
# merge_checksum.sh ROCKSWEEP CONFIG DIR: each part stores a checksum of its result datasets when
# it finishes, the same at any rank count; merge verifies it: a part whose outcome was edited
# afterwards is refused (exit 2, one line naming the part and its scenario, no output), a part
# without a checksum (from before it was stored) is merged with a warning naming it.
set -u
rs="$1"; cfg="$2"; dir="$3"
rm -rf "$dir"; mkdir -p "$dir"; cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
grid=(--config "$cfg" --anchorages free constant --theta-f-ratios 1 --omega-ratio-points 20 --amplitude-ratio-points 15 --quiet)
"$rs" sweep "${grid[@]}" --part 1/2 -o p1.h5 || fail "part 1"
"$rs" sweep "${grid[@]}" --part 2/2 -o p2.h5 || fail "part 2"
mpi=(mpirun --oversubscribe -np 2)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
"${mpi[@]}" "$rs" sweep "${grid[@]}" --part 1/2 --chunk 1 -o p1_two_ranks.h5 || fail "part 1 on two ranks"
checksums() { h5dump -a /spectra/free/results_fnv1a64 -a /spectra/constant_tf1/results_fnv1a64 "$1" | grep '(0)'; }
c1=$(checksums p1.h5); c2=$(checksums p1_two_ranks.h5)
echo "part 1: $c1"
[ -n "$c1" ] && [ "$c1" = "$c2" ] || fail "checksums differ between rank counts: $c1 / $c2"
grep -q '(0): 0$' <<<"$c1" && fail "a finished part stores no checksum"
# The checksum is what docs/hdf5.md says: FNV-1a 64 over the ten datasets' bytes, in order.
/usr/bin/python3 -c "import h5py, sys, numpy as np
cols = ('outcome max_rotation impacts impacts_total t_overturn peak_force_ratio broken mu_required '
        'pivot_uplift done').split()
with h5py.File(sys.argv[1], 'r') as f:
    for name, g in f['spectra'].items():
        h = 0xcbf29ce484222325
        for c in cols:
            for b in np.ascontiguousarray(g[c][...]).tobytes():
                h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
        stored = int(np.int64(g.attrs['results_fnv1a64']).view(np.uint64))
        assert h == stored, (name, hex(h), hex(stored))
        print(name, hex(h))" p1.h5 || fail "the stored checksum is not docs/hdf5.md's FNV-1a"
"$rs" merge "${grid[@]}" p1.h5 p2.h5 -o merged.h5 2>err.txt || fail "merge of intact parts"
[ ! -s err.txt ] || fail "merge of intact parts said: $(cat err.txt)"
# One outcome edited inside part 2, the checksum left as it was.
cp p2.h5 edited.h5
/usr/bin/python3 -c "import h5py, sys, numpy as np
with h5py.File(sys.argv[1], 'r+') as f:
    d = f['spectra/constant_tf1/outcome']; o = d[...]
    done = f['spectra/constant_tf1/done'][...]
    i = np.argwhere(done == 1)[0]; o[tuple(i)] = 1 - o[tuple(i)]; d[...] = o" edited.h5 || fail "h5py"
err=$("$rs" merge "${grid[@]}" p1.h5 edited.h5 -o bad.h5 2>&1); status=$?
echo "edited part -> $err"
[ "$status" -eq 2 ] || fail "edited part: exit status $status, expected 2"
[ "$(grep -c . <<<"$err")" -eq 1 ] || fail "edited part: not one line"
grep -Eq "^rocksweep: error: part file = edited.h5 is invalid: .*checksum.*scenario constant_tf1" <<<"$err" || fail "edited part: message"
[ ! -e bad.h5 ] && [ ! -e bad.h5.tmp ] && [ ! -e bad.h5.lock ] || fail "edited part: an output was left"
# A part from before checksums: merged, with a warning naming it (even with --quiet).
cp p2.h5 old.h5
/usr/bin/python3 -c "import h5py, sys
with h5py.File(sys.argv[1], 'r+') as f:
    for g in f['spectra'].values(): del g.attrs['results_fnv1a64']" old.h5 || fail "h5py"
err=$("$rs" merge "${grid[@]}" p1.h5 old.h5 -o merged_old.h5 2>&1); status=$?
echo "old part -> $err"
[ "$status" -eq 0 ] || fail "old part: exit status $status"
grep -q "^warning: old.h5 stores no checksum of the results of its scenarios (written before" <<<"$err" || fail "old part: no warning"
h5diff merged.h5 merged_old.h5 /spectra /spectra || fail "the old part merged to other results"
# The merged file carries the checksums of its data: merged again, it verifies.
"$rs" merge "${grid[@]}" merged.h5 -o merged_again.h5 2>err.txt && [ ! -s err.txt ] || fail "a merged file did not verify"
echo ok
