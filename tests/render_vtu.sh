#!/usr/bin/env bash
# postprocess/render_vtu.py on the ParaView output of real runs with one and
# with two rings (the title formats every ring's voltage from the step's field
# data): a non-empty PNG and exit 0 for each; a missing collection gives a
# message and a non-zero exit, and no PNG.
source "$(dirname "$0")/script_helpers.bash"
script="$src/postprocess/render_vtu.py"
if ! "$PYTHON" -c "import vtk, matplotlib" 2>/dev/null; then
  fail "python3 lacks vtk or matplotlib"; finish; exit
fi
cp -r "$src/prm" prm
for layout in "1, 3|5" "1, 1.7, 3|5, 4"; do
  edges=${layout%|*} volts=${layout#*|}
  rings=$(($(tr -cd ',' <<< "$edges" | wc -c)))
  out="out$rings"
  if ! "$exe" run prm/paraview.prm --set "Electrodes/Ring edges (r/a)=$edges" \
       --set "Electrodes/Voltage path (kV)=$volts" --set "Output/Directory=$out" > run.log 2>&1; then
    fail "$rings ring(s): cdea run failed: $(tail -3 run.log)"; continue
  fi
  if "$PYTHON" "$script" "$out/paraview.pvd" "ring$rings.png" > render.log 2>&1 &&
     [ -s "ring$rings.png" ]; then
    ok "$rings ring(s) ($volts kV): ring$rings.png, $(stat -c %s "ring$rings.png") bytes"
  else
    fail "$rings ring(s): render_vtu.py failed: $(tail -3 render.log)"
  fi
done
if "$PYTHON" "$script" missing.pvd missing.png > render.log 2>&1; then
  fail "a missing collection gave exit 0"
elif [ -e missing.png ] || ! grep -q "missing.pvd" render.log; then
  fail "a missing collection: a PNG left or no message naming it: $(cat render.log)"
else
  ok "a missing collection: $(tail -1 render.log)"
fi
finish
