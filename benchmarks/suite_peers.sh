#!/usr/bin/env bash
# suite_peers.sh [ROUNDS]: the whole shared suite (configs/suite_smatteo.toml's 8640 cells) on
# one thread per integrator setting -- the sweep default (error-controlled), the old fixed default, steps crossing the samples, the paper's
# method -- at 1 and 8 lanes, in interleaved rounds; the ratio to the paper's method within each
# round (median [min, max]), the RK4 steps, and the steps per record. The outcomes these settings
# get wrong over the same cells: benchmarks/records_outcomes.sh.
#   benchmarks/suite_peers.sh 3     -> benchmarks/results/suite_peers.txt  (about 2 min)
source "$(dirname "${BASH_SOURCE[0]}")/common.sh" suite_peers
rounds="${1:-3}"
settings=(events48 tolerance events48_cross paper)
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
field() { awk -v k="$1" '{for (i = 1; i < NF; ++i) if ($i == k) print $(i + 1)}'; }
{
  echo "benchmarks/suite_peers.sh $rounds, $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, rocksweep $(git rev-parse --short HEAD 2>/dev/null || echo '?')"
  echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
  for ((r = 1; r <= rounds; r++)); do
    for lanes in 1 8; do
      for s in "${settings[@]}"; do
        line="$(build/benchmarks/suite_peers --setting "$s" --lanes "$lanes")"
        echo "round $r: $line"
        echo "$r $lanes $s $(field seconds <<<"$line") $(field steps <<<"$line")" >>"$tmp/times"
      done
    done
  done
  echo
  echo "== cells per second per core, and x paper within a round: median [min, max] =="
  awk -v R="$rounds" '
    {t[$1, $2, $3] = $4; st[$3] = $5; L[$2] = 1; S[$3] = 1}
    function sort(a, n,   i, j, x) {for (i = 2; i <= n; i++) {x = a[i]; for (j = i - 1; j > 0 && a[j] > x; j--) a[j + 1] = a[j]; a[j + 1] = x}}
    function med(a, n) {return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2}
    END {
      printf "%-16s %5s %12s %22s %12s %10s\n", "setting", "lanes", "cells/s", "x paper", "RK4 steps", "x paper"
      for (l = 1; l <= 8; l += 7) for (s in S) {
        for (r = 1; r <= R; r++) {c[r] = 8640 / t[r, l, s]; q[r] = t[r, l, "paper"] / t[r, l, s]}
        sort(c, R); sort(q, R)
        printf "%-16s %5d %12.0f %8.2f [%5.2f, %5.2f] %12d %10.2f\n", s, l, med(c, R), med(q, R), q[1], q[R], st[s], st["paper"] / st[s]
      }
    }' "$tmp/times" | sort -k2,2n -k1,1
  echo
  echo "== RK4 steps per record (one run each, 8 lanes), and the paper's / this setting's =="
  for s in "${settings[@]}"; do build/benchmarks/suite_peers --setting "$s" --cells "$tmp/$s.cells" >/dev/null; done
  printf "%-28s %11s %11s %11s %9s %9s\n" record events48 cross paper "x events" "x cross"
  paste -d' ' "$tmp/events48.cells" "$tmp/events48_cross.cells" "$tmp/paper.cells" | awk '
    {a[$2] += $5; b[$2] += $10; p[$2] += $15; dt[$2] = 1}
    END {for (k in dt) printf "%-28s %11d %11d %11d %9.1f %9.1f\n", k, a[k], b[k], p[k], p[k] / a[k], p[k] / b[k]}' | sort
  echo
  echo "  events48        the sweep default before issue 22: events, 48 steps per period, every record sample ends a step"
  echo "  tolerance       the sweep default since issue 22: steps chosen from the error, --tolerance's default"
  echo "  events48_cross  the same with steps that cross the samples on moment nodes (--record-steps cross)"
  echo "  paper           the paper's method: fixed-step RK4, dt 0.0025 s, impact at the step end"
  echo "  Cells are computed in chunks of 64 as a rank gets them; only the computation is timed."
} | tee "$out/suite_peers.txt"
