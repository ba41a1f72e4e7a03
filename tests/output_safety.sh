#!/usr/bin/env bash
# Results that survive concurrent runs, re-runs killed early, a vanished
# output directory, a file size limit (a full disk) and a closed stdout pipe;
# `cdea recover` with nothing to recover. Every file is read back with h5py.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/long_runs.bash"
source "$(dirname "$0")/python_forks.bash"
source "$(dirname "$0")/cdea_forks.bash"

prm short.prm 0.25
prm long.prm 0.003
prm other.prm 0.003 281
prm verylong.prm 0.0002 # 25,000 steps: still running when the second run starts
# h5check FILE MIN_ROWS [MASS]: readable, at least MIN_ROWS rows, one group
# per row, made with the given mass
h5check() {
  "$PYTHON" - "$@" <<'PY'
import sys, h5py
path, least = sys.argv[1], int(sys.argv[2])
with h5py.File(path, "r") as f:
    n = f["summary/stage"].shape[0]
    assert n >= least and len(f["steps"]) == n, (n, least, len(f["steps"]))
    if len(sys.argv) > 3:
        mass = [l.split("=")[1].strip() for l in f.attrs["parameters"].splitlines()
                if "set Mass (g)" in l]
        assert mass == [sys.argv[3]], mass
    print(n, f.attrs["run_status"])
PY
}

# 1. A second run onto the same file fails at once; the first goes on.
# (the real executable: its pid is the one the lock file names)
( with_sigint "$real_exe" run verylong.prm ) > a.out 2> a.err &
first=$!
wait_for_steps a.out 5
start=$(date +%s.%N)
"$exe" run other.prm > b.out 2> b.err
rc=$?
took=$("$PYTHON" -c 'import sys; print("%.2f" % (float(sys.argv[1]) - float(sys.argv[2])))' "$(date +%s.%N)" "$start")
if [ $rc -eq 1 ] && grep -q "another cdea process (pid $first) is writing out/long.h5" b.err; then
  ok "second writer refused with exit 1 in $took s: $(cat b.err)"
else fail "second writer: exit $rc, $(cat b.err)"; fi
# (On a busy machine the first may have ended meanwhile: exit 0.)
kill -INT $first 2> /dev/null; bounded_wait $first; rc=$?
if { [ $rc -eq 0 ] || { [ $rc -eq 2 ] && grep -q interrupted a.err; }; } &&
   h5check out/long.h5 "$(steps_printed a.out)" 280 > /dev/null; then
  ok "the first run (exit $rc) has its own $(steps_printed a.out) steps (mass 280 g)"
else fail "first run after the refused second: exit $rc, $(cat a.err)"; fi
# Two started together: exactly one runs, and the file holds its steps alone.
rm -rf out
"$exe" run long.prm > c1.out 2> c1.err & p1=$!
"$exe" run other.prm > c2.out 2> c2.err & p2=$!
bounded_wait $p1; r1=$?; bounded_wait $p2; r2=$?
# (On a busy machine one may start only after the other ended: both exit 0,
# and the file is the later one's.)
case "$r1$r2" in
  01) mass=280 ;;
  10) mass=281 ;;
  00) mass=$(h5check out/long.h5 1600 280 > /dev/null 2>&1 && echo 280 || echo 281) ;;
  *) mass=none ;;
esac
if [ $mass != none ] && h5check out/long.h5 1600 $mass > /dev/null; then
  ok "two runs started together: exits $r1 and $r2, the file of one run alone (mass $mass g)"
else fail "two runs started together: exits $r1 and $r2: $(cat c1.err c2.err)"; fi

# 2. A re-run killed early leaves the older results; the next run saves the
#    killed run's steps beside them.
rm -rf out
"$exe" run short.prm > /dev/null 2>&1
old=$(sha256sum < out/long.h5)
# (the real executable: SIGKILL, which a fork client cannot forward)
"$real_exe" run other.prm > k.out 2> k.err & pid=$!
wait_for_steps k.out 3; kill -KILL $pid; bounded_wait $pid 2> /dev/null
[ "$(sha256sum < out/long.h5)" = "$old" ] && [ -e out/long.h5.journal ] \
  && ok "re-run killed after $(steps_printed k.out) steps: older file unchanged, journal kept" \
  || fail "re-run killed early changed the older file ($(ls out))"
"$exe" run short.prm > n.out 2> n.err
if [ $? -eq 0 ] && grep -q "did not finish its file" n.err && h5check out/long.recovered.h5 "$(steps_printed k.out)" 281 > /dev/null; then
  ok "the next run saved them: $(cat n.err)"
else fail "the next run: $(cat n.err) $(ls out)"; fi

# 3. The output directory vanishes mid-run: exit 2, steps written to the
#    directory created again, the message says so.
rm -rf out
"$exe" run long.prm > v.out 2> v.err & pid=$!
wait_for_steps v.out 50; rm -rf out; bounded_wait $pid; rc=$?
if [ $rc -eq 2 ] && grep -q "vanished" v.err && rows=$(h5check out/long.h5 "$(steps_printed v.out)"); then
  ok "vanished directory: exit 2, $rows in out/long.h5 again"
else fail "vanished directory: exit $rc, $(cat v.err)"; fi

# 4. A file size limit (a full disk): exit 2, no crash, the leading steps that
#    fit in a readable file; after the limit is lifted `cdea recover` gives
#    every step from the journal.
#    (2000 kB: the journal full after about 350 of the 1673 steps)
rm -rf out
(ulimit -f 2000; exec "$exe" run long.prm > f.out 2> f.err); rc=$?
if [ $rc -eq 2 ] && grep -q "File too large" f.err && rows=$(h5check out/long.h5 1) \
   && [ "$(stat -c %s out/long.h5)" -le 2048000 ]; then
  ok "ulimit -f 2000: exit 2, $rows ($(stat -c %s out/long.h5) bytes)"
else fail "ulimit -f 2000: exit $rc, $(cat f.err)"; fi
if "$exe" recover out/long.h5 > r.out 2> r.err && h5check out/long.recovered.h5 "$(steps_printed f.out)" > /dev/null; then
  ok "recover after the limit: $(cat r.out)"
else fail "recover after the limit: $(cat r.out r.err)"; fi
"$exe" recover out/long.h5 > /dev/null 2> r2.err
[ $? -eq 1 ] && grep -q "nothing to recover" r2.err && ok "recover with no journal: exit 1" \
  || fail "recover with no journal: $(cat r2.err)"

# 5. A closed stdout (| head) does not stop the run; the lost table is
# reported (exit 2, one line), the file is complete.
rm -rf out
"$exe" run long.prm 2> p.err | head -3 > /dev/null
rc=${PIPESTATUS[0]}
if [ $rc -eq 2 ] && grep -q "cannot write to standard output: the pipe was closed" p.err \
   && rows=$(h5check out/long.h5 1600) && [[ $rows == *complete ]]; then
  ok "cdea run | head -3: exit 2, $(head -c 70 p.err), $rows"
else fail "cdea run | head -3: exit $rc, $(cat p.err)"; fi

echo "$failures failed"
[ $failures -eq 0 ]
