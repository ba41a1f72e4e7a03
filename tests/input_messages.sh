#!/usr/bin/env bash
# Bad input of issue 13: exit 1 naming the parameter, at once, nothing left
# behind, one short line (no deal.II stack trace, a 1 MB value not echoed
# whole); duplicate entries warned; trailing separators refused alike by run
# and sweep; step table columns apart for t >= 1000; a sweep none of whose
# layouts reaches the inner voltage exits 2 and says so.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"

# bad NAME "sed expression on prm/default.prm" "text the message must contain" [PRM]
# (with PRM, that file with the edit instead of prm/default.prm)
bad() {
  local name=$1 edit=$2 expect=$3
  sed -e "$edit" -e "s|set Directory           = results|set Directory           = out-$name/sub|" \
      "${4:-$src/prm/default.prm}" > "$name.prm"
  timeout 20 "$exe" run "$name.prm" > "$name.out" 2> "$name.err"
  local rc=$? ok=1
  [ $rc -eq 1 ] || { fail "$name: exit $rc, expected 1"; ok=0; }
  grep -qF -- "$expect" "$name.err" || { fail "$name: stderr lacks '$expect': $(head -c 300 "$name.err")"; ok=0; }
  [ "$(wc -l < "$name.err")" -eq 1 ] && [ "$(wc -c < "$name.err")" -lt 1600 ] \
    || { fail "$name: stderr is not one short line ($(wc -c < "$name.err") bytes)"; ok=0; }
  ! grep -qiE "stacktrace|-----|An error occurred in line" "$name.err" || { fail "$name: deal.II trace"; ok=0; }
  [ ! -e "out-$name" ] || { fail "$name: left out-$name behind"; ok=0; }
  [ $ok -eq 1 ] && ok "$name: $(head -c 160 "$name.err")"
}
v='s/set Voltage path (kV)   = 5/set Voltage path (kV)   = '
bad tiny-thickness  's/Film thickness (mm) = 1$/Film thickness (mm) = 1e-320/' "Film thickness (mm)"
bad tiny-disk       's/Disk radius (mm)    = 14/Disk radius (mm)    = 1e-320/' "Disk radius (mm)"
bad tiny-permittivity 's/Permittivity (F\/m)  = 3.98e-11/Permittivity (F\/m)  = 1e-320/' "Permittivity (F/m)"
bad small-permittivity 's/Permittivity (F\/m)  = 3.98e-11/Permittivity (F\/m)  = 1e-13/' "Material/Permittivity (F/m) must be between"
bad huge-voltage    "${v}1e306/" "Electrodes/Voltage path (kV): 1e+306 kV is above the ceiling of 1600 kV"
bad huge-modulus    's/Shear modulus (kPa) = 25.1/Shear modulus (kPa) = 1.7e306/' "Material/Shear modulus (kPa) must be between 1e-12 and 1e+12"
bad hang-1e16       "${v}5; 1e16/" "Electrodes/Voltage path (kV): 1e+16 kV is above the ceiling"
bad hang-3e15       "${v}5; 3e15/" "Electrodes/Voltage path (kV): 3e+15 kV is above the ceiling"
bad huge-mass       's/Mass (g)            = 280/Mass (g)            = 1e13/' "Loading/Mass (g) must be 0 or between"
bad huge-frame      's/Disk radius (mm)    = 14/Disk radius (mm)    = 0.01/; s/Ring edges (r\/a)    = 1, 3/Ring edges (r\/a)    = 1, 4200/' "Geometry/Frame radius (mm) / Geometry/Disk radius (mm) must be between 1 and 1000"
bad trailing-comma  "${v}5,/" "Electrodes/Voltage path (kV): empty entry at the end of '5,'"
bad trailing-semicolon "${v}5;/" "Electrodes/Voltage path (kV): empty waypoint at the end of '5;'"
bad edges-trailing  's/Ring edges (r\/a)    = 1, 3/Ring edges (r\/a)    = 1, 3,/' "Electrodes/Ring edges (r/a): empty entry at the end"
bad long-base-name  "s/set Base name           = default/set Base name           = $(printf 'b%.0s' $(seq 300))/" "Output/Base name must have at most 200 characters, got 300"
# 1 MB values (made by python: too long for a command line)
/usr/bin/python3 - "$src/prm/default.prm" <<'PY'
import sys
text = open(sys.argv[1]).read()
mega = "7" * 1000000 + "x"
open("mega-path.in", "w").write(text.replace("Voltage path (kV)   = 5", "Voltage path (kV)   = " + mega))
open("mega-mass.in", "w").write(text.replace("Mass (g)            = 280", "Mass (g)            = " + mega))
# 300,001 equal waypoints: at least one step each, past the in-memory cap
repeated = "; ".join(["5"] * 300001) + " x"
open("repeated.in", "w").write(text.replace("Voltage path (kV)   = 5", "Voltage path (kV)   = " + repeated))
PY
bad repeated-waypoints 's/ x$//' "the results of at least 300025 steps" repeated.in
bad mega-value      's/x/x/' "Electrodes/Voltage path (kV): '777777" mega-path.in
[ "$(grep -o "characters\]" mega-value.err | wc -l)" -eq 1 ] && ok "mega-value: the value echoed once" \
  || fail "mega-value: the value is echoed $(grep -o "characters\]" mega-value.err | wc -l) times"
