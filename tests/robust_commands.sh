#!/usr/bin/env bash
# Every command as safe as `run` (issue 22): input that names the line or
# parameter (subsection/end, nan/inf, '#' in a name, FIFOs and devices as
# input), `cdea fit` on data its start cannot reach (no crash: exit 1, the
# point named, an older fit file kept) and on bad CSVs, write errors on
# stdout (exit 2), `cdea recover` on a FIFO, a device, a directory, a live
# journal, a journal appended to itself and a checkpoint without a journal.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"
cp -r "$src/prm" prm

expect() { # label expected-exit pattern command...
  local label=$1 code=$2 pattern=$3; shift 3
  timeout 60 "$@" > out.txt 2> err.txt
  local rc=$?
  if [ $rc -eq "$code" ] && grep -q -- "$pattern" err.txt && [ "$(wc -l < err.txt)" -le 3 ]; then
    ok "$label: exit $rc, $(grep -m1 -- "$pattern" err.txt | head -c 110)"
  else
    fail "$label: exit $rc (expected $code), stderr: $(head -c 400 err.txt)"
  fi
}

# Parameter files: the line and the subsection named.
printf 'subsection Loading\n  set Mass (g) = 200\nsubsection Material\n  set Jlim = 200\nend\n' > u1.prm
expect "subsection inside another" 1 "line 3: subsection 'Material' inside subsection 'Loading' (opened on line 1)" "$exe" run u1.prm
printf 'subsection Loading\n  set Mass (g) = 200\nend\nend\n' > u2.prm
expect "an end too many" 1 "line 4: 'end' without a subsection to close" "$exe" run u2.prm
printf 'subsection Loading\n  set Mass (g) = 200\n' > u3.prm
expect "an end missing" 1 "subsection 'Loading' (opened on line 1) has no 'end'" "$exe" run u3.prm
printf 'subsection Material\n  set Jlim = -inf\nend\n' > u4.prm
expect "inf in a file" 1 "line 2: Material/Jlim must be a finite number, got '-inf'" "$exe" run u4.prm
expect "nan as an override" 1 "Loading/Mass (g) must be a finite number, got 'nan'" \
  "$exe" run prm/default.prm --set 'Loading/Mass (g)=nan'
printf 'subsection Output\n  set Base name = run#2\nend\n' > u5.prm
expect "'#' in Base name" 1 "'#' starts a comment in a parameter file, so the value would be cut to 'run'" \
  "$exe" run u5.prm
expect "'#' in an override" 1 "'#' starts a comment" "$exe" run prm/default.prm --set 'Output/Base name=a#b'
# Time runs: a sine sampled too coarsely is refused with the step it needs.
expect "a 1 Hz sine in 1 s steps" 1 "Time/Time step (s) = 1 is too coarse for the sine of Time/Frequency (Hz) = 1: it needs at least 10 steps per period, a time step of at most 0.1 s" \
  "$exe" run prm/response.prm --set 'Time/Time step (s)=1'
[ ! -e results ] && ok "nothing written for bad input" || fail "bad input wrote $(ls results)"
mkfifo fifo.prm
expect "a FIFO as parameter file" 1 "it is not a regular file (a FIFO)" "$exe" run fifo.prm
printf 'include /dev/zero\n' > inc.prm
expect "include of a device" 1 "cannot include '/dev/zero': it is not a regular file (a device)" "$exe" run inc.prm

# A time run whose rings stay at 0 V says so (and still completes).
"$exe" run prm/response.prm --set 'Electrodes/Voltage path (kV)=0' --set 'Time/Cycles=1' \
  --set 'Time/Time step (s)=0.1' --set 'Time/Inertia=false' --set 'Output/Base name=no-drive' \
  > out.txt 2> err.txt
rc=$?
[ $rc -eq 0 ] && grep -q "warning: the drive never rose: every ring was at 0 V at every time step" err.txt \
  && [ -s results/no-drive.h5 ] && ok "a drive at 0 V: exit 0 with the warning" \
  || fail "a drive at 0 V: exit $rc, $(head -c 400 err.txt)"
"$exe" run prm/response.prm --set 'Time/Cycles=1' --set 'Time/Time step (s)=0.1' \
  --set 'Time/Inertia=false' --set 'Output/Base name=drive' > out.txt 2> err.txt
! grep -q "never rose" err.txt && ok "a drive that rises: no warning" || fail "a rising drive warned: $(cat err.txt)"
rm -rf results

# Write errors on stdout: exit 2 with a line; the work itself is done.
for command in "print-parameters" "--help" "--version" "print-parameters --json"; do
  "$exe" $command > /dev/full 2> err.txt
  rc=$?
  [ $rc -eq 2 ] && grep -q "cannot write to standard output" err.txt && ok "$command > /dev/full: exit 2" \
    || fail "$command > /dev/full: exit $rc, $(cat err.txt)"
