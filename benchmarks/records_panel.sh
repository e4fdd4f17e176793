#!/usr/bin/env bash
# The work-precision records panel (issue 22; benchmarks/README.md, "Work against precision under
# records"), all peers in one run:
#  - theta error: the 12 runs of benchmarks/records_peers.csv, rocksweep at --tolerance 1e-6..1e-10,
#    the paper's fixed-step RK4 at dt 0.0025 s / 1, 2, 4, 8, 16 and the scipy script
#    (records_peers.py) at rtol 1e-4..1e-10 with atol = rtol / 1000 (its peer's 1e-6 / 1e-9),
#    timed in ROUNDS interleaved rounds, against the records peers' tight reference;
#  - wrong outcomes: the slice of the shared suite at the S. Matteo block's own size
#    (configs/records_suite.csv, 30 PGA levels, free / constant / adaptive: 1 080 cells, one
#    round), against --tolerance 1e-12 (cells where 1e-11 disagrees left out as sensitive);
#    the scipy script on a subset it can run (free and constant, the 10 two-column records,
#    every fifth level: 120 cells) at rtol 1e-4, 1e-6, 1e-8.
#   benchmarks/records_panel.sh [ROUNDS]    (default 4; about 6 min on a loaded 2-core machine)
# Writes benchmarks/results/records_panel.csv and records_panel.txt; the figure:
#   /usr/bin/python3 benchmarks/plot_records_panel.py benchmarks/results/records_panel.csv docs/figures/records_work_precision
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" records_peers suite_peers
rounds="${1:-4}"
py=/usr/bin/python3  # Debian's, with numpy and scipy
tmp="$(mktemp -d)"
rtols=(1e-4 1e-5 1e-6 1e-7 1e-8 1e-9 1e-10)
echo "[records_panel.sh] raw files in $tmp" >&2
log() { echo "[records_panel.sh $(date -u +%H:%M:%S)] $*, load $(cut -d' ' -f1 /proc/loadavg)" >&2; }

# theta error: histories of every setting (the reference pair included), then timed rounds.
log "records: histories"
build/benchmarks/records_peers histories --out "$tmp"
echo "round,label,runs,passes,wall_s,cpu_s" >"$tmp/records_peers_timing.csv"
for ((r = 1; r <= rounds; r++)); do
  log "records: round $r of $rounds"
  for rt in "${rtols[@]}"; do
    "$py" benchmarks/records_peers.py --out "$tmp" --rtol "$rt" --atol "$(awk -v r="$rt" 'BEGIN {print r / 1000}')" \
      --label "scipy_rtol$rt" | sed "s/^/$r,/" >>"$tmp/records_peers_timing.csv"
  done
  build/benchmarks/records_peers time --min-seconds 1 | sed "s/^/$r,/" >>"$tmp/records_peers_timing.csv"
done

# wrong outcomes over the suite slice: one pass per setting on one thread, one lane.
suite() { build/benchmarks/suite_peers --radii 1 --lanes 1 --cells "$tmp/suite_$1.cells" "${@:2}" | sed "s/^/$1 /"; }
log "suite: references and rocksweep"
{
  suite reference --setting tolerance --tolerance 1e-12
  suite check --setting tolerance --tolerance 1e-11
  for t in 1e-6 1e-7 1e-8 1e-9 1e-10; do suite "tol$t" --setting tolerance --tolerance "$t"; done
  log "suite: the paper's method"
  for k in 1 2 4 8 16; do
    dt="$(awk -v k="$k" 'BEGIN {printf "%.6g", 0.0025 / k}')"
    suite "paper_dt$dt" --setting paper --paper-dt "$dt"
  done
} >"$tmp/suite_timing.txt"
log "suite: scipy"
"$py" benchmarks/records_panel.py scipy-suite configs/records_suite.csv "$tmp/scipy_suite.csv"
for rt in 1e-4 1e-6 1e-8; do
  "$py" benchmarks/records_peers.py --suite "$tmp/scipy_suite.csv" --out "$tmp" --rtol "$rt" --atol "$(awk -v r="$rt" 'BEGIN {print r / 1000}')" --settle 1e-3 \
    --label "suite_scipy_rtol$rt" >>"$tmp/suite_scipy_timing.csv"
done
log "collecting"
{
  echo "benchmarks/records_panel.sh $rounds, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)),"
  echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg); rocksweep $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo
  "$py" benchmarks/records_panel.py collect "$tmp" "$out/records_panel.csv"
} | tee "$out/records_panel.txt"
# Kept when anything above failed (set -e stops before this line): the raw files, to collect again.
rm -rf "$tmp"
