# The prm/ examples that no other test runs with its numbers asserted, one
# ctest test per example (tests/CMakeLists.txt: prm_example_NAME runs
# `bash prm_example.bash NAME`): the file as shipped (a time run with
# 'Time/Time step (s)=1', a sweep or an optimization on fewer rows or
# starts), and the numbers its document quotes, with tolerances that say
# what the example shows. Not a test by itself (no .sh: the glob of
# tests/CMakeLists.txt skips it).
source "$(dirname "$0")/script_helpers.bash"
ln -s "$src/prm" prm

# near WHAT VALUE EXPECTED TOLERANCE: |VALUE - EXPECTED| <= TOLERANCE
near() {
  if awk -v v="$2" -v e="$3" -v t="$4" 'BEGIN { d = v - e; exit !(v != "" && (d < 0 ? -d : d) <= t) }'; then
    ok "$1: $2 (expected $3 +- $4)"
  else fail "$1: '$2', expected $3 +- $4"; fi
}
# value PATTERN FILE: the first number after PATTERN (an extended regex) in FILE
value() { grep -oE -- "$1 *-?[0-9.e+-]+" "$2" | head -1 | grep -oE -- "-?[0-9.e+-]+$"; }
has() { grep -qF -- "$2" "$3" && ok "$1" || fail "$1: '$2' not in $3: $(head -c 600 "$3")"; }

case "$1" in
relaxed-full) # doc/stability.md: the relaxed law loses ellipticity at the onset
  "$exe" run prm/relaxed-full.prm > out 2> err; rc=$?
  [ $rc -eq 2 ] && ok "stops early: exit 2" || fail "exit $rc, expected 2"
  has "pull-in bracketed at the onset" "between 5.3823776 kV (last valid state, reported) and 5.3823786 kV: the relaxed (tension-field) law loses ellipticity" err
  has "at the disk edge, lambda1 4.92024" "at r = 14 mm (r/a = 1, lambda1 = 4.92024," err
  # The plain law's loss of tension (prm/fold-full.prm, doc/stability.md's table): 25.093 mm.
  near "displacement at the last valid state (mm)" "$(value 'displacement' out)" 25.093 0.0005 ;;
relaxed-rv1.7) # doc/stability.md: stops exactly at the red line, r/a = 1.7
  "$exe" run prm/relaxed-rv1.7.prm > out 2> err; rc=$?
  [ $rc -eq 2 ] && ok "stops early: exit 2" || fail "exit $rc, expected 2"
  has "pull-in at the red line's outer 6.485261 kV" "between 5, 6.485261 kV (last valid state, reported)" err
  has "at the outer ring's inner edge, natural width 2.507" "at r = 23.8 mm (r/a = 1.7, lambda1 = 4.01644, lambda2 = 2.507, natural width 2.507)" err
  # prm/fold-rv1.7.prm's loss of tension: 6.48526 kV, 26.978 mm.
  near "displacement at the last valid state (mm)" "$(value 'displacement' out)" 26.978 0.0005 ;;
staircase-full | staircase-rv1.7) # doc/time.md, scenes 1 and 2 (tau = 2 s)
  # 1 s steps instead of 0.05 s: with tau = 2 s each 20 s hold ends at the
  # long-time (quasi-static) displacement, which the step does not change;
  # backward Euler in 1 s steps leaves at most 1e-3 mm of the 0.27 mm creep.
  # Expected: the holds' last seconds of scene 1's table (1, 3, 4, 5 kV) and
  # the quasi-static column of scene 2's (5.0 / 5.0, 5.5, 6.0 kV).
  "$exe" run "prm/$1.prm" --set 'Time/Time step (s)=1' > out 2> err; rc=$?
  [ $rc -eq 0 ] && ok "exit 0" || fail "exit $rc: $(cat err)"
  [ "$1" = staircase-full ] && ends="40:18.41663 120:19.88558 160:21.39707 200:23.79319" \
    || ends="200:23.79359 220:24.61164 240:25.65070"
  # Each hold's end: the displacement of the row nearest its time.
  times=(); for end in $ends; do times+=("${end%%:*}"); done
  got=($("$PYTHON" - "$1" "${times[@]}" <<'PY'
import sys, h5py, numpy as np
s = h5py.File(f"results/{sys.argv[1]}.h5", "r")["summary"]
t, d = s["time_s"][()], s["displacement_mm"][()]
print(" ".join(str(d[np.nanargmin(np.abs(t - float(e)))]) for e in sys.argv[2:]))
PY
))
  k=0
  for end in $ends; do
    near "end of the hold at t = ${end%%:*} s (mm)" "${got[$k]:-}" "${end#*:}" 0.002; k=$((k + 1))
  done
  if [ "$1" = staircase-rv1.7 ]; then
    # The film creeps into the loss of tension 5.7 s into the last hold
    # (t = 245.72 s with 0.05 s steps), at the outer ring's inner edge.
    near "loss of tension during the 5.0 / 6.5 kV hold (s)" "$(value 'loss of tension \(s2 = 0\) at t =' out)" 245.72 1
    has "at r = 23.8 mm" "5, 6.5 kV, radius r = 23.8 mm" out
  fi ;;
