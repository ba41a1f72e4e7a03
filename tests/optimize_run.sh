#!/usr/bin/env bash
# `cdea optimize` as a command: the paper's case (two rings, inner ring at
# 5 kV, edge and outer voltage free) writes <Base name>_optimum.h5 with the
# documented root attributes and history, and <Base name>_optimum.prm, which
# `cdea run` replays to the same state without wrinkling; with a field limit
# the replay reports the largest field, at the limit; an optimizer stopped early exits 2
# with the best layout written; `mpirun -np 2` gives the same file contents;
# bad input (and a time run, a trailing ',', a voltage above the film's
# ceiling) exits 1 with one message naming the parameter and writes nothing;
# an output locked by another run exits 1 at once; no start reaching a layout
# exits 2 and leaves nothing; SIGTERM stops the starts and writes the best
# layout so far (exit 2).
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"

cat > paper.prm <<'EOF'
subsection Optimization
  set Rings                  = 2
  set Fixed voltages (kV)    = 5, free
  set Fixed ring edges (r/a) = free
  set Starts                 = 2
end
subsection Output
  set Directory = out
  set Base name = paper
end
EOF

"$exe" optimize paper.prm > out.txt 2> err.txt
rc=$?
[ $rc -eq 0 ] && ok "converged run exits 0" || { fail "exit $rc"; cat err.txt; }
grep -q "Optimum (start" out.txt && ok "the optimum is printed" || fail "no optimum in stdout"
[ -s out/paper_optimum.h5 ] && [ -s out/paper_optimum.prm ] && ok "both files written" \
  || fail "files missing: $(ls out)"
[ -z "$(ls out | grep tmp)" ] && ok "no temporary file left" || fail "left: $(ls out)"

"$PYTHON" - out/paper_optimum.h5 <<'PY' && ok "root attributes and history as documented" || fail "file content"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
a = f.attrs
need = ["ring_edges_over_a", "voltages_kV", "displacement_mm", "stroke_mm", "volume_change_mm3",
        "min_s2_kPa", "max_field_MV_per_m", "active_constraints", "iterations", "solves"]
missing = [k for k in need if k not in a]
assert not missing, missing
assert len(a["ring_edges_over_a"]) == 3 and len(a["voltages_kV"]) == 2
assert a["voltages_kV"][0] == 5.0
# The paper's case: the red line's maximum (doc/optimization.md).
assert abs(a["stroke_mm"] - 8.75568) < 2e-5, a["stroke_mm"]
assert abs(a["ring_edges_over_a"][1] - 1.6186) < 2e-3, a["ring_edges_over_a"]
assert a["min_s2_kPa"] >= 0, a["min_s2_kPa"]  # feasible: the replay is not wrinkled
s = a["active_constraints"]
s = s.decode() if isinstance(s, bytes) else s
assert "inner edge of ring 2" in s, s
assert a["iterations"] > 0 and a["solves"] > a["iterations"]
h = f["history"]
n = len(h["objective"])
assert n == a["iterations"] and h["free_values"].shape == (n, 2)
assert len(f["starts/objective"]) == 2
PY

# The replay: `cdea run` on the written parameter file reaches the optimum.
"$exe" run out/paper_optimum.prm > run.txt 2> run_err.txt
rc=$?
[ $rc -eq 0 ] && ok "cdea run on the replay file exits 0" || { fail "replay exit $rc"; cat run_err.txt; }
"$PYTHON" - out/paper_optimum.h5 out/paper_optimum_run.h5 <<'PY' && ok "the replay reaches the same state" || fail "replay differs"
import sys, h5py
o, r = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
d_opt = o.attrs["displacement_mm"]
d_run = r["summary/displacement_mm"][-1]
print("   displacement: optimum %.12f mm, replay %.12f mm" % (d_opt, d_run))
assert abs(d_run / d_opt - 1) < 1e-9
assert abs(r["summary/stroke_mm"][-1] / o.attrs["stroke_mm"] - 1) < 1e-9
PY

# The chosen start is feasible: its replay by `cdea run` finds no wrinkling.
grep -q "Wrinkling onset: none along the path" run.txt && ok "the replay is not wrinkled" \
  || fail "replay: $(grep -i wrinkl run.txt)"

# A field limit: the replay file sets it as the breakdown field, so that
# `cdea run` reports the largest field, which is the limit (active).
cat > field.prm <<'EOF2'
subsection Optimization
  set Rings                  = 2
  set Fixed voltages (kV)    = 5, free
  set Fixed ring edges (r/a) = 1.8
  set Maximum field (MV/m)   = 59
  set Starts                 = 1
