#!/usr/bin/env bash
# The structure of the code as doc/architecture.md states it ("Folder order"):
# tests/structure_check.py finds no include against the folder order, no
# include cycle between files, no function above 80 lines, no file above 600,
# no friend declaration in fe/ and no unit factor beyond the few allowed
# outside the table of quantities in the repository; and, so that the check
# itself cannot pass by finding nothing, it fails on a scratch tree with one
# of each and names every one of them.
source "$(dirname "$0")/script_helpers.bash"
check="$src/tests/structure_check.py"

if out=$("$PYTHON" "$check" "$src" 2>&1); then
  ok "the repository: ${out##*: }"
else
  fail "the repository has structure problems:"; echo "$out"
fi

# A scratch tree: folders a -> b -> fe, a file of a that includes b
# (upward), two files of b that include each other, a function of 93 lines, a
# file of 601 lines, a class of fe/ with a friend (one in a comment and one in
# a string do not count), one unit factor more than the check allows outside
# the table of quantities (one per line of a file; a tolerance 1e-9 * x,
# written before its scale, is not one) and a row of the table made outside it.
mkdir -p tree/doc tree/include/cdea/a tree/include/cdea/b tree/include/cdea/fe tree/source/a \
  tree/source/b
printf '# x\n## Folder order\n\n    a -> b -> fe\n' > tree/doc/architecture.md
printf '#pragma once\n#include <cdea/b/two.h>\n' > tree/include/cdea/a/up.h
printf '#pragma once\n#include <cdea/b/two.h>\n' > tree/include/cdea/b/one.h
printf '#pragma once\n#include <cdea/b/one.h>\n' > tree/include/cdea/b/two.h
{
  printf '#include <cdea/a/up.h>\nint long_function()\n{\n'
  for i in $(seq 1 90); do printf '  int x%d = %d;\n' "$i" "$i"; done
  printf '}\n'
} > tree/source/a/up.cc
for i in $(seq 1 601); do printf '// line %d\n' "$i"; done > tree/source/b/long_file.cc
printf '%s\n' '#pragma once' '// a friend of the model' 'const char *s = "friend";' \
  'class Model' '{' '  friend class Sensitivity;' '};' > tree/include/cdea/fe/model.h
allowed=$(sed -n 's/^MAX_UNIT_FACTORS = //p' "$check")
n_factors=$((allowed + 1))
{
  for i in $(seq 1 "$n_factors"); do printf 'double mm%d(double x) { return x * 1e3; }\n' "$i"; done
  printf 'bool near(double x, double y) { return x - y < 1e-9 * y; }\n'
  printf 'constexpr Quantity stroke{"stroke_mm"};\n'
} > tree/source/b/units.cc
if out=$("$PYTHON" "$check" tree 2>&1); then
  fail "structure_check passed a tree with seven problems"; echo "$out"
else
  ok "structure_check fails on the scratch tree"
  for expected in "a/up.h" "b/one -> b/two" "long_function" "long_file.cc: 601 lines" \
                  "fe/model.h:6: a friend declaration" \
                  "$n_factors unit factors outside" "units.cc:$((n_factors + 2)): a row of the table"; do
    if grep -q "$expected" <<< "$out"; then ok "names $expected"
    else fail "does not name $expected:"; echo "$out"; fi
  done
fi
finish
