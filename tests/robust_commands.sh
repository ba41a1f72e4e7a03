#!/usr/bin/env bash
# Every command as safe as `run` (issues 22 and 31): input that names the
# line or parameter (subsection/end, nan/inf, '#' in a name, FIFOs and devices
# as input, includes and their loops, CR line ends, bounds of the work,
# no line quoted of a file that is not cdea's), `cdea fit` on data its start cannot reach (no crash: exit 1, the
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
ln -s /dev/zero zero.prm && printf 'include zero.prm\n' > inc.prm
expect "include of a device" 1 "cannot include 'zero.prm': it is not a regular file (a device)" "$exe" run inc.prm

# Issue 31: hostile parameter and table files (items 1, 2, 7, 8).
# nothing_quoted LABEL: stderr quotes no line of /etc/passwd
nothing_quoted() { ! grep -q "root:" err.txt && ok "$1: no line of the file quoted" || fail "$1 quoted: $(cat err.txt)"; }
table=(prm/response.prm --set Time/Waveform=table)
expect "Table file /dev/zero" 1 "Time/Table file '/dev/zero': the table must be a CSV file whose name ends in .csv" \
  "$exe" run "${table[@]}" --set 'Time/Table file=/dev/zero'
ln -s /dev/zero zero.csv
expect "Table file: a link to /dev/zero" 1 "cannot read 'zero.csv' (relative to the working directory: $PWD/zero.csv): it is not a regular file (a device)" \
  "$exe" run "${table[@]}" --set 'Time/Table file=zero.csv'
mkfifo table.csv
expect "Table file: a FIFO" 1 "cannot read 'table.csv' (relative to the working directory: $PWD/table.csv): it is not a regular file (a FIFO)" \
  "$exe" run "${table[@]}" --set 'Time/Table file=table.csv'
expect "Table file /etc/passwd" 1 "the table must be a CSV file" "$exe" run "${table[@]}" --set 'Time/Table file=/etc/passwd'
nothing_quoted "Table file /etc/passwd"
expect "fit data /etc/passwd" 1 "cannot read data file '/etc/passwd': the data must be a CSV file whose name ends in .csv" \
  "$exe" fit prm/fit-example.prm /etc/passwd
nothing_quoted "fit data /etc/passwd"
printf 'include self.prm\n' > self.prm
expect "a file that includes itself" 1 "in parameter file 'self.prm': line 1: cannot include 'self.prm': it is this file itself, an include loop: self.prm line 1 -> self.prm" \
  "$exe" run self.prm
printf 'include b.prm\n' > a.prm
printf 'subsection Loading\n  include a.prm\nend\n' > b.prm
expect "two files that include each other" 1 "in parameter file 'b.prm' (included from a.prm line 1): line 2: cannot include 'a.prm': it is 'a.prm', which includes this file, an include loop: a.prm line 1 -> b.prm line 2 -> a.prm" \
  "$exe" run a.prm
for k in $(seq 0 17); do printf 'include d%s.prm\n' $((k + 1)) > d$k.prm; done
expect "includes 17 deep" 1 "cannot include 'd17.prm': includes nest more than 16 deep: d0.prm line 1 -> " "$exe" run d0.prm
printf 'include /etc/passwd\n' > pw.prm
expect "include /etc/passwd" 1 "cannot include '/etc/passwd': only a parameter file (a name ending in .prm) can be included" \
  "$exe" run pw.prm
nothing_quoted "include /etc/passwd"
# A bare CR after a comment no longer swallows the next line (a bad mass
# there is found), nor does CR LF; an error names its line in either file.
printf '# a note\rsubsection Loading\r  set Mass (g) = -5\rend\r' > cr.prm
expect "bare CR line ends" 1 "Loading/Mass (g) must be zero or positive, got -5" "$exe" run cr.prm
printf '# a note\r\nsubsection Loading\r\n  set Mass (g) = nan\r\nend\r\n' > crlf.prm
expect "CR LF line ends" 1 "in parameter file 'crlf.prm': line 3: Loading/Mass (g) must be a finite number, got 'nan'" "$exe" run crlf.prm
printf 'subsection Output\n  set Base name = run#2\nend\n' > named.prm
printf '# the output\ninclude named.prm\n' > main.prm
expect "'#' in an included name" 1 "in parameter file 'named.prm' (included from main.prm line 2): line 2: Output/Base name = 'run#2': '#' starts a comment" \
  "$exe" run main.prm
printf 'subsection Loading\n  set Masss (g) = 2\nend\n' > typo.prm
printf '# one\n# two\ninclude typo.prm\n' > outer.prm
expect "an error in an included file" 1 "in parameter file 'typo.prm' (included from outer.prm line 3): line 2: subsection Loading has no entry 'Masss (g)' (cdea print-parameters lists every parameter)" \
  "$exe" run outer.prm
