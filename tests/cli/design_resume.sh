#!/usr/bin/env bash
# design_resume.sh ROCKSWEEP CONFIG WORKDIR
# A design stopped between rounds (its later round files and its output missing, as after a
# kill) and one stopped inside a round by SIGINT both end, with --resume, in exactly the
# design file of an uninterrupted run. An existing output is refused without --resume, as is a
# fresh design over an unfinished one (named by its output); a finished design leaves no round
# files; a resume with other options names the option. A refined design reads its rounds back,
# and resumes only with the same refinement.
set -u
rs="$1"; cfg="$2"; dir="$3"
rm -rf "$dir"; mkdir -p "$dir"
small=(--omega-ratio-points 9 --amplitude-ratio-points 11 --coarse-points 5 --rounds 2 --quiet)
fail() { echo "$1"; exit 1; }
"$rs" design --config "$cfg" "${small[@]}" -o "$dir/ref.h5" || fail "reference run failed"

msg=$("$rs" design --config "$cfg" "${small[@]}" -o "$dir/ref.h5" 2>&1); status=$?
[ "$status" -eq 2 ] || fail "an existing output: status $status, expected 2"
grep -q -- "--output = .*ref.h5 is invalid: a new file; it exists: pass --resume" <<<"$msg" || fail "message: $msg"

# A finished design removes its round files: nothing of them is left to resume (issue 21).
for r in 0 1 2; do [ ! -e "$dir/ref.round$r.h5" ] || fail "ref.round$r.h5 left by a finished design"; done
loud=(--omega-ratio-points 9 --amplitude-ratio-points 11 --coarse-points 5 --rounds 2)
msg=$("$rs" design --config "$cfg" "${loud[@]}" -o "$dir/ref.h5" --resume 2>&1) || fail "resume of a finished design: $msg"
grep -q "ref.h5: design already complete; nothing to do" <<<"$msg" || fail "message: $msg"
msg=$("$rs" design --config "$cfg" "${small[@]}" -o "$dir/ref.h5" --resume --strength-ratio 0.5 2>&1); status=$?
[ "$status" -eq 2 ] || fail "resume of a finished design with another --strength-ratio: status $status"
grep -q -- "--strength-ratio = 0.5 is invalid: 0.4, as .*ref.h5 was computed with" <<<"$msg" || fail "message: $msg"

# --keep-rounds keeps them, and they are the rounds' spectra the design was scored on.
"$rs" design --config "$cfg" "${small[@]}" --keep-rounds -o "$dir/kept.h5" || fail "design --keep-rounds failed"
h5diff --exclude-path /provenance "$dir/ref.h5" "$dir/kept.h5" || fail "--keep-rounds changed the design"
for r in 0 1 2; do [ -e "$dir/kept.round$r.h5" ] || fail "kept.round$r.h5 not kept"; done

# Stopped after round 0: a directory in round 1's place makes it fail there, round 0 kept.
mkdir "$dir/cut.round1.h5"
"$rs" design --config "$cfg" "${small[@]}" -o "$dir/cut.h5" 2>/dev/null && fail "round 1 in a directory's place ran"
rmdir "$dir/cut.round1.h5"
[ -e "$dir/cut.round0.h5" ] && [ ! -e "$dir/cut.h5" ] || fail "an unfinished design must keep round 0 and write no design"
# A fresh design to the same output is refused in the words the user wrote (its output).
msg=$("$rs" design --config "$cfg" "${small[@]}" -o "$dir/cut.h5" 2>&1); status=$?
[ "$status" -eq 2 ] || fail "fresh design over an unfinished one: status $status"
grep -q -- "--output = .*cut.h5 is invalid: a new design; an unfinished design for it left .*cut.round0.h5: pass --resume" <<<"$msg" ||
  fail "message: $msg"
# Resumed with another --strength-ratio: the option is named with both values.
msg=$("$rs" design --config "$cfg" "${small[@]}" -o "$dir/cut.h5" --resume --strength-ratio 0.5 2>&1); status=$?
[ "$status" -eq 2 ] || fail "resume with another --strength-ratio: status $status"
grep -q -- "--strength-ratio = 0.5 is invalid: 0.4, as .*cut.round0.h5 was computed with" <<<"$msg" || fail "message: $msg"
"$rs" design --config "$cfg" "${small[@]}" -o "$dir/cut.h5" --resume --chunk 7 --lanes 4 --checkpoint-interval 3 ||
  fail "resume after round 0 (other chunks, lanes and checkpoints: results unchanged) failed"
h5diff --exclude-path /provenance "$dir/ref.h5" "$dir/cut.h5" || fail "resumed design differs"
[ ! -e "$dir/cut.round0.h5" ] || fail "round files left by the resumed design"

# SIGINT inside round 0 of a larger grid: exit 130, rounds kept, then --resume.
big=(--omega-ratio-points 80 --amplitude-ratio-points 80 --coarse-points 3 --rounds 0 --quiet --checkpoint-interval 0.2)
"$rs" design --config "$cfg" "${big[@]}" -o "$dir/big_ref.h5" || fail "big reference failed"
"$rs" design --config "$cfg" "${big[@]}" -o "$dir/big.h5" & pid=$!
for _ in $(seq 200); do [ -e "$dir/big.round0.h5.lock" ] && break; sleep 0.02; done
sleep 0.3
kill -INT "$pid"; wait "$pid"; status=$?
[ "$status" -eq 130 ] || [ "$status" -eq 0 ] || fail "SIGINT: status $status, expected 130 (or 0 if it had finished)"
[ ! -e "$dir/big.h5" ] || [ "$status" -eq 0 ] || fail "a design file was written by a stopped run"
"$rs" design --config "$cfg" "${big[@]}" -o "$dir/big.h5" --resume || fail "resume after SIGINT failed"
h5diff --exclude-path /provenance "$dir/big_ref.h5" "$dir/big.h5" || fail "design resumed after SIGINT differs"
sigint_status=$status

# Refined rounds: each round file records the refinement, the design reads them back with it.
mkdir "$dir/refined.round2.h5"
"$rs" design --config "$cfg" "${small[@]}" --refine 4 -o "$dir/refined.h5" 2>/dev/null && fail "round 2 in a directory's place ran"
rmdir "$dir/refined.round2.h5"
msg=$("$rs" design --config "$cfg" "${small[@]}" --refine 2 -o "$dir/refined.h5" --resume 2>&1); status=$?
[ "$status" -eq 2 ] || fail "resume with another --refine: status $status, expected 2"
grep -q -- "--refine = 2 is invalid: 4, as .*refined.round0.h5 was computed with" <<<"$msg" || fail "message: $msg"
"$rs" design --config "$cfg" "${small[@]}" --refine 4 -o "$dir/refined.h5" --resume || fail "refined resume failed"
echo "resumed designs identical (SIGINT status $sigint_status); a refined one resumed"
