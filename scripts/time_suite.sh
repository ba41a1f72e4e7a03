#!/usr/bin/env bash
# Times the README's test command's ctest part as on a fresh build:
#   bash scripts/time_suite.sh [BUILD_DIR] [JOBS]
# removes BUILD_DIR/Testing/Temporary/CTestCostData.txt (so that ctest orders
# the tests by their COST properties, as after `scripts/setup.sh --all`), runs
# `ctest --test-dir BUILD_DIR --output-on-failure -jJOBS` (default: build, 2)
# and prints its wall time, the CPU time of ctest and all it waited for
# (user + system: on a shared machine the figure that load changes least;
# over 2 cores it bounds the wall time of -j2 from below), the sum of the
# tests' own times (the serial figure), the load average before and after,
# the ten longest tests and the failures. The log stays in
# BUILD_DIR/time_suite.log.
set -u
build=${1:-build}
jobs=${2:-2}
log="$build/time_suite.log"
rm -f "$build/Testing/Temporary/CTestCostData.txt"
before=$(cut -d' ' -f1-3 /proc/loadavg)
TIMEFORMAT='%R %U %S'
{ time ctest --test-dir "$build" --output-on-failure -j"$jobs" > "$log" 2>&1; } 2> "$log.time"
rc=0; grep -q "100% tests passed" "$log" || rc=1
read -r wall user sys < "$log.time"
after=$(cut -d' ' -f1-3 /proc/loadavg)
awk -v w="$wall" -v u="$user" -v y="$sys" -v b="$before" -v a="$after" -v j="$jobs" '
  / Test +#[0-9]+: / {
    for (i = 1; i <= NF; i++) if ($i == "sec") t = $(i - 1)
    name = $0; sub(/^.*Test +#[0-9]+: /, "", name); sub(/ .*/, "", name)
    sum += t; n++; times[name] = t
    if ($0 !~ /Passed/) failed = failed " " name
  }
  END {
    printf "ctest -j%d: %d tests, wall %.1f s, CPU %.1f s, sum of test times %.1f s\n", j, n, w, u + y, sum
    printf "load average (1, 5, 15 min) before: %s, after: %s\n", b, a
    printf "failed:%s\n", failed == "" ? " none" : failed
    print "ten longest (s):"
    for (k = 0; k < 10; k++) {
      best = ""; for (m in times) if (best == "" || times[m] > times[best]) best = m
      if (best == "") break
      printf "  %-32s %6.1f\n", best, times[best]; delete times[best]
    }
  }' "$log"
exit $rc