printf 'subsection Loading\n  include mass.prm\nend\n' > sub.prm
printf 'set Mass (g) = 300\r\n' > mass.prm
"$exe" run sub.prm --set 'Solver/Voltage increment (kV)=1' --set 'Output/Directory=inc' > out.txt 2> err.txt \
  && "$PYTHON" -c "import h5py; p = h5py.File('inc/default.h5')['/'].attrs['parameters']; assert 'set Mass (g)        = 300' in p, p" \
  && ok "an include inside a subsection with CR LF ends: its entry set (exit 0)" || fail "include in a subsection: $(cat err.txt)"
# Bounds: ParaView output (3600 segments x 4000 elements per ring), a frequency sweep
# of 100000 frequencies without its confirmation.
expect "ParaView output of 37 GB a step" 1 "Output/ParaView segments = 3600 with 64000 samples per step: a step's ParaView file would take about 37095 MB, more than the 256 MB allowed" \
  "$exe" run prm/paraview.prm --set 'Output/ParaView segments=3600' --set 'Discretization/Elements per ring=4000'
expect "100000 frequencies" 1 "Frequency sweep: 100000 frequencies are more than 1000 (each takes seconds or more: hours in all): set Frequency sweep/Confirm long sweep = true" \
  "$exe" frequency-sweep prm/frequency-sweep.prm --set 'Frequency sweep/Frequencies (Hz)=' --set 'Frequency sweep/Frequencies=100000'
expect "100001 frequencies" 1 "Frequency sweep/Frequencies must be between 1 and 100000, got 100001" \
  "$exe" frequency-sweep prm/frequency-sweep.prm --set 'Frequency sweep/Frequencies (Hz)=' --set 'Frequency sweep/Frequencies=100001'
many_edges=(--set 'Sweep/Ring edge values (r/a)=1.2, 1.21, ..., 2.6' --set 'Sweep/Outer voltage range (kV)=5, 8, 0.0003')
expect "a map of 1.4e6 points" 1 "the map would have 1.41014e+06 points, more than 1e+06 (minutes to hours of work): set Sweep/Confirm long sweep = true" \
  "$exe" sweep prm/sweep-inner5.prm "${many_edges[@]}"
expect "a map of 1.4e7 points" 1 "the map would have 1.40503e+07 points (281 x 50001), more than the 1e+07 it may hold in memory" \
  "$exe" sweep prm/sweep-inner5.prm --set 'Sweep/Ring edge values (r/a)=1.2, 1.205, ..., 2.6' \
  --set 'Sweep/Outer voltage range (kV)=5, 8, 0.00006' --set 'Sweep/Confirm long sweep=true'
# confirmed LABEL PATTERN FILE ARGS...: the confirmed long work starts, prints
# its estimate first, and stops cleanly on SIGTERM (a background job of a
# script ignores SIGINT), FILE (readable) all it leaves
confirmed() {
  local label=$1 pattern=$2 file=$3; shift 3
  rm -rf long
  "$real_exe" "$@" --set Output/Directory=long > out.txt 2> err.txt &
  local pid=$! rc
  for _ in $(seq 600); do grep -q "^work: " out.txt && break; sleep 0.05; done
  sleep 1.5 && kill -TERM $pid
  wait $pid
  rc=$?
  if [ $rc -eq 2 ] && grep -q -- "$pattern" out.txt && grep -q "interrupted by SIGTERM" err.txt \
     && [ "$(ls long)" = "$file" ] && "$PYTHON" -c "import h5py; h5py.File('long/$file')"; then
    ok "$label: $(grep -m1 '^work: ' out.txt | head -c 120); $(grep -m1 interrupted err.txt | head -c 120)"
  else
    fail "$label: exit $rc, $(grep -m1 '^work' out.txt), $(tail -c 300 err.txt), $(ls long)"
  fi
}
confirmed "1001 frequencies confirmed" "^work: 1001 periodic steady states" frequency-sweep_frequency_sweep.h5 \
  frequency-sweep prm/frequency-sweep.prm --set 'Frequency sweep/Frequencies (Hz)=' \
  --set 'Frequency sweep/Frequencies=1001' --set 'Frequency sweep/Confirm long sweep=true'
confirmed "a map of 1.4e6 points confirmed" "^work: 1410141 map points (the progress shows the time left), results about 56.5 MB" \
  sweep-inner5_map.h5 \
  sweep prm/sweep-inner5.prm "${many_edges[@]}" --set 'Sweep/Confirm long sweep=true'

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
mkdir folder.csv
expect "a directory as data file" 1 "cannot read data file 'folder.csv': it is a directory" "$exe" fit prm/fit-example.prm folder.csv

# cdea recover: regular files only, its exit codes.
mkdir rec
mkfifo rec/a.h5.journal
expect "recover: a FIFO journal" 1 "the journal rec/a.h5.journal is not a regular file (a FIFO" "$exe" recover rec/a.h5
ln -s /dev/zero rec/b.h5.journal
expect "recover: a link to /dev/zero as journal" 1 "the journal rec/b.h5.journal is a symbolic link, not a journal cdea wrote" "$exe" recover rec/b.h5
[ -L rec/b.h5.journal ] && ok "the link is kept" || fail "the journal link was removed"
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
