#!/usr/bin/env bash
# RK4 steps across a record's samples: the research prototype of benchmarks/RECORD_STEPS.md, on the
# runs of benchmarks/records_peers.csv, against the records peers' tight reference and beside the
# engine's paper method (and events48/384) timed in the same process.
#   benchmarks/record_steps.sh [ROUNDS] [MIN_SECONDS]   (defaults 5 and 0.1: ~40 s of CPU in all)
# Writes benchmarks/results/record_steps_ref/ (the reference pair, from `records_peers histories`)
# and benchmarks/results/record_steps.txt (the table).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" records_peers record_steps
rounds="${1:-5}"
min_s="${2:-0.1}"
ref="$out/record_steps_ref"
mkdir -p "$ref"
build/benchmarks/records_peers histories --out "$ref" 2>/dev/null
{
  echo "benchmarks/record_steps.sh $rounds $min_s, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)),"
  echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg); rocksweep $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo
  build/benchmarks/record_steps --ref "$ref" --rounds "$rounds" --min-seconds "$min_s" 2>/dev/null
  echo
  echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
} | tee "$out/record_steps.txt"
