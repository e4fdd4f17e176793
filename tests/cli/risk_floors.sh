#!/usr/bin/env bash
# risk_floors.sh RS REPO DIR: the risk of a suite on two floors (scenarios SCENARIO@FLOOR): its
# groups come in the suite's order with their floor named, the ground's rates are bitwise those
# of the same suite run on the ground alone (the hazard curve is the ground's whatever the floor),
# and the floor's rates differ from them; read_risk.py and read_risk.m read them in that order.
set -eu
rs="$1"; repo="$2"; dir="$3"
mkdir -p "$dir"
common=(suite --config "$repo/configs/suite_floors.toml" --suite "$repo/configs/records_suite.csv"
        --anchorages free constant --intensity-points 8 --quiet --overwrite)
"$rs" "${common[@]}" --floor ground "f4: 0.5 0.05 1.241; 0.174 0.05 -0.333" -o "$dir/floors.h5"
"$rs" "${common[@]}" --floor ground -o "$dir/ground.h5"
for s in floors ground; do
  "$rs" risk --suite-file "$dir/$s.h5" --hazard "$repo/configs/hazard_illustrative_pga.csv" -o "$dir/risk_$s.h5" \
    --overwrite > "$dir/risk_$s.txt"
done
cat "$dir/risk_floors.txt"
/usr/bin/python3 - "$dir" "$repo/scripts" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[2])
import read_risk
import read_suite
d = sys.argv[1]
S = read_suite.load(d + "/floors.h5")
R, G = read_risk.load(d + "/risk_floors.h5"), read_risk.load(d + "/risk_ground.h5")
assert list(R["scenarios"]) == list(S["scenarios"]), (list(R["scenarios"]), list(S["scenarios"]))
assert list(R["scenarios"]) == ["free@ground", "constant_tf1@ground", "free@f4", "constant_tf1@f4"], list(R["scenarios"])
assert list(G["scenarios"]) == ["free", "constant_tf1"], list(G["scenarios"])
for name, sc in R["scenarios"].items():
    assert sc["floor"] == S["scenarios"][name]["attrs"]["floor"], (name, sc["floor"])
    base = name.split("@")[0]
    if sc["floor"] == "ground":
        for key in ("rate_fit", "rate_fit_lo", "rate_fit_hi", "rate_empirical", "deaggregation_fit"):
            assert np.array_equal(sc[key], G["scenarios"][base][key], equal_nan=True), (name, key)
    else:
        assert not np.allclose(sc["rate_empirical"], G["scenarios"][base]["rate_empirical"]), name
print("ok: {} scenarios in the suite's order, floors named, ground rates bitwise those of the ground-only suite"
      .format(len(R["scenarios"])))
PY
# read_risk.m: the same order, and each scenario's floor.
out=$(octave-cli --no-gui --quiet --norc --eval "addpath('$repo/scripts'); R = read_risk('$dir/risk_floors.h5', 'free@f4');
  printf('%s|%s|%s\n', strjoin(R.scenario_names, ' '), R.scenario, R.floor);" 2>/dev/null | grep '|')
echo "octave: $out"
[ "$out" = "free@ground constant_tf1@ground free@f4 constant_tf1@f4|free@f4|f4" ]
# The printed table names every scenario, however long, in the suite's order.
grep -n "@f4" "$dir/risk_floors.txt" >/dev/null
[ "$(grep -c '^[a-z_0-9.]*@ground ' "$dir/risk_floors.txt")" = 2 ]
