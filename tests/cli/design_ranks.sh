#!/usr/bin/env bash
# design_ranks.sh ROCKSWEEP CONFIG WORKDIR NP
# A small design run: the design file must be bitwise identical at NP ranks to that of one
# process (h5diff of everything but /provenance), leave no round file, and name its optimum.
set -eu
rs="$1"; cfg="$2"; dir="$3"; np="$4"
rm -rf "$dir"; mkdir -p "$dir"
small=(--omega-ratio-points 9 --amplitude-ratio-points 11 --coarse-points 5 --rounds 2 --quiet --overwrite)
mpi=(mpirun --oversubscribe -np "$np")
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
"$rs" design --config "$cfg" "${small[@]}" -o "$dir/one.h5"
"${mpi[@]}" "$rs" design --config "$cfg" "${small[@]}" --chunk 7 -o "$dir/np$np.h5"
h5diff --exclude-path /provenance "$dir/one.h5" "$dir/np$np.h5" || { echo "design files differ"; exit 1; }
# The rounds' files are gone once the design file holds their scores (their spectra are the
# sweeps' own, bitwise at any rank count: sweep_identical).
for r in 0 1 2 3; do
  [ ! -e "$dir/one.round$r.h5" ] && [ ! -e "$dir/np$np.round$r.h5" ] || { echo "round $r left behind"; exit 1; }
done
h5dump -a /constant/optimum_stiffness_N_per_m "$dir/np$np.h5" | grep -q "(0): [0-9]" || { echo "no optimum K"; exit 1; }
h5dump -a /adaptive/optimum_kmin_ratio "$dir/np$np.h5" | grep -q "(0): [0-9]" || { echo "no optimum K_min/K_max"; exit 1; }
echo "np=$np: identical"
