#!/usr/bin/env bash
# compare_builds.sh REV [RUNS]: the default S. Matteo sweep (configs/smatteo.toml, one rank,
# 267 337 cells) timed with the build of REV and with this tree's build, alternately RUNS times
# (default 5) in one run, so that machine noise hits both alike; prints each time, the medians
# and their ratio, and whether the result datasets are bitwise equal (h5diff without /provenance
# and the root's attributes, the run's description, to which newer builds add, e.g. parameter_axes).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" rocksweep
rev="$1"; runs="${2:-5}"
old="$out/build-$rev"
if [ ! -x "$old/rocksweep" ]; then
  src="$(mktemp -d)"
  git archive "$rev" | tar -x -C "$src"
  cmake -S "$src" -B "$old" -DCMAKE_BUILD_TYPE=Release -DROCKSWEEP_BUILD_TESTS=OFF -DROCKSWEEP_BUILD_BENCHMARKS=OFF >/dev/null 2>&1 ||
    cmake -S "$src" -B "$old" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$old" -j 2 --target rocksweep >/dev/null
  rm -rf "$src"
fi
args=(sweep --config configs/smatteo.toml --quiet --overwrite)
t_old=(); t_new=()
for ((i = 0; i < runs; i++)); do
  t_old+=("$(wall "$old/rocksweep" "${args[@]}" -o "$out/cmp_old.h5")")
  t_new+=("$(wall build/rocksweep "${args[@]}" -o "$out/cmp_new.h5")")
  echo "run $((i + 1)): $rev ${t_old[-1]} s, this tree ${t_new[-1]} s"
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
m_old=$(median "${t_old[@]}"); m_new=$(median "${t_new[@]}")
echo "median: $rev $m_old s, this tree $m_new s, ratio (this tree / $rev) $(awk -v a="$m_new" -v b="$m_old" 'BEGIN {printf "%.3f", a / b}')"
if h5diff --exclude-path /provenance --exclude-attribute / "$out/cmp_old.h5" "$out/cmp_new.h5" >/dev/null 2>&1; then
  echo "result datasets: bitwise equal"
else
  echo "result datasets: differ (h5diff --exclude-path /provenance --exclude-attribute / $out/cmp_old.h5 $out/cmp_new.h5)"
fi
