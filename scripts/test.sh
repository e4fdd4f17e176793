#!/usr/bin/env bash
# Installs what is missing, builds Release, runs the whole test suite.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# For the tests only (tests/io): the files read by ncdump, by xarray with both its netCDF
# engines, and by GNU Octave through scripts/read_*.m (octave is ~70 MB to download).
extra_packages=(netcdf-bin python3-xarray python3-netcdf4 python3-h5netcdf python3-scipy octave octave-netcdf)
source "$here/scripts/setup.sh"
cd "$here/build"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" "$@"
