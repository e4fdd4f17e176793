#!/usr/bin/env bash
# record_history.sh ROCKSWEEP CONFIG RECORD DIR: a record-driven history records what defined it
# and nothing of the pulse it did not use (no omega_ratio, amplitude_ratio, pulse keys), and a
# free block no anchorage ratios; a pulse history keeps its pulse.
set -u
rs="$1"; cfg="$2"; record="$3"; dir="$4"
rm -rf "$dir"; mkdir -p "$dir"; cd "$dir" || exit 1
"$rs" simulate --config "$cfg" --record "$record" --record-units m/s^2 --t-end 5 -o record.h5 --quiet || exit 1
"$rs" simulate --config "$cfg" --anchorage constant --theta-f-ratio 0.5 -o pulse.h5 --quiet || exit 1
/usr/bin/python3 - <<'PY'
import h5py
def names(path):
    with h5py.File(path, "r") as f:
        config = f.attrs["config"]
        config = config.decode() if isinstance(config, bytes) else config
        return set(f.attrs), [line.split(" = ")[0] for line in config.splitlines()]
attrs, keys = names("record.h5")
print(sorted(attrs), keys, sep="\n")
assert not {"omega_ratio", "amplitude_ratio", "theta_f_ratio", "kmin_ratio"} & attrs, "unused pulse or anchorage attributes"
assert "record" in attrs
pulse_keys = {"phase", "vertical-amplitude", "vertical-phase", "simulate.pulse", "simulate.omega-ratio", "simulate.amplitude-ratio",
              "strength-ratio", "adaptive-break", "simulate.theta-f-ratio", "simulate.kmin-ratio",
              "omega-ratio-range", "anchorages", "theta-f-ratios", "kmin-ratios"}
assert not pulse_keys & set(keys), sorted(pulse_keys & set(keys))
assert "simulate.record-units" in keys and "simulate.record" in keys
attrs, keys = names("pulse.h5")
assert {"omega_ratio", "amplitude_ratio", "theta_f_ratio"} <= attrs and "kmin_ratio" not in attrs, sorted(attrs)
assert {"simulate.omega-ratio", "simulate.amplitude-ratio", "simulate.theta-f-ratio", "strength-ratio"} <= set(keys), keys
print("ok")
PY
