# Sourced by the benchmark scripts: builds the given targets (Release, build/), goes to the
# repository root, and provides `out` (results folder), `mpi` (mpirun with the flags this
# machine needs; add -np N) and `wall CMD...` (wall seconds of CMD, its output dropped).
set -euo pipefail
cd "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j 2 --target "$@" >/dev/null
out=benchmarks/results
mkdir -p "$out"
mpi=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
wall() { /usr/bin/time -f "%e" "$@" 2>&1 >/dev/null | tail -1; }