sweep-refined-inner5) # doc/optimization.md, section 4: the red line's maximum
  # Three of the file's 31 rows: the maximum at 1.618 and its neighbours.
  "$exe" sweep prm/sweep-refined-inner5.prm --set 'Sweep/Ring edge values (r/a)=1.616, 1.618, 1.62' > out 2> err; rc=$?
  [ $rc -eq 0 ] && ok "exit 0" || fail "exit $rc: $(cat err)"
  has "largest increase on the red line at 1.618" "largest stroke increase on the red line: 57.91 % at r_v/a = 1.618 (outer 6.3815 kV)" out ;;
optimize-rings) # doc/optimization.md, section 3: four rings, every edge and voltage free
  "$exe" optimize prm/optimize-rings.prm --set 'Optimization/Starts=1' > out 2> err; rc=$?
  [ $rc -eq 0 ] && ok "exit 0" || fail "exit $rc: $(cat err)"
  near "stroke (mm), N = 4 of the table" "$(value 'stroke' out)" 11.5845 0.00005
  [ "$(grep -c "s2 >= 0 kPa at r/a = .* (inner edge of ring [1-4])" out)" = 4 ] \
    && ok "s2 >= 0 active at the inner edge of all four rings" || fail "active constraints: $(cat out)" ;;
response) # doc/dynamics.md: the frequency response of the viscoelastic film
  "$exe" response prm/response.prm > out 2> err; rc=$?
  [ $rc -eq 0 ] && ok "exit 0" || fail "exit $rc: $(cat err)"
  has "equilibrium 23.793589 mm at 5 kV" "Equilibrium at 5 kV: displacement 23.793589 mm" out
  has "mode 1 at 3.787466 Hz" "mode 1: natural frequency 3.787466 Hz," out
  near "mode 1's damping ratio" "$(value 'damping ratio' out)" 0.0025 0.000005
  near "3.03 mm/kV at 0.01 Hz" "$(value '^ +0\.01 ' out)" 3.03 0.005
  near "3.97 mm/kV at 2.47 Hz" "$(value '^ +2\.4658 ' out)" 3.97 0.005
  near "1.35 mm/kV at 6.22 Hz" "$(value '^ +6\.2226 ' out)" 1.35 0.005 ;;
paraview) # doc/usage.md: prm/default.prm with ParaView output
  "$exe" run prm/paraview.prm > out 2> err; rc=$?
  [ $rc -eq 0 ] && ok "exit 0" || fail "exit $rc: $(cat err)"
  has "the default case's final state" "Final state: voltages 5 kV, displacement 23.7935894 mm, stroke 5.5448282 mm" out
  n=$(grep -oE "^results: [0-9]+ steps" out | grep -oE "[0-9]+")
  [ -n "$n" ] && [ "$(ls results/paraview_vtu | wc -l)" = "$n" ] && [ "$(grep -c "<DataSet" results/paraview.pvd)" = "$n" ] \
    && has "one VTU file per step" "ParaView: $n steps in results/paraview.pvd" out \
    || fail "ParaView files: $(ls results/paraview_vtu | wc -l) VTU, $n steps" ;;
