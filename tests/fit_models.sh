#!/usr/bin/env bash
# Model selection of `cdea fit` (Calibration/Candidate models,
# doc/materials.md "Choosing a model") on prm/fit-material.prm's three
# histories, made by the program's material point from a one-branch Gent
# film (mu_A = 25 kPa, branch 20 kPa at 5 s, Jlim 270) with 0.1 kPa of noise:
# 1. candidates elastic 0, 1, 2: the one-branch model better than the
#    elastic one by AIC, BIC and held-out error; the two-branch model not
#    better in held-out error than the one-branch one by more than the
#    spread; AIC and BIC against n ln(RSS/n) + 2k and + k ln n from the
#    written RSS, and that RSS against the written residuals of the
#    recommended model's _fit.h5; the one-branch constants within 3 standard
#    errors of the truth; the three files written;
# 2. one file: the held-out error cannot be computed, the data cannot decide;
# 3. bad candidate lists: exit 1, the entry and what is allowed named,
#    nothing written;
# 4. postprocess/plot_fit.py (Agg) draws the material-test fit and the model
#    selection of 1, and refuses a file of neither.
source "$(dirname "$0")/script_helpers.bash"
sed 's/set Directory           = results/set Directory = out/' "$src/prm/fit-material.prm" > fit.prm
cp "$src"/prm/fit-material-*.csv .
files=(fit-material-uniaxial.csv fit-material-equibiaxial.csv fit-material-pure-shear.csv)
candidates="Calibration/Candidate models=elastic 0, elastic 1, elastic 2"

# 1. Three candidates on three files.
"$exe" fit fit.prm "${files[@]}" --set "$candidates" > models.txt 2> models_err.txt
rc=$?
[ $rc -eq 0 ] && ok "three candidates: exit 0" || { fail "three candidates: exit $rc"; cat models_err.txt; }
[ -s out/fit-material_models.h5 ] && [ -s out/fit-material_fit.h5 ] && [ -s out/fit-material_fit.prm ] \
  && ok "_models.h5, _fit.h5 and _fit.prm written" || fail "files: $(ls out 2>&1)"
grep -q "^recommended: " models.txt && ok "$(grep '^recommended: ' models.txt | head -c 200)" \
  || fail "no recommendation printed"
# The recommended model's _fit.prm is the prm made that model: its law, its
# branch and every constant it fitted free (Jlim too), so it fits again as is.
grep -qE "^  set Free parameters +=  ?shear modulus, Jlim, Branch 1 shear modulus \(Pa\), Branch 1 relaxation time \(s\)$" out/fit-material_fit.prm \
  && grep -qE "^  set Model +=  ?viscoelastic$" out/fit-material_fit.prm \
  && ok "_fit.prm: the recommended model's law and free constants" \
  || fail "_fit.prm: $(grep -E 'Free parameters|  set Model ' out/fit-material_fit.prm)"
"$PYTHON" - out/fit-material_models.h5 out/fit-material_fit.h5 <<'PY' && ok "AIC, BIC, held-out and RSS as they must be" || fail "model selection file"
import sys, h5py, numpy as np
m, fit = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
g = m["models"]
names = list(g["model"].asstr()[()])
assert names == ["elastic 0", "elastic 1", "elastic 2"], names
k, n, rss = g["constants"][()], g["samples"][()], g["rss_kPa2"][()]
aic, bic, held = g["aic"][()], g["bic"][()], g["held_out_error"][()]
print("   k", k, "n", n, "RSS", rss, "AIC", aic, "BIC", bic, "held-out", held)
assert list(k) == [2, 4, 6] and list(n) == [1323] * 3
assert np.allclose(aic, n * np.log(rss / n) + 2 * k, rtol=1e-12, atol=1e-9)
assert np.allclose(bic, n * np.log(rss / n) + k * np.log(n), rtol=1e-12, atol=1e-9)
# One branch against none: every criterion agrees.
assert aic[1] < aic[0] and bic[1] < bic[0] and held[1] < held[0]
# Two branches: not better in held-out error by more than the spread.
spread = m.attrs["spread"]
print("   held-out 1 - 2:", held[1] - held[2], "spread", spread, "verdict:", m.attrs["verdict"])
assert held[1] - held[2] < spread
# Undecided between one and two branches: the simpler recommended and written.
assert m.attrs["recommended"] == "elastic 1", m.attrs["recommended"]
assert "recommended: the simpler, elastic 1" in m.attrs["verdict"]
# 0.1 kPa of noise: the RSS per sample near 0.01 kPa^2 for the viscous models.
assert 0.008 < rss[1] / n[1] < 0.012
# The recommended model's residuals in _fit.h5 sum to its RSS.
best = names.index(m.attrs["recommended"])
r = fit["samples/residual_kPa"][()]
assert abs(np.sum(r**2) / rss[best] - 1) < 1e-9, (np.sum(r**2), rss[best])
# The per-file rms of the fit on every file against _fit.h5's.
assert np.allclose(g["rms_kPa"][best], fit["tests/rms_kPa"][()], rtol=1e-9)
# The one-branch model's constants within 3 standard errors of the truth.
c = m["constants"]
rows = c["model"][()] == 1
v, e = c["value"][()][rows], c["standard_error"][()][rows]
names1 = list(c["constant"].asstr()[()][rows])
truth = {"shear modulus": 25e3, "Jlim": 270, "Branch 1 shear modulus (Pa)": 20e3,
         "Branch 1 relaxation time (s)": 5.0}
