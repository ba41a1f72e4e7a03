#!/usr/bin/env bash
# Results that survive a damaged journal, a deleted lock file, write failures
# before and at the first steps, and a ParaView output whose folder vanishes:
# nothing is deleted that was not recovered whole, and every exit code and
# file left is checked (h5py reads every file).
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/long_runs.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"

prm long.prm 0.003
prm other.prm 0.003 281
prm verylong.prm 0.0002
prm paraview.prm 0.01 280 'subsection Output\n  set ParaView = true\n  set ParaView segments = 8\nend\n'
rows() { # FILE: rows of /summary (one /steps group each), or "unreadable"
  "$PYTHON" -c "
import sys, h5py
with h5py.File(sys.argv[1], 'r') as f:
    n = f['summary/stage'].shape[0]
    assert len(f['steps']) == n
    print(n)" "$1" 2> /dev/null || echo unreadable
}
flip() { # FILE OFFSET: invert one byte
  "$PYTHON" -c "
import sys
with open(sys.argv[1], 'r+b') as f:
    f.seek(int(sys.argv[2])); b = f.read(1); f.seek(int(sys.argv[2])); f.write(bytes([b[0] ^ 0xff]))" "$1" "$2"
}

# 1. A killed run leaves a journal and a checkpoint; then the journal is damaged.
rm -rf out
# (the real executable: SIGKILL, which a fork client cannot forward)
CDEA_CHECKPOINT_SECONDS=0.2 "$real_exe" run verylong.prm > k.out 2> k.err & pid=$!
wait_for_steps k.out 1500; kill -KILL $pid; bounded_wait $pid 2> /dev/null
printed=$(steps_printed k.out)
[ -e out/long.h5.journal ] && [ -e out/long.partial.h5 ] || fail "kill left $(ls out)"
cp -r out killed
checkpoint=$(rows out/long.partial.h5)

# 1a. The first record damaged: exit 2, the checkpoint's steps recovered,
#     journal and checkpoint kept; the next run refuses to start (exit 1).
flip out/long.h5.journal 10
sum=$(sha256sum < out/long.h5.journal)
"$exe" recover out/long.h5 > r.out 2> r.err; rc=$?
if [ $rc -eq 2 ] && grep -q "is damaged at byte 8" r.err && [ "$(rows out/long.h5)" = "$checkpoint" ] \
   && [ "$(sha256sum < out/long.h5.journal)" = "$sum" ] && [ "$(rows out/long.partial.h5)" = "$checkpoint" ]; then
  ok "first record damaged: exit 2, the checkpoint's $checkpoint steps recovered, journal and checkpoint kept"
else fail "first record damaged: exit $rc, $(cat r.err r.out) rows $(rows out/long.h5) ($(ls out))"; fi
"$exe" run other.prm > n.out 2> n.err; rc=$?
if [ $rc -eq 1 ] && grep -q "is damaged at byte 8" n.err && [ "$(sha256sum < out/long.h5.journal)" = "$sum" ] \
   && [ -e out/long.partial.h5 ]; then
  ok "the next run onto a damaged journal: exit 1, journal kept: $(head -c 200 n.err)"
else fail "run onto a damaged journal: exit $rc, $(cat n.err) ($(ls out))"; fi

# 1b. A record in the middle damaged: the steps before it (or the checkpoint's,
#     if more) recovered, exit 2, the journal kept whole.
rm -rf out; cp -r killed out
size=$(stat -c %s out/long.h5.journal)
flip out/long.h5.journal $((size / 2))
sum=$(sha256sum < out/long.h5.journal)
"$exe" recover out/long.h5 > r.out 2> r.err; rc=$?
got=$(rows out/long.h5)
if [ $rc -eq 2 ] && grep -q "is damaged at byte" r.err && [ "$got" != unreadable ] \
   && [ "$got" -ge "$checkpoint" ] && [ "$got" -ge $((printed / 3)) ] && [ "$got" -lt "$printed" ] \
   && [ "$(sha256sum < out/long.h5.journal)" = "$sum" ]; then
  ok "middle record damaged: exit 2, $got of $printed steps recovered, journal kept: $(head -c 240 r.err)"
else fail "middle record damaged: exit $rc, rows $got of $printed: $(cat r.err r.out)"; fi

# 1c. The last record cut short (a kill during its write): every whole step
#     recovered (the cut one was the last printed), exit 0, the journal removed.
rm -rf out; cp -r killed out
truncate -s -100 out/long.h5.journal
"$exe" recover out/long.h5 > r.out 2> r.err; rc=$?
got=$(rows out/long.h5)
if [ $rc -eq 0 ] && [ "$got" -ge $((printed - 1)) ] && [ ! -e out/long.h5.journal ] && [ ! -e out/long.partial.h5 ]; then
  ok "last record cut short: exit 0, $got steps: $(cat r.out)"
