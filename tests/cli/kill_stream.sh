#!/usr/bin/env bash
# kill_stream.sh ROCKSWEEP CONFIG WORKDIR NP [REFINE]
# The streaming writer under SIGKILL: checkpoints every 0.1 s (the shortest allowed, so that kills land in or
# near one), killed at many instants (two from the start, s0.05 and s0.12, before or about the first checkpoint,
# the rest after the output first appears: kill_job.sh); each time a reader must open the file while the sweep runs
# and after the kill, and --resume must end with result datasets bitwise those of an
# uninterrupted run (h5diff without /provenance). REFINE (a stride) kills a refined sweep.
set -eu
rs="$1"; cfg="$2"; dir="$3"; np="$4"; refine="${5:-0}"
source "$(dirname "${BASH_SOURCE[0]}")/kill_job.sh"
rm -rf "$dir"; mkdir -p "$dir"
grid=(--anchorages free constant --theta-f-ratios 1 0.5 --omega-ratio-points 160 --amplitude-ratio-points 120
      --quiet --checkpoint-interval 0.1 --chunk 32)
[ "$refine" -gt 0 ] && grid+=(--refine "$refine")
run=("$rs")
if [ "$np" -gt 1 ]; then
  run=(mpirun --oversubscribe -np "$np"); [ "$(id -u)" -eq 0 ] && run+=(--allow-run-as-root); run+=("$rs")
fi
ref="$dir/ref.h5"
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$ref"
partial=0; read_while_running=0
for delay in s0.05 s0.12 0 0.03 0.07 0.12 0.18 0.26 0.36 0.5; do
  out="$dir/killed-$delay.h5"
  "${run[@]}" sweep --config "$cfg" "${grid[@]}" -o "$out" &
  pid=$!
  case "$delay" in
    s*) sleep "${delay#s}" ;;
    *) wait_for_output "$pid" "$out"; sleep "$delay" ;;
  esac
  # A reader while the sweep runs: the file (once published) opens and its done column reads.
  if [ -f "$out" ] && h5dump -d /spectra/free/done "$out" >/dev/null 2>&1; then read_while_running=$((read_while_running + 1)); fi
  kill_job "$pid" "$out"
  if [ -f "$out" ]; then
    h5dump -d /spectra/free/done "$out" >/dev/null || { echo "killed at $delay s: the file does not read"; exit 1; }
    h5dump -a /complete "$out" | grep -q "(0): 0" && partial=$((partial + 1))
  fi
  "${run[@]}" sweep --config "$cfg" "${grid[@]}" -o "$out" --resume
  h5diff --exclude-path /provenance "$ref" "$out" || { echo "resumed after a kill at $delay s differs"; exit 1; }
  [ ! -e "$out.tmp" ] || { echo "killed at $delay s: $out.tmp left after the resume"; exit 1; }
done
[ "$partial" -ge 2 ] || { echo "only $partial kills left a partial file: the sweep is too short to test resume"; exit 1; }
echo "kill and resume on $np rank(s): identical ($partial partial files resumed, $read_while_running read while running)"
