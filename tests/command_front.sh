#!/usr/bin/env bash
# The command front (commands/): --set overrides on the command line (applied
# after the file, repeatable, the last one wins, in the results file and in
# the parameter files the design commands write; bad ones refused with the
# Python module's messages), the input warnings of run printed by optimize and
# fit too, --help made from the command table (every command listed, every
# command marked for Python present in the module), and a clean stop of sweep
# on SIGINT and of fit on SIGHUP (exit 2, the results so far readable, no
# lock left).
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"
pymodule="$(dirname "$real_exe")/python"

# --- overrides --------------------------------------------------------------
"$exe" run "$src/prm/default.prm" --set 'Loading/Mass (g)=250' --set 'Output/Directory = set' \
  --set='Loading/Mass (g)=300' > set.out 2> set.err
rc=$?
"$PYTHON" - <<'PY' && [ $rc -eq 0 ] && ok "--set: applied after the file, the last one wins, in the file's parameters" \
  || fail "--set run: exit $rc, $(cat set.err)"
import h5py
f = h5py.File("set/default.h5", "r")
assert f["summary/mass_g"][-1] == 300, f["summary/mass_g"][-1]
text = f.attrs["parameters"]
text = text.decode() if isinstance(text, bytes) else text
assert "set Mass (g)" in text and "= 300" in text.split("set Mass (g)")[1].split("\n")[0], text
PY

# bad NAME 'expected message' ARGS...: exit 1, one line naming the override,
# the Python module's message for the same override, nothing written
bad_set() {
  local name=$1 expect=$2; shift 2
  "$exe" run "$src/prm/default.prm" --set 'Output/Directory=bad' "$@" > "$name.out" 2> "$name.err"
  local rc=$?
  if [ $rc -eq 1 ] && grep -qF -- "$expect" "$name.err" && [ "$(wc -l < "$name.err")" -eq 1 ] && [ ! -e bad ]; then
    ok "$name: $(cat "$name.err")"
  else
    fail "$name: exit $rc, $(cat "$name.err")"
  fi
}
bad_set no-slash "cdea: override 'Mass': expected 'Subsection/Entry', e.g. 'Loading/Mass (g)'" --set 'Mass=300'
bad_set no-entry "cdea: override 'Loading/Mass (kg)': subsection Loading has no entry 'Mass (kg)'" --set 'Loading/Mass (kg)=0.3'
bad_set no-section "cdea: override 'Load/Mass (g)': there is no subsection 'Load'" --set 'Load/Mass (g)=300'
bad_set bad-value "cdea: override 'Loading/Mass (g)' = 'heavy': " --set 'Loading/Mass (g)=heavy'
bad_set out-of-range "cdea: Loading/Mass (g) must be zero or positive, got -1" --set 'Loading/Mass (g)=-1'
bad_set no-equal "cdea: --set 'Loading/Mass (g)': expected 'Subsection/Entry=value'" --set 'Loading/Mass (g)'
bad_set no-value "cdea: --set needs a value" --set

# The same overrides through the Python module give the same messages.
PYTHONPATH="$pymodule" "$PYTHON" - "$src/prm/default.prm" <<'PY' && ok "the Python module's overrides give the same messages" || fail "Python override messages"
import sys, cdea
for name, key, value in [("no-slash", "Mass", 300), ("no-entry", "Loading/Mass (kg)", 0.3),
                         ("no-section", "Load/Mass (g)", 300), ("bad-value", "Loading/Mass (g)", "heavy"),
                         ("out-of-range", "Loading/Mass (g)", -1)]:
    try:
        cdea.parameters(sys.argv[1], {"Output/Directory": "bad", key: value})
        sys.exit(f"{name}: accepted")
    except ValueError as e:
        line = open(name + ".err").read().strip()
        assert line == "cdea: " + str(e), (line, str(e))
PY

