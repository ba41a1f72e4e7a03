#!/usr/bin/env bash
# Old against new, in one invocation on one machine:
#  1. speed: the benchmarks bench_default (prm/default.prm, in-process runs and
#     whole `cdea run` processes), bench_sweep (prm/sweep-inner5.prm, the
#     full figure-8 map in-process), bench_optimize (optimize two and eight
#     rings, fit; whole processes) and bench_time (the pump's time run,
#     prm/pump-time.prm, in-process) of revision REV and of this tree, run
#     alternately ROUNDS times (old first in odd rounds, new first in even
#     ones); printed: the median over the rounds of each invocation's median,
#     the range over the rounds and the ratio new / old;
#  2. results: `cdea run` of both on the twelve scenes of
#     tests/test_validation_agreement.cc (benchmarks/validation_scenes.py,
#     default discretization and solver settings); printed: the largest
#     difference per /summary column.
#
#   benchmarks/compare_revisions.sh REV [ROUNDS]
#
# REV is built from `git archive` into build-<rev>/ next to build/ (ignored by
# git; reused by later calls, delete it to rebuild); this tree is built in
# build/ (or $NEW_BUILD_DIR). Both builds use at most $JOBS (2) jobs. All
# other output goes to a temporary folder that is removed at the end.
# Exit code: 0, or 1 if a build, a benchmark or a run fails, or the results
# differ in their rows.
set -euo pipefail

usage="usage: benchmarks/compare_revisions.sh REV [ROUNDS]"
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "$usage" >&2; exit 1; }
repo=$(cd "$(dirname "$0")/.." && pwd)
rounds=${2:-7}
[[ "$rounds" =~ ^[1-9][0-9]*$ ]] || { echo "compare_revisions: ROUNDS must be a positive integer, got '$rounds'" >&2; exit 1; }
rev=$(git -C "$repo" rev-parse --short=7 --verify "$1^{commit}" 2>/dev/null) ||
  { echo "compare_revisions: '$1' is not a revision of $repo" >&2; exit 1; }
jobs=${JOBS:-2}
old_dir="$repo/build-$rev"
new_build=${NEW_BUILD_DIR:-$repo/build}
python=/usr/bin/python3
scenes="$repo/benchmarks/validation_scenes.py"
targets=(--target cdea bench_default bench_sweep bench_optimize bench_time)

# --- builds -------------------------------------------------------------------
if [ ! -x "$old_dir/build/benchmarks/bench_time" ] || [ ! -x "$old_dir/build/cdea" ]; then
  echo "building $rev in $old_dir (once; delete the folder to rebuild)"
  rm -rf "$old_dir"
  mkdir -p "$old_dir/src"
  git -C "$repo" archive "$rev" | tar -x -C "$old_dir/src"
  cmake -S "$old_dir/src" -B "$old_dir/build" -DCMAKE_BUILD_TYPE=Release > "$old_dir/configure.log" 2>&1 ||
    { cat "$old_dir/configure.log" >&2; echo "compare_revisions: configuring $rev failed" >&2; exit 1; }
  cmake --build "$old_dir/build" -j "$jobs" "${targets[@]}" > "$old_dir/build.log" 2>&1 ||
    { tail -30 "$old_dir/build.log" >&2; echo "compare_revisions: building $rev failed" >&2; exit 1; }
fi
if [ ! -f "$new_build/CMakeCache.txt" ]; then
  cmake -S "$repo" -B "$new_build" -DCMAKE_BUILD_TYPE=Release > /dev/null
