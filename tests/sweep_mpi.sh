#!/usr/bin/env bash
# `cdea sweep` serial and under `mpirun -np 2`: the two map files must hold the
# same data bit for bit (the rows are dealt round-robin to the ranks and each is
# computed from scratch; rank 0 gathers them) and, having no run-dependent
# content, be the same bytes. Also: rank 0 alone prints (one table, one
# progress report), plain progress lines under mpirun without being told to,
# bad input under mpirun (one message, non-zero exit, no file), and
# postprocess/plot_map.py on the result. Needs mpirun (Debian: openmpi-bin) and
# python3 with h5py.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/python_forks.bash"

command -v mpirun > /dev/null || { echo "FAIL mpirun not found (Debian: openmpi-bin)"; exit 1; }
# Root (containers, CI) needs the explicit permission; allow more ranks than
# cores; no shared-memory single-copy (needs ptrace rights that containers lack).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
mpirun_() { timeout 300 mpirun --oversubscribe -np "$@"; }

# 7 layouts x 13 outer voltages: folds inside the range for small r_v/a,
# both lines everywhere, one grid point below the inner voltage.
sed -e 's/set Ring edge values (r\/a)   = 1.2, 1.25, ..., 2.6/set Ring edge values (r\/a)   = 1.2, 1.4, ..., 2.4/' \
    -e 's/set Outer voltage range (kV) = 5, 8, 0.05/set Outer voltage range (kV) = 4.75, 7.75, 0.25/' \
    -e 's/set Base name           = sweep-inner5/set Base name           = small/' \
    "$src/prm/sweep-inner5.prm" > small.prm
mkdir serial parallel
(cd serial && CDEA_PROGRESS=lines CDEA_PROGRESS_SECONDS=0 "$exe" sweep ../small.prm > out.txt 2> err.txt)
rc_s=$?
# No CDEA_PROGRESS here: under mpirun the program itself must choose plain
# lines (each rank's stdout is a pseudo-terminal of OpenMPI's).
(cd parallel && CDEA_PROGRESS_SECONDS=0 mpirun_ 2 -x CDEA_PROGRESS_SECONDS "$exe" sweep ../small.prm > out.txt 2> err.txt)
rc_p=$?
[ $rc_s -eq 0 ] && ok "serial run exits 0" || { fail "serial run exit $rc_s"; cat serial/err.txt; }
[ $rc_p -eq 0 ] && ok "mpirun -np 2 exits 0" || { fail "mpirun exit $rc_p"; cat parallel/err.txt parallel/out.txt; }
f_s=serial/results/small_map.h5
f_p=parallel/results/small_map.h5
if [ -s $f_s ] && [ -s $f_p ]; then
  ok "both map files written"
  "$PYTHON" - "$f_s" "$f_p" <<'PY' && ok "every dataset and attribute bit-identical (serial vs 2 ranks)" || fail "datasets differ"
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
bad = 0
if sorted(a.keys()) != sorted(b.keys()):
    print("dataset names differ"); bad += 1
for k in a.keys():
    x, y = a[k][()], b[k][()]
    if x.dtype.kind == "f":
        same = x.shape == y.shape and np.array_equal(x.view(np.uint64), y.view(np.uint64))
    else:
        same = x.shape == y.shape and np.array_equal(x, y)
    if not same:
        print("dataset differs:", k); bad += 1
for k in a.attrs.keys():
    if not np.array_equal(np.asarray(a.attrs[k]), np.asarray(b.attrs[k])):
        print("attribute differs:", k); bad += 1
d = a["displacement_mm"][()]
if not (np.isnan(d).any() and (~np.isnan(d)).sum() > 40):
    print("expected NaN beyond folds and many reached points"); bad += 1
sys.exit(1 if bad else 0)
PY
  cmp -s $f_s $f_p && ok "the two files are the same bytes" || fail "files differ in bytes (data identical?)"
else
  fail "map file missing: $(ls -R)"
fi
n_s=$(grep -c "^largest stroke increase on the red line" serial/out.txt)
n_p=$(grep -c "^largest stroke increase on the red line" parallel/out.txt)
[ "$n_s" = 1 ] && [ "$n_p" = 1 ] && ok "one result table (rank 0 only)" || fail "result tables: serial $n_s, parallel $n_p"
grep -q "2 ranks" parallel/out.txt && ok "the parallel run reports 2 ranks" || fail "no '2 ranks' in the output"
# Progress: plain lines (not a terminal), points done / total / time left, ending at 91/91.
if grep -q "progress: [0-9]*/91 points (.* %), .* elapsed, .* left" parallel/out.txt &&
   grep -q "progress: 91/91 points (100 %)" parallel/out.txt &&
   grep -q "progress: 91/91 points (100 %)" serial/out.txt &&
   ! grep -q $'\r' parallel/out.txt; then
  ok "plain progress lines: $(grep -c progress: parallel/out.txt) on 2 ranks, last: $(grep progress: parallel/out.txt | tail -n 1)"
else
  fail "progress lines:"; grep progress parallel/out.txt serial/out.txt | head
fi
[ ! -s parallel/err.txt ] && ok "nothing on stderr" || { fail "stderr not empty:"; cat parallel/err.txt; }

# Bad input under mpirun: one message, non-zero exit, no file.
sed -e 's/set Outer voltage range (kV) = 4.75, 7.75, 0.25/set Outer voltage range (kV) = 5, 8, -0.25/' \
    -e 's/set Base name           = small/set Base name           = bad/' small.prm > bad.prm
mkdir bad && (cd bad && mpirun_ 2 "$exe" sweep ../bad.prm > out.txt 2> err.txt)
rc=$?
if [ $rc -ne 0 ] && [ "$(grep -c "the step must be positive" bad/err.txt)" = 1 ] && [ ! -e bad/results ]; then
  ok "bad input under mpirun: exit $rc, one message: $(grep "step must" bad/err.txt)"
else
  fail "bad input under mpirun: exit $rc, stderr:"; cat bad/err.txt
fi

# The plots of the map.
if "$PYTHON" "$src/postprocess/plot_map.py" $f_s --out plots --combined plots/both.png --paper \
     --rows --find-increase 1.6:20 > plot.txt 2>&1 &&
   [ -s plots/small_map.png ] && [ -s plots/small_increase.png ] && [ -s plots/both.png ] &&
   grep -q "largest stroke increase on the red line" plot.txt && grep -q "reaches 20 %" plot.txt; then
  ok "plot_map.py wrote small_map.png, small_increase.png and both.png"
else
  fail "plot_map.py:"; cat plot.txt
fi
"$PYTHON" "$src/postprocess/plot_map.py" does-not-exist_map.h5 > perr.txt 2>&1 &&
  fail "plot_map.py on a missing file exits 0" ||
  { grep -q "plot_map.py: error: no such file" perr.txt && ok "plot_map.py: missing file rejected" || fail "plot_map.py message: $(cat perr.txt)"; }
"$PYTHON" -c "import h5py, sys; h5py.File(sys.argv[1], 'w').create_dataset('x', data=[1])" other.h5
"$PYTHON" "$src/postprocess/plot_map.py" other.h5 > perr.txt 2>&1 &&
  fail "plot_map.py on a non-map file exits 0" ||
  { grep -q "not a cdea map file" perr.txt && ok "plot_map.py: non-map file rejected" || fail "plot_map.py message: $(cat perr.txt)"; }

finish
