#!/usr/bin/env bash
# physics_split.sh OLD_BUILD [NEW_BUILD]: the system / event stepper / observers split of the
# kernel (issue 8), and the anchorage law as a type on it (anchorage_law.hpp), against another
# build (default NEW_BUILD: build/ of this tree). A refactor
# that only moves code must give the same bits, and inlining across the new headers must
# cost nothing; both are measured here rather than assumed.
#  1. bitwise: the runs below with both builds, h5diff of everything but /provenance and the root's
#     attributes (the run's description; newer builds add some, e.g. parameter_axes). The set
#     reaches every path the split touched: the full default sweep (constant, adaptive, free);
#     two more pulse families (Ricker's tails, cycloidal C's jump at t = 0); the linearised
#     equations (the linear branch of the shared right-hand side, base reactions, potentials);
#     an adaptive spring breaking past alpha (the energy decision's potential slope and first
#     maximum), the passive law and the force break rule; the paper's method; no energy stop;
#     histories of the sample case and of a record; a basin map.
#  2. instructions: callgrind on the reduced default sweep (46 x 53), as pulse_seam.sh (wall
#     time on a shared machine is noise; instruction counts are not). Twice: the whole program,
#     and only inside integrate_cells (--toggle-collect): the whole program's count moves by a
#     few percent from run to run with the machine's load (same binary: 3.06e9 to 4.06e9; some
#     work outside the kernel depends on time, not traced further), the kernel's does not.
# Skip a part with PHYSICS_SPLIT_SKIP=bitwise or =callgrind; PHYSICS_SPLIT_REUSE_OLD=1 keeps the
# old build's outputs of an earlier run.
set -euo pipefail
cd "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
old="$(cd "$1" && pwd)"
new="$(cd "${2:-build}" && pwd)"
out=benchmarks/results/physics_split
mkdir -p "$out/old" "$out/new"
skip="${PHYSICS_SPLIT_SKIP:-}"
reduced=(--omega-ratio-points 46 --amplitude-ratio-points 53)
cases=(
  "smatteo|sweep --config configs/smatteo.toml"
  "ricker|sweep --config configs/pulse_ricker.toml"
  "cycloidal_c|sweep --config configs/pulse_cycloidal_c.toml"
  "linearised|sweep --config configs/smatteo.toml ${reduced[*]} --equations linearised"
  "adaptive_break_past_alpha|sweep --config configs/paper_adaptive.toml ${reduced[*]} --adaptive-theta-f-ratio 2 --kmin-ratios 0.1"
  "passive_force|sweep --config configs/paper_adaptive.toml ${reduced[*]} --adaptive-law passive --adaptive-break force"
  "paper_method|sweep --config configs/smatteo.toml ${reduced[*]} --method paper"
  "no_energy_stop|sweep --config configs/paper_constant.toml ${reduced[*]} --no-energy-stop"
  "vertical|sweep --config configs/smatteo.toml ${reduced[*]} --vertical-amplitude 0.3 --vertical-phase 1"
  "hist_free|simulate --config configs/smatteo.toml --anchorage free"
  "hist_constant|simulate --config configs/smatteo.toml --anchorage constant"
  "hist_adaptive|simulate --config configs/smatteo.toml --anchorage adaptive --kmin-ratio 0.1"
  "hist_record|simulate --record tests/data/elcentro_1940_NS.dat --record-units g --anchorage adaptive --kmin-ratio 0.1"
  "hist_record_constant|simulate --record tests/data/elcentro_1940_NS.dat --record-units g --record-scale 2 --anchorage constant --theta-f-ratio 0.5"
  "basin|basin --config configs/basin.toml --theta-ratio-points 41 --theta-dot-ratio-points 41"
)
if [[ "$skip" != *bitwise* ]]; then
  n_equal=0; n_diff=0
  for c in "${cases[@]}"; do
    name="${c%%|*}"; args="${c#*|}"
    # shellcheck disable=SC2086
    [ "${PHYSICS_SPLIT_REUSE_OLD:-0}" = 1 ] && [ -f "$out/old/$name.h5" ] ||
      "$old/rocksweep" $args --quiet --overwrite -o "$out/old/$name.h5"
    # shellcheck disable=SC2086
    "$new/rocksweep" $args --quiet --overwrite -o "$out/new/$name.h5"
    if h5diff --exclude-path /provenance --exclude-attribute / "$out/old/$name.h5" "$out/new/$name.h5" >/dev/null 2>&1; then
      echo "$name ($args): bitwise equal"; n_equal=$((n_equal + 1))
    else
      echo "$name ($args): DIFFER (h5diff -v --exclude-path /provenance --exclude-attribute / $out/old/$name.h5 $out/new/$name.h5)"
      n_diff=$((n_diff + 1))
    fi
  done
  echo "bitwise: $n_equal equal, $n_diff differ"
fi
if [[ "$skip" != *callgrind* ]]; then
  sweep=(sweep --config configs/smatteo.toml "${reduced[@]}" --quiet --overwrite)
  count() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 | awk '/Collected/ {print $4}'; }
  for scope in program integrate_cells; do
    opt=(); [ "$scope" = integrate_cells ] && opt=(--toggle-collect='*integrate_cells*')
    n_old=$(count "${opt[@]}" "$old/rocksweep" "${sweep[@]}" -o "$out/cg_old.h5")
    n_new=$(count "${opt[@]}" "$new/rocksweep" "${sweep[@]}" -o "$out/cg_new.h5")
    echo "instructions, $scope (${sweep[*]}): old $n_old, new $n_new, ratio $(awk -v a="$n_new" -v b="$n_old" 'BEGIN {printf "%.4f", a / b}')"
  done
fi