bad mega-pattern    's/x/x/' "Mass (g)" mega-mass.in
sed -e 's|set Directory           = results|set Directory           = out-steps|' "$src/prm/default.prm" > steps.prm
printf 'subsection Solver\n  set Voltage increment (kV) = 1e-8\n  set Min voltage increment (kV) = 1e-9\nend\n' >> steps.prm
"$exe" run steps.prm > /dev/null 2> steps.err
[ $? -eq 1 ] && grep -q "the run would take at least 5e+08 steps" steps.err && [ ! -e out-steps ] \
  && ok "too many steps: $(cat steps.err)" || fail "too many steps: $(cat steps.err)"

# Duplicate entries: a warning naming both lines; the last value is used.
sed -e 's/  set Mass (g)            = 280/  set Mass (g)            = 280\n  set Mass (g) = 300/' \
    -e 's|set Directory           = results|set Directory           = out-dup|' "$src/prm/default.prm" > dup.prm
"$exe" run dup.prm > dup.out 2> dup.err
rc=$?
if [ $rc -eq 0 ] && grep -q "dup.prm line 24: Loading/Mass (g) is set again (first on line 23); the last value is used" dup.err &&
   /usr/bin/python3 -c "import h5py,sys; sys.exit(int(h5py.File('out-dup/default.h5')['summary/mass_g'][-1] != 300))"; then
  ok "duplicate entry warned, last value used: $(cat dup.err)"
else fail "duplicate entry: exit $rc, $(cat dup.err)"; fi

# Trailing separators: sweep refuses them like run.
sed -e 's/set Ring edge values (r\/a)   = 1.2, 1.25, ..., 2.6/set Ring edge values (r\/a)   = 1.2, 1.4,/' \
    -e 's|set Directory           = results|set Directory           = out-sweep|' "$src/prm/sweep-inner5.prm" > sweep-trailing.prm
"$exe" sweep sweep-trailing.prm > /dev/null 2> sweep-trailing.err
[ $? -eq 1 ] && grep -q "Sweep/Ring edge values (r/a): empty entry at the end of" sweep-trailing.err && [ ! -e out-sweep ] \
  && ok "sweep: $(cat sweep-trailing.err)" || fail "sweep trailing separator: $(cat sweep-trailing.err)"
# ... and run refuses the same file with the same message (every command checks
# the Sweep lists).
timeout 60 "$exe" run sweep-trailing.prm > /dev/null 2> run-trailing.err
[ $? -eq 1 ] && cmp -s sweep-trailing.err run-trailing.err && [ ! -e out-sweep ] \
  && ok "run: the same verdict: $(cat run-trailing.err)" \
  || fail "run on the sweep file with a trailing ',': $(cat run-trailing.err)"

# Step table: t >= 1000 keeps a blank before it (1005 waypoints at 1 kV).
path=$(printf '1; %.0s' $(seq 1005))1
sed -e "s/set Voltage path (kV)   = 5/set Voltage path (kV)   = $path/" \
    -e 's|set Directory           = results|set Directory           = out-columns|' "$src/prm/default.prm" > columns.prm
"$exe" run columns.prm > columns.out 2> columns.err
if [ $? -eq 0 ] && grep -qE '^ +[0-9]+ +voltage +1005\.00000 +1\.000 ' columns.out; then
  ok "columns apart at t = 1005: $(grep -E ' 1005\.00000 ' columns.out | head -1)"
else fail "columns at t >= 1000: $(grep -E '1005\.0' columns.out | head -1)"; fi

# A sweep none of whose layouts reaches the inner voltage: exit 2, said so,
# the map (with each row's reason) written.
sed -e 's/set Ring edge values (r\/a)   = 1.2, 1.25, ..., 2.6/set Ring edge values (r\/a)   = 1.5, 2/' \
    -e 's/set Inner voltage (kV)       = 5$/set Inner voltage (kV)       = 9/' \
    -e 's/set Outer voltage range (kV) = 5, 8, 0.05/set Outer voltage range (kV) = 9, 9.5, 0.5/' \
    -e 's|set Directory           = results|set Directory           = out-unreached|' "$src/prm/sweep-inner5.prm" > unreached.prm
CDEA_PROGRESS=off "$exe" sweep unreached.prm > unreached.out 2> unreached.err
rc=$?
if [ $rc -eq 2 ] && grep -q "no layout reached the inner voltage of 9 kV" unreached.err && [ -s out-unreached/sweep-inner5_map.h5 ]; then
  ok "sweep with no layout reaching 9 kV: exit 2: $(head -c 200 unreached.err)"
else fail "unreachable sweep: exit $rc, $(cat unreached.err)"; fi

echo "$failures failed"
[ $failures -eq 0 ]
