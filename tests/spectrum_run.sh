#!/usr/bin/env bash
# The relaxation spectrum as a user meets it (doc/materials.md, "The
# relaxation spectrum"): prm/spectrum.prm (three branches) run for one cycle,
# its results file holding every branch's viscous stretches; `cdea chart` of
# it, whose DMA table is the Prony series of the three branches to 1e-10; and
# a bad list refused with exit 1 naming the entry.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"

"$exe" run "$src/prm/spectrum.prm" --set 'Time/Cycles=1' --set 'Output/Directory=out' > run.txt 2>&1
rc=$?
[ $rc -eq 0 ] && [ -s out/spectrum.h5 ] && ok "spectrum.prm, one cycle: exit 0, file written" \
  || { fail "exit $rc"; tail -5 run.txt; }
"$PYTHON" - out/spectrum.h5 <<'PY' && ok "every branch's xi1, xi2 in /steps, relaxed at the start" || fail "steps"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
steps = sorted(f["steps"].keys())
first, last = f["steps"][steps[0]], f["steps"][steps[-1]]
for name in ("xi1", "xi2", "xi1_b2", "xi2_b2", "xi1_b3", "xi2_b3"):
    assert name in last, name
assert "q1_b3" not in last
# The fast branch (0.2 s) follows the stretch more closely than the 2 s one.
l1 = last["lambda1"][()]
assert np.max(np.abs(last["xi1"][()] - l1)) < np.max(np.abs(last["xi1_b2"][()] - l1))
assert np.all(first["xi1_b3"][()] == first["lambda1"][()])
PY

"$exe" chart "$src/prm/spectrum.prm" --set 'Output/Directory=out' > chart.txt 2>&1
grep -q "DMA chart (small-strain uniaxial tension, relaxation spectrum):" chart.txt \
  && grep -q "relaxed modulus 75.3 kPa, instantaneous 210.3 kPa" chart.txt \
  && ok "chart summary: a spectrum, relaxed and instantaneous moduli" || { fail "chart summary"; cat chart.txt; }
"$PYTHON" - out/spectrum_chart.h5 <<'PY' && ok "chart file: the Prony series of three branches to 1e-10" || fail "chart file"
import sys, h5py, numpy as np
d = h5py.File(sys.argv[1], "r")["dma"]
fr = d["frequency_Hz"][()]
storage, loss = 3 * 25.1 + 0 * fr, 0 * fr
for mu, tau in ((25, 0.2), (15, 2), (5, 20)):
    x = 2 * np.pi * fr * tau
    storage = storage + 3 * mu * x**2 / (1 + x**2)
    loss = loss + 3 * mu * x / (1 + x**2)
assert np.max(np.abs(d["storage_modulus_kPa"][()] / storage - 1)) < 1e-10
assert np.max(np.abs(d["loss_modulus_kPa"][()] / loss - 1)) < 1e-10
assert d.attrs["relaxation_time_s"] == 0
PY

# Output/Step rows: the terminal shows fewer rows, the file every step. The
# first run's table has a row per step ("time" rows: the drive's steps).
rows() { grep -cE '^ +[0-9]+ +time ' "$1"; }
"$exe" run "$src/prm/spectrum.prm" --set 'Time/Cycles=1' --set 'Output/Directory=progress' \
  --set 'Output/Step rows=progress' > progress.txt 2>&1
"$exe" run "$src/prm/spectrum.prm" --set 'Time/Cycles=1' --set 'Output/Directory=none' \
  --set 'Output/Step rows=none' > none.txt 2>&1
every=$(rows run.txt); progress=$(rows progress.txt); none=$(rows none.txt)
[ "$every" -gt 100 ] && [ "$progress" -ge 20 ] && [ "$progress" -le 21 ] && [ "$none" -eq 0 ] \
  && ! grep -q "^ *step " none.txt && grep -q "^Final state: t = 2 s" none.txt \
  && ok "Step rows: every $every, progress $progress (a twentieth of 2 s each), none 0 rows" \
  || fail "Step rows: every $every, progress $progress, none $none rows"
"$PYTHON" - out/spectrum.h5 progress/spectrum.h5 none/spectrum.h5 <<'PY' \
  && ok "Step rows: the three files hold the same steps" || fail "Step rows: files differ"
import sys, h5py, numpy as np
d = [h5py.File(p, "r")["summary"]["displacement_mm"][()] for p in sys.argv[1:]]
assert len(d[0]) > 100 and all(np.array_equal(d[0], x) for x in d[1:])
PY

"$exe" run "$src/prm/spectrum.prm" --set 'Time/Cycles=1' --set 'Output/Directory=bad' \
  --set 'Material/Branch relaxation times (s)=0.2, 2' > bad.txt 2>&1
rc=$?
[ $rc -eq 1 ] && grep -q "Material/Branch relaxation times (s) must list as many relaxation times as Material/Branch shear moduli (kPa) lists moduli (3), got 2" bad.txt \
  && ok "unequal lists: exit 1 naming the entry" || { fail "unequal lists: exit $rc"; cat bad.txt; }
finish
