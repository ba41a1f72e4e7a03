#!/usr/bin/env bash
# `cdea chart` as a command (doc/materials.md, "Material charts"): the
# viscoelastic film of prm/pump-time.prm and the neo-Hookean default film,
# the chart files read back against the closed forms (Gent and neo-Hooke
# stress-stretch, the standard linear solid), the summary on stdout, bad
# input with exit 1 naming the parameter and no file left, and
# postprocess/plot_chart.py with measurements laid on the charts.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"

# (the real executable once: the start of `cdea chart` itself; tests/cdea_forks.bash)
"$real_exe" chart "$src/prm/pump-time.prm" --set 'Output/Directory=out' > visco.txt 2> visco_err.txt
rc=$?
[ $rc -eq 0 ] && [ -s out/pump-time_chart.h5 ] && ok "chart of the viscoelastic film: exit 0, file written" \
  || { fail "exit $rc"; cat visco_err.txt; }
grep -q "relaxed modulus E_A 75.3 kPa, instantaneous E_A + E_B 210.3 kPa, relaxation time 2 s" visco.txt \
  && grep -q "largest loss factor 0.536397 at 0.0476177 Hz" visco.txt && grep -q "^wrote out/pump-time_chart.h5" visco.txt \
  && ok "summary: the moduli, the relaxation time, the peak loss factor" || { fail "summary"; cat visco.txt; }
"$PYTHON" - out/pump-time_chart.h5 <<'PY' && ok "chart file: Gent curves (both networks) and the standard linear solid to 1e-10" || fail "chart file"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
mu_a, mu_b, jlim, tau = 25.1, 45.0, 270.0, 2.0
assert f.attrs["material_model"] == "viscoelastic" and f.attrs["voltage_V"] == 0
for path, I1, shape in (("uniaxial", lambda L: L**2 + 2 / L, lambda L: L - L**-2),
                        ("equibiaxial", lambda L: 2 * L**2 + L**-4, lambda L: L - L**-5)):
    g = f[path]
    L = g["stretch"][()]
    assert len(L) == 51 and L[0] == 1 and L[-1] == 6 and np.isinf(g.attrs["locking_stretch"])
    assert g["nominal_stress_kPa"].attrs["unit"] == "kPa" and g["stretch"].attrs["unit"] == "1"
    factor = shape(L) / (1 - (I1(L) - 3) / jlim)
    for name, mu in (("nominal_stress_kPa", mu_a), ("instantaneous_stress_kPa", mu_a + mu_b)):
        err = np.abs(g[name][()] - mu * factor) / (mu * np.abs(factor) + mu_a)
        assert err.max() < 1e-10, (path, name, err.max())
d = f["dma"]
fr = d["frequency_Hz"][()]
assert len(fr) == 61 and abs(fr[0] - 1e-3) < 1e-15 and abs(fr[-1] / 1e3 - 1) < 1e-13
assert d["frequency_Hz"].attrs["unit"] == "Hz" and d["storage_modulus_kPa"].attrs["unit"] == "kPa"
x = 2 * np.pi * fr * tau
ea, eb = 3 * mu_a, 3 * mu_b
storage, loss = ea + eb * x**2 / (1 + x**2), eb * x / (1 + x**2)
assert np.max(np.abs(d["storage_modulus_kPa"][()] / storage - 1)) < 1e-10
assert np.max(np.abs(d["loss_modulus_kPa"][()] / loss - 1)) < 1e-10
assert np.max(np.abs(d["loss_factor"][()] / (loss / storage) - 1)) < 1e-10
assert abs(d.attrs["relaxation_time_s"] / tau - 1) < 1e-10
PY

"$exe" chart "$src/prm/default.prm" --set 'Output/Directory=out' --set 'Material/Model=neo-hooke' > neo.txt 2>&1
rc=$?
[ $rc -eq 0 ] && grep -q "DMA chart: none (Material/Model = neo-hooke is elastic: no internal variables, no loss)" neo.txt \
  && ok "neo-Hooke: exit 0, no DMA chart, said so" || { fail "neo-hooke: exit $rc"; cat neo.txt; }
