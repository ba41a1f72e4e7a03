#!/usr/bin/env bash
# Early stops exit 2 with the converged steps in the file (README: exit 2
# means the run stopped before the end of its path): arc-length continuation
# when the dead load alone is past Max displacement and when Max arc-length
# steps runs out; load stepping past the fold of a 20 kV path with cut-backs
# allowed below the resolution of t, which reaches the stepper's check "the
# load parameter cannot advance" (a step that cannot change t is an error,
# not a loop).
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"

# arc NAME "extra Solver lines" [MASS]
arc() {
  sed -e "s|set Directory           = results|set Directory           = out-$1|" \
      -e "s/set Mass (g)            = 280/set Mass (g)            = ${3:-280}/" \
      "$src/prm/default.prm" > "$1.prm"
  printf 'subsection Solver\n  set Continuation = arc length\n%b\nend\n' "$2" >> "$1.prm"
  timeout 300 "$exe" run "$1.prm" > "$1.out" 2> "$1.err"
}
rows() {
  "$PYTHON" -c "import h5py, sys; print(h5py.File(sys.argv[1], 'r')['summary/stage'].shape[0])" "$1" 2> /dev/null || echo 0
}

arc heavy '' 5000
rc=$?
n=$(rows out-heavy/default.h5)
if [ $rc -eq 2 ] && grep -qi "displacement" heavy.err && [ "$n" -ge 1 ]; then
  ok "Mass 5000 g with arc length: exit 2, $n steps: $(head -c 200 heavy.err)"
else fail "Mass 5000 g with arc length: exit $rc, $n steps, $(cat heavy.err)"; fi

arc few '  set Max arc-length steps = 3'
rc=$?
n=$(rows out-few/default.h5)
if [ $rc -eq 2 ] && grep -q "Max arc-length steps reached" few.out few.err && [ "$n" -ge 3 ]; then
  ok "Max arc-length steps = 3: exit 2, $n steps in the file"
else fail "Max arc-length steps = 3: exit $rc, $n steps, $(cat few.err)"; fi

# Load stepping past the fold, 100 cut-backs, no smallest increment.
sed -e 's|set Directory           = results|set Directory           = out-stuck|' \
    -e 's/set Voltage path (kV)   = 5/set Voltage path (kV)   = 20/' "$src/prm/default.prm" > stuck.prm
printf 'subsection Solver\n  set Max cutbacks = 100\n  set Min voltage increment (kV) = 1e-300\nend\n' >> stuck.prm
timeout 120 "$exe" run stuck.prm > stuck.out 2> stuck.err
rc=$?
n=$(rows out-stuck/default.h5)
if [ $rc -eq 2 ] && grep -q "the load parameter cannot advance beyond t = 0.33" stuck.err \
   && [ "$n" -ge 50 ]; then
  ok "t cannot advance: exit 2, $n steps: $(head -c 160 stuck.err)"
else fail "t cannot advance: exit $rc, $n steps, $(cat stuck.err)"; fi

finish
