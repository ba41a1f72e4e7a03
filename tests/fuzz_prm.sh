#!/usr/bin/env bash
# Fuzz test (tests/fuzz_prm.py): 500 mutated copies of prm/*.prm, seeded,
# no crash, hang, stack trace or leftover. CDEA_FUZZ_CASES and
# CDEA_FUZZ_SEED change the count and seed (doc/usage.md quotes 10,000).
set -eu
cd "$(mktemp -d)"
exec /usr/bin/python3 "${CDEA_SOURCE_DIR:?}/tests/fuzz_prm.py" "${CDEA_EXECUTABLE:?}" \
  "$CDEA_SOURCE_DIR" "${CDEA_FUZZ_CASES:-500}" "${CDEA_FUZZ_SEED:-13}" 2 2