"$PYTHON" - out/default_chart.h5 <<'PY' && ok "neo-Hooke chart file: mu (L - L^-2), mu (L - L^-5) to 1e-10, no /dma" || fail "neo-hooke file"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
mu = 25.1
assert "dma" not in f and f.attrs["dma"].startswith("none")
L = f["uniaxial/stretch"][()]
assert np.max(np.abs(f["uniaxial/nominal_stress_kPa"][()] - mu * (L - L**-2)) / (mu * (L - L**-2) + mu)) < 1e-10
assert np.max(np.abs(f["uniaxial/transverse_stretch"][()] - L**-0.5)) < 1e-12
L = f["equibiaxial/stretch"][()]
assert np.max(np.abs(f["equibiaxial/nominal_stress_kPa"][()] - mu * (L - L**-5)) / (mu * (L - L**-5) + mu)) < 1e-10
assert "instantaneous_stress_kPa" not in f["uniaxial"]
PY

# Bad input: exit 1, one message naming the parameter, nothing written.
check_refused() { # NAME EXPECTED-MESSAGE ARGS...
  local name=$1 message=$2
  shift 2
  "$exe" chart "$@" --set "Output/Directory=$name" > "$name.txt" 2> "$name.err"
  local rc=$?
  [ $rc -eq 1 ] && grep -qF "$message" "$name.err" && [ ! -e "$name" ] \
    && ok "refused: $(head -c 110 "$name.err")" || { fail "$name: exit $rc, $(cat "$name.err")"; }
}
check_refused bad_mu_b "Material/Network B shear modulus (kPa)" "$src/prm/pump-time.prm" \
  --set 'Material/Network B shear modulus (kPa)=-1'
check_refused bad_jlim "Jlim" "$src/prm/default.prm" --set 'Material/Jlim=-3'
check_refused bad_model "Model" "$src/prm/default.prm" --set 'Material/Model=rubber'
check_refused no_time "Time/Enabled = true" "$src/prm/pump-time.prm" --set 'Time/Enabled=false'
"$exe" chart > usage.txt 2>&1
[ $? -eq 1 ] && grep -q "chart FILE.prm" usage.txt && ok "no file: usage, exit 1" || fail "usage: $(cat usage.txt)"

# The plot with measurements.
printf 'stretch, stress_kPa\n1.5, 30\n2, 50\n3, 80\n' > uni.csv
printf 'frequency_Hz, storage_kPa, loss_kPa\n0.01, 80, 20\n0.1, 150, 60\n1, 200, 15\n' > dma.csv
"$PYTHON" "$src/postprocess/plot_chart.py" out/pump-time_chart.h5 --uniaxial uni.csv --equibiaxial uni.csv \
  --dma dma.csv --out visco.png > plot.txt 2>&1 && [ -s visco.png ] \
  && "$PYTHON" "$src/postprocess/plot_chart.py" out/default_chart.h5 > plot2.txt 2>&1 && [ -s out/default_chart.png ] \
  && ok "plot_chart.py: both charts, with measurements" || { fail "plot_chart.py"; cat plot.txt plot2.txt; }
printf 'stretch, stress_kPa\n1.5, 30\n2, x\n' > bad.csv
"$PYTHON" "$src/postprocess/plot_chart.py" out/pump-time_chart.h5 --uniaxial bad.csv > bad_plot.txt 2>&1
[ $? -ne 0 ] && grep -q "bad.csv, line 3" bad_plot.txt && ok "plot_chart.py: a bad CSV line named" \
  || fail "bad csv: $(cat bad_plot.txt)"
"$PYTHON" "$src/postprocess/plot_chart.py" out/default_chart.h5 --dma dma.csv > elastic_dma.txt 2>&1
[ $? -ne 0 ] && grep -q "is elastic" elastic_dma.txt && ok "plot_chart.py: --dma on an elastic chart refused" \
  || fail "elastic --dma: $(cat elastic_dma.txt)"
finish
