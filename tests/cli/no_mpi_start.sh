#!/usr/bin/env bash
# no_mpi_start.sh ROCKSWEEP CONFIG WORKDIR
# A process started on its own must not initialise MPI (issue 21: Open MPI's singleton start-up
# cost every command 0.33 s). The probe: OMPI_MCA_pml names a component that does not exist, so
# any MPI_Init fails. First shown under mpirun (so the probe is known to bite), then every
# command run on its own with the same environment must succeed.
set -u
rs="$1"; cfg="$2"; dir="$3"
rm -rf "$dir"; mkdir -p "$dir"
fail() { echo "$1"; exit 1; }
mpi=(mpirun --oversubscribe -np 1)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
export OMPI_MCA_pml=no_such_component
if "${mpi[@]}" "$rs" info --config "$cfg" >"$dir/probe.log" 2>&1; then
  fail "the probe does not bite: MPI_Init under mpirun succeeded with OMPI_MCA_pml=$OMPI_MCA_pml"
fi
"$rs" --help >/dev/null || fail "--help initialised MPI"
"$rs" info --config "$cfg" >/dev/null || fail "info initialised MPI"
"$rs" simulate --config "$cfg" --quiet -o "$dir/one.h5" || fail "simulate initialised MPI"
"$rs" sweep --config "$cfg" --anchorages free --omega-ratio-points 3 --amplitude-ratio-points 3 --quiet \
  -o "$dir/sweep.h5" || fail "a one-process sweep initialised MPI"
[ "$(h5dump -a /provenance/ranks "$dir/sweep.h5" | grep -c "(0): 1")" -eq 1 ] || fail "provenance ranks is not 1"
echo "no command started on its own initialised MPI"
