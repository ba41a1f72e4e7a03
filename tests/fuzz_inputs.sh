#!/usr/bin/env bash
# Fuzzing of the inputs in-process (tests/fuzz_python.py): mutated fit CSVs
# through cdea.fit() (every 10th also through `cdea fit`) and mutated prm
# text with mutated overrides through cdea.parameters() and cdea.run(); no
# crash, hang, stack trace or message of more than one line. A fixed-seed
# sample; the issue's counts by hand:
#   PYTHONPATH=build/python /usr/bin/python3 tests/fuzz_python.py . build/cdea csv 1000 22
#   PYTHONPATH=build/python /usr/bin/python3 tests/fuzz_python.py . build/cdea prm 1000 22
source "$(dirname "$0")/script_helpers.bash"
export PYTHONPATH="$(dirname "$exe")/python"
for mode in "csv ${CDEA_FUZZ_CSV_CASES:-40}" "prm ${CDEA_FUZZ_PRM_CASES:-150}"; do
  set -- $mode
  if "$PYTHON" "$src/tests/fuzz_python.py" "$src" "$exe" "$1" "$2" 22 > "fuzz_$1.txt" 2>&1; then
    ok "$(head -1 "fuzz_$1.txt")"
  else
    fail "$1:"; tail -20 "fuzz_$1.txt"
  fi
done
echo "$failures failed"
[ $failures -eq 0 ]
