#!/usr/bin/env bash
# `cdea fit` on material tests (doc/materials.md, "Fitting material tests"):
# histories made by the program's own material point (tests/material_history)
# at known constants of a one-branch viscoelastic Gent film (mu_A = 25 kPa,
# branch 20 kPa at 5 s), a uniaxial and an equibiaxial one fitted jointly
# from prm/fit-material.prm's start (15 kPa, 10 kPa, 1 s), a pure-shear one
# predicted:
# 1. exact data: the constants recovered to 1e-6, every file's printed rms
#    (fitted and predicted) below 1e-6 kPa, the files written; the uniaxial
#    test as raw machine columns through the specimen entries fits the same;
# 2. 0.1 kPa of noise: the constants within 3 standard errors, each fitted
#    file's printed rms 0.1 kPa within 15 %, its relative rms the rms over
#    the file's largest |stress|, the h5 rows per file and per sample;
#    a '# weight 4' line read as the file's weight, which fits as the file
#    given four times;
#    SIGINT during a long fit: exit 2, both files written;
# 3. bad input (a stretch below 1, a bad weight line, a mix with a creep
#    curve, --predict with other data): exit 1, the file, line and column,
#    nothing written.
source "$(dirname "$0")/script_helpers.bash"
history="${CDEA_MATERIAL_HISTORY:?}"
truth=("Material/Shear modulus (kPa)=25" "Material/Branch shear moduli (kPa)=20"
       "Material/Branch relaxation times (s)=5")
sed 's/set Directory           = results/set Directory = out/' "$src/prm/fit-material.prm" > fit.prm
make() { "$history" fit.prm "$@" "${truth[@]}"; }
make uniaxial 3 0.05 20 0.25 0 1 > u.csv && make equibiaxial 2 0.02 20 0.25 0 2 > e.csv \
  && make pure_shear 2.5 0.03 10 0.25 0 3 > p.csv && ok "three exact histories made" \
  || fail "material_history"

# The printed row of FILE: "FILE role weight samples rms largest relative kind".
row() { grep -E "^$1 +(fitted|predicted) " "$2"; }
field() { row "$1" "$3" | awk -v k="$2" '{ print $k }'; }
below() { awk -v v="$2" -v m="$3" 'BEGIN { exit !(v != "" && v + 0 < m) }' && ok "$1: $2 < $3" || fail "$1: '$2', expected < $3"; }

# 1. Exact data.
"$exe" fit fit.prm u.csv e.csv --predict p.csv > exact.txt 2> exact_err.txt
rc=$?
[ $rc -eq 0 ] && ok "exact data: exit 0" || { fail "exact data: exit $rc"; cat exact_err.txt exact.txt; }
[ -s out/fit-material_fit.h5 ] && [ -s out/fit-material_fit.prm ] && ok "fit file and parameter file written" \
  || fail "files: $(ls out 2>&1)"
for f in u.csv e.csv p.csv; do below "exact data: $f rms (kPa)" "$(field $f 5 exact.txt)" 1e-6; done
[ "$(field p.csv 2 exact.txt)" = predicted ] && [ "$(field p.csv 8 exact.txt)" = pure ] \
  && [ "$(field e.csv 8 exact.txt)" = equibiaxial ] && [ "$(field e.csv 2 exact.txt)" = fitted ] && ok "roles and kinds printed" \
  || fail "rows: $(row '[a-z]+.csv' exact.txt)"
"$PYTHON" - out/fit-material_fit.h5 <<'PY' && ok "exact data: 25 kPa, 20 kPa, 5 s recovered to 1e-6" || fail "exact constants"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
v = f.attrs["fitted_values"]
print("   fitted", v)
assert np.allclose(v, [25e3, 20e3, 5.0], rtol=1e-6, atol=0)
assert list(f["tests/file"].asstr()[()]) == ["u.csv", "e.csv", "p.csv"]
assert list(f["tests/fitted"][()]) == [1, 1, 0] and list(f["tests/samples"][()]) == [401, 481, 441]
PY
grep -qE "set Branch relaxation times \(s\) *= (5|4\.99999|5\.00000)" out/fit-material_fit.prm \
  && ok "the parameter file holds the fitted relaxation time" \
  || fail "fit.prm: $(grep 'Branch relaxation' out/fit-material_fit.prm)"

