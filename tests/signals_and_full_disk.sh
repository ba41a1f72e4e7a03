#!/usr/bin/env bash
# A fixed-seed sample of tests/signal_trials.py (SIGINT, SIGTERM or SIGHUP
# at a random moment in every command: exit 2 with a message, or ended
# before, or killed before any output; the older file kept, readable results
# beside it, no lock) and of tests/disk_full_trials.py (a tmpfs too small for
# a run, a map, a frequency sweep, a response or a chart: exit 2, the older
# file byte-identical, the partial result readable; skipped without root).
# The issue's counts by hand:
#   /usr/bin/python3 tests/signal_trials.py build/cdea . 20 2026
#   /usr/bin/python3 tests/disk_full_trials.py build/cdea . 20 2026
source "$(dirname "$0")/script_helpers.bash"
if "$PYTHON" "$src/tests/signal_trials.py" "$exe" "$src" 1 11 > signals.txt 2>&1; then
  ok "signals: $(grep -c trials signals.txt) commands, $(tail -1 signals.txt)"
else
  fail "signals:"; cat signals.txt
fi
if "$PYTHON" "$src/tests/disk_full_trials.py" "$exe" "$src" 2 3 > disk.txt 2>&1; then
  ok "full disk: $(tail -1 disk.txt)"
else
  fail "full disk:"; cat disk.txt
fi
# (the commands that write one file of the same size each time: a disk
# filled after the older file)
if "$PYTHON" "$src/tests/disk_full_trials.py" "$exe" "$src" 3 3 frequency-sweep,response,chart \
   > disk2.txt 2>&1; then
  ok "full disk, frequency-sweep, response, chart: $(tail -1 disk2.txt)"
else
  fail "full disk, frequency-sweep, response, chart:"; cat disk2.txt
fi
finish
