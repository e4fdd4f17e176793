#!/usr/bin/env bash
# Peers on recorded ground motions, side by side in one run (benchmarks/README.md, "Peers on
# recorded ground motions"): rocksweep's events method (the sweep's and simulate's defaults),
# the paper's fixed-step RK4 (dt 0.0025 s) and a scipy solve_ivp script (RK45, rtol 1e-6), on the
# runs of benchmarks/records_peers.csv, against a tight reference.
#   benchmarks/records_peers.sh [ROUNDS]     (default 3; about 20 s of CPU a round)
# Writes benchmarks/results/records_peers_*.csv (histories, outcomes, timings) and
# benchmarks/results/records_peers.txt (the table).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" records_peers
rounds="${1:-3}"
py=/usr/bin/python3  # Debian's, with numpy and scipy

# Accuracy: the reference pair and rocksweep's histories (not timed), then the scipy peer at a
# tight tolerance, which checks that it integrates the same equations as rocksweep.
build/benchmarks/records_peers histories --out "$out"
"$py" benchmarks/records_peers.py --out "$out" --rtol 1e-11 --atol 1e-13 --settle 1e-8 --label scipy_tight >/dev/null

# Speed: the peers alternate, round after round, so that a load change hits them alike; the
# table takes each round's ratios. The scipy peer rewrites its histories every round (same values).
timing="$out/records_peers_timing.csv"
echo "round,label,runs,passes,wall_s,cpu_s" >"$timing"
loads=""
for ((r = 1; r <= rounds; r++)); do
  loads+=" $(cut -d' ' -f1 /proc/loadavg)"
  echo "[records_peers.sh] round $r of $rounds, load $(cut -d' ' -f1-3 /proc/loadavg)" >&2
  "$py" benchmarks/records_peers.py --out "$out" | sed "s/^/$r,/" >>"$timing"
  build/benchmarks/records_peers time --min-seconds 1 | sed "s/^/$r,/" >>"$timing"
done
{
  echo "benchmarks/records_peers.sh $rounds, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)),"
  echo "load average at the start of each round:$loads; rocksweep $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo
  "$py" benchmarks/records_peers_table.py "$out"
} | tee "$out/records_peers.txt"