# The uniaxial test as a machine's raw columns through the specimen
# (gauge 20 mm, width 10 mm, thickness 1 mm: displacement 20 (L - 1) mm,
# force 0.01 s1/kPa N): the same constants.
awk -F', ' '/^[0-9]/ { printf "%s, %.12g, %.12g\n", $1, 20 * ($2 - 1), 0.01 * $3; next }
  /^time_s/ { print "time_s, displacement_mm, force_N"; next } { print }' u.csv > raw.csv
specimen=(--set "Calibration/Specimen gauge length (mm)=20" --set "Calibration/Specimen width (mm)=10"
          --set "Calibration/Specimen thickness (mm)=1" --set "Output/Base name=raw")
"$exe" fit fit.prm raw.csv e.csv "${specimen[@]}" > raw.txt 2>&1 \
  && "$PYTHON" - out/fit-material_fit.h5 out/raw_fit.h5 <<'PY' && ok "raw columns through the specimen: the same constants" || fail "raw columns: $(tail -3 raw.txt)"
import sys, h5py, numpy as np
a, b = (h5py.File(x, "r").attrs["fitted_values"] for x in sys.argv[1:])
assert np.allclose(a, b, rtol=1e-7, atol=0), (a, b)
PY

# 2. Noisy data, the equibiaxial file weighted 4.
make uniaxial 3 0.05 20 0.25 0.1 1 > un.csv && { echo "# weight 4"; make equibiaxial 2 0.02 20 0.25 0.1 2; } > en.csv
sed 's/Base name           = fit-material/Base name = noisy/' fit.prm > noisy.prm
"$exe" fit noisy.prm un.csv en.csv --predict p.csv > noisy.txt 2> noisy_err.txt
rc=$?
[ $rc -eq 0 ] && ok "noisy data: exit 0" || { fail "noisy data: exit $rc"; cat noisy_err.txt noisy.txt; }
for f in un.csv en.csv; do
  rms=$(field $f 5 noisy.txt); largest=$(field $f 6 noisy.txt); relative=$(field $f 7 noisy.txt)
  awk -v r="$rms" 'BEGIN { exit !(r > 0.085 && r < 0.115) }' && ok "noisy data: $f rms $rms kPa (noise 0.1)" \
    || fail "noisy data: $f rms '$rms'"
  awk -v r="$rms" -v l="$largest" -v q="$relative" 'BEGIN { d = r / l - q; exit !(d < 0.01 * q && -d < 0.01 * q) }' \
    && ok "noisy data: $f relative rms $relative = $rms / $largest" || fail "$f relative '$relative'"
done
[ "$(field en.csv 3 noisy.txt)" = 4 ] && ok "the '# weight 4' line is the file's weight" \
  || fail "weight: $(row en.csv noisy.txt)"
below "noisy data: the predicted p.csv rms (kPa)" "$(field p.csv 5 noisy.txt)" 0.05
"$PYTHON" - out/noisy_fit.h5 <<'PY' && ok "noisy data: constants within 3 standard errors, the h5 rows" || fail "noisy constants"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
v, e = f.attrs["fitted_values"], f.attrs["standard_errors"]
print("   fitted", v, "+-", e)
assert np.all(np.abs(v - [25e3, 20e3, 5.0]) < 3 * e) and np.all(e / v < 0.02)
c = f["covariance"][()]
assert np.allclose(np.sqrt(np.diag(c)), e, rtol=1e-9)
assert list(f["tests/weight"][()]) == [1, 4, 1]
s = f["samples"]
assert len(s["test"]) == 401 + 481 + 441
assert np.allclose(s["model_stress_kPa"][()] - s["measured_stress_kPa"][()], s["residual_kPa"][()])
for k in range(3):
    r = s["residual_kPa"][()][s["test"][()] == k]
    assert abs(np.sqrt(np.mean(r**2)) - f["tests/rms_kPa"][k]) < 1e-9
