#!/usr/bin/env bash
# resume_settings.sh ROCKSWEEP CONFIG DIR: --resume refuses a file computed with another value of
# any setting that shapes results (exit 2, one line naming the option, the given value and the
# file's), and leaves the file byte for byte as it was.
set -u
rs="$1"; cfg="$2"; dir="$3"
rm -rf "$dir"; mkdir -p "$dir"; out="$dir/partial.h5"
fail() { echo "FAIL: $*"; exit 1; }
grid=(--anchorages free --omega-ratio-points 4 --amplitude-ratio-points 3 --quiet)
"$rs" sweep --config "$cfg" "${grid[@]}" -o "$out" || fail "first sweep"
sum=$(md5sum < "$out")
n=0
check() {  # check REGEX OPTIONS...: --resume with OPTIONS must be refused with REGEX
  local regex="$1"; shift
  local err status
  err=$("$rs" sweep --config "$cfg" "${grid[@]}" "$@" -o "$out" --resume 2>&1 >/dev/null); status=$?
  echo "$* -> $err"
  [ "$status" -eq 2 ] || fail "$*: exit status $status, expected 2"
  [ "$(grep -c . <<<"$err")" -eq 1 ] || fail "$*: not one line"
  grep -Eq -- "$regex" <<<"$err" || fail "$*: message does not match /$regex/"
  [ "$(md5sum < "$out")" = "$sum" ] || fail "$*: the file changed"
  [ ! -e "$out.tmp" ] && [ ! -e "$out.lock" ] || fail "$*: tmp or lock left"
  n=$((n + 1))
}
tail="as $out was computed with \(--resume continues a file only with the settings that shaped its results\)"
check "^rocksweep: error: --method = paper is invalid: events, $tail" --method paper
check "^rocksweep: error: --steps-per-period = 96 is invalid: 48, $tail" --steps-per-period 96
check "^rocksweep: error: --max-steps = 5000 is invalid: 2000000, $tail" --max-steps 5000
check "^rocksweep: error: --no-energy-stop = given is invalid: not given, $tail" --no-energy-stop
check "^rocksweep: error: --record-steps = cross is invalid: samples, $tail" --record-steps cross
check "^rocksweep: error: --tolerance = 1e-0?7 is invalid: 1e-0?8, $tail" --tolerance 1e-7
check "^rocksweep: error: --impact-threshold = 0.002 is invalid: 0.001, $tail" --impact-threshold 0.002
check "^rocksweep: error: --equations = linearised is invalid: nonlinear, $tail" --equations linearised
check "^rocksweep: error: --pulse = ricker is invalid: one-sine, $tail" --pulse ricker
# Not only the integrator's: every option the file's /provenance/config records (issue 21). The
# friction coefficient is stored but no attribute check covers it; the others are each refused
# with the file named (by the file's own attribute checks where they exist, which speak first).
check "^rocksweep: error: --friction-coefficient = 0.6 is invalid: 0, $tail" --friction-coefficient 0.6
for opt in "--mass 3000" "--gravity 9.8" "--restitution 0.8" "--phase 0.5" "--vertical-amplitude 0.1" \
           "--vertical-phase 1" "--half-height 1.4" "--omega-ratio-range 1 9" "--amplitude-ratio-range 1 20"; do
  # shellcheck disable=SC2086
  check "^rocksweep: error: (${opt%% *} = .* is invalid: .*, as $out was computed with|.*$out is invalid: a file written for the same sweep)" $opt
done
# The paper's method: its step shapes results; --steps-per-period is then not asked for.
paper="$dir/paper.h5"
"$rs" sweep --config "$cfg" "${grid[@]}" --method paper -o "$paper" || fail "paper sweep"
sum_paper=$(md5sum < "$paper")
err=$("$rs" sweep --config "$cfg" "${grid[@]}" --method paper --paper-dt 0.001 -o "$paper" --resume 2>&1 >/dev/null); status=$?
echo "--method paper --paper-dt 0.001 -> $err"
[ "$status" -eq 2 ] || fail "paper-dt: exit status $status, expected 2"
grep -Eq -- "^rocksweep: error: --paper-dt = 0.001 is invalid: 0.0025, as $paper was computed with" <<<"$err" || fail "paper-dt: message"
[ "$(md5sum < "$paper")" = "$sum_paper" ] || fail "paper-dt: the file changed"
n=$((n + 1))
# Refinement chooses which cells are computed: a pass of another stride, or over other axes,
# would pick other cells. The pair counts in grid order, whichever order it was given in.
check "^rocksweep: error: --refine = 2 is invalid: not given, $tail" --refine 2
refined="$dir/refined.h5"
axis=(--axis restitution=0.8,0.9 --refine 2)
"$rs" sweep --config "$cfg" "${grid[@]}" "${axis[@]}" -o "$refined" || fail "refined sweep"
sum_refined=$(md5sum < "$refined")
refuse() {  # refuse REGEX OPTIONS...: resuming the refined file with OPTIONS is refused with REGEX
  local regex="$1"; shift
  local err status
  err=$("$rs" sweep --config "$cfg" "${grid[@]}" --axis restitution=0.8,0.9 "$@" -o "$refined" --resume 2>&1 >/dev/null); status=$?
  echo "$* -> $err"
  [ "$status" -eq 2 ] && [ "$(grep -c . <<<"$err")" -eq 1 ] || fail "$*: exit status $status or not one line"
  grep -Eq -- "^rocksweep: error: $regex, as $refined was computed with" <<<"$err" || fail "$*: message"
  [ "$(md5sum < "$refined")" = "$sum_refined" ] || fail "$*: the file changed"
  n=$((n + 1))
}
refuse "--refine = 4 is invalid: 2" --refine 4
refuse "--refine = not given is invalid: 2"
refuse "--refine-axes = restitution omega_ratio is invalid: amplitude_ratio omega_ratio" --refine 2 --refine-axes restitution omega_ratio
"$rs" sweep --config "$cfg" "${grid[@]}" "${axis[@]}" --refine-axes omega-ratio amplitude_ratio -o "$refined" --resume \
  || fail "the same pair in the other order refused"
# A file from before these were recorded: its samples ended steps; its refinement is unknown,
# so any is accepted.
before="$dir/before.h5"
cp "$refined" "$before"
/usr/bin/python3 -c "import h5py, sys
with h5py.File(sys.argv[1], 'r+') as f:
    for a in ('record_steps', 'refine_stride', 'refine_axes'): del f.attrs[a]" "$before" || fail "h5py"
err=$("$rs" sweep --config "$cfg" "${grid[@]}" --axis restitution=0.8,0.9 --record-steps cross -o "$before" --resume 2>&1 >/dev/null)
grep -Eq -- "^rocksweep: error: --record-steps = cross is invalid: samples, as $before" <<<"$err" || fail "old file, record-steps: $err"
"$rs" sweep --config "$cfg" "${grid[@]}" --axis restitution=0.8,0.9 --refine 8 -o "$before" --resume || fail "old file refused a refinement"
# Settings that do not change a bit (lanes, chunk) are free to differ; a number written otherwise
# (48.0 for 48) is the same number.
"$rs" sweep --config "$cfg" "${grid[@]}" --lanes 4 --chunk 3 --steps-per-period 48.0 -o "$out" --resume || fail "lanes/chunk refused"
echo "ok: $n settings refused"
