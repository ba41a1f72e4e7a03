#!/usr/bin/env bash
# `cdea frequency-sweep` with bad input: one clear message on stderr that
# names the entry, exit code 1, and no output created; then a good run of one
# frequency on a coarse mesh writes its file. Starts from
# prm/frequency-sweep.prm and changes entries with --set. (The settings' checks
# and the steady states themselves are tested in-process by
# tests/test_steady_state.cc.)
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"

# case NAME "text the message must contain" --set ...
case_() {
  local name=$1 expect=$2
  shift 2
  "$exe" frequency-sweep "$src/prm/frequency-sweep.prm" --set "Output/Directory=out-$name" "$@" \
    > "$name.out" 2> "$name.err"
  local rc=$? ok=1
  [ $rc -eq 1 ] || { echo "FAIL $name: exit code $rc, not 1"; ok=0; }
  grep -qF -- "$expect" "$name.err" || { echo "FAIL $name: stderr lacks '$expect':"; cat "$name.err"; ok=0; }
  [ ! -e "out-$name" ] || { echo "FAIL $name: output was created"; ok=0; }
  [ $ok -eq 1 ] && echo "ok   $name: $(head -c 200 "$name.err")" || failures=$((failures + 1))
}

case_ empty-list "Frequency sweep/Frequencies" \
  --set "Frequency sweep/Frequencies (Hz)=" --set "Frequency sweep/Frequencies=0"
case_ negative "Frequency sweep/Frequencies (Hz)" --set "Frequency sweep/Frequencies (Hz)=1, -2"
case_ ramp-hold "Time/Waveform" --set "Time/Waveform=ramp-hold"
case_ time-off "Time/Enabled" --set "Time/Enabled=false" --set "Material/Model=elastic"

"$exe" frequency-sweep "$src/prm/frequency-sweep.prm" --set "Output/Directory=good" \
  --set "Frequency sweep/Frequencies (Hz)=6" --set "Discretization/Polynomial degree=2" \
  --set "Discretization/Elements per ring=2" > good.out 2> good.err
rc=$?
if [ $rc -eq 0 ] && [ -s good/frequency-sweep_frequency_sweep.h5 ] && grep -q "usable band" good.out; then
  ok "one frequency: $(grep -c '1/1,' good.out) progress lines, $(grep 'usable band' good.out)"
else
  fail "one frequency: exit code $rc"; cat good.out good.err
fi
finish
