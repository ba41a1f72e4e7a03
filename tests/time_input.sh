#!/usr/bin/env bash
# Time-dependent runs from the command line (doc/time.md):
#  - bad Material/Model and Time entries (a malformed first table row, a
#    directory as table, more than 1e6 steps, entries outside the ranges the
#    solver can meet): exit 1, a message naming the
#    parameter, no results file;
#  - short runs of every waveform (ramp-hold with inertia and a rest time,
#    square, sine, a table with a header): exit 0, one /summary row per time
#    step with increasing time_s, the viscous stretches in the fields of a
#    viscoelastic run, fields only at the breakpoints of the waveform;
#  - postprocess/plot_time.py on them;
#  - the other commands refuse Time/Enabled = true.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"

# A short viscoelastic ramp-hold on the default scene; cases append to it.
base() {
  sed -e "s|set Directory           = results|set Directory           = out-$1|" \
      -e "s|set Base name           = default|set Base name           = $1|" "$src/prm/default.prm"
  cat <<'EOF'
subsection Material
  set Model = viscoelastic
end
subsection Time
  set Enabled = true
  set Ramp time (s) = 0.2
  set Hold time (s) = 0.3
  set Time step (s) = 0.02
end
EOF
}

# bad NAME "extra prm lines" "text the message must contain" ["another text"]
# (one run for texts of the same input)
bad() {
  local name=$1 extra=$2 expect
  { base "$name"; printf '%b\n' "$extra"; } > "$name.prm"
  "$exe" run "$name.prm" > "$name.out" 2> "$name.err"
  local rc=$? ok=1
  [ $rc -eq 1 ] || { echo "FAIL $name: exit code $rc, expected 1"; ok=0; }
  for expect in "${@:3}"; do
    grep -qF -- "$expect" "$name.err" || { echo "FAIL $name: stderr lacks '$expect':"; cat "$name.err"; ok=0; }
  done
  [ ! -e "out-$name" ] || { echo "FAIL $name: output was created"; ok=0; }
  [ $ok -eq 1 ] && echo "ok   $name: $(head -c 160 "$name.err")" || failures=$((failures + 1))
}

sub() { printf 'subsection %s\\n  set %s\\nend' "$1" "$2"; }
bad model-unknown   "$(sub Material 'Model = plastic')" "Model"
bad mu-b-zero       "$(sub Material 'Network B shear modulus (kPa) = 0')" "Material/Network B shear modulus (kPa) must be between 1e-6 and 1e4 times Material/Shear modulus (kPa) (2.51e-05 to 251000 kPa), got 0"
bad mu-b-huge       "$(sub Material 'Network B shear modulus (kPa) = 1e306')" "Material/Network B shear modulus (kPa) must be between 1e-6 and 1e4"
bad jlim-b-negative "$(sub Material 'Network B Jlim = -3')" "Material/Network B Jlim must be between 1e-12 and 1e12, got -3"
bad tau-zero        "$(sub Material 'Relaxation time (s) = 0')" "Material/Relaxation time (s) must be between 1e-12 and 1e12 s, got 0"
bad tau-huge        "$(sub Material 'Relaxation time (s) = 1e306')" "Material/Relaxation time (s) must be between 1e-12 and 1e12 s, got 1e+306"
bad rest-huge       "$(sub Time 'Rest time before voltage (s) = 1e306')" "Time/Rest time before voltage (s) must be 'relaxed' or at most 1e12 s, got 1e+306"
bad rise-tiny       "$(sub Time 'Waveform = square\n  set Rise time (s) = 1e-300')" "Time/Rise time (s) must be at least Time/Min time step (s) = 1e-08 s"
bad visco-no-time   "$(sub Time 'Enabled = false')" "Material/Model = viscoelastic needs Time/Enabled = true"
bad visco-relaxed   "$(sub Wrinkling 'Model = relaxed')" "Wrinkling/Model = relaxed needs Material/Model = elastic"
bad arc-length      "$(sub Solver 'Continuation = arc length')" "Solver/Continuation = load stepping"
bad waveform        "$(sub Time 'Waveform = triangle')" "Waveform"
bad ramp-zero       "$(sub Time 'Ramp time (s) = 0')" "Time/Ramp time (s) must be positive"
bad hold-negative   "$(sub Time 'Hold time (s) = -1')" "Time/Hold time (s) must be zero or positive"
bad step-zero       "$(sub Time 'Time step (s) = 0')" "Time/Time step (s) must be positive"
bad min-step        "$(sub Time 'Min time step (s) = 1')" "Time/Min time step (s) must not exceed Time/Time step (s)"
bad rest            "$(sub Time 'Rest time before voltage (s) = soon')" "Time/Rest time before voltage (s) must be 'relaxed' or a time >= 0"
bad fields-interval "$(sub Time 'Fields interval (s) = -1')" "Time/Fields interval (s) must be zero or positive"
bad frequency       "$(sub Time 'Waveform = square\n  set Frequency (Hz) = 0')" "Time/Frequency (Hz) must be positive"
bad rise            "$(sub Time 'Waveform = square\n  set Rise time (s) = 2')" "Time/Rise time (s) must be shorter than half a period"
bad table-missing   "$(sub Time 'Waveform = table')" "Time/Table file must be given"
printf '0, 0\n1, 2\n0.5, 3\n' > decreasing.csv
bad table-order     "$(sub Time 'Waveform = table\n  set Table file = decreasing.csv')" "decreasing.csv', line 3: times must be >= 0 and increase strictly"
printf 'time_s, kV\n0, 0\n1, 2, 3\n' > columns.csv
bad table-columns   "$(sub Time 'Waveform = table\n  set Table file = columns.csv')" "columns.csv', line 3: expected time and 1 voltage(s), got 3 value(s)"
printf '0, 0\n1, -2\n' > negative.csv
bad table-negative  "$(sub Time 'Waveform = table\n  set Table file = negative.csv')" "voltages must not be negative"
printf '0, 0\n1, two\n' > text.csv
printf '0, 0\n1, 1e306\n' > huge.csv
bad table-ceiling   "$(sub Time 'Waveform = table\n  set Table file = huge.csv')" "huge.csv', line 2: 1e+306 kV is above the voltage ceiling of 1600 kV"
bad table-text      "$(sub Time 'Waveform = table\n  set Table file = text.csv')" "text.csv', line 2: 'two' is not a number"
# A malformed first row is an error, not a header (its 0.5 s row would be lost).
printf '0.5, 3x\n1, 2\n' > first-row.csv
bad table-first-row "$(sub Time 'Waveform = table\n  set Table file = first-row.csv')" "first-row.csv', line 1: '3x' is not a number"
here=$(pwd -P)
bad table-absent    "$(sub Time 'Waveform = table\n  set Table file = nowhere.csv')" "Time/Table file: cannot read 'nowhere.csv'" \
                    "cannot read 'nowhere.csv' (relative to the working directory: $here/nowhere.csv)"
