#!/usr/bin/env bash
# Every kind of bad input: one clear message on stderr that names the parameter
# (or file), a non-zero exit, and no results file created.
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"

# case NAME "sed expression on prm/default.prm" "text the message must contain"
case_() {
  local name=$1 edit=$2 expect=$3
  sed -e "$edit" "$src/prm/default.prm" > "$name.prm"
  sed -i "s|set Directory           = results|set Directory           = out-$name|" "$name.prm"
  "$exe" run "$name.prm" > "$name.out" 2> "$name.err"
  local rc=$?
  local ok=1
  [ $rc -ne 0 ] || { echo "FAIL $name: exit code 0"; ok=0; }
  grep -qF -- "$expect" "$name.err" || { echo "FAIL $name: stderr lacks '$expect':"; cat "$name.err"; ok=0; }
  [ ! -e "out-$name" ] || { echo "FAIL $name: output was created"; ok=0; }
  [ $ok -eq 1 ] && echo "ok   $name: $(head -c 200 "$name.err")" || failures=$((failures + 1))
}

case_ negative-disk     's/Disk radius (mm)    = 14/Disk radius (mm)    = -14/' "Geometry/Disk radius (mm) must be positive"
case_ zero-thickness    's/Film thickness (mm) = 1/Film thickness (mm) = 0/' "Geometry/Film thickness (mm) must be positive"
case_ frame-inside-disk 's/Frame radius (mm)   = 42/Frame radius (mm)   = 10/' "Geometry/Frame radius (mm) must be larger than"
case_ prestretch-one    's/Prestretch          = 2.5/Prestretch          = 1/' "Geometry/Prestretch must be larger than 1"
case_ zero-modulus      's/Shear modulus (kPa) = 25.1/Shear modulus (kPa) = 0/' "Material/Shear modulus (kPa) must be positive"
case_ negative-jlim     's/Jlim                = 270/Jlim                = -2/' "Material/Jlim must be positive"
case_ zero-permittivity 's/Permittivity (F\/m)  = 3.98e-11/Permittivity (F\/m)  = 0/' "Material/Permittivity (F/m) must be positive"
case_ negative-mass     's/Mass (g)            = 280/Mass (g)            = -5/' "Loading/Mass (g) must be zero or positive"
case_ gent-exceeded     's/Jlim                = 270/Jlim                = 9/' "already exceeds the Gent limit"
case_ edges-decreasing  's/Ring edges (r\/a)    = 1, 3/Ring edges (r\/a)    = 1, 2, 1.5, 3/' "Electrodes/Ring edges (r/a): edges must increase"
case_ edges-first       's/Ring edges (r\/a)    = 1, 3/Ring edges (r\/a)    = 1.2, 3/' "Electrodes/Ring edges (r/a): the first edge must be 1"
case_ edges-last        's/Ring edges (r\/a)    = 1, 3/Ring edges (r\/a)    = 1, 2.5/' "Electrodes/Ring edges (r/a): the last edge must be b/a"
case_ edges-text        's/Ring edges (r\/a)    = 1, 3/Ring edges (r\/a)    = 1, two, 3/' "Electrodes/Ring edges (r/a): 'two' is not a number"
case_ waypoint-count    's/Voltage path (kV)   = 5/Voltage path (kV)   = 5, 6/' "Electrodes/Voltage path (kV): waypoint"
case_ waypoint-negative 's/Voltage path (kV)   = 5/Voltage path (kV)   = -5/' "Electrodes/Voltage path (kV): voltages must not be negative"
case_ unknown-parameter 's/set Mass (g)            = 280/set Mass (kg) = 0.28/' "Mass (kg)"
case_ bad-number        's/Mass (g)            = 280/Mass (g)            = heavy/' "Mass (g)"
case_ unknown-section   's/subsection Loading/subsection Load/' "Load"

# A missing file, and a file that cannot be read.
"$exe" run does-not-exist.prm > /dev/null 2> missing.err
rc=$?
if [ $rc -ne 0 ] && grep -q "does-not-exist.prm" missing.err; then echo "ok   missing file"; else echo "FAIL missing file"; failures=$((failures + 1)); fi
cp "$src/prm/default.prm" unreadable.prm && chmod 000 unreadable.prm
if [ "$(id -u)" -ne 0 ]; then
  "$exe" run unreadable.prm > /dev/null 2> unreadable.err
  if [ $? -ne 0 ] && grep -q "unreadable.prm" unreadable.err; then echo "ok   unreadable file"; else echo "FAIL unreadable file"; failures=$((failures + 1)); fi
fi
# A directory given as the parameter file.
mkdir adir.prm
"$exe" run adir.prm > /dev/null 2> dir.err
if [ $? -ne 0 ] && grep -q "adir.prm" dir.err; then echo "ok   directory as file"; else echo "FAIL directory as file: $(cat dir.err)"; failures=$((failures + 1)); fi
# Unknown command.
"$exe" frobnicate > /dev/null 2>&1 && { echo "FAIL unknown command exits 0"; failures=$((failures + 1)); } || echo "ok   unknown command"

echo "$failures failed"
[ $failures -eq 0 ]
