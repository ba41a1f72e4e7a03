#!/usr/bin/env bash
# `cdea fit` as a command on the example (prm/fit-example.prm with its CSV:
# synthetic data at mu = 25.1 kPa, Jlim = 270 with 0.02 mm of noise): exit 0,
# the fitted values within two standard errors of the truth, the fit file
# and the parameter file with the fitted values, postprocess/plot_fit.py on
# the result; parameters the data cannot separate are named in a warning;
# bad data exit 1 with one message naming file, line and column, and write
# nothing; so do a time run and the viscoelastic law, naming the parameter.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"

sed 's/set Directory           = results/set Directory = out/' "$src/prm/fit-example.prm" > fit.prm
cp "$src/prm/fit-example.csv" data.csv
"$exe" fit fit.prm data.csv > out.txt 2> err.txt
rc=$?
[ $rc -eq 0 ] && ok "fit exits 0" || { fail "exit $rc"; cat err.txt; }
[ -s out/fit-example_fit.h5 ] && [ -s out/fit-example_fit.prm ] && ok "fit file and parameter file written" \
  || fail "files: $(ls out 2>&1)"
"$PYTHON" - out/fit-example_fit.h5 <<'PY' && ok "mu and Jlim within two standard errors of 25.1 kPa and 270" || fail "fitted values"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
v, e = f.attrs["fitted_values"], f.attrs["standard_errors"]
print("   mu = %.4f +- %.4f kPa, Jlim = %.2f +- %.2f" % (v[0] * 1e-3, e[0] * 1e-3, v[1], e[1]))
assert abs(v[0] - 25.1e3) < 2 * e[0] and abs(v[1] - 270) < 2 * e[1]
assert f["correlation"].shape == (2, 2) and abs(f["correlation"][0, 1]) < 1
assert len(f["data/residual_mm"]) == 20 and 0.01 < f.attrs["rms_residual_mm"] < 0.03
assert len(f["curve/displacement_mm"]) == 1 + 19 * 8
PY
grep -q "set Shear modulus (kPa) *= 25.1" out/fit-example_fit.prm && ok "the parameter file holds the fitted shear modulus" \
  || fail "fit.prm: $(grep 'Shear modulus' out/fit-example_fit.prm)"
"$PYTHON" "$src/postprocess/plot_fit.py" out/fit-example_fit.h5 --out fit.png > plot.txt 2>&1 && [ -s fit.png ] \
  && ok "plot_fit.py writes the figure" || { fail "plot_fit.py"; cat plot.txt; }

# Not identifiable: the potential depends on eps/mu and F/mu only.
sed -e 's/set Free parameters     = shear modulus, Jlim/set Free parameters = shear modulus, permittivity, mass/' \
    -e 's/Base name           = fit-example/Base name = degenerate/' fit.prm > degenerate.prm
"$exe" fit degenerate.prm data.csv > degenerate.txt 2>&1
grep -q "WARNING: the data do not determine shear modulus, permittivity, mass separately" degenerate.txt \
  && ok "not identifiable: $(grep WARNING degenerate.txt | head -c 120)" || fail "no warning: $(tail -5 degenerate.txt)"

# Bad data: a message naming file, line and column; exit 1; nothing written.
printf 'V1_kV, V2_kV, displacement_mm\n1, 1, 18.4\n2, 2, abc\n' > bad.csv
sed 's/Directory = out/Directory = bad/' fit.prm > bad.prm
"$exe" fit bad.prm bad.csv > bad.txt 2> bad_err.txt
rc=$?
[ $rc -eq 1 ] && grep -q "bad.csv, line 3, column displacement_mm: 'abc' is not a number" bad_err.txt \
  && [ ! -e bad ] && ok "bad data: $(head -c 120 bad_err.txt)" || fail "bad data: exit $rc, $(cat bad_err.txt)"
"$exe" fit bad.prm missing.csv > /dev/null 2> missing_err.txt
[ $? -eq 1 ] && grep -q "cannot read data file 'missing.csv'" missing_err.txt && ok "missing data file" \
  || fail "missing data file: $(cat missing_err.txt)"

# The fit works on quasi-static elastic equilibria: a time run or the
# viscoelastic law is refused by name (exit 1, nothing written).
for change in "Time|Enabled = true|Time/Enabled = true is not supported by cdea fit" \
              "Material|Model = viscoelastic|Material/Model = viscoelastic is not supported by cdea fit"; do
  IFS='|' read -r section entry message <<< "$change"
  { sed 's/Directory = out/Directory = refused/' fit.prm
    printf 'subsection Time\n  set Enabled = true\nend\n'
    [ "$section" = Material ] && printf 'subsection Material\n  set %s\nend\n' "$entry"; } > refused.prm
  "$exe" fit refused.prm data.csv > refused.txt 2> refused_err.txt
  rc=$?
  [ $rc -eq 1 ] && grep -q "$message" refused_err.txt && [ ! -e refused ] \
    && [ "$(wc -l < refused_err.txt)" -le 1 ] \
    && ok "refused: $(head -c 110 refused_err.txt)" || fail "$section: exit $rc, $(cat refused_err.txt)"
done

# A creep fit asked to stop (SIGTERM) ends its time run within a step and
# exits 2 with the values reached in a readable fit file.
sed -e 's#set Directory           = results#set Directory = stopped#' \
    -e "s#prm/fit-creep-voltages.csv#$src/prm/fit-creep-voltages.csv#" "$src/prm/fit-creep.prm" > creep.prm
"$exe" fit creep.prm "$src/prm/fit-creep.csv" --set 'Calibration/Free parameters=shear modulus, branch 2 shear modulus, branch 3 shear modulus, branch 2 relaxation time, branch 3 relaxation time' > creep.txt 2>&1 &
creep_pid=$!
# (once its first iteration is printed: within the work, with values reached)
for _ in $(seq 1200); do grep -q "^ *0 " creep.txt && break; sleep 0.02; done
kill -TERM $creep_pid
wait $creep_pid
rc=$?
[ $rc -eq 2 ] && grep -q "interrupted by SIGTERM" creep.txt \
  && "$PYTHON" -c 'import h5py, sys; h5py.File(sys.argv[1], "r").attrs["fitted_values"]' stopped/fit-creep_fit.h5 \
  && ok "creep fit stopped by SIGTERM: exit 2, $(grep -o '[0-9]* evaluations' creep.txt), readable fit file" \
  || fail "creep fit and SIGTERM: exit $rc, $(tail -3 creep.txt)"

echo "$failures failed"
[ $failures -eq 0 ]