fit-dma) # doc/materials.md, "Fits": 7 constants from the DMA table, each near its truth
  "$exe" fit prm/fit-dma.prm prm/fit-dma.csv > out 2> err; rc=$?
  [ $rc -eq 0 ] && ok "exit 0" || fail "exit $rc: $(cat err)"
  has "converged" "Converged:" out
  near "shear modulus (kPa), true 25.1" "$(value 'shear modulus \(kPa\) +20 +' out)" 25.1147 0.0001
  near "branch 1 modulus (Pa), true 25000" "$(value 'Branch 1 shear modulus \(Pa\) +30000 +' out)" 25111.2 0.1
  near "branch 3 time (s), true 20" "$(value 'Branch 3 relaxation time \(s\) +30 +' out)" 20.1038 0.0001
  near "rms residual (kPa), noise 0.3" "$(value 'weighted rms residual' out)" 0.2442 0.0001
  grep -q "Branch shear moduli (kPa) *= 25.111" results/fit-dma_fit.prm && ok "fitted moduli in the Branch list" \
    || fail "results/fit-dma_fit.prm: $(grep Branch results/fit-dma_fit.prm)" ;;
fit-creep) # doc/materials.md, "Fits": one Gauss-Newton step from the true constants
  # (the whole fit from the file's start values takes 6 iterations, about
  # 1.5 s of CPU) lands on the fit's optimum.
  "$exe" fit prm/fit-creep.prm prm/fit-creep.csv --set 'Material/Shear modulus (kPa)=25.1' \
    --set 'Material/Branch shear moduli (kPa)=25, 15, 5' --set 'Calibration/Max iterations=1' > out 2> err; rc=$?
  [ $rc -eq 2 ] && ok "one iteration: exit 2" || fail "exit $rc: $(cat err)"
  near "shear modulus (kPa)" "$(value 'shear modulus \(kPa\) +25.1 +' out)" 25.1001 0.0001
  near "branch 2 modulus (Pa), true 15000" "$(value 'Branch 2 shear modulus \(Pa\) +15000 +' out)" 15262 5
  near "branch 3 modulus (Pa), true 5000" "$(value 'Branch 3 shear modulus \(Pa\) +5000 +' out)" 4993.6 1
  near "rms residual (mm), noise 0.005" "$(value 'weighted rms residual' out)" 0.004261 0.000002 ;;
shear-thinning) # doc/materials.md, "The relaxation spectrum": the staircase with the
  # shear-thinning viscosity of Kumar and Lopez-Pamies (VHB 4910), in 1 s steps
  # instead of 0.05 s (the final displacement differs by 2e-6 mm). At the
  # pre-stretch the viscous stretch's I1v = 12.5 stiffens the dashpot about
  # 51-fold, so the holds hardly creep: 0.0006 mm over the last 20 s (the
  # Newtonian dashpot of the same eta_0: 0.041 mm).
  "$exe" run prm/shear-thinning.prm --set 'Time/Time step (s)=1' > out 2> err; rc=$?
  [ $rc -eq 0 ] && ok "exit 0" || fail "exit $rc: $(cat err)"
  near "final displacement (mm)" "$(value 'displacement' out)" 22.934231 0.0005
  got=($("$PYTHON" - <<'PY'
import h5py, numpy as np
s = h5py.File("results/shear-thinning.h5", "r")["summary"]
t, d = s["time_s"][()], s["displacement_mm"][()]
at = lambda e: d[np.nanargmin(np.abs(t - e))]
print(at(120.), at(160.), at(200.) - at(181.))
PY
))
  near "end of the 3.5 kV hold, t = 120 s (mm)" "${got[0]:-}" 19.68101 0.0005
  near "end of the 4.5 kV hold, t = 160 s (mm)" "${got[1]:-}" 20.96822 0.0005
  near "creep over the last hold (mm)" "${got[2]:-}" 0.0006 0.0003 ;;
fold-full) # doc/stability.md: arc length through both folds of the plain law; the
  # states whose meridian leaves the frame are marked in the table, counted in
  # a line after it and said of the final state, as the file's column has them.
  "$exe" run prm/fold-full.prm > out 2> err; rc=$?
  [ $rc -eq 0 ] && ok "exit 0" || fail "exit $rc: $(cat err)"
  marked=$(grep -c '! not physical: beyond the frame' out)
  in_file=$("$PYTHON" -c 'import h5py, numpy as np
print(int(np.sum(h5py.File("results/fold-full.h5", "r")["summary"]["nonphysical"][()] > 0)))')
  [ "$marked" -gt 0 ] && [ "$marked" = "$in_file" ] \
    && ok "$marked rows marked, as many as the file's nonphysical column" \
    || fail "$marked rows marked, the file has $in_file"
  has "the count after the table" "$in_file of 122 states are not physical" out
  has "the final state said to be not physical" "  not physical: beyond the frame" out ;;
*) fail "no example '$1'" ;;
esac
finish