end
subsection Output
  set Directory = out
  set Base name = field
end
EOF2
"$exe" optimize field.prm > field.txt 2> field_err.txt
rc=$?
[ $rc -eq 0 ] && ok "field-limited run exits 0" || { fail "field-limited: exit $rc"; cat field_err.txt; }
grep -q "set Breakdown field (MV/m) *= 59$" out/field_optimum.prm \
  && ok "the replay file sets Breakdown field (MV/m) = 59" \
  || fail "replay file: $(grep 'Breakdown' out/field_optimum.prm)"
"$exe" run out/field_optimum.prm > field_run.txt 2> field_run_err.txt
"$PYTHON" - out/field_optimum_run.h5 <<'PY' && ok "the replay reports the field at the limit" || fail "replay field"
import sys, h5py
E = h5py.File(sys.argv[1], "r")["summary/max_field_MV_per_m"][-1]
print("   largest field of the replay: %.9f MV/m" % E)
assert 59 * (1 - 1e-6) <= E <= 59 * (1 + 1e-6), E
PY

# Stopped before converging: exit 2, the best layout still written.
sed -e 's/set Starts                 = 2/set Starts = 1\n  set Max evaluations = 2/' \
    -e 's/Base name = paper/Base name = early/' paper.prm > early.prm
"$exe" optimize early.prm > early.txt 2> early_err.txt
rc=$?
[ $rc -eq 2 ] && ok "stopped early: exit 2" || fail "stopped early: exit $rc"
grep -q "without converging" early_err.txt && ok "says so on stderr" || fail "stderr: $(cat early_err.txt)"
"$PYTHON" -c "
import h5py; f = h5py.File('out/early_optimum.h5', 'r')
assert f.attrs['converged'] == 0 and len(f.attrs['voltages_kV']) == 2" \
  && ok "the best layout is written (converged = 0)" || fail "early file"

# Two ranks: the starts are dealt round-robin; the same file contents.
if command -v mpirun > /dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
  sed 's/Directory = out/Directory = parallel/' paper.prm > parallel.prm
  # (mpirun starts the real executable on each rank)
  timeout 300 mpirun --oversubscribe -np 2 "$real_exe" optimize parallel.prm > par.txt 2> par_err.txt
  rc=$?
  [ $rc -eq 0 ] && ok "mpirun -np 2 exits 0" || { fail "mpirun exit $rc"; cat par_err.txt; }
  [ "$(grep -c 'Optimum (start' par.txt)" = 1 ] && ok "one summary (rank 0)" || fail "summaries: $(grep -c 'Optimum' par.txt)"
  "$PYTHON" - out/paper_optimum.h5 parallel/paper_optimum.h5 <<'PY' && ok "same attributes and history as the serial run" || fail "serial and parallel differ"
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
for k in a.attrs:
    if k == "parameters":
        continue
    assert np.array_equal(np.asarray(a.attrs[k]), np.asarray(b.attrs[k])), k
for k in ["history/objective", "history/free_values", "starts/objective"]:
    assert np.array_equal(a[k][()], b[k][()], equal_nan=True), k
PY
else
  fail "mpirun not found (Debian: openmpi-bin)"
fi

# Bad input: one message naming the parameter, exit 1, nothing written.
sed -e 's/set Fixed voltages (kV)    = 5, free/set Fixed voltages (kV) = 5/' \
    -e 's/Directory = out/Directory = bad/' paper.prm > bad.prm
"$exe" optimize bad.prm > bad.txt 2> bad_err.txt
rc=$?
[ $rc -eq 1 ] && grep -q "Optimization/Fixed voltages (kV)" bad_err.txt && [ ! -e bad ] \
  && [ "$(wc -l < bad_err.txt)" -le 1 ] \
  && ok "bad input: $(head -c 150 bad_err.txt)" || fail "bad input: exit $rc, $(cat bad_err.txt)"
# Quasi-static elastic equilibria only: a time run is refused by name.
{ sed 's/Directory = out/Directory = timed/' paper.prm
  printf 'subsection Time\n  set Enabled = true\nend\n'; } > timed.prm
"$exe" optimize timed.prm > timed.txt 2> timed_err.txt
rc=$?
[ $rc -eq 1 ] && grep -q "Time/Enabled = true is not supported by cdea optimize" timed_err.txt \
  && [ ! -e timed ] && [ "$(wc -l < timed_err.txt)" -le 1 ] \
  && ok "time run refused: $(head -c 110 timed_err.txt)" || fail "time run: exit $rc, $(cat timed_err.txt)"
