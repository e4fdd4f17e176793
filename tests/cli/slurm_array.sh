#!/usr/bin/env bash
# slurm_array.sh ROCKSWEEP SOURCE_DIR DIR: scripts/slurm/sweep_array.sbatch run as three array
# tasks (a stand-in `srun` that runs its command, as one task would) and joined by merge gives
# the unsplit sweep bitwise; a rerun of a finished task resumes its own part.
set -u
rs="$1"; src="$2"; dir="$3"
rm -rf "$dir"; mkdir -p "$dir/bin" "$dir/build"; cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
printf '#!/bin/sh\nexec "$@"\n' > bin/srun; chmod +x bin/srun
ln -s "$rs" build/rocksweep  # the script runs build/rocksweep from the repository root
cfg="$src/configs/smatteo.toml"
opts=(--omega-ratio-points 21 --amplitude-ratio-points 19 --anchorages free --quiet)
"$rs" sweep --config "$cfg" "${opts[@]}" -o ref.h5 || fail "reference"
for k in 1 2 3; do
  SLURM_ARRAY_TASK_ID=$k PATH="$dir/bin:$PATH" bash "$src/scripts/slurm/sweep_array.sbatch" "$cfg" out/run 3 "${opts[@]}" \
    || fail "task $k"
done
SLURM_ARRAY_TASK_ID=2 PATH="$dir/bin:$PATH" bash "$src/scripts/slurm/sweep_array.sbatch" "$cfg" out/run 3 "${opts[@]}" \
  || fail "task 2 resubmitted"
ls out
"$rs" merge --config "$cfg" "${opts[@]}" -o all.h5 out/run.part0000{1,2,3}.h5 || fail "merge"
h5diff --exclude-path /provenance ref.h5 all.h5 || fail "merged array differs from the unsplit sweep"
echo ok
