#!/usr/bin/env bash
# The default S. Matteo sweep, all seven scenarios, on 2 MPI ranks, then every kind of figure:
#   results/smatteo.h5                the spectra (extra arguments go to the sweep)
#   results/smatteo.png|pdf           overturning spectra (the paper's Figs. 4 and 8-13)
#   results/smatteo_<field>.png|pdf   maps of every other stored field
#   results/adaptive_vs_constant.*    where the adaptive law (K_min = 0.5 K_max) saves / loses the block
#   results/sample_*.h5, history.*, phase.*   the paper's sample case (Figs. 14-16) and its phase plane
#   results/housner.*                 Housner's constant acceleration (Fig. 3)
#   results/restoring.*               restoring moments (Figs. 5-6)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_targets=(rocksweep)  # only what this script runs: the tests are test.sh's
source "$here/scripts/setup.sh"
cfg="$here/configs/smatteo.toml"
mpirun "${mpi_run[@]}" "$rs" sweep --config "$cfg" -o "$res/smatteo.h5" --overwrite "$@"

# One time history per anchorage at the paper's sample case, w_p/p = 4, a_p0/(alpha g) = 2.7.
for a in free constant adaptive; do
  "$rs" simulate --config "$cfg" --anchorage "$a" --kmin-ratio 0.5 --omega-ratio 4 --amplitude-ratio 2.7 \
    -q --overwrite -o "$res/sample_$a.h5"
done
# Housner's pair: 1.3 alpha g held just longer and just shorter than t* = 0.63796 s.
for d in 0.6380 0.6300; do
  "$rs" simulate --config "$cfg" --pulse constant --amplitude-ratio 1.3 --duration "$d" \
    --equations linearised --t-end 6 -q --overwrite -o "$res/housner_$d.h5"
done

s="$here/scripts"
$py "$s/plot_spectra.py" "$res/smatteo.h5" -o "$res/smatteo"
$py "$s/plot_spectra.py" "$res/smatteo.h5" --field max_rotation t_overturn peak_force_ratio mu_required \
  pivot_uplift impacts broken -o "$res/smatteo"
$py "$s/plot_spectra.py" "$res/smatteo.h5" --diff constant_tf1 adaptive_rho0.5 -o "$res/adaptive_vs_constant"
$py "$s/plot_history.py" "$res"/sample_{free,constant,adaptive}.h5 -o "$res/history"
$py "$s/plot_phase.py" "$res"/sample_{free,constant,adaptive}.h5 -o "$res/phase"
$py "$s/plot_housner.py" "$res/housner_0.6380.h5" "$res/housner_0.6300.h5" -o "$res/housner"
$py "$s/plot_restoring.py" "$res/smatteo.h5" -o "$res/restoring"
echo "spectra: $res/smatteo.h5"
echo "figures: $res/*.png (each also as .pdf)"
