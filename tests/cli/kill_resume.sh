#!/usr/bin/env bash
# kill_resume.sh ROCKSWEEP CONFIG WORKDIR [NP]
# SIGKILL a sweep at several moments; each time the file (if any) must open, and --resume
# must end with exactly the datasets of an uninterrupted run. The first kill comes 0.1 s after
# the start (s0.1), mostly before any checkpoint; the others at delays after the output first appears
# (kill_job.sh says why).
set -eu
rs="$1"; cfg="$2"; dir="$3"; np="${4:-1}"
source "$(dirname "${BASH_SOURCE[0]}")/kill_job.sh"
mkdir -p "$dir"
grid=(--anchorages free constant --theta-f-ratios 1 0.5 0.25 --omega-ratio-points 160 --amplitude-ratio-points 150
      --quiet --checkpoint-interval 0.2 --chunk 64)
run=("$rs")
if [ "$np" -gt 1 ]; then
  run=(mpirun --oversubscribe -np "$np")
  [ "$(id -u)" -eq 0 ] && run+=(--allow-run-as-root)
  run+=("$rs")
fi
ref="$dir/ref.h5"
rm -f "$ref"
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$ref"
partial=0
for delay in s0.1 0 0.4; do
  out="$dir/killed-$delay.h5"
  rm -f "$out" "$out.tmp"
  "${run[@]}" sweep --config "$cfg" "${grid[@]}" -o "$out" &
  pid=$!
  if [ "$delay" = s0.1 ]; then sleep 0.1; else wait_for_output "$pid" "$out"; sleep "$delay"; fi
  kill_job "$pid" "$out"
  if [ -f "$out" ]; then
    h5ls -r "$out" >/dev/null || { echo "killed at $delay s: file does not open"; exit 1; }
    n_done=$(h5dump -a /n_done "$out" | sed -n 's/.*(0): *//p')
    echo "killed at $delay s: $n_done of $(h5dump -a /n_cells "$out" | sed -n 's/.*(0): *//p') cells saved"
    h5dump -a /complete "$out" | grep -q "(0): 0" && partial=$((partial + 1))
  else
    echo "killed at $delay s: no checkpoint yet"
  fi
  rm -f "$out.tmp"
  "${run[@]}" sweep --config "$cfg" "${grid[@]}" -o "$out" --resume
  h5diff --exclude-path /provenance "$ref" "$out" || { echo "resumed after a kill at $delay s differs"; exit 1; }
done
[ "$partial" -ge 1 ] || { echo "no kill left a partial file: the sweep is too short to test resume"; exit 1; }
echo "kill and resume: identical ($partial partial files resumed)"
