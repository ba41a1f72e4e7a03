#!/usr/bin/env bash
# The pump scene's input (issue 6): bad Reservoir entries give one clear
# message on stderr that names the parameter, a non-zero exit and no results
# file; the water load is refused by the solvers that lack it (shoot,
# compare). Then prm/pump.prm runs and its results file holds the volume
# columns: volume_mm3 everywhere, volume_change_mm3 and level_drop_mm NaN
# before the end of the load stage, level_drop = volume_change / (20 x 20);
# postprocess/plot_pump.py plots it.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"

# case NAME COMMAND "sed expression on prm/pump.prm" "text the message must contain"
case_() {
  local name=$1 command=$2 edit=$3 expect=$4
  sed -e "$edit" -e "s|set Directory           = results|set Directory           = out-$name|" \
    "$src/prm/pump.prm" > "$name.prm"
  "$exe" "$command" "$name.prm" > "$name.out" 2> "$name.err"
  local rc=$?
  local ok=1
  [ $rc -ne 0 ] || { echo "FAIL $name: exit code 0"; ok=0; }
  grep -qF -- "$expect" "$name.err" || { echo "FAIL $name: stderr lacks '$expect':"; cat "$name.err"; ok=0; }
  [ ! -e "out-$name" ] || { echo "FAIL $name: output was created"; ok=0; }
  [ $ok -eq 1 ] && echo "ok   $name: $(head -c 200 "$name.err")" || failures=$((failures + 1))
}

case_ negative-width  run 's/set Width (mm)             = 20/set Width (mm)             = -3/' \
  "Reservoir/Width (mm) must be positive, got -3"
case_ zero-depth      run 's/set Depth (mm)             = 20/set Depth (mm)             = 0/' \
  "Reservoir/Depth (mm) must be positive, got 0"
case_ negative-water  run 's/set Water volume (ml)      = 150/set Water volume (ml)      = -150/' \
  "Reservoir/Water volume (ml) must be positive, got -150"
case_ zero-density    run 's/set Water density (kg\/m^3) = 1000/set Water density (kg\/m^3) = 0/' \
  "Reservoir/Water density (kg/m^3) must be positive, got 0"
case_ water-load-text run 's/set Water load             = \(true\|false\)/set Water load             = maybe/' \
  "Water load"
case_ shoot-water     shoot 's/set Water load             = \(true\|false\)/set Water load             = true/' \
  "Reservoir/Water load = true is implemented in the FE model only"
case_ compare-water   compare 's/set Water load             = \(true\|false\)/set Water load             = true/' \
  "Reservoir/Water load = true is implemented in the FE model only"

# prm/pump.prm runs, and its summary holds the volume columns.
sed -e "s|set Directory           = results|set Directory           = out-pump|" \
  "$src/prm/pump.prm" > pump.prm
if "$exe" run pump.prm > pump.out 2> pump.err; then
  echo "ok   prm/pump.prm runs"
  grep -q "dV (mm3)" pump.out && echo "ok   table has the dV column" ||
    { echo "FAIL no dV column on stdout"; failures=$((failures + 1)); }
  grep -q "level drop" pump.out && echo "ok   final state reports the level drop" ||
    { echo "FAIL no level drop in the final state"; failures=$((failures + 1)); }
  if "$PYTHON" -c "import h5py, numpy" 2> /dev/null; then
    if "$PYTHON" - out-pump/pump.h5 <<'PYEOF'
import sys
import h5py
import numpy as np
with h5py.File(sys.argv[1], "r") as f:
    s = f["summary"]
    stage, t = s["stage"][...], s["load_factor"][...]
    v, dv, drop = s["volume_mm3"][...], s["volume_change_mm3"][...], s["level_drop_mm"][...]
    for name in ("volume_mm3", "volume_change_mm3", "level_drop_mm"):
        assert s[name].attrs["unit"] in (b"mm^3", b"mm", "mm^3", "mm"), name
    ref = int(np.flatnonzero((stage == 1) & (t == 1.0))[0])
    assert np.all(np.isfinite(v)) and v[0] == 0.0, "volume everywhere, 0 when flat"
    assert np.all(np.isnan(dv[:ref])) and np.all(np.isnan(drop[:ref])), "NaN before the load end"
    assert dv[ref] == 0.0, "zero change at the reference"
    assert np.allclose(dv[ref:], v[ref:] - v[ref], rtol=0, atol=1e-6), "change = V - V_ref"
    assert np.allclose(drop[ref:], dv[ref:] / 400.0, rtol=1e-12), "drop = dV / (20 x 20)"
    assert drop[-1] > 10.0, "a level drop of centimetres at 4 / 5 kV"
print("volume columns consistent; level drop at the end %.4f mm" % drop[-1])
PYEOF
    then echo "ok   /summary volume columns"; else echo "FAIL /summary volume columns"; failures=$((failures + 1)); fi
    # postprocess/plot_pump.py on this file: the PNG, the waypoint table, and a clear error.
    if "$PYTHON" "$src/postprocess/plot_pump.py" out-pump/pump.h5 --out plots > plot.out 2>&1 &&
       [ -s plots/pump_level_drop.png ] && grep -q "4 / 5 kV: level drop" plot.out; then
      echo "ok   plot_pump.py wrote plots/pump_level_drop.png"
    else
      echo "FAIL plot_pump.py:"; cat plot.out; failures=$((failures + 1))
    fi
    if "$PYTHON" "$src/postprocess/plot_pump.py" missing.h5 > plot.err 2>&1; then
      echo "FAIL plot_pump.py: exit 0 for a missing file"; failures=$((failures + 1))
    elif grep -q "plot_pump.py: error: no such file" plot.err; then
      echo "ok   plot_pump.py: missing file rejected"
    else
      echo "FAIL plot_pump.py missing file: $(cat plot.err)"; failures=$((failures + 1))
    fi
  else
    echo "skip /summary check: python3 lacks h5py"
  fi
else
  echo "FAIL prm/pump.prm: $(cat pump.err)"; failures=$((failures + 1))
fi

finish