"$exe" recover out/x.h5 --set 'Loading/Mass (g)=300' > recover.out 2> recover.err
[ $? -eq 1 ] && grep -q "cdea recover: wrong arguments (got 'out/x.h5' '--set' 'Loading/Mass (g)=300')" recover.err \
  && ok "--set only for the commands that read a parameter file" || fail "recover --set: $(head -1 recover.err)"

# --- a command without its file, a command's --help, an unknown command ------
"$exe" run > none.out 2> none.err
if [ $? -eq 1 ] && [ ! -s none.out ] && grep -q "^cdea run: wrong arguments (got no arguments); usage:" none.err &&
   grep -q "^  cdea run FILE.prm" none.err && ! grep -q "cdea sweep" none.err; then
  ok "cdea run without its file: $(head -1 none.err)"
else
  fail "cdea run without its file: exit $?, $(head -2 none.err)"
fi
for flag in --help -h; do
  "$exe" fit $flag > help.out 2> help.err
  if [ $? -eq 0 ] && [ ! -s help.err ] && grep -q "^  cdea fit FILE.prm DATA.csv" help.out &&
     ! grep -q "cdea run" help.out; then
    ok "cdea fit $flag: the command's usage, exit 0"
  else
    fail "cdea fit $flag: $(head -2 help.err) $(head -2 help.out)"
  fi
done
"$exe" runn prm.prm > unknown.out 2> unknown.err
[ $? -eq 1 ] && grep -q "^cdea: unknown command 'runn'" unknown.err && grep -q "cdea sweep FILE.prm" unknown.err \
  && ok "an unknown command: its name and the whole usage" || fail "unknown command: $(head -1 unknown.err)"

# --- the warnings of run, printed by every command that reads FILE.prm --------
twice='subsection Loading\n  set Mass (g) = 280\n  set Mass (g) = 280\nend\n'
{ cat "$src/prm/optimize-paper.prm"; printf "$twice"; } > dup-opt.prm
{ cat "$src/prm/fit-example.prm"; printf "$twice"; } > dup-fit.prm
for cmd in "run dup-opt.prm" "optimize dup-opt.prm" "fit dup-fit.prm $src/prm/fit-example.csv"; do
  # An unwritable output stops the command right after its input is read.
  "$exe" $cmd --set 'Output/Directory=/proc/cdea-none' > warn.out 2> warn.err
  rc=$?
  if [ $rc -eq 1 ] && grep -q "warning: dup-...\.prm line [0-9]*: Loading/Mass (g) is set again" warn.err \
     && grep -q "/proc/cdea-none" warn.err; then
    ok "${cmd%% *}: the duplicate entry warned"
  else fail "${cmd%% *} warnings: exit $rc, $(cat warn.err)"; fi
done

# --- the design commands' parameter files carry the overrides -------------------
"$exe" optimize "$src/prm/optimize-paper.prm" --set 'Output/Directory=opt' \
  --set 'Optimization/Starts=1' --set 'Optimization/Max evaluations=2' --set 'Loading/Mass (g)=275' \
  > opt.out 2> opt.err
rc=$?
{ [ $rc -eq 0 ] || [ $rc -eq 2 ]; } && grep -qE "set Mass \(g\) += 275$" opt/optimize-paper_optimum.prm \
  && ok "optimize: the replay file keeps the override (exit $rc)" \
  || fail "optimize --set: exit $rc, $(grep 'Mass' opt/optimize-paper_optimum.prm) $(cat opt.err)"

# --- --help from the table ------------------------------------------------------
"$exe" --help > help.txt
missing=""
for c in run shoot compare sweep recover optimize fit print-parameters --version --help; do
  grep -q "^  cdea $c" help.txt || missing="$missing $c"
done
python_commands=$(sed -n 's/^In Python (import cdea, doc\/python.md): \(.*\)\.$/\1/p' help.txt)
[ -z "$missing" ] && grep -q -- "--set 'Subsection/Entry=value'" help.txt && [ -n "$python_commands" ] \
  && PYTHONPATH="$pymodule" "$PYTHON" -c "
