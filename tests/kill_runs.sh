#!/usr/bin/env bash
# Kill test (tests/kill_runs.py): 30 random SIGKILL/SIGINT/SIGTERM kills of a
# 1700-step run; every file left readable by h5py and h5dump, with every
# printed step, or the older results intact.
set -eu
exec /usr/bin/python3 "${CDEA_SOURCE_DIR:?}/tests/kill_runs.py" "${CDEA_EXECUTABLE:?}" \
  "$CDEA_SOURCE_DIR" "${CDEA_KILLS:-30}" "${CDEA_KILL_SEED:-20251123}"