fi
cmake --build "$new_build" -j "$jobs" "${targets[@]}" > /dev/null ||
  { echo "compare_revisions: building this tree in $new_build failed" >&2; exit 1; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/cdea-compare.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

head_rev=$(git -C "$repo" rev-parse --short=7 HEAD)
dirty=""
[ -z "$(git -C "$repo" status --porcelain --untracked-files=no)" ] || dirty=" with uncommitted changes"
echo "old: $rev $(git -C "$repo" log -1 --format=%s "$rev")"
echo "new: $head_rev$dirty $(git -C "$repo" log -1 --format=%s HEAD)"
echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start"

# --- 1. speed -----------------------------------------------------------------
default_prm="$repo/prm/default.prm"
sweep_prm="$repo/prm/sweep-inner5.prm"
# Every figure goes into $tmp/times as a line "old|new quantity value".
bench() { # bench old|new PROGRAM ARGUMENTS...: its output into $tmp/log
  local which=$1 program=$2 dir
  shift 2
  [ "$which" = old ] && dir="$old_dir/build" || dir="$new_build"
  "$dir/benchmarks/$program" "$@" > "$tmp/log" 2>&1 ||
    { cat "$tmp/log" >&2; echo "compare_revisions: $which $program failed" >&2; exit 1; }
}
record() { # record old|new QUANTITY SED-PATTERN: the first match of \1 in $tmp/log
  echo "$1 $2 $(sed -n "s/$3/\1/p" "$tmp/log" | head -1)" >> "$tmp/times"
}
number='[^0-9]*\([0-9.eE+-]*\).*'
round() { # round old|new
  bench "$1" bench_default "$default_prm" 31 3
  record "$1" default_ms ".*median time per run:$number"
  record "$1" process_ms ".*cdea run\`, median of [0-9]*:$number"
  record "$1" default_work '^unknowns: \([0-9]*, converged steps: [0-9]*, Newton iterations: [0-9]*\).*'
  bench "$1" bench_sweep "$sweep_prm" 3 0
  record "$1" map_ms ".*median wall time of a map, in-process, 1 core:$number"
  record "$1" map_cpu_ms ".*median CPU time of a map, in-process:$number"
  record "$1" map_work '^\(equilibrium solves per map: [0-9]*, Newton iterations: [0-9]*\).*'
  bench "$1" bench_optimize 3 8 8
  record "$1" optimize2_s '^optimize: 2 rings[^,]*, [0-9]* starts *\([0-9.]*\).*'
  record "$1" optimize8_s '^optimize: 8 rings[^,]*, [0-9]* starts *\([0-9.]*\).*'
  record "$1" fit_s '^fit: [^0-9]*20 points *\([0-9.]*\).*'
  # CPU time of the process (user + system): less sensitive to other jobs.
  record "$1" optimize8_cpu_s '^optimize: 8 rings[^,]*, [0-9]* starts *[0-9.]* *[0-9.]* *\([0-9.]*\).*'
  record "$1" fit_cpu_s '^fit: [^0-9]*20 points *[0-9.]* *[0-9.]* *\([0-9.]*\).*'
  bench "$1" bench_time "$repo/prm/pump-time.prm" 0 3 1 0
  record "$1" time_ms ".*median time per run (no output):$number"
  record "$1" time_cpu_ms ".*median time per run (no output):[^(]*(CPU$number"
}
echo
echo "speed: $rounds rounds of bench_default ${default_prm#$repo/} 31 3, bench_sweep ${sweep_prm#$repo/} 3 0,"
echo "       bench_optimize 3 8 8 and bench_time prm/pump-time.prm 0 3 1 0"
for ((k = 1; k <= rounds; ++k)); do
  if ((k % 2)); then round old; round new; else round new; round old; fi
  echo "  round $k of $rounds done (load average $(cut -d' ' -f1 /proc/loadavg))"
done
"$python" - "$tmp/times" <<'EOF'
import statistics, sys
values = {}
for line in open(sys.argv[1]):
    which, quantity, value = line.rstrip("\n").split(" ", 2)
    values.setdefault(quantity, {}).setdefault(which, []).append(value)
labels = [("default_ms", "default case in-process, ms per run"),
          ("process_ms", "default case, whole `cdea run`, ms"),
          ("map_ms", "figure-8 map in-process, ms (wall)"),
          ("map_cpu_ms", "figure-8 map in-process, ms (CPU)"),
          ("optimize2_s", "optimize 2 rings, process, s"),
          ("optimize8_s", "optimize 8 rings, process, s"),
          ("optimize8_cpu_s", "optimize 8 rings, process, s (CPU)"),
          ("fit_s", "fit mu and Jlim, process, s"),
          ("fit_cpu_s", "fit mu and Jlim, process, s (CPU)"),
          ("time_ms", "pump time run in-process, ms"),
          ("time_cpu_ms", "pump time run in-process, ms (CPU)")]
print(f"{'quantity (median over rounds of the medians)':<46}{'old':>9}{'new':>9}{'new/old':>9}"
      "   range over the rounds: old; new")
for key, label in labels:
    old = [float(v) for v in values[key]["old"]]
    new = [float(v) for v in values[key]["new"]]
    mo, mn = statistics.median(old), statistics.median(new)
    print(f"{label:<46}{mo:9.4g}{mn:9.4g}{mn / mo:9.3f}   {min(old):.4g}-{max(old):.4g}; "
          f"{min(new):.4g}-{max(new):.4g}")
for key, label in [("default_work", "default case"), ("map_work", "map")]:
    for which in ("old", "new"):
        print(f"{label}, {which}: {' / '.join(sorted(set(values[key][which])))}")
EOF
echo "load average at the end of the timing: $(cut -d' ' -f1-3 /proc/loadavg)"

# --- 2. results ---------------------------------------------------------------
echo
echo "results: cdea run on the 12 scenes of tests/test_validation_agreement.cc"
status=0
for which in old new; do
  [ "$which" = old ] && exe="$old_dir/build/cdea" || exe="$new_build/cdea"
  "$python" "$scenes" write "$tmp/prm-$which" "$tmp/$which" > /dev/null
  for prm in "$tmp/prm-$which"/*.prm; do
    rc=0
    "$exe" run "$prm" > "$tmp/log" 2>&1 || rc=$?
    if [ $rc -ne 0 ]; then
      echo "  $which: $(basename "$prm" .prm) exit code $rc: $(tail -1 "$tmp/log")"
      status=1
    fi
  done
done
"$python" "$scenes" compare "$tmp/old" "$tmp/new" || status=1
exit $status
