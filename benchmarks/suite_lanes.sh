#!/usr/bin/env bash
# suite_lanes.sh REV [ROUNDS] [DRIVER OPTIONS...]: cells/s of a record suite's cells (issue 9,
# "lanes of one batch share a record"), the build of REV against this tree's, in one run.
# benchmarks/suite_lanes (suite_lanes.cpp) computes every cell of configs/suite_smatteo.toml's
# suite (8640 cells, one thread, chunks of 64 as a rank gets them) and times only that; it is
# built in both trees (the REV tree gets this tree's driver). Rounds alternate old/new so that
# the shared machine's noise hits both alike; prints each round, the median and range of each
# build's cells/s, the median ratio new/old, whether the result hashes agree, and the
# instructions of one run of each (perf stat, where the machine counts them).
# Then bitwise: physics_split.sh's runs with both builds' rocksweep (histories of a record at scale
# 1 and 2, every analytic family's sweep whose lane loop this touches, basins), h5diff of
# everything but /provenance. SUITE_LANES_SKIP=bitwise skips that part.
# Driver options (e.g. --levels 10 --radii 2 for a quick look) pass through.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" suite_lanes rocksweep
rev="$1"; rounds="${2:-5}"; shift; [ $# -gt 0 ] && shift
old="$out/build-suite-lanes-$rev"
if [ ! -x "$old/benchmarks/suite_lanes" ] || [ ! -x "$old/rocksweep" ]; then
  src="$(mktemp -d)"
  git archive "$rev" | tar -x -C "$src"
  cp benchmarks/suite_lanes.cpp benchmarks/suite_peers.cpp benchmarks/suite_smatteo.hpp benchmarks/CMakeLists.txt "$src/benchmarks/"
  cmake -S "$src" -B "$old" -DCMAKE_BUILD_TYPE=Release -DROCKSWEEP_BUILD_TESTS=OFF >/dev/null
  cmake --build "$old" -j 2 --target suite_lanes rocksweep >/dev/null
  rm -rf "$src"
fi
field() { awk -v k="$1" '{for (i = 1; i < NF; ++i) if ($i == k) print $(i + 1)}'; }
r_old=(); r_new=()
for ((i = 0; i < rounds; i++)); do
  o="$("$old/benchmarks/suite_lanes" "$@")"; n="$(build/benchmarks/suite_lanes "$@")"
  r_old+=("$(field cells_per_s <<<"$o")"); r_new+=("$(field cells_per_s <<<"$n")")
  h_old="$(field hash <<<"$o")"; h_new="$(field hash <<<"$n")"
  echo "round $((i + 1)): $rev ${r_old[-1]} cells/s, this tree ${r_new[-1]} cells/s ($(field cells <<<"$n") cells)"
done
stats() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2; printf "%.1f (range %.1f-%.1f)", m, a[1], a[NR]}'; }
median() { stats "$@" | awk '{print $1}'; }
echo "$rev: $(stats "${r_old[@]}") cells/s"
echo "this tree: $(stats "${r_new[@]}") cells/s"
echo "ratio of medians (this tree / $rev): $(awk -v a="$(median "${r_new[@]}")" -v b="$(median "${r_old[@]}")" 'BEGIN {printf "%.3f", a / b}')"
if [ "$h_old" = "$h_new" ]; then echo "results: same bits (hash $h_new)"; else echo "results: differ (hash $rev $h_old, this tree $h_new)"; fi
# Where they differ: cells whose outcome (safe / mode 1 / mode 2) or max |theta| changed, per record.
"$old/benchmarks/suite_lanes" "$@" --outcomes "$out/suite_lanes_old.txt" >/dev/null
build/benchmarks/suite_lanes "$@" --outcomes "$out/suite_lanes_new.txt" >/dev/null
paste -d' ' "$out/suite_lanes_old.txt" "$out/suite_lanes_new.txt" | awk '
  {n[$2]++; if ($3 != $7) o[$2]++; if ($4 != $8) r[$2]++
   if ($3 == 0 && $7 == 0 && $4 > 0) {d = ($8 - $4) / $4; d = d < 0 ? -d : d; if (d > m[$2]) m[$2] = d}}
  END {for (k in n) printf "  %-28s %5d cells: outcome differs in %4d, max rotation in %4d (largest relative change where safe %.1e)\n",
                           k, n[k], o[k] + 0, r[k] + 0, m[k] + 0}' | sort
if command -v perf >/dev/null && ! perf stat -e instructions true 2>&1 | grep -q "not supported"; then
  count() { perf stat -x, -e instructions "$@" 2>&1 >/dev/null | awk -F, '/instructions/ {print $1}'; }
  i_old=$(count "$old/benchmarks/suite_lanes" "$@"); i_new=$(count build/benchmarks/suite_lanes "$@")
  echo "instructions (whole run, records read included): $rev $i_old, this tree $i_new, ratio $(awk -v a="$i_new" -v b="$i_old" 'BEGIN {printf "%.3f", a / b}')"
fi
[[ "${SUITE_LANES_SKIP:-}" == *bitwise* ]] && exit 0
PHYSICS_SPLIT_SKIP=callgrind benchmarks/physics_split.sh "$old" build