mkdir -p folder.csv
bad table-directory "$(sub Time 'Waveform = table\n  set Table file = folder.csv')" "cannot read 'folder.csv' (relative to the working directory: $here/folder.csv): it is a directory"
# Run length: more than 1e6 steps is refused, naming the entries that set it.
printf '0, 0\n1e300, 2\n' > forever.csv
bad steps-table     "$(sub Time 'Waveform = table\n  set Table file = forever.csv')" "over Time/Time step (s) = 0.02" \
                    "the last time in Time/Table file"
bad steps-hold      "$(sub Time 'Hold time (s) = 1e6')" "the run would take 5e+07 time steps, more than 1e+06: its duration 1e+06 s (Time/Ramp time (s) + Time/Hold time (s))"
bad steps-rest      "$(sub Time 'Rest time before voltage (s) = 3e5')" "+ Time/Rest time before voltage (s)) over Time/Time step (s)"
bad steps-cycles    "$(sub Time 'Waveform = sine\n  set Cycles = 10000000\n  set Frequency (Hz) = 0.5')" "(Time/Cycles / Time/Frequency (Hz))"

# The other commands refuse time runs.
base shoot > shoot.prm
printf 'subsection Material\n  set Model = elastic\nend\n' >> shoot.prm
for command in shoot compare sweep; do
  "$exe" "$command" shoot.prm > "$command.out" 2> "$command.err"
  if [ $? -eq 1 ] && grep -q "Time/Enabled = true" "$command.err"; then
    echo "ok   cdea $command refuses Time/Enabled = true"
  else
    echo "FAIL cdea $command: $(cat "$command.err")"; failures=$((failures + 1))
  fi
done

# Runs of every waveform.
run() {
  local name=$1 extra=$2
  { base "$name"; printf '%b\n' "$extra"; } > "$name.prm"
  if "$exe" run "$name.prm" > "$name.out" 2> "$name.err"; then
    echo "ok   run $name: $(tail -1 "$name.out")"
  else
    echo "FAIL run $name exited with $?: $(cat "$name.err")"; failures=$((failures + 1))
  fi
}
run ramp-hold "$(sub Time 'Rest time before voltage (s) = 0.1')"
run square    "$(sub Time 'Waveform = square\n  set Frequency (Hz) = 5\n  set Cycles = 2\n  set Scheme = trapezoidal')"
run sine      "$(sub Time 'Waveform = sine\n  set Frequency (Hz) = 5\n  set Cycles = 1\n  set Inertia = false')"
printf '# a staircase\ntime_s, kV\n0.1, 1\n0.3, 1\n0.32, 2\n0.5, 2\n' > stairs.csv
# Fixed steps (the old scheme) land on every Fields interval; error-controlled
# ones write the fields at the first step after it.
run table     "$(sub Time 'Waveform = table\n  set Table file = stairs.csv\n  set Fields interval (s) = 0.1\n  set Scheme = backward Euler')"
printf 'subsection Material\n  set Model = elastic\nend\n' > elastic-extra
run elastic   "$(cat elastic-extra)"

