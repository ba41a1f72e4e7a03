#!/usr/bin/env bash
# Arc-length continuation stops early with exit 2 (README: exit 2 means the
# run stopped before the end of its path, every converged step in the file):
# when the dead load alone is past Max displacement, and when Max arc-length
# steps runs out. (The stepping check "the load parameter cannot advance"
# of the load stepper is not reached here: after validation it needs a path
# of about 1e5 waypoints, so that t's resolution exceeds the smallest
# increment, and a run of minutes; it is a guard, not a tested path.)
source "$(dirname "$0")/script_helpers.bash"

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

finish