z = [(v[j] - truth[names1[j]]) / e[j] for j in range(len(v))]
print("   one branch:", dict(zip(names1, v)), "z", z)
assert all(abs(x) < 3 for x in z)
assert m["models/held_out_relative_rms"].shape == (3, 3)
PY

# 2. One file: no held-out error, the data cannot decide.
"$exe" fit fit.prm fit-material-uniaxial.csv --set "Output/Base name=one" \
  --set "Calibration/Candidate models=elastic 0, elastic 1" > one.txt 2>&1
rc=$?
[ $rc -eq 0 ] && grep -q "the held-out error cannot be computed (one file" one.txt \
  && grep -q "(the data cannot decide)" one.txt \
  && "$PYTHON" -c "
import h5py, numpy as np
m = h5py.File('out/one_models.h5', 'r')
assert np.all(np.isnan(m['models/held_out_error'][()])) and m.attrs['decided'] == 0
assert m.attrs['recommended'] == 'elastic 1'
" && ok "one file: $(grep '^recommended' one.txt | head -c 160)" || fail "one file: exit $rc, $(tail -5 one.txt)"

# 3. Bad candidate lists: exit 1, the entry named, nothing written.
refused() { # WHAT MESSAGE LIST
  "$exe" fit fit.prm "${files[0]}" --set "Output/Directory=refused" \
    --set "Calibration/Candidate models=$3" > refused.txt 2> refused_err.txt
  local rc=$?
  [ $rc -eq 1 ] && grep -qF -- "$2" refused_err.txt && [ ! -e refused ] \
    && ok "$1: $(head -c 170 refused_err.txt)" || fail "$1: exit $rc, $(cat refused_err.txt)"
}
allowed="each item 'LAW N': LAW a Material/Model without internal variables ("
refused "an unknown law" "Calibration/Candidate models: 'gent 1' does not name a law without internal variables ($allowed" "elastic 0, gent 1"
refused "the viscous law itself" "'viscoelastic 1' does not name a law without internal variables" "viscoelastic 1"
refused "branches beside another law" "'neo-hooke 1' puts branches beside neo-hooke: the viscous branches stand beside network A's Gent law only" "neo-hooke 1"
refused "no branch count" "'elastic' is not 'LAW N'" "elastic"
refused "a branch count not a number" "'elastic x' has no branch count from 0 to 20" "elastic x"
refused "too many branches" "'elastic 21' has no branch count from 0 to 20" "elastic 21"
refused "a model twice" "Calibration/Candidate models: 'elastic 1' is given twice" "elastic 1, elastic 1"
refused "an empty item" "'' is not 'LAW N'" "elastic 0,, elastic 1"

# 4. The plots of the fit and of the selection.
# (what the material-test figure shows, curve by curve: tests/test_plot_products.py)
"$PYTHON" "$src/postprocess/plot_fit.py" out/fit-material_fit.h5 --out fit.png > p1.txt 2>&1 \
  && [ -s fit.png ] && ok "plot_fit.py: the material-test fit" || { fail "plot_fit.py on the fit"; cat p1.txt; }
"$PYTHON" "$src/postprocess/plot_fit.py" out/fit-material_models.h5 > p2.txt 2>&1 \
  && [ -s out/fit-material_models.png ] && ok "plot_fit.py: the model selection" \
  || { fail "plot_fit.py on the selection"; cat p2.txt; }
"$PYTHON" "$src/postprocess/plot_fit.py" out/one_models.h5 --out one.png > p3.txt 2>&1 && [ -s one.png ] \
  && ok "plot_fit.py: a selection of one file (no held-out error)" || { fail "plot_fit.py, one file"; cat p3.txt; }
"$PYTHON" "$src/postprocess/plot.py" out/fit-material_models.h5 -o selection.png > p5.txt 2>&1 \
  && [ -s selection.png ] && grep -q "model selection: wrote" p5.txt \
  && ok "plot.py recognises the model selection" || { fail "plot.py on the selection"; cat p5.txt; }
printf 'x' > not.h5
"$PYTHON" "$src/postprocess/plot_fit.py" not.h5 > p4.txt 2>&1
[ $? -ne 0 ] && grep -q "plot_fit.py: error: cannot read 'not.h5'" p4.txt && ok "plot_fit.py refuses a file it cannot read" \
  || fail "plot_fit.py on not.h5: $(cat p4.txt)"
finish
