#!/usr/bin/env bash
# sweep_axes.sh ROCKSWEEP CONFIG WORKDIR
# A sweep over parameter axes (--axis): bitwise the same on 1 and 2 ranks, with and without
# refinement; each of its planes bitwise the sweep run with that parameter set; netCDF readers
# (ncdump, xarray's two engines) see the axes as dimensions with their units; a resume with
# other axes is refused and leaves the file as it was.
set -eu
rs="$1"; cfg="$2"; dir="$3"
py=/usr/bin/python3
rm -rf "$dir" && mkdir -p "$dir"
grid=(--config "$cfg" --omega-ratio-points 17 --amplitude-ratio-points 13 --anchorages free constant --theta-f-ratios 1 --quiet)
axes=(--axis phase_rad=0,1.5707963267948966 --axis restitution=0.85,0.9)
mpi=(mpirun --oversubscribe -np 2)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)

"$rs" sweep "${grid[@]}" "${axes[@]}" -o "$dir/one.h5"
"${mpi[@]}" "$rs" sweep "${grid[@]}" "${axes[@]}" --chunk 7 -o "$dir/two.h5"
h5diff --exclude-path /provenance "$dir/one.h5" "$dir/two.h5" || { echo "1 and 2 ranks differ"; exit 1; }
"$rs" sweep "${grid[@]}" "${axes[@]}" --refine 4 -o "$dir/one_refine.h5"
"${mpi[@]}" "$rs" sweep "${grid[@]}" "${axes[@]}" --refine 4 --chunk 3 -o "$dir/two_refine.h5"
h5diff --exclude-path /provenance "$dir/one_refine.h5" "$dir/two_refine.h5" || { echo "refined: 1 and 2 ranks differ"; exit 1; }

# Refinement over another pair (a parameter axis and the amplitude): planes that are not
# contiguous in the file, gathered and scattered back.
wide=(--config "$cfg" --omega-ratio-points 5 --amplitude-ratio-points 17 --anchorages constant --theta-f-ratios 1 --quiet)
pair=(--axis phase_rad=0:1.5707963267948966:9 --refine 4 --refine-axes phase_rad amplitude_ratio)
"$rs" sweep "${wide[@]}" --axis phase_rad=0:1.5707963267948966:9 -o "$dir/pair_full.h5"
"$rs" sweep "${wide[@]}" "${pair[@]}" -o "$dir/pair_one.h5"
"${mpi[@]}" "$rs" sweep "${wide[@]}" "${pair[@]}" --chunk 2 -o "$dir/pair_two.h5"
h5diff --exclude-path /provenance "$dir/pair_one.h5" "$dir/pair_two.h5" || { echo "refined over a pair: 1 and 2 ranks differ"; exit 1; }

# The plane psi = pi/2, e = 0.85, as a sweep of its own.
"$rs" sweep "${grid[@]}" --phase 1.5707963267948966 --restitution 0.85 -o "$dir/plane.h5"

"$py" - "$dir" <<'PY'
import subprocess, sys
import h5py, numpy as np, xarray as xr
d = sys.argv[1]
full, plane, refined = (h5py.File(f"{d}/{n}.h5", "r") for n in ("one", "plane", "one_refine"))
names = full.attrs["parameter_axes"]
assert (names.decode() if isinstance(names, bytes) else names) == "phase_rad, restitution", names
for sc in ("free", "constant_tf1"):
    g = full["spectra"][sc]
    assert g["outcome"].shape == (2, 2, 13, 17), g["outcome"].shape
    for col in ("outcome", "max_rotation", "impacts", "impacts_total", "t_overturn", "peak_force_ratio", "broken",
                "mu_required", "pivot_uplift", "done"):
        a, b = g[col][1, 0], plane["spectra"][sc][col][()]
        assert np.array_equal(a, b, equal_nan=True), (sc, col)
    # Refinement works plane by plane: every plane computed some cells and inferred others, and
    # its outcomes agree with the full sweep wherever it computed them.
    r = refined["spectra"][sc]
    done, out = r["done"][()], r["outcome"][()]
    assert np.all(done != 0)
    computed = done == 1
    assert np.array_equal(out[computed], g["outcome"][()][computed])
    for i in range(2):
        for j in range(2):
            assert 0 < np.count_nonzero(computed[i, j]) < 13 * 17, (sc, i, j)
print("planes: bitwise the sweep with their values; refinement per plane")

# Over (phase, amplitude): for each omega a 9 x 17 plane; computed cells agree with the full sweep,
# inferred ones take a uniform square's outcome, and some of both exist in every plane.
full, ref = h5py.File(f"{d}/pair_full.h5", "r"), h5py.File(f"{d}/pair_one.h5", "r")
done = ref["spectra/constant_tf1/done"][()]
assert done.shape == (9, 17, 5) and np.all(done != 0)
computed = done == 1
want = full["spectra/constant_tf1/outcome"][()]
assert np.array_equal(ref["spectra/constant_tf1/outcome"][()][computed], want[computed])
for j in range(5):
    assert 0 < np.count_nonzero(computed[:, :, j]) < 9 * 17, j
