#!/usr/bin/env bash
# expect_error.sh STATUS REGEX OUTPUT -- COMMAND...
# Runs COMMAND; passes if it exits with STATUS, its stderr matches REGEX (extended, on one
# line), and neither OUTPUT nor OUTPUT.tmp exists afterwards.
set -u
want_status="$1"; regex="$2"; output="$3"; shift 4
rm -f "$output" "$output.tmp"
err="$("$@" 2>&1 >/dev/null)"; status=$?
fail=0
if [ "$status" -ne "$want_status" ]; then echo "exit status $status, expected $want_status"; fail=1; fi
if ! grep -Eq -- "$regex" <<<"$err"; then echo "message does not match /$regex/"; fail=1; fi
if [ -e "$output" ] || [ -e "$output.tmp" ]; then echo "an output file was left: $output"; fail=1; fi
echo "--- stderr:"; echo "$err"
exit $fail
