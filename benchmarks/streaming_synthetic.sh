#!/usr/bin/env bash
# streaming_synthetic.sh BUILD_DIR [WORKDIR] [SIZES] [CELL_NS]
# The streaming writer and the MPI scheduler at up to 1e9 cells with a synthetic cell cost
# (benchmarks/streaming_synthetic.cpp: CELL_NS ns per cell, default 0, made-up values), on 2
# ranks: one row per size (default "1e6 1e7 1e8 1e9") with the wall time, cells/s, checkpoint
# time and share, and rank 0's VmHWM. A 1e9-cell file is 46 GB (written, then removed): check
# `df -h WORKDIR` first.
set -eu
build="$1"; dir="${2:-/tmp/streaming_synthetic}"; sizes="${3:-1e6 1e7 1e8 1e9}"; ns="${4:-0}"
mkdir -p "$dir"
runner=(mpirun --oversubscribe -np 2); [ "$(id -u)" -eq 0 ] && runner+=(--allow-run-as-root)
printf '| %-10s | %8s | %10s | %11s | %8s | %12s | %10s |\n' cells wall_s cells/s checkpoints ckpt_s "ckpt % wall" "rank0 MiB"
for n in $sizes; do
  side=$(python3 -c "import math; print(round(math.sqrt(float('$n'))))")
  out="$dir/synthetic-$n.h5"
  line=$("${runner[@]}" "$build/benchmarks/streaming_synthetic" --rows "$side" --cols "$side" --cell-ns "$ns" \
         --chunk 16384 -o "$out")
  rm -f "$out"
  # cells N ranks R wall_s W cells_per_s C checkpoints K checkpoint_s S overhead_pct P rank0_vmhwm_mib M
  set -- $line
  printf '| %-10s | %8.1f | %10.0f | %11s | %8.2f | %12.2f | %10.0f |\n' "${2}" "${6}" "${8}" "${10}" "${12}" "${14}" "${16}"
done
