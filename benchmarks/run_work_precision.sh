#!/usr/bin/env bash
# Work-precision benchmark in one command, from anywhere:
#   benchmarks/run_work_precision.sh [--quick] [--grid N] [--out DIR]
# Builds the work_precision target (Release) into build/ if needed, runs it on one thread,
# and plots. Writes DIR/work_precision_{single,spectra,mismatches}.csv, DIR/work_precision.txt
# (the printed tables) and DIR/work_precision.png; DIR defaults to benchmarks/results.
# The default run takes about 2 min 10 s on a quiet 2-core machine; --quick (60 x 60) ~40 s.
# BUILD_DIR overrides the build directory (default: build).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
build="${BUILD_DIR:-build}"

out="benchmarks/results"
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  case "${args[$i]}" in
    --out) out="${args[$((i + 1))]:-$out}" ;;
    --out=*) out="${args[$i]#--out=}" ;;
  esac
done

if ! grep -q 'work_precision.cmake' benchmarks/CMakeLists.txt; then
  echo "run_work_precision.sh: benchmarks/CMakeLists.txt does not include(work_precision.cmake) yet," >&2
  echo "  so there is no work_precision target to build." >&2
  exit 2
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
build_type="$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")"
if [ "$build_type" != "Release" ]; then
  echo "run_work_precision.sh: $build is configured as '$build_type', not Release; timings would" >&2
  echo "  mean nothing. Reconfigure it, or set BUILD_DIR to a fresh directory." >&2
  exit 2
fi
cmake --build "$build" -j2 --target work_precision

mkdir -p "$out"
start=$(date +%s)
"$build/benchmarks/work_precision" "$@" | tee "$out/work_precision.txt"
echo "wall time of the benchmark: $(( $(date +%s) - start )) s"
/usr/bin/python3 "$here/benchmarks/plot_work_precision.py" "$out"