done
"$exe" run prm/default.prm >&- 2> err.txt
rc=$?
[ $rc -eq 2 ] && grep -q "standard output: it was closed" err.txt && [ -s results/default.h5 ] \
  && ok "run >&-: exit 2, the file written" || fail "run >&-: exit $rc, $(cat err.txt)"

# cdea fit: a start that cannot reach a point, and bad data.
cp prm/fit-example.csv n.csv
echo "5.00, 7.20, 31.0" >> n.csv
"$exe" fit prm/fit-example.prm prm/fit-example.csv > /dev/null 2>&1
before=$(sha256sum results/fit-example_fit.h5)
expect "fit beyond the fold at the start" 1 "data point 21 (5, 7.2 kV) cannot be reached at shear modulus 20 kPa, Jlim 150: from zero voltage:" \
  "$exe" fit prm/fit-example.prm n.csv
grep -q "nor from data point 20 (5, 6.5 kV), the nearest point reached" err.txt \
  && ok "the continuation from the nearest point reached was tried" || fail "no continuation: $(cat err.txt)"
[ "$(sha256sum results/fit-example_fit.h5)" = "$before" ] && [ ! -e results/fit-example_fit.h5.lock ] \
  && ok "the older fit file kept, no lock" || fail "fit file or lock: $(ls results)"
printf '\xef\xbb\xbfV1_kV, V2_kV, displacement_mm\n1, 1, -18.4\n' > neg.csv
expect "negative displacement (after a BOM)" 1 "neg.csv, line 2, column displacement_mm: a displacement is the distance" \
  "$exe" fit prm/fit-example.prm neg.csv
printf 'V1_kV, V2_kV, displacement_mm\n1, 2000, 18.4\n' > high.csv
expect "a voltage above the film's ceiling" 1 "high.csv, line 2, column V2_kV: 2000 kV is above the ceiling of 1600 kV" \
  "$exe" fit prm/fit-example.prm high.csv
printf 'V1_kV, V2_kV\xc2\xa0, displacement_mm\n' > nbsp.csv
expect "an invisible byte in a column name" 1 "unknown column 'V2_kV\\\\xC2\\\\xA0'" "$exe" fit prm/fit-example.prm nbsp.csv
mkfifo fifo.csv
expect "a FIFO as data file" 1 "cannot read data file 'fifo.csv': it is not a regular file (a FIFO)" \
  "$exe" fit prm/fit-example.prm fifo.csv
expect "a directory as data file" 1 "cannot read data file 'prm': it is a directory" "$exe" fit prm/fit-example.prm prm

# cdea recover: regular files only, its exit codes.
mkdir rec
mkfifo rec/a.h5.journal
expect "recover: a FIFO journal" 1 "the journal rec/a.h5.journal is not a regular file (a FIFO" "$exe" recover rec/a.h5
ln -s /dev/zero rec/b.h5.journal
expect "recover: /dev/zero as journal" 1 "is not a regular file (a FIFO, device or socket)" "$exe" recover rec/b.h5
mkdir rec/c.h5.journal
expect "recover: a directory as journal" 1 "the journal rec/c.h5.journal is not a regular file (a directory)" \
  "$exe" recover rec/c.h5
sed 's/set Directory           = results/set Directory = kill/' prm/default.prm > long.prm
# (the real executable: SIGKILL below; tests/cdea_forks.bash)
CDEA_CHECKPOINT_SECONDS=0 "$real_exe" run long.prm --set 'Solver/Voltage increment (kV)=0.0005' > /dev/null 2>&1 &
pid=$!
for i in $(seq 100); do [ -s kill/default.partial.h5 ] && break; sleep 0.05; done
rm -f kill/default.h5.lock  # the journal's own flock still marks it live
expect "recover: a live journal" 1 "still writing the journal" "$exe" recover kill/default.h5
kill -KILL $pid; wait $pid 2> /dev/null
cp -r kill saved
"$PYTHON" -c "import sys; p = sys.argv[1]; d = open(p, 'rb').read(); open(p, 'wb').write(d + d[8:])" \
  kill/default.h5.journal
expect "recover: a journal appended to itself" 2 "is damaged at byte" "$exe" recover kill/default.h5
rows=$("$PYTHON" -c "import h5py; print(h5py.File('kill/default.h5')['summary/stage'].shape[0])")
grep -q "the $rows step(s) of the journal before the damage" err.txt \
  && ok "the rows reported are the rows written ($rows)" || fail "rows $rows: $(cat err.txt)"
rm -rf kill && mv saved kill && rm kill/default.h5.journal
"$exe" recover kill/default.h5 > out.txt 2> err.txt
rc=$?
[ $rc -eq 0 ] && grep -q "there is no journal kill/default.h5.journal; the checkpoint's" out.txt \
  && [ -s kill/default.h5 ] && [ ! -e kill/default.partial.h5 ] \
  && ok "recover: a checkpoint without a journal: $(head -c 100 out.txt)" || fail "checkpoint alone: exit $rc, $(cat out.txt err.txt)"
finish
