#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then only what was installed: the installed
# rocksweep runs a small sweep with an installed config, the installed Python reader and the
# installed Octave reader open its file, and an installed suite finds its installed records.
# usage: test_install.sh CMAKE BUILD_DIR WORK_DIR
set -euo pipefail
cmake=$1 build=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
prefix="$work/prefix"
"$cmake" --install "$build" --prefix "$prefix" >/dev/null
share="$prefix/share/rocksweep"
fail() { echo "FAIL: $*"; exit 1; }
for f in bin/rocksweep share/rocksweep/scripts/read_spectra.py share/rocksweep/scripts/read_suite.py \
         share/rocksweep/scripts/plot_spectra.py share/rocksweep/scripts/rsplot.py share/rocksweep/scripts/read_spectra.m \
         share/rocksweep/scripts/private/load_netcdf.m share/rocksweep/configs/smatteo.toml \
         share/rocksweep/configs/records_suite.csv share/rocksweep/records/elcentro_1940_NS.dat; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done
[ -e "$share/scripts/setup.sh" ] && fail "the repository's setup.sh was installed"

cd "$work"  # nothing of the repository or the build on the way
"$prefix/bin/rocksweep" sweep --config "$share/configs/smatteo.toml" --anchorages free constant --theta-f-ratios 1 \
  --omega-ratio-points 3 --amplitude-ratio-points 4 --quiet -o sweep.h5
summary=$(/usr/bin/python3 "$share/scripts/read_spectra.py" sweep.h5)
grep -q "grid: 4 amplitude_ratio x 3 omega_ratio" <<<"$summary" || fail "read_spectra.py: $summary"
grep -q "^constant_tf1 " <<<"$summary" || fail "read_spectra.py lists no constant_tf1: $summary"

octave=$(octave-cli --no-gui --quiet --no-init-file --eval \
  "addpath('$share/scripts'); S = read_spectra('sweep.h5'); printf('%d %d %s\n', size(S.free.outcome), S.attrs.title);")
[ "$octave" = "4 3 rocksweep overturning spectra" ] || fail "read_spectra.m: $octave"

# The installed suite CSV names the installed records (its config names it relative to share/rocksweep).
(cd "$share" && "$prefix/bin/rocksweep" suite --config configs/suite_smatteo.toml --anchorages free \
  --intensity-points 2 --radius-points 2 --quiet -o "$work/suite.h5")
summary=$(/usr/bin/python3 "$share/scripts/read_suite.py" "$work/suite.h5")
grep -q "^records: elcentro_1940_ns sylmar_1994 " <<<"$summary" || fail "read_suite.py: $summary"
echo "ok: installed rocksweep, readers (Python, Octave), configs and records work from $prefix"
