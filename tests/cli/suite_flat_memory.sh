#!/usr/bin/env bash
# suite_flat_memory.sh ROCKSWEEP CONFIG RECORD DIR: rank 0 of `suite` holds the cells finished
# since its last checkpoint, not the suite's results (docs/streaming.md). A 10^8-run suite (one
# record x 1000 block sizes x 100 000 levels: 4.5 GB of results if rank 0 held them) is started,
# read by h5py while it runs (the running file opens and counts its cells), stopped by SIGINT
# after a few checkpoints, then resumed and stopped the same way. Each run's peak resident
# memory must stay under 300 MB, and every cell the file counts done must hold its values.
# Last, --overwrite of a finished file leaves it as it was until the new run's first checkpoint.
set -u
rs="$1"; cfg="$2"; record="$3"; dir="$4"
source "$(dirname "${BASH_SOURCE[0]}")/kill_job.sh"
rm -rf "$dir"; mkdir -p "$dir"
fail() { echo "FAIL: $*"; exit 1; }
limit_kb=$((300 * 1024))
printf 'name,file,format,units\nloma,%s,time_accel,m/s^2\n' "$record" > "$dir/one.csv"
{ echo "name,file,format,units"; for i in $(seq -w 0 999); do echo "loma$i,$record,time_accel,m/s^2"; done; } > "$dir/many.csv"
out="$dir/big.h5"
base=(suite --config "$cfg" --suite "$dir/many.csv" --anchorages free --intensity-points 100
      --radius-range 0.5 3 --radius-points 1000 -o "$out")
args=("${base[@]}" --checkpoint-interval 0.2)

# run_and_stop NAME [OPTION...]: the suite under /usr/bin/time, read while it runs, then SIGINT.
run_and_stop() {
  local name="$1"; shift
  /usr/bin/time -f "%M" -o "$dir/$name.rss" "$rs" "${args[@]}" "$@" > "$dir/$name.log" 2>&1 &
  local pid=$!
  wait_for_output "$pid" "$out"
  # Past the start-up (a resumed file exists from the first instant): a background job of a
  # script starts with SIGINT ignored until rocksweep installs its handler, before it says this.
  for ((i = 0; i < 600; i++)); do grep -Eq "cells already done|cells \(" "$dir/$name.log" && break; sleep 0.05; done
  sleep 0.5
  /usr/bin/python3 - "$out" <<'PY' || fail "$name: the running file does not open"
import sys, time, h5py
for _ in range(100):  # a checkpoint with runs in it: within 10 s even on a loaded machine
    with h5py.File(sys.argv[1], "r") as f:
        assert f.attrs["n_cells"] == 10**8 and f.attrs["complete"] == 0, dict(f.attrs)
        assert f["suite/free/done"].shape == (1000, 1, 1000, 100)
        if f.attrs["n_done"] > 0:
            break
    time.sleep(0.1)
else:
    raise SystemExit("no run counted done in the running file")
PY
  pkill -INT -P "$pid"
  wait "$pid"
  local status=$?
  [ "$status" -eq 130 ] || { cat "$dir/$name.log"; fail "$name: exit status $status after SIGINT, not 130"; }
  grep -q "rerun with --resume to continue" "$dir/$name.log" || { cat "$dir/$name.log"; fail "$name: no resume hint"; }
  local kb
  kb=$(tail -n 1 "$dir/$name.rss")
  echo "$name: peak RSS $((kb / 1024)) MB (limit $((limit_kb / 1024)) MB)"
  [ "$kb" -lt "$limit_kb" ] || fail "$name: peak RSS ${kb} KB: rank 0 holds the results, not only the pending cells"
}

run_and_stop first
run_and_stop resumed --resume
grep -q "resuming" "$dir/resumed.log" || { cat "$dir/resumed.log"; fail "the second run did not resume"; }
/usr/bin/python3 - "$out" <<'PY' || fail "the stopped file"
import sys, h5py, numpy as np
with h5py.File(sys.argv[1], "r") as f:
    g = f["suite/free"]
    done = g["done"][:, 0]
    n = int(np.count_nonzero(done))
    assert n == f.attrs["n_done"] and f.attrs["complete"] == 0, (n, dict(f.attrs))
    rot = g["max_rotation"][:, 0][done != 0]
    assert np.all(np.isfinite(rot)) and np.all(rot >= 0), "a cell counted done without its values"
    print(f"{n} runs done of 10^8 after two stops; file {f.id.get_filesize() / 1e6:.0f} MB apparent")
PY

# --overwrite: the previous file stays whole until the new run has something to show.
"$rs" suite --config "$cfg" --suite "$dir/one.csv" --anchorages free --intensity-points 4 --quiet -o "$out" --overwrite ||
  fail "small suite"
sum=$(md5sum < "$out")
"$rs" "${base[@]}" --overwrite --checkpoint-interval 60 > "$dir/overwrite.log" 2>&1 &
pid=$!
for ((i = 0; i < 300; i++)); do [ -f "$out.tmp" ] && break; sleep 0.05; done
[ -f "$out.tmp" ] || fail "--overwrite: no $out.tmp while the new run starts"
sleep 0.5
[ "$(md5sum < "$out")" = "$sum" ] || fail "--overwrite replaced the previous file before the first checkpoint"
kill -INT "$pid"
wait "$pid"
[ ! -e "$out.tmp" ] || fail "--overwrite: $out.tmp left after SIGINT"
h5dump -a /n_cells "$out" | grep -q "(0): 100000000$" || fail "--overwrite: SIGINT did not save the new run"
rm -f "$out"
echo "suite rank-0 memory flat at 10^8 runs; --overwrite keeps the previous file until a checkpoint"
