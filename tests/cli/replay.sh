#!/usr/bin/env bash
# replay.sh ROCKSWEEP DIR COMMAND ARGS...: run COMMAND (sweep or simulate) with ARGS, then again
# from nothing but the output's own stored config (/provenance/config, a history's `config`
# attribute) with --config. The result datasets must be bitwise the same (h5diff, /provenance
# aside), and the replay must store the very same config text: it is a fixed point.
set -u
rs="$1"; dir="$2"; cmd="$3"; shift 3
rm -rf "$dir"; mkdir -p "$dir"; cd "$dir" || exit 1

stored_config() {  # FILE.h5 OUT.toml
    /usr/bin/python3 - "$1" "$2" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    text = (f["provenance"] if "provenance" in f else f).attrs["config"]
open(sys.argv[2], "w").write(text.decode() if isinstance(text, bytes) else text)
PY
}

"$rs" "$cmd" "$@" -o first.h5 --quiet || { echo "first run failed"; exit 1; }
stored_config first.h5 first.toml || exit 1
cat first.toml
if grep -n '= ""' first.toml; then echo "an unset option was written"; exit 1; fi
"$rs" "$cmd" --config first.toml -o replay.h5 --quiet || { echo "replay from first.toml failed"; exit 1; }
stored_config replay.h5 replay.toml || exit 1
cmp first.toml replay.toml || { diff first.toml replay.toml; echo "the replay stored another config"; exit 1; }
h5diff --exclude-path /provenance first.h5 replay.h5 || { echo "result datasets differ"; exit 1; }
echo ok
