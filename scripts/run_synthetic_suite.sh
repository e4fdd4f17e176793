#!/usr/bin/env bash
# run_synthetic_suite.sh [COUNT] [NP]: S. Matteo (configs/suite_smatteo.toml: free, constant
# theta_f = alpha, adaptive K_min = 0.1 K_max, 30 PGA levels) at its own size over COUNT motions
# of the model fitted to each of the eleven shared records (seed k for the k-th record, the
# Mexico City N-S component): the README's synthetic fragility. Writes results/synthetic/ (the
# motions and their suite CSV) and results/suite_synthetic_pooled.h5.
set -eu
count="${1:-100}"; np="${2:-2}"
cd "$(dirname "$0")/.."
out=results/synthetic
rm -rf "$out"; mkdir -p "$out"
seed=0
while read -r file units; do
  seed=$((seed + 1))
  u=(--record-units "$units"); [ "$units" = - ] && u=()
  build/rocksweep synth --record "tests/data/$file" "${u[@]}" --seed "$seed" --count "$count" -o "$out/${file%%.*}" \
    | sed -n 2p | sed "s|^|${file%%.*}: |"
done <<'LIST'
elcentro_1940_NS.dat g
northridge_1994_sylmar.dat m/s^2
cape_mendocino_1992.dat m/s^2
kocaeli_1999.dat m/s^2
loma_prieta_1989.dat m/s^2
san_fernando_1971.dat m/s^2
spitak_1988.dat m/s^2
san_salvador_1986_gic090.txt m/s^2
cephalonia_2014_chv1_E.txt cm/s^2
mexico_city_1985_sct.txt g
RSN1044_northridge_1994_newhall_rot.AT2 -
LIST
# One suite CSV: each folder's rows with the folder in the file's path.
{
  sed -n 2p "$out/elcentro_1940_NS/suite.csv"
  for d in "$out"/*/; do tail -n +3 "$d/suite.csv" | sed "s|^\([^,]*\),\([^,]*\)|\1,$(basename "$d")/\2|"; done
} > "$out/suite.csv"
mpi=(); [ "$np" -gt 1 ] && mpi=(mpirun --oversubscribe -np "$np")
[ "$np" -gt 1 ] && [ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
"${mpi[@]}" build/rocksweep suite --config configs/suite_smatteo.toml --suite "$out/suite.csv" --radius-points 1 \
  --radius-range 1.392695228684288 1.392695228684288 --overwrite -o results/suite_synthetic_pooled.h5