for case in "Fixed ring edges (r/a) = 1.5,|Optimization/Fixed ring edges (r/a): empty entry at the end" \
            "Fixed voltages (kV) = 5, 2000|Optimization/Fixed voltages (kV): 2000 kV is above the voltage ceiling" \
            "Voltage bounds (kV) = 0, 1e5|Optimization/Voltage bounds (kV): the upper bound 100000 kV is above the voltage ceiling"; do
  entry=${case%%|*} expect=${case#*|}
  { sed 's/Directory = out/Directory = range/' paper.prm; printf 'subsection Optimization\n  set %s\nend\n' "$entry"; } > range.prm
  "$exe" optimize range.prm > range.txt 2> range_err.txt
  rc=$?
  [ $rc -eq 1 ] && grep -qF "$expect" range_err.txt && [ ! -e range ] \
    && ok "refused: $(head -c 120 range_err.txt)" || fail "'$entry': exit $rc, $(cat range_err.txt)"
done

# Another process holds the output's lock: exit 1 at once, nothing computed.
mkdir -p locked
sed 's/Directory = out/Directory = locked/' paper.prm > locked.prm
# The shell itself holds the lock (no child that could outlive the test and
# keep ctest's output pipe open); the command does not inherit descriptor 9.
exec 9> locked/paper_optimum.h5.lock
flock 9
"$exe" optimize locked.prm > locked.txt 2> locked_err.txt 9>&-
rc=$?
exec 9>&-
[ $rc -eq 1 ] && grep -q "paper_optimum.h5" locked_err.txt && ! grep -q "Optimum" locked.txt \
  && [ ! -e locked/paper_optimum.h5 ] && ok "locked output: exit 1 ($(head -c 100 locked_err.txt))" \
  || fail "locked output: exit $rc, $(cat locked_err.txt)"

# No start reaches a layout (the inner ring far past the fold): exit 2, the
# output folders the run made are gone again.
{ sed 's/Directory = out/Directory = unreachable\/deeper/' paper.prm
  printf 'subsection Optimization\n  set Fixed voltages (kV) = 900, free\n  set Voltage bounds (kV) = 0, 1000\nend\n'; } > unreachable.prm
"$exe" optimize unreachable.prm > unreachable.txt 2> unreachable_err.txt
rc=$?
[ $rc -eq 2 ] && grep -q "no start reached a layout" unreachable_err.txt && [ ! -e unreachable ] \
  && ok "no start reaches a layout: exit 2, nothing left" \
  || fail "unreachable: exit $rc, $(ls unreachable 2>&1), $(cat unreachable_err.txt)"

# SIGTERM while the starts run: they stop, the best layout so far is written.
cat > eight.prm <<'EOF'
subsection Optimization
  set Rings  = 8
  set Starts = 8
end
subsection Output
  set Directory = term
  set Base name = eight
end
EOF
"$exe" optimize eight.prm > term.txt 2> term_err.txt &
runner=$!
for _ in $(seq 200); do grep -q "^ *0 *[0-9]" term.txt 2> /dev/null && break; sleep 0.05; done
kill -TERM $runner
wait $runner
rc=$?
"$PYTHON" -c "
import h5py; f = h5py.File('term/eight_optimum.h5', 'r')
assert len(f.attrs['voltages_kV']) == 8 and f.attrs['converged'] == 0" 2> /dev/null
readable=$?
[ $rc -eq 2 ] && grep -q "interrupted by SIGTERM" term_err.txt && [ $readable -eq 0 ] \
  && [ -z "$(ls term | grep -v '^eight_optimum\.\(h5\|prm\)$')" ] \
  && ok "SIGTERM: exit 2, the best layout so far written, nothing else left" \
  || fail "SIGTERM: exit $rc, readable $readable, $(ls term), $(cat term_err.txt)"

touch blocker
sed 's/Directory = out/Directory = blocker\/sub/' paper.prm > blocked.prm
"$exe" optimize blocked.prm > blocked.txt 2> blocked_err.txt
rc=$?
[ $rc -eq 1 ] && grep -q "blocker/sub" blocked_err.txt && ok "unwritable output: exit 1" \
  || fail "unwritable output: exit $rc, $(cat blocked_err.txt)"

echo "$failures failed"
[ $failures -eq 0 ]
