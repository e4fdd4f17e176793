#!/usr/bin/env bash
# scripts/setup.sh with stand-ins for cmake, dpkg-query and ccache on PATH (nothing is installed
# or built): run.sh's `build_targets=(rocksweep)` must build that target alone, test.sh (no
# build_targets) everything, both configuring build/ with the same options so that one reuses
# the other's objects; ccache is used when it is on PATH, not otherwise.
# usage: test_setup_targets.sh REPO_ROOT WORKDIR
set -euo pipefail
root=$1 work=$2
rm -rf "$work" && mkdir -p "$work/bin" "$work/repo/scripts"
cp "$root/scripts/setup.sh" "$work/repo/scripts/"
log="$work/cmake.log"
printf '#!/bin/sh\necho "$*" >> "%s"\n' "$log" > "$work/bin/cmake"
printf '#!/bin/sh\necho "install ok installed"\n' > "$work/bin/dpkg-query"
chmod +x "$work/bin/cmake" "$work/bin/dpkg-query"
# PATH is this directory alone, so that a real ccache is not found: the tools setup.sh calls.
for tool in dirname grep id nproc mkdir; do ln -s "$(command -v "$tool")" "$work/bin/$tool"; done
fail() { echo "FAIL: $*"; cat "$log"; exit 1; }

# $1: "ccache" to put a stand-in ccache on PATH; the rest: the sourcing script's build_targets.
run_setup() {
  rm -f "$log" "$work/bin/ccache"
  if [ "$1" = ccache ]; then printf '#!/bin/sh\n' > "$work/bin/ccache"; chmod +x "$work/bin/ccache"; fi
  shift
  PATH="$work/bin" /bin/bash -c 'set -euo pipefail; [ $# -eq 0 ] || build_targets=("$@"); source "$0/scripts/setup.sh"' \
    "$work/repo" "$@" >/dev/null
}

run_setup ccache rocksweep
configure_run=$(sed -n 1p "$log")
grep -qx -- "--build $work/repo/build -j [0-9]* --target rocksweep" <(sed -n 2p "$log") || fail "run.sh must build rocksweep alone"
grep -q -- "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache" <<<"$configure_run" || fail "ccache on PATH but not used"

run_setup ccache
configure_test=$(sed -n 1p "$log")
grep -qx -- "--build $work/repo/build -j [0-9]*" <(sed -n 2p "$log") || fail "test.sh must build every target"
[ "$configure_run" = "$configure_test" ] || fail "run.sh and test.sh configure build/ differently"

run_setup none rocksweep
grep -q -- "LAUNCHER" <(sed -n 1p "$log") && fail "no ccache on PATH, yet configured with it"
for script in run.sh run_pulses.sh run_suite.sh; do
  grep -qx 'build_targets=(rocksweep) .*' "$root/scripts/$script" || fail "$script does not ask for rocksweep alone"
done
echo "ok: run.sh builds rocksweep alone, test.sh everything, one configuration, ccache used"