agree = np.mean(ref["spectra/constant_tf1/outcome"][()] == want)
assert agree > 0.97, agree
print("refinement over phase_rad x amplitude_ratio: computed cells exact, {:.1%} of outcomes as the full sweep".format(agree))

for engine in ("h5netcdf", "netcdf4"):
    ds = xr.open_dataset(f"{d}/one.h5", group="spectra/constant_tf1", engine=engine)
    assert ds["outcome"].dims == ("phase_rad", "restitution", "amplitude_ratio", "omega_ratio"), ds["outcome"].dims
    assert ds["phase_rad"].attrs["units"] == "rad" and ds["restitution"].attrs["units"] == "1"
    assert np.allclose(ds["phase_rad"].values, [0, np.pi / 2])
    sel = ds["max_rotation"].sel(phase_rad=np.pi / 2, restitution=0.85, method="nearest").values
    assert np.array_equal(sel, plane["spectra/constant_tf1/max_rotation"][()], equal_nan=True)
head = subprocess.run(["ncdump", "-h", f"{d}/one.h5"], capture_output=True, text=True, check=True).stdout
assert "phase_rad = 2 ;" in head and "restitution = 2 ;" in head, head[:2000]
assert "outcome(phase_rad, restitution, amplitude_ratio, omega_ratio)" in head
print("netCDF readers: axes are dimensions with units")
PY

# theta_f / alpha as an axis: the constant scenarios of the list become one, "constant", whose
# plane theta_f = alpha is the list's constant_tf1.
small=(--config "$cfg" --omega-ratio-points 17 --amplitude-ratio-points 13 --anchorages constant --quiet)
"$rs" sweep "${small[@]}" --axis theta_f_ratio=0.5,1 -o "$dir/tf.h5"
"$rs" sweep "${small[@]}" --theta-f-ratios 1 -o "$dir/tf1.h5"
"$py" - "$dir" <<'PY'
import sys
import h5py, numpy as np
d = sys.argv[1]
tf, plain = h5py.File(f"{d}/tf.h5", "r"), h5py.File(f"{d}/tf1.h5", "r")
assert list(tf["spectra"]) == ["constant"], list(tf["spectra"])
for col in ("outcome", "max_rotation", "impacts", "t_overturn", "peak_force_ratio", "broken", "mu_required"):
    assert np.array_equal(tf["spectra/constant"][col][1], plain["spectra/constant_tf1"][col][()], equal_nan=True), col
print("theta_f axis: one constant group, its theta_f = alpha plane bitwise the list's")
PY

# The spectrum in the pulse's own terms (T_p [s] x a_p0 [g]) over two sizes: the bigger block
# survives more of the same pulses (Housner's size effect), which the ratio axes hide.
phys=(--config "$cfg" --anchorages constant --theta-f-ratios 1 --quiet)
"$rs" sweep "${phys[@]}" --period-range 0.25 2.5 --period-points 12 --pga-range 0.05 1.5 --pga-points 11 \
  --axis radius_m=0.7,2.8 -o "$dir/physical.h5"
"$py" - "$dir" <<'PY'
import sys
import h5py, numpy as np
f = h5py.File(sys.argv[1] + "/physical.h5", "r")
g = f["spectra/constant_tf1"]
text = lambda v: v.decode() if isinstance(v, bytes) else v
assert text(f.attrs["spectrum_axes"]) == "pga_g, period_s", f.attrs["spectrum_axes"]
assert text(g["outcome"].attrs["dimensions"]) == "radius_m, pga_g, period_s"
assert text(g["period_s"].attrs["units"]) == "s" and g["period_s"][0] == 0.25 and g["pga_g"][-1] == 1.5
small, big = (np.count_nonzero(g["outcome"][k]) for k in (0, 1))
assert big < small, (small, big)
print("T_p x a_p0 axes: R = 0.7 m overturns in {} cells, R = 2.8 m in {}".format(small, big))
PY

# --resume with other axes: refused in one line, the file untouched.
before=$(md5sum < "$dir/one.h5")
set +e
msg=$("$rs" sweep "${grid[@]}" --axis phase_rad=0,1.5707963267948966 --resume -o "$dir/one.h5" 2>&1)
rc=$?
set -e
[ "$rc" -eq 2 ] || { echo "resume with other axes: exit $rc"; echo "$msg"; exit 1; }
echo "$msg" | grep -q "parameter axes phase_rad, restitution" || { echo "message: $msg"; exit 1; }
[ "$(echo "$msg" | wc -l)" -eq 1 ] || { echo "not one line: $msg"; exit 1; }
[ "$(md5sum < "$dir/one.h5")" = "$before" ] || { echo "the file changed"; exit 1; }
echo "resume with other axes refused: $msg"
set +e
msg=$("$rs" sweep "${phys[@]}" --omega-ratio-points 12 --amplitude-ratio-points 11 --axis radius_m=0.7,2.8 --resume -o "$dir/physical.h5" 2>&1)
rc=$?
set -e
[ "$rc" -eq 2 ] && echo "$msg" | grep -q "spectrum axes = amplitude_ratio, omega_ratio is invalid: pga_g, period_s, as" ||
  { echo "resume on ratio axes of a T_p x a_p0 file: exit $rc: $msg"; exit 1; }
echo "resume with the ratio axes refused: $msg"
