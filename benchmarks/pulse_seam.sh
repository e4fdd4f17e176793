#!/usr/bin/env bash
# pulse_seam.sh REV: the excitation seam against the build of REV (e.g. the commit before it).
#  1. bitwise: configs/smatteo.toml (267 337 cells, one rank) with both builds, h5diff of the
#     result datasets (/spectra and /axes; the root gained the attributes pulse, pulse_cycles);
#  2. instructions: callgrind on the reduced sweep (46 x 53 grid) with both builds, side by side
#     in one run, and their ratio (wall time is noisy on a shared machine; instruction counts
#     are not).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep
rev="$1"
old="$out/build-$rev"
if [ ! -x "$old/rocksweep" ]; then
  src="$(mktemp -d)"
  git archive "$rev" | tar -x -C "$src"
  cmake -S "$src" -B "$old" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$old" -j 2 --target rocksweep >/dev/null
  rm -rf "$src"
fi
full=(sweep --config configs/smatteo.toml --quiet --overwrite)
"$old/rocksweep" "${full[@]}" -o "$out/seam_old.h5"
build/rocksweep "${full[@]}" -o "$out/seam_new.h5"
for g in /spectra /axes; do
  if h5diff "$out/seam_old.h5" "$out/seam_new.h5" "$g" "$g" >/dev/null 2>&1; then
    echo "configs/smatteo.toml $g: bitwise equal"
  else
    echo "configs/smatteo.toml $g: DIFFER (h5diff $out/seam_old.h5 $out/seam_new.h5 $g $g)"
  fi
done
reduced=(sweep --config configs/smatteo.toml --omega-ratio-points 46 --amplitude-ratio-points 53 --quiet --overwrite)
count() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 | awk '/Collected/ {print $4}'; }
n_old=$(count "$old/rocksweep" "${reduced[@]}" -o "$out/seam_cg_old.h5")
n_new=$(count build/rocksweep "${reduced[@]}" -o "$out/seam_cg_new.h5")
echo "instructions: $rev $n_old, this tree $n_new, ratio $(awk -v a="$n_new" -v b="$n_old" 'BEGIN {printf "%.4f", a / b}')"
