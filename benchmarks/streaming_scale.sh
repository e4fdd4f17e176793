#!/usr/bin/env bash
# streaming_scale.sh ROCKSWEEP [WORKDIR] [SIZES] [CHECKPOINT_S]
# Rank-0 peak memory and checkpoint cost of `rocksweep sweep` against the cell count, on 2 ranks:
# the free spectrum of configs/smatteo.toml with the omega and amplitude axes grown to about
# SIZES cells (default "1e5 1e6 1e7"; a 1e7 run takes 2-3 min on 2 cores). Prints one table row
# per run: cells, wall [s], cells/s, checkpoint seconds and share of the wall (from
# /provenance/checkpoint_s, absent in files of rocksweep before the streaming writer), rank 0's
# VmHWM [MiB] (sampled from /proc every 0.2 s), file size [MB].
# ROCKSWEEP may be another build (e.g. main's, for the before/after table); CHECKPOINT_S (default
# 5, rocksweep's) set to 86400 gives the run without checkpoints, for the wall ratio.
# The synthetic-cost runs up to 1e9 cells are benchmarks/streaming_synthetic.sh.
set -eu
rs="$1"; dir="${2:-/tmp/streaming_scale}"; sizes="${3:-1e5 1e6 1e7}"; every="${4:-5}"
here="$(cd "$(dirname "$0")" && pwd)"
cfg="$here/../configs/smatteo.toml"
mkdir -p "$dir"
runner=(mpirun --oversubscribe -np 2); [ "$(id -u)" -eq 0 ] && runner+=(--allow-run-as-root)

# Peak resident memory [MiB] of rank 0 of the mpirun job $1, until it ends.
rank0_hwm() {
  local job="$1" hwm=0 p v
  while kill -0 "$job" 2>/dev/null; do
    for p in $(pgrep -P "$job" 2>/dev/null); do
      if tr '\0' '\n' < "/proc/$p/environ" 2>/dev/null | grep -qx 'OMPI_COMM_WORLD_RANK=0'; then
        v=$(awk '/^VmHWM:/ {print $2}' "/proc/$p/status" 2>/dev/null || echo 0)
        [ -n "$v" ] && [ "$v" -gt "$hwm" ] && hwm=$v
      fi
    done
    sleep 0.2
  done
  echo $((hwm / 1024))
}

printf '| %-9s | %8s | %9s | %8s | %12s | %10s | %8s |\n' cells wall_s cells/s ckpt_s "ckpt % wall" "rank0 MiB" "file MB"
for n in $sizes; do
  side=$(python3 -c "import math; print(round(math.sqrt(float('$n'))))")
  out="$dir/scale-$n.h5"
  rm -f "$out" "$out.tmp"
  t0=$(date +%s.%N)
  "${runner[@]}" "$rs" sweep --config "$cfg" --anchorages free --omega-ratio-points "$side" \
    --amplitude-ratio-points "$side" --checkpoint-interval "$every" --quiet -o "$out" &
  job=$!
  hwm=$(rank0_hwm "$job")
  wait "$job"
  t1=$(date +%s.%N)
  /usr/bin/python3 - "$out" "$t0" "$t1" "$hwm" <<'PY'
import os, sys, h5py
path, t0, t1, hwm = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
with h5py.File(path, "r") as f:
    cells = int(f.attrs["n_cells"])
    p = f["provenance"].attrs
    wall = float(p["wall_s"])
    ck = float(p["checkpoint_s"]) if "checkpoint_s" in p else float("nan")
print(f"| {cells:9d} | {wall:8.1f} | {cells / wall:9.0f} | {ck:8.2f} | {100 * ck / wall:12.2f} | {hwm:>10} | "
      f"{os.path.getsize(path) / 1e6:8.1f} |")
PY
  rm -f "$out"
done
