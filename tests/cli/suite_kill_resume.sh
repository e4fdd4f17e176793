#!/usr/bin/env bash
# suite_kill_resume.sh ROCKSWEEP CONFIG SUITE WORKDIR NP [OPTION...]
# SIGKILL a suite sweep at several moments; each time the file (if any) must open, and
# --resume must end with exactly the datasets of an uninterrupted run. The kills come at fixed
# delays after the output file first appears (its first checkpoint), not after the start, so
# that a faster engine or a slower MPI start does not move them past the run's end: 64 levels,
# about 3 s on one rank. SUITE "-": no CSV; the OPTIONs (synthetic motions, floors, measures)
# are added to every run; LEVELS and RADII in the environment replace the 64 levels and 4 sizes
# (many motions need fewer).
set -eu
rs="$1"; cfg="$2"; suite="$3"; dir="$4"; np="$5"; shift 5  # the rest: options added to every run
source "$(dirname "${BASH_SOURCE[0]}")/kill_job.sh"
mkdir -p "$dir"
source_args=(--suite "$suite")
[ "$suite" = - ] && source_args=()
args=(suite --config "$cfg" "${source_args[@]}" --anchorages free constant adaptive --theta-f-ratios 1 --kmin-ratios 0.1
      --intensity-points "${LEVELS:-64}" --radius-range 0.6 3 --radius-points "${RADII:-4}" --steps-per-period 96 --quiet
      --checkpoint-interval 0.2
      "$@")
run=("$rs")
if [ "$np" -gt 1 ]; then
  run=(mpirun --oversubscribe -np "$np")
  [ "$(id -u)" -eq 0 ] && run+=(--allow-run-as-root)
  run+=("$rs")
fi
ref="$dir/ref.h5"
rm -f "$ref"
"$rs" "${args[@]}" -o "$ref"
partial=0
for delay in 0 0.3 0.8; do
  out="$dir/killed-$delay.h5"
  rm -f "$out" "$out.tmp"
  "${run[@]}" "${args[@]}" -o "$out" &
  pid=$!
  wait_for_output "$pid" "$out"
  sleep "$delay"
  kill_job "$pid" "$out"
  if [ -f "$out" ]; then
    h5ls -r "$out" >/dev/null || { echo "killed at $delay s: file does not open"; exit 1; }
    h5dump -a /complete "$out" | grep -q "(0): 0" && partial=$((partial + 1))
  fi
  rm -f "$out.tmp"
  "${run[@]}" "${args[@]}" -o "$out" --resume
  h5diff --exclude-path /provenance "$ref" "$out" || { echo "resumed after a kill at $delay s differs"; exit 1; }
done
[ "$partial" -ge 1 ] || { echo "no kill left a partial file: the suite is too short to test resume"; exit 1; }
echo "suite kill and resume: identical ($partial partial files resumed)"
