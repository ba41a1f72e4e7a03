#!/usr/bin/env bash
# Fuzz test (tests/fuzz_prm.py): 500 mutated copies of prm/*.prm, seeded,
# no crash, hang, stack trace or leftover; each case runs at most 1.5 s before
# SIGINT (a sweep of a 2 x 2 map: at most 300 s, then it is a hang).
# CDEA_FUZZ_CASES, CDEA_FUZZ_SEED and CDEA_FUZZ_LIMIT change the count,
# seed and time limit (doc/usage.md quotes 10,000 cases). The cases run in
# forks of one loaded program (tests/cdea_forks.bash), four at a time: each
# waits on its process for part of its time, and with two at a time the test
# kept only 1.25 of its two cores busy (13.3 s against 8.9 s with four).
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"
"$PYTHON" "$src/tests/fuzz_prm.py" "$exe" "$src" "${CDEA_FUZZ_CASES:-500}" "${CDEA_FUZZ_SEED:-13}" 4 \
  "${CDEA_FUZZ_LIMIT:-1.5}"
rc=$?
# Failing inputs stay for a look; a clean run leaves nothing.
if [ $rc -ne 0 ]; then
  kept=$(mktemp -d)
  mv "$work/fuzz-failures" "$kept/" && echo "failing inputs: $kept/fuzz-failures"
fi
exit $rc