"$PYTHON" - <<'PY' || failures=$((failures + 1))
import sys
import h5py
import numpy as np

failures = 0
def check(cond, what):
    global failures
    print(("  ok   " if cond else "  FAIL ") + what)
    failures += 0 if cond else 1

for name, rest, t_end, breakpoints in [("ramp-hold", 0.1, 0.5, [0.0, 0.2, 0.5]),
                                       ("square", None, 0.4, [0.0, 0.01, 0.1, 0.11, 0.2]),
                                       ("sine", None, 0.2, [0.0, 0.2]),
                                       ("table", None, 0.5, [0.0, 0.1, 0.3, 0.32, 0.5]),
                                       ("elastic", None, 0.5, [0.0, 0.2, 0.5])]:
    with h5py.File(f"out-{name}/{name}.h5", "r") as f:
        print(name)
        s = f["summary"]
        t = s["time_s"][...]
        rows = np.isfinite(t)
        times = t[rows]
        check(np.all(s["stage"][...][~rows] < 2), "rows without time are the quasi-static stages")
        check(np.all(np.diff(times) > 0), "time_s increases")
        check(abs(times[0] - (-rest if rest else 0.0)) < 1e-12, "starts at -rest (or 0)")
        check(abs(times[-1] - t_end) < 1e-9, f"ends at {t_end} s")
        steps = sorted(f["steps"].keys())
        written = sorted(t[int(k)] for k in steps if np.isfinite(t[int(k)]))
        for b in breakpoints:
            check(any(abs(w - b) < 1e-9 for w in written), f"fields written at t = {b}")
        if name == "table":
            check(any(abs(w - 0.2) < 1e-9 for w in written), "and every Fields interval")
        check(len(written) < rows.sum(), "not at every step")
        group = f["steps"][steps[-1]]
        viscous = name != "elastic"
        check(("xi1" in group and "xi2" in group) == viscous,
              "xi1, xi2 in the fields" if viscous else "no xi for the elastic law")
        if viscous:
            xi1, lam1 = group["xi1"][...], group["lambda1"][...]
            # The dashpot follows the stretch from behind: where the stretch
            # has come back (end of a sine), xi1 may exceed it a little.
            check(np.all(xi1 > 1) and np.all(xi1 < 1.01 * lam1.max()),
                  f"1 < xi1 < 1.01 x the largest meridian stretch (xi1 up to {xi1.max():.4f}, "
                  f"lambda1 up to {lam1.max():.4f})")
            check(np.abs(xi1 - lam1).max() > 1e-3, "the dashpot lags the stretch")
        for c in ("electrical_work_mJ", "stored_energy_change_mJ", "dissipated_energy_mJ"):
            check(c in s, f"/summary/{c}")
        d = s["dissipated_energy_mJ"][...][rows]
        check(np.all(np.diff(d) >= 0), "dissipated energy never decreases")
sys.exit(1 if failures else 0)
PY

for name in ramp-hold square table; do
  if "$PYTHON" "$src/postprocess/plot_time.py" "out-$name/$name.h5" --out plots --min-hold 0.1 > "plot-$name.out" 2>&1 \
     && [ -s "plots/${name}_time.png" ]; then
    echo "ok   plot_time.py $name"
  else
    echo "FAIL plot_time.py $name: $(cat "plot-$name.out")"; failures=$((failures + 1))
  fi
done
grep -q "cycle  level B" plot-square.out && echo "ok   square: per-cycle levels" || { echo "FAIL square cycles"; failures=$((failures + 1)); }
grep -q "hold  voltages" plot-table.out && echo "ok   table: holds" || { echo "FAIL table holds"; failures=$((failures + 1)); }
"$PYTHON" "$src/postprocess/plot_time.py" "out-elastic/elastic.h5" --out plots --elastic out-elastic/elastic.h5 > holds.out 2>&1 \
  && [ -s plots/elastic_holds.png ] && echo "ok   plot_time.py --elastic" || { echo "FAIL --elastic: $(cat holds.out)"; failures=$((failures + 1)); }
"$PYTHON" "$src/postprocess/plot_time.py" --response plots/response.png out-square/square.h5 out-sine/sine.h5 > response.out 2>&1 \
  && [ -s plots/response.png ] && echo "ok   plot_time.py --response" || { echo "FAIL --response: $(cat response.out)"; failures=$((failures + 1)); }
"$PYTHON" "$src/postprocess/plot_time.py" "$src/prm/default.prm" > notime.out 2>&1 \
  && { echo "FAIL plot_time.py accepts a non-HDF5 file"; failures=$((failures + 1)); } || echo "ok   plot_time.py refuses a non-HDF5 file"

echo "$failures failed"
[ $failures -eq 0 ]
