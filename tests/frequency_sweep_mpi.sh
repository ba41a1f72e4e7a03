#!/usr/bin/env bash
# `cdea frequency-sweep` serial and under `mpirun -np 2` on a coarse mesh at 3
# frequencies: the frequencies are dealt round-robin to the ranks, each solved
# from scratch, and rank 0 gathers them, so every dataset and attribute must be
# bit-identical to the serial run's, except the computing times (the
# `seconds` dataset and attribute). Also: rank 0 alone prints (one table, one
# summary, one progress report), and bad input under mpirun gives one message,
# a non-zero exit and no file. Needs mpirun (Debian: openmpi-bin) and python3
# with h5py.
source "$(dirname "$0")/script_helpers.bash"

command -v mpirun > /dev/null || { echo "FAIL mpirun not found (Debian: openmpi-bin)"; exit 1; }
# As in tests/sweep_mpi.sh: root (containers, CI) needs the explicit
# permission; more ranks than cores; no shared-memory single-copy.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
mpirun_() { timeout 300 mpirun --oversubscribe -np "$@"; }

prm="$src/prm/frequency-sweep.prm"
small=(--set 'Discretization/Elements per ring=2' --set 'Discretization/Polynomial degree=2'
       --set 'Frequency sweep/Frequencies (Hz)=3, 6, 12')
# The same command line in two folders (the parameters attribute holds it).
mkdir serial parallel
(cd serial && "$exe" frequency-sweep "$prm" "${small[@]}" > ../serial.txt 2> ../serial.err)
rc_s=$?
(cd parallel && CDEA_PROGRESS_SECONDS=0 mpirun_ 2 -x CDEA_PROGRESS_SECONDS "$exe" frequency-sweep \
   "$prm" "${small[@]}" > ../parallel.txt 2> ../parallel.err)
rc_p=$?
[ $rc_s -eq 0 ] && ok "serial run exits 0" || { fail "serial run exit $rc_s"; cat serial.err; }
[ $rc_p -eq 0 ] && ok "mpirun -np 2 exits 0" || { fail "mpirun exit $rc_p"; cat parallel.err parallel.txt; }
f_s=serial/results/frequency-sweep_frequency_sweep.h5
f_p=parallel/results/frequency-sweep_frequency_sweep.h5
if [ -s $f_s ] && [ -s $f_p ]; then
  "$PYTHON" - "$f_s" "$f_p" <<'PY' && ok "datasets and attributes bit-identical (serial vs 2 ranks; seconds excepted)" || fail "results differ"
import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
bad = 0
names = sorted(a["sweep"].keys())
if names != sorted(b["sweep"].keys()):
    print("dataset names differ"); bad += 1
for k in names:
    if k == "seconds":
        continue
    x, y = a["sweep"][k][()], b["sweep"][k][()]
    same = x.shape == y.shape and (np.array_equal(x.view(np.uint64), y.view(np.uint64))
                                   if x.dtype.kind == "f" else np.array_equal(x, y))
    if not same:
        print("dataset differs:", k, x, y); bad += 1
if sorted(a.attrs.keys()) != sorted(b.attrs.keys()):
    print("attribute names differ"); bad += 1
for k in a.attrs.keys():
    if k != "seconds" and not np.array_equal(np.asarray(a.attrs[k]), np.asarray(b.attrs[k]),
                                             equal_nan=np.asarray(a.attrs[k]).dtype.kind == "f"):
        print("attribute differs:", k); bad += 1
if a["sweep/frequency_Hz"].shape != (3,) or not a["sweep/converged"][()].all():
    print("expected 3 converged frequencies"); bad += 1
sys.exit(1 if bad else 0)
PY
else
  fail "sweep file missing: $(ls -R)"
fi
n_s=$(grep -c "^quasi-static stroke amplitude" serial.txt)
n_p=$(grep -c "^quasi-static stroke amplitude" parallel.txt)
n_rows=$(grep -cE "^ +(3|6|12) +[0-9]" parallel.txt)
[ "$n_s" = 1 ] && [ "$n_p" = 1 ] && [ "$n_rows" = 3 ] && grep -q "on 2 ranks" parallel.txt &&
  ok "rank 0 alone prints: one table of 3 rows, one summary, '2 ranks'" ||
  { fail "output: summaries serial $n_s, parallel $n_p, rows $n_rows"; cat parallel.txt; }
# Rank 0's report alone: each count once (3/3 again at the end).
grep -q "progress: 3/3 frequencies (100 %)" parallel.txt && [ "$(grep -c 'progress: 1/3' parallel.txt)" -le 1 ] &&
  [ "$(grep -c 'progress: 2/3' parallel.txt)" -le 1 ] && [ "$(grep -c 'progress:' parallel.txt)" -le 4 ] &&
  ok "one progress report: $(grep progress: parallel.txt | tail -n 1)" ||
  { fail "progress lines:"; grep progress parallel.txt; }
[ ! -s parallel.err ] && ok "nothing on stderr" || { fail "stderr not empty:"; cat parallel.err; }

# Bad input under mpirun: one message, non-zero exit, no file.
mkdir bad && (cd bad && mpirun_ 2 "$exe" frequency-sweep "$prm" \
  --set 'Frequency sweep/Frequencies (Hz)=6, 3' > ../bad.txt 2> ../bad.err)
rc=$?
if [ $rc -ne 0 ] && [ "$(grep -c "must be increasing frequencies" bad.err)" = 1 ] &&
   [ ! -e bad/results ]; then
  ok "bad input under mpirun: exit $rc, one message: $(grep "must be increasing" bad.err)"
else
  fail "bad input under mpirun: exit $rc, stderr:"; cat bad.err
fi
finish
