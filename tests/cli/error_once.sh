#!/usr/bin/env bash
# error_once.sh ROCKSWEEP CONFIG: a config error under mpirun is printed once, exit status non-zero.
set -u
rs="$1"; cfg="$2"
mpi=(mpirun --oversubscribe -np 3); [ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
err=$("${mpi[@]}" "$rs" sweep --config "$cfg" --mass 0 -o /tmp/rocksweep_error_once.h5 2>&1 >/dev/null); status=$?
echo "$err"
[ "$status" -ne 0 ] || { echo "exit status 0"; exit 1; }
[ "$(grep -c "rocksweep: error: --mass = 0 is invalid" <<<"$err")" -eq 1 ] || { echo "not printed exactly once"; exit 1; }
[ ! -e /tmp/rocksweep_error_once.h5 ] || { echo "output written"; exit 1; }
echo ok