else fail "last record cut short: exit $rc, rows $got of $printed: $(cat r.err r.out)"; fi

# 1d. An empty journal: nothing to recover, exit 1.
rm -rf out; mkdir out; : > out/long.h5.journal
"$exe" recover out/long.h5 > r.out 2> r.err; rc=$?
[ $rc -eq 1 ] && grep -q "nothing to recover" r.err && ok "empty journal: exit 1: $(cat r.err)" \
  || fail "empty journal: exit $rc, $(cat r.out r.err)"

# 2. The lock file deleted while a run writes: a second run must not take
#    the first's live journal (the journal's own flock); the first finishes.
rm -rf out
( with_sigint "$exe" run verylong.prm ) > a.out 2> a.err & first=$!
wait_for_steps a.out 5
rm -f out/long.h5.lock
"$exe" run other.prm > b.out 2> b.err; rc=$?
if [ $rc -eq 1 ] && grep -q "still writing the journal" b.err && [ -e out/long.h5.journal ] \
   && [ ! -e out/long.recovered.h5 ]; then
  ok "lock file deleted: the second run exits 1 and leaves the journal: $(head -c 200 b.err)"
else fail "lock file deleted: second run exit $rc, $(cat b.err) ($(ls out))"; fi
kill -INT $first 2> /dev/null; bounded_wait $first; rc=$?
got=$(rows out/long.h5)
# (On a fast machine it may have ended meanwhile: exit 0.)
if { [ $rc -eq 2 ] || [ $rc -eq 0 ]; } && [ "$got" != unreadable ] && [ "$got" -ge "$(steps_printed a.out)" ]; then
  ok "the first run (exit $rc) has its $got steps"
else fail "first run after the lock was deleted: exit $rc, rows $got, $(cat a.err)"; fi

# 3. Write failures from the first byte on (ulimit -f in kB): exit 1 with
#    nothing left, or exit 2 with a readable file; never a journal of 0 steps.
for limit in 4 8 100 300; do
  rm -rf out
  (ulimit -f $limit; exec "$exe" run long.prm > w.out 2> w.err); rc=$?
  if [ $rc -eq 1 ] && [ ! -e out ] && ! grep -q "0 steps" w.err; then
    ok "ulimit -f $limit: exit 1, nothing left: $(head -c 200 w.err)"
  elif [ $rc -eq 2 ] && got=$(rows out/long.h5) && [ "$got" != unreadable ] && [ "$got" -ge 1 ]; then
    ok "ulimit -f $limit: exit 2, $got steps in out/long.h5"
  else fail "ulimit -f $limit: exit $rc, $(cat w.err) ($(ls out 2> /dev/null))"; fi
done

# 4. ParaView: the output directory moved away mid-run: exit 2, the HDF5
#    results written, the final lines printed, a message about ParaView.
rm -rf out pvgone
"$exe" run paraview.prm > v.out 2> v.err & pid=$!
wait_for_steps v.out 20; mv out pvgone; bounded_wait $pid; rc=$?
got=$(rows out/long.h5)
if [ $rc -eq 2 ] && grep -q "ParaView output is incomplete" v.err && grep -q "^Final state" v.out \
   && [ "$got" != unreadable ] && [ "$got" -ge "$(steps_printed v.out)" ]; then
  ok "ParaView folder gone: exit 2, $got steps in out/long.h5: $(grep ParaView v.err | head -c 200)"
else fail "ParaView folder gone: exit $rc, rows $got, $(cat v.err)"; fi
# An older ParaView output stays whole until the new one is complete: a run
# stopped by the file size limit keeps it, and no step file is cut short.
rm -rf out pvgone
"$exe" run paraview.prm > /dev/null 2>&1
old=$(cat out/long_vtu/*.vtu | sha256sum)
(ulimit -f 200; exec "$exe" run paraview.prm > u.out 2> u.err); rc=$?
bad=0
for f in out/long_vtu/*.vtu; do tail -c 20 "$f" | grep -q "</VTKFile>" || bad=$((bad + 1)); done
if [ $rc -eq 2 ] && [ $bad -eq 0 ] && { [ "$(cat out/long_vtu/*.vtu | sha256sum)" = "$old" ] ||
   [ "$(ls out/long_vtu | wc -l)" -ge 1 ]; } && [ -e out/long.pvd ]; then
  ok "ParaView under ulimit -f 200: exit 2, $(ls out/long_vtu | wc -l) whole VTU files in place"
else fail "ParaView under ulimit -f 200: exit $rc, $bad cut short, $(cat u.err)"; fi

finish
