#!/usr/bin/env bash
# Fuzz test (tests/fuzz_prm.py): 500 mutated copies of prm/*.prm, seeded,
# no crash, hang, stack trace or leftover; each case runs at most 1.5 s before
# SIGINT (a sweep of a 2 x 2 map: at most 300 s, then it is a hang).
# CDEA_FUZZ_CASES, CDEA_FUZZ_SEED and CDEA_FUZZ_LIMIT change the count,
# seed and time limit (doc/usage.md quotes 10,000 cases).
set -u
work=$(mktemp -d)
cd "$work"
/usr/bin/python3 "${CDEA_SOURCE_DIR:?}/tests/fuzz_prm.py" "${CDEA_EXECUTABLE:?}" \
  "$CDEA_SOURCE_DIR" "${CDEA_FUZZ_CASES:-500}" "${CDEA_FUZZ_SEED:-13}" 2 "${CDEA_FUZZ_LIMIT:-1.5}"
rc=$?
# Failing inputs stay for a look; a clean run leaves nothing.
if [ $rc -eq 0 ]; then rm -rf "$work"; else echo "failing inputs: $work/fuzz-failures"; fi
exit $rc
