#!/usr/bin/env bash
# output_claim.sh MODE ROCKSWEEP CONFIG DIR: the output is claimed before any computing.
#   tmp_dir    an existing directory NAME.tmp is refused (exit 2) and left alone
#   simulate   simulate keeps an existing file (its own config too) unless --overwrite
#   lock       a second sweep to an output being written fails at once (exit 2); the first
#              goes on undisturbed, and a SIGKILLed run leaves no lock blocking --resume
set -u
mode="$1"; rs="$2"; cfg="$3"; dir="$4"
rm -rf "$dir"; mkdir -p "$dir"
small=(--omega-ratio-points 3 --amplitude-ratio-points 3 --quiet)
fail() { echo "FAIL: $*"; exit 1; }
expect() {  # expect STATUS REGEX CMD...: runs CMD, checks its status and stderr
  local want="$1" regex="$2"; shift 2
  local err status
  err=$("$@" 2>&1 >/dev/null); status=$?
  echo "$err"
  [ "$status" -eq "$want" ] || fail "exit status $status, expected $want"
  grep -Eq -- "$regex" <<<"$err" || fail "message does not match /$regex/"
}
case "$mode" in
tmp_dir)
  out="$dir/out.h5"; mkdir "$out.tmp"; touch "$out.tmp/keep"
  expect 2 "^rocksweep: error: --output = $out is invalid: a name whose temporary file $out.tmp is free or a regular file" \
    "$rs" sweep --config "$cfg" "${small[@]}" -o "$out"
  [ -f "$out.tmp/keep" ] || fail "the directory $out.tmp was touched"
  [ ! -e "$out" ] && [ ! -e "$out.lock" ] || fail "output or lock left"
  ;;
simulate)
  out="$dir/history.h5"
  "$rs" simulate --config "$cfg" -q -o "$out" || fail "first simulate"
  sum=$(md5sum < "$out")
  expect 2 "^rocksweep: error: --output = $out is invalid: a new file; it exists: pass --overwrite to replace it" \
    "$rs" simulate --config "$cfg" -q -o "$out"
  [ "$(md5sum < "$out")" = "$sum" ] || fail "existing file changed"
  cp "$cfg" "$dir/own.toml"; sum=$(md5sum < "$dir/own.toml")
  expect 2 "--output = $dir/own.toml is invalid" \
    "$rs" simulate --config "$dir/own.toml" -q -o "$dir/own.toml"
  [ "$(md5sum < "$dir/own.toml")" = "$sum" ] || fail "the config was overwritten"
  "$rs" simulate --config "$cfg" -q -o "$out" --overwrite || fail "--overwrite refused"
  [ ! -e "$out.tmp" ] && [ ! -e "$out.lock" ] || fail "tmp or lock left"
  ;;
lock)
  out="$dir/out.h5"
  # ~2.5 s of cells: the first run still computes when the second has started up.
  slow=(--anchorages free --omega-ratio-points 2 --amplitude-ratio-points 2 --steps-per-period 100000
        --no-energy-stop --quiet)
  "$rs" sweep --config "$cfg" "${slow[@]}" -o "$out" 2>"$dir/first.txt" & pid=$!
  for _ in $(seq 1 300); do [ -e "$out.lock" ] && break; sleep 0.02; done  # claimed
  expect 2 "^rocksweep: error: --output = $out is invalid: an output no other run is writing \(another rocksweep holds $out.lock\)" \
    "$rs" sweep --config "$cfg" "${slow[@]}" -o "$out" --overwrite
  kill -0 "$pid" 2>/dev/null || fail "the first sweep ended before the second was refused: too fast a test"
  wait "$pid" || fail "the first sweep failed"
  h5dump -a /complete "$out" | grep -q "(0): 1" || fail "first sweep incomplete"
  [ ! -e "$out.lock" ] && [ ! -e "$out.tmp" ] || fail "lock or tmp left after a finished run"
  # A SIGKILLed run leaves its lock file, but no lock: --resume goes ahead at once.
  rm -f "$out"
  "$rs" sweep --config "$cfg" "${slow[@]}" --checkpoint-interval 0.1 -o "$out" 2>"$dir/killed.txt" & pid=$!
  for _ in $(seq 1 300); do [ -e "$out.lock" ] && break; sleep 0.02; done
  kill -KILL "$pid"; wait "$pid" 2>/dev/null
  [ -e "$out.lock" ] || fail "expected the killed run's lock file to stay"
  "$rs" sweep --config "$cfg" "${slow[@]}" -o "$out" --resume || fail "--resume after SIGKILL refused"
  ;;
*) fail "unknown mode $mode" ;;
esac
echo ok
