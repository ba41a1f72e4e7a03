#!/usr/bin/env bash
# `cdea sweep` with bad input: one clear message on stderr that names the
# parameter, a non-zero exit, and no output created. Starts from
# prm/sweep-inner5.prm and changes one entry per case. (Every check of the
# subsection Sweep is also tested in-process, without the process start-up
# per case, by tests/test_sweep.cc.)
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"

# case NAME "sed expression on prm/sweep-inner5.prm" "text the message must contain"
case_() {
  local name=$1 edit=$2 expect=$3
  sed -e "$edit" "$src/prm/sweep-inner5.prm" > "$name.prm"
  sed -i "s|set Directory           = results|set Directory           = out-$name|" "$name.prm"
  if cmp -s "$name.prm" "$src/prm/sweep-inner5.prm"; then
    echo "FAIL $name: the edit '$edit' changed nothing"; failures=$((failures + 1)); return
  fi
  "$exe" sweep "$name.prm" > "$name.out" 2> "$name.err"
  local rc=$?
  local ok=1
  [ $rc -ne 0 ] || { echo "FAIL $name: exit code 0"; ok=0; }
  grep -qF -- "$expect" "$name.err" || { echo "FAIL $name: stderr lacks '$expect':"; cat "$name.err"; ok=0; }
  [ "$(wc -l < "$name.err")" -le 1 ] || { echo "FAIL $name: more than one line on stderr"; ok=0; }
  [ ! -e "out-$name" ] || { echo "FAIL $name: output was created"; ok=0; }
  [ $ok -eq 1 ] && echo "ok   $name: $(head -c 200 "$name.err")" || failures=$((failures + 1))
}

edges='s/set Ring edge values (r\/a)   = 1.2, 1.25, ..., 2.6/set Ring edge values (r\/a)   = '
range='s/set Outer voltage range (kV) = 5, 8, 0.05/set Outer voltage range (kV) = '
inner='s/set Inner voltage (kV)       = 5$/set Inner voltage (kV)       = '

case_ rv-above-frame   "${edges}1.2, 3.2/"          "Sweep/Ring edge values (r/a): 3.2 is not inside (1, 3)"
case_ rv-decreasing    "${edges}2, 1.5/"            "Sweep/Ring edge values (r/a): values must increase strictly"
case_ rv-off-sequence  "${edges}1.2, 1.25, ..., 2.62/" "Sweep/Ring edge values (r/a): 2.62 after '...' is not on the sequence"
case_ range-empty      "${range}8, 5, 0.05/"        "Sweep/Outer voltage range (kV): the range is empty"
case_ range-negative-step "${range}5, 8, -0.05/"    "Sweep/Outer voltage range (kV): the step must be positive, got -0.05"
case_ inner-zero       "${inner}0/"                 "Sweep/Inner voltage (kV) must be positive"
case_ unknown-entry    's/set Inner voltage (kV)       = 5$/set Inner volts = 5/' "Inner volts"

# An output directory that cannot be created: a file is in the way.
sed -e "s|set Directory           = results|set Directory           = blocker/sub|" \
    "$src/prm/sweep-inner5.prm" > blocked.prm
touch blocker
"$exe" sweep blocked.prm > blocked.out 2> blocked.err
if [ $? -ne 0 ] && grep -q "blocker/sub" blocked.err && [ ! -e blocker/sub ]; then
  echo "ok   unwritable output: $(head -c 200 blocked.err)"
else
  echo "FAIL unwritable output: $(cat blocked.err)"; failures=$((failures + 1))
fi
# A missing parameter file.
"$exe" sweep does-not-exist.prm > /dev/null 2> missing.err
if [ $? -ne 0 ] && grep -q "does-not-exist.prm" missing.err; then echo "ok   missing file"; else echo "FAIL missing file"; failures=$((failures + 1)); fi

echo "$failures failed"
[ $failures -eq 0 ]