PY
grep -v "^# weight" en.csv > e1.csv
sed 's/Base name = noisy/Base name = repeated/' noisy.prm > repeated.prm
"$exe" fit repeated.prm un.csv e1.csv e1.csv e1.csv e1.csv > repeated.txt 2>&1 \
  && "$PYTHON" - out/noisy_fit.h5 out/repeated_fit.h5 <<'PY' && ok "weight 4 fits as the file given 4 times" || fail "weight 4 against 4 copies: $(tail -3 repeated.txt)"
import sys, h5py, numpy as np
a, b = (h5py.File(x, "r").attrs["fitted_values"] for x in sys.argv[1:])
print("   weight 4:", a, " 4 copies:", b)
assert np.allclose(a, b, rtol=1e-6, atol=0)
PY

# SIGINT during a long fit (two 60000-sample files): exit 2, the values
# reached written to the fit file and the parameter file together.
make uniaxial 3 0.02 100 0.005 0.1 1 > long1.csv && cp long1.csv long2.csv
sed 's/Base name = noisy/Base name = interrupted/' noisy.prm > interrupted.prm
set -m # a background job of a script ignores SIGINT without job control
"$exe" fit interrupted.prm long1.csv long2.csv > interrupted.txt 2> interrupted_err.txt &
pid=$!
for _ in $(seq 600); do grep -qE "^ +0 " interrupted.txt && break; sleep 0.1; done
kill -INT $pid
wait $pid
rc=$?
set +m
[ $rc -eq 2 ] && grep -q "interrupted by SIGINT" interrupted_err.txt && [ -s out/interrupted_fit.h5 ] \
  && [ -s out/interrupted_fit.prm ] && ok "SIGINT: exit 2, $(head -c 100 interrupted_err.txt)" \
  || fail "SIGINT: exit $rc, $(cat interrupted_err.txt), $(ls out)"

# 3. Bad input: exit 1, the place named, nothing written.
refused() { # WHAT MESSAGE FILES...
  local what=$1 message=$2; shift 2
  sed 's/Directory = out/Directory = refused/' fit.prm > refused.prm
  "$exe" fit refused.prm "$@" > refused.txt 2> refused_err.txt
  local rc=$?
  [ $rc -eq 1 ] && grep -qF -- "$message" refused_err.txt && [ ! -e refused ] \
    && ok "$what: $(head -c 150 refused_err.txt)" || fail "$what: exit $rc, $(cat refused_err.txt)"
}
{ head -5 u.csv; echo "1, 0.99, 3"; } > below.csv
refused "a stretch below 1" "below.csv, line 6, column uniaxial_stretch: a tension test's stretch must be at least 1" u.csv below.csv
refused "the same in a file to predict" "below.csv, line 6, column uniaxial_stretch" u.csv --predict below.csv
{ echo "# weight -2"; cat e.csv; } > weight.csv
refused "a bad weight line" "weight.csv, line 1: '# weight' must be followed by one number above 0" u.csv weight.csv
printf 'time_s, V1_kV, displacement_mm\n0, 0, 0\n1, 1, 0.5\n' > creep.csv
refused "a mix with a creep curve" "creep.csv holds a creep curve, the other files material tests" u.csv creep.csv
refused "--predict with other data" "creep.csv holds a creep curve: several data files and --predict are for material tests" creep.csv --predict creep.csv
refused "--predict without files" "--predict needs at least one data file after it" u.csv --predict
refused "raw columns without the specimen" "raw.csv: raw machine columns (time_s, displacement_mm, force_N) need the specimen" raw.csv e.csv
finish
