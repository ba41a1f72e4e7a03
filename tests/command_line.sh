#!/usr/bin/env bash
# The command line around the solvers: cdea --version and --help (which lists
# every command); print-parameters --json
# (deal.II's JSON form) holding every entry of the .prm form with the same
# default; 'cdea run' under mpirun with two ranks refuses (one message, exit 1,
# nothing written) and runs with one; the Trilinos KLU solver, which starts
# MPI itself when it is first used, gives the banded LU's answer.
source "$(dirname "$0")/script_helpers.bash"

version=$("$exe" --version) && [[ "$version" =~ ^cdea\ [0-9]+\.[0-9]+\.[0-9]+\ \(deal\.II\ 9\.[0-9.]+\)$ ]] &&
  ok "--version: $version" || fail "--version: '$version'"

help=$("$exe" --help)
[[ "$help" == *"cdea --version"* && "$help" == *"cdea print-parameters --json"* ]] &&
  ok "--help lists --version and print-parameters --json" || fail "--help: $help"

"$exe" print-parameters > defaults.prm && "$exe" print-parameters --json > defaults.json &&
"$PYTHON" - <<'PY' && ok "print-parameters --json: the same entries and defaults as the .prm form" || fail "JSON defaults"
import json, re
tree = json.load(open("defaults.json"))
prm, path = {}, []
for line in open("defaults.prm"):
    line = line.split("#")[0].strip()
    if line.startswith("subsection "):
        path.append(line[len("subsection "):].strip())
    elif line == "end":
        path.pop()
    elif line.startswith("set "):
        name, value = line[4:].split("=", 1)
        prm[tuple(path + [name.strip()])] = value.strip()
def entries(node, path=()):
    for key, value in node.items():
        if "default_value" in value:
            yield path + (key,), value
        else:
            yield from entries(value, path + (key,))
js = dict(entries(tree))
bad = [k for k in prm if k not in js or js[k]["default_value"] != prm[k]]
assert len(prm) > 40 and not bad and len(js) == len(prm), (len(prm), len(js), bad[:3])
assert all(v["documentation"] for v in js.values()), "every entry documented"
assert js[("Output", "ParaView")]["pattern_description"] == "[Bool]"
PY

"$exe" print-parameters --xml > /dev/null 2> err.txt && fail "print-parameters --xml exits 0" ||
  ok "print-parameters --xml rejected"

if command -v mpirun > /dev/null; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
  mkdir two one
  (cd two && timeout 120 mpirun --oversubscribe -np 2 "$exe" run "$src/prm/default.prm" > out.txt 2> err.txt)
  rc=$?
  n=$(grep -c "is a serial job" two/err.txt)
  [ $rc -ne 0 ] && [ "$n" = 1 ] && [ ! -e two/results ] &&
    ok "mpirun -np 2 cdea run refuses: exit $rc, one message, nothing written" ||
    { fail "mpirun -np 2 cdea run: exit $rc, $n messages"; cat two/err.txt; ls two; }
  (cd one && timeout 120 mpirun -np 1 "$exe" run "$src/prm/default.prm" > out.txt 2> err.txt)
  rc=$?
  [ $rc -eq 0 ] && [ -s one/results/default.h5 ] && ok "mpirun -np 1 cdea run runs" ||
    { fail "mpirun -np 1: exit $rc"; cat one/err.txt; }
else
  fail "mpirun not found (Debian: openmpi-bin)"
fi

sed 's/set Base name           = default/set Base name           = klu/' "$src/prm/default.prm" > klu.prm
printf 'subsection Solver\n  set Linear solver = Trilinos KLU\nend\n' >> klu.prm
"$exe" run "$src/prm/default.prm" > lu.txt 2>&1 && "$exe" run klu.prm > klu.txt 2>&1 &&
"$PYTHON" - <<'PY' && ok "Trilinos KLU (MPI started on first use) = banded LU to 1e-12 mm" || { fail "Trilinos KLU run"; tail -3 klu.txt; }
import h5py, numpy as np
a = h5py.File("results/default.h5", "r")["summary/displacement_mm"][:]
b = h5py.File("results/klu.h5", "r")["summary/displacement_mm"][:]
assert a.shape == b.shape and np.max(np.abs(a - b)) < 1e-12, np.max(np.abs(a - b))
PY

finish