import cdea, sys
names = [n.strip() for n in sys.argv[1].split(',')]
absent = [n for n in names if not callable(getattr(cdea, n, None))]
assert not absent, absent" "$python_commands" \
  && ok "--help lists every command; the Python module has $python_commands" \
  || fail "--help: missing$missing; Python: '$python_commands'"

# --- SIGINT: a clean stop -------------------------------------------------------
# wait_for PATTERN FILE: up to 60 s until FILE has a line matching PATTERN
wait_for() { for _ in $(seq 1200); do grep -q "$1" "$2" 2> /dev/null && return 0; sleep 0.05; done; return 1; }
no_lock() { [ -z "$(find "$1" -name '*.lock' 2> /dev/null)" ]; }
# A background job of a script starts with SIGINT ignored (and cdea keeps an
# ignored signal ignored, as under nohup): start it with the default action.
# (the interpreter itself: the job's pid must be the process that execs)
with_sigint() { exec /usr/bin/python3 -c 'import os, signal, sys
signal.signal(signal.SIGINT, signal.SIG_DFL)
os.execv(sys.argv[1], sys.argv[1:])' "$@"; }

CDEA_PROGRESS=lines CDEA_PROGRESS_SECONDS=0.05 with_sigint "$exe" sweep "$src/prm/sweep-inner5.prm" \
  --set 'Output/Directory=sw' --set 'Sweep/Ring edge values (r/a)=1.2, 1.21, ..., 2.6' \
  --set 'Sweep/Outer voltage range (kV)=5, 8, 0.01' --set 'Discretization/Elements per ring=32' \
  > sweep.out 2> sweep.err &
pid=$!
wait_for "progress: [1-9]" sweep.out
kill -INT $pid
wait $pid
rc=$?
"$PYTHON" - <<'PY'
import h5py, numpy as np
f = h5py.File("sw/sweep-inner5_map.h5", "r")
status = f.attrs["run_status"]
status = status.decode() if isinstance(status, bytes) else status
assert status.startswith("stopped: interrupted by SIGINT after "), status
d = f["displacement_mm"][:]
done = ~np.all(np.isnan(d), axis=1)
assert done.any() and not done.all(), done.sum()
PY
readable=$?
[ $rc -eq 2 ] && grep -q "interrupted by SIGINT after [0-9]* of 141 layouts; the map so far is in sw/sweep-inner5_map.h5" sweep.err \
  && [ $readable -eq 0 ] && no_lock sw \
  && ok "sweep on SIGINT: exit 2, $(cat sweep.err), the map readable, no lock left" \
  || fail "sweep SIGINT: exit $rc, readable $readable, $(ls sw), $(cat sweep.err)"

# (five copies of the data: a fit long enough that SIGHUP comes after its
# first iteration and before its end)
for _ in $(seq 5); do grep -v '^#\|^V1' "$src/prm/fit-example.csv"; done > many.csv
sed -i '1i V1_kV, V2_kV, displacement_mm' many.csv
"$exe" fit "$src/prm/fit-example.prm" many.csv --set 'Output/Directory=fit' \
  --set 'Discretization/Elements per ring=32' > fit.out 2> fit.err &
pid=$!
wait_for "^ *0 " fit.out
kill -HUP $pid
wait $pid
rc=$?
"$PYTHON" -c "import h5py; f = h5py.File('fit/fit-example_fit.h5', 'r'); assert f.attrs['converged'] == 0" 2> /dev/null
readable=$?
[ $rc -eq 2 ] && grep -q "interrupted by SIGHUP; the values reached are in fit/fit-example_fit.h5" fit.err \
  && [ $readable -eq 0 ] && no_lock fit \
  && ok "fit on SIGHUP: exit 2, the values reached written, no lock left" \
  || fail "fit SIGHUP: exit $rc, readable $readable, $(ls fit), $(cat fit.err)"

finish
