#!/usr/bin/env bash
# Kill test (tests/kill_runs.py): 12 SIGKILL/SIGINT/SIGTERM kills of a
# 1700-step run at moments relative to its timed duration, every outcome class
# among them (CDEA_KILLS, CDEA_KILL_SEED override the count and the seed);
# every file left readable by h5py and h5dump, with every
# printed step, or the older results intact. The killed runs are the real
# executable; the short run before them and `cdea recover` after them run in
# forks of one loaded program (tests/cdea_forks.bash).
source "$(dirname "$0")/script_helpers.bash"
source "$(dirname "$0")/cdea_forks.bash"
"$PYTHON" "$src/tests/kill_runs.py" "$real_exe" "$src" "${CDEA_KILLS:-12}" \
  "${CDEA_KILL_SEED:-20251123}" "$exe"
